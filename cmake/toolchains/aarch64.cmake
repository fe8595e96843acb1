# 64-bit ARM (little-endian): long double is IEEE binary128, in software.
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(GIZMO_CROSS_TRIPLE aarch64-linux-gnu)
set(GIZMO_MULTIARCH aarch64-linux-gnu)
set(GIZMO_QEMU qemu-aarch64)
include(${CMAKE_CURRENT_LIST_DIR}/linux-cross.cmake)
