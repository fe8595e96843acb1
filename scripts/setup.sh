#!/usr/bin/env bash
# Installs the Debian 12 packages that gizmo builds and tests with, when any is missing, and then
# the npm package that the Box2D v3 cross-check runs under node (scripts/setup-box2d3.sh); with
# --portable, only those of the portable `gizmo` command (what a first `scripts/dev run` builds,
# so that it waits for no multiprecision library, test library or gnuplot); with --command, those
# of the full command; or, given package names, those instead (tests/slurm/run.sh: slurm-wlm munge).
# Non-interactive and idempotent: when everything is present it only checks and returns.
#   scripts/setup.sh [--portable | --command | PACKAGE...]
set -euo pipefail

# The portable build of the `gizmo` command (what a first `scripts/dev run` builds; every build
# compiles through ccache, cmake/GizmoCompilerCache.cmake), then the
# libraries the full command adds (multiprecision, Box2D).
portable_packages=(cmake ninja-build g++ ccache pkgconf libpugixml-dev libcli11-dev nlohmann-json3-dev)
command_packages=("${portable_packages[@]}" libboost-dev libgmp-dev libmpfr-dev libmpfi-dev libbox2d-dev)
# The tests, the benchmarks and the study's charts (gizmo study runs gnuplot).
test_packages=(libgtest-dev libgmock-dev libbenchmark-dev librapidcheck-dev gnuplot-nox)
packages=("${command_packages[@]}" "${test_packages[@]}")
# The tests run Box2D v3 too (docs/verification.md, "Box2D v3"): only the full set installs it.
with_box2d3=false
[ $# -eq 0 ] && with_box2d3=true
if [ "${1:-}" = --portable ]; then
  packages=("${portable_packages[@]}")
elif [ "${1:-}" = --command ]; then
  packages=("${command_packages[@]}")
elif [ $# -gt 0 ]; then
  packages=("$@")
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  "$(dirname "$0")/apt-install.sh" "${missing[@]}"
fi
if $with_box2d3; then
  exec "$(dirname "$0")/setup-box2d3.sh"
fi
