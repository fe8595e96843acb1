# The host's g++ at its highest optimisation (vectorisation, inlining across the board).
set(CMAKE_CXX_COMPILER g++)
set(CMAKE_CXX_FLAGS_RELEASE_INIT "-O3 -DNDEBUG")
