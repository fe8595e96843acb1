# The host's g++ without optimisation: every value goes through memory, nothing is reordered or
# folded, so the bits it gives are those of the source as written.
set(CMAKE_CXX_COMPILER g++)
set(CMAKE_CXX_FLAGS_RELEASE_INIT "-O0")
