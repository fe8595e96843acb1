# What every Linux cross target shares (docs/determinism.md, "Adding a target"). The target's own
# file sets GIZMO_CROSS_TRIPLE (the compiler's prefix), GIZMO_MULTIARCH (Debian's folder for the
# target's libraries, /usr/lib/GIZMO_MULTIARCH) and GIZMO_QEMU, then includes this one.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_CXX_COMPILER ${GIZMO_CROSS_TRIPLE}-g++)
# Debian's cross compilers search /usr/include and /usr/lib/TRIPLE themselves, so the target's
# multiarch packages (libpugixml-dev:ARCH) and the header-only ones are found without a sysroot.
set(CMAKE_LIBRARY_ARCHITECTURE ${GIZMO_MULTIARCH})
# Programs built for the target run through qemu-user (-L: the cross compiler's folder as the
# target's root). They are linked statically: dynamically linked, the cross compiler's loader
# (Debian's libc6-ARCH-cross) met the C library of the multiarch packages (libc6:ARCH, a newer
# revision) and s390x programs died at start ("stack smashing detected").
set(CMAKE_CROSSCOMPILING_EMULATOR ${GIZMO_QEMU} -L /usr/${GIZMO_CROSS_TRIPLE})
set(CMAKE_EXE_LINKER_FLAGS_INIT -static)
