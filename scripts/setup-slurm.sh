#!/usr/bin/env bash
# Installs Debian's Slurm and munge for the cluster test (tests/slurm), when either is missing.
# Non-interactive and idempotent: when both are there it only checks and returns. The packages'
# own services are not used: the test starts its daemons itself, with a configuration of its own.
set -euo pipefail

packages=(slurm-wlm munge)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup-slurm: installing ${missing[*]}" >&2
run_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }
export DEBIAN_FRONTEND=noninteractive
run_root apt-get update -qq
run_root apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
