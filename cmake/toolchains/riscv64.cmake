# 64-bit RISC-V (RV64GC, little-endian): long double is IEEE binary128, in software. Debian 12 has
# no riscv64 packages, so no pugixml: this target reads text boards only.
set(CMAKE_SYSTEM_PROCESSOR riscv64)
set(GIZMO_CROSS_TRIPLE riscv64-linux-gnu)
set(GIZMO_MULTIARCH riscv64-linux-gnu)
set(GIZMO_QEMU qemu-riscv64)
include(${CMAKE_CURRENT_LIST_DIR}/linux-cross.cmake)
