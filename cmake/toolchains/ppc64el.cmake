# 64-bit POWER, little-endian: long double is IBM's double-double (two doubles), GCC 12's default.
set(CMAKE_SYSTEM_PROCESSOR ppc64le)
set(GIZMO_CROSS_TRIPLE powerpc64le-linux-gnu)
set(GIZMO_MULTIARCH powerpc64le-linux-gnu)
set(GIZMO_QEMU qemu-ppc64le)
include(${CMAKE_CURRENT_LIST_DIR}/linux-cross.cmake)
