# The host, compiled by clang instead of g++ (their code generation differs: a second opinion on
# the flags that keep arithmetic as written).
set(CMAKE_CXX_COMPILER clang++)
