#!/usr/bin/env bash
# scripts/dev cross TARGET: the portable build (docs/determinism.md) for one target, into
# build/cross-TARGET: the command at build/cross-TARGET/cli/gizmo (cli/gizmo.js for wasm32, run by
# node), and build/cross-TARGET/gizmo-run, which runs it on this machine (through qemu-user or
# node). Installs what the target needs first (scripts/setup-cross.sh). Warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
targets="x86_64-gcc-O0 x86_64-gcc-O3 x86_64-clang i686 aarch64 riscv64 ppc64el s390x wasm32"
target=${1:-}
if [ -z "$target" ] || ! [[ " $targets " == *" $target "* ]]; then
  echo "usage: scripts/dev cross TARGET, TARGET one of: $targets" >&2
  exit 2
fi
scripts/setup-cross.sh "$target"
# emscripten's optimiser runs under node and needs Debian's node modules (acorn).
[ "$target" = wasm32 ] && export NODE_PATH=/usr/share/nodejs
dir=build/cross-$target
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DGIZMO_PORTABLE=ON \
  -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/toolchains/$target.cmake" -DCMAKE_COMPILE_WARNING_AS_ERROR=ON >/dev/null
cmake --build "$dir" -j2
