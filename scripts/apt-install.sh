#!/usr/bin/env bash
# Installs Debian packages by name, as root (through sudo otherwise), non-interactively: the one
# place where the set-up scripts (setup.sh, setup-cross.sh, setup-browser.sh, fuzz-run.sh) talk
# to the package registry.
#   scripts/apt-install.sh PACKAGE...
# A registry in the middle of a sync serves index files of the wrong size for a while ("File has
# unexpected size ... Mirror sync in progress?"), and `apt-get update` then fails although most
# indexes are fine: seen on this project's machines for the i386 and ppc64el security indexes.
# So a failed update is only a warning, the install is what must succeed, and a failed install
# is tried again after a pause with a fresh update (four tries, 30 s apart).
set -uo pipefail
[ $# -gt 0 ] || { echo "usage: scripts/apt-install.sh PACKAGE..." >&2; exit 2; }
run_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }
export DEBIAN_FRONTEND=noninteractive
for try in 1 2 3 4; do
  run_root apt-get update -qq || echo "apt-install: 'apt-get update' failed (try $try); installing with the indexes it has" >&2
  run_root apt-get install -y -qq --no-install-recommends "$@" >&2 && exit 0
  [ "$try" -lt 4 ] && { echo "apt-install: installing $* failed (try $try of 4); again in 30 s" >&2; sleep 30; }
done
echo "apt-install: could not install $*" >&2
exit 1
