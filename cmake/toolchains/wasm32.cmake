# WebAssembly through Debian's emscripten (3.1.6). long double is IEEE binary128, in software.
# C++ exceptions as WebAssembly exceptions (node 20 runs them): the readers and the command report
# bad input by throwing, and emscripten's default would abort instead. Every object must use the
# same model, so the flag is set here for every target, including a web page's own (issue 21).
include(/usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake)
set(CMAKE_CXX_FLAGS_INIT "-fwasm-exceptions")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-fwasm-exceptions")
set(CMAKE_CROSSCOMPILING_EMULATOR node)
