#!/usr/bin/env bash
# Installs what `scripts/dev cross TARGET` needs for one target, when any of it is missing: the
# cross compiler, qemu-user and the target's pugixml (Debian multiarch), or emscripten for wasm32.
# Non-interactive and idempotent, like scripts/setup.sh: when everything is there it only checks.
#   scripts/setup-cross.sh TARGET...
set -euo pipefail

# riscv64 is not one of Debian 12's release architectures, so its registry has no riscv64
# pugixml: that target, like wasm32, reads text boards only.
arch_of() {  # the Debian architecture of a target's multiarch libraries ("" for none)
  case "$1" in
    i686) echo i386 ;;
    aarch64) echo arm64 ;;
    ppc64el) echo ppc64el ;;
    s390x) echo s390x ;;
    *) echo "" ;;
  esac
}

packages=()
archs=()
for target in "$@"; do
  case "$target" in
    x86_64-gcc-O0 | x86_64-gcc-O3) packages+=(g++ libpugixml-dev) ;;
    x86_64-clang) packages+=(clang libpugixml-dev) ;;
    i686) packages+=(g++-i686-linux-gnu) ;;
    aarch64) packages+=(g++-aarch64-linux-gnu) ;;
    riscv64) packages+=(g++-riscv64-linux-gnu) ;;
    ppc64el) packages+=(g++-powerpc64le-linux-gnu) ;;
    s390x) packages+=(g++-s390x-linux-gnu) ;;
    wasm32) packages+=(emscripten) ;;
    *) echo "setup-cross: unknown target '$target'" >&2; exit 2 ;;
  esac
  arch=$(arch_of "$target")
  case "$target" in x86_64-* | wasm32) ;; *) packages+=(qemu-user) ;; esac
  if [ -n "$arch" ]; then
    packages+=("libpugixml-dev:$arch")
    archs+=("$arch")
  fi
  # CLI11 and nlohmann-json are headers only, the same for every target.
  packages+=(libcli11-dev nlohmann-json3-dev cmake ninja-build)
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

run_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }
export DEBIAN_FRONTEND=noninteractive
for arch in "${archs[@]}"; do
  dpkg --print-foreign-architectures | grep -qx "$arch" || run_root dpkg --add-architecture "$arch"
done
echo "setup-cross: installing ${missing[*]}" >&2
exec "$(dirname "$0")/apt-install.sh" "${missing[@]}"
