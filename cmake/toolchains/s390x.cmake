# IBM Z, big-endian: the log's little-endian bytes are written and read by byte order, not by
# memory layout. long double is IEEE binary128 (in hardware on z14 and later, in software before).
set(CMAKE_SYSTEM_PROCESSOR s390x)
set(GIZMO_CROSS_TRIPLE s390x-linux-gnu)
set(GIZMO_MULTIARCH s390x-linux-gnu)
set(GIZMO_QEMU qemu-s390x)
include(${CMAKE_CURRENT_LIST_DIR}/linux-cross.cmake)
