# 32-bit x86. GCC's default for i686 computes float and double on the x87 unit, in 80-bit
# registers, and rounds to the type only when it stores a value: the same source gives other bits
# than on every other target, and different bits again at another optimisation level. SSE2 rounds
# each operation to its type, as IEEE 754 says: -msse2 -mfpmath=sse (any x86 CPU since 2001 has
# it). long double stays on the x87 unit, which is its format (x87-extended80, as on x86-64).
set(CMAKE_SYSTEM_PROCESSOR i686)
set(GIZMO_CROSS_TRIPLE i686-linux-gnu)
set(GIZMO_MULTIARCH i386-linux-gnu)
set(GIZMO_QEMU qemu-i386)
set(CMAKE_CXX_FLAGS_INIT "-msse2 -mfpmath=sse")
include(${CMAKE_CURRENT_LIST_DIR}/linux-cross.cmake)
