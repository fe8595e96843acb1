#!/usr/bin/env bash
# Installs the Debian 12 packages that gizmo builds and tests with, when any is missing; or, given
# package names, those instead (tests/slurm/run.sh: slurm-wlm munge).
# Non-interactive and idempotent: when everything is present it only checks and returns.
#   scripts/setup.sh [PACKAGE...]
set -euo pipefail

packages=(
  cmake ninja-build g++ pkgconf
  libgtest-dev libgmock-dev libbenchmark-dev
  libboost-dev libgmp-dev libmpfr-dev libmpfi-dev
  libpugixml-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  librapidcheck-dev libbox2d-dev
  gnuplot-nox
)
[ $# -gt 0 ] && packages=("$@")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
run_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }
export DEBIAN_FRONTEND=noninteractive
run_root apt-get update -qq
run_root apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
