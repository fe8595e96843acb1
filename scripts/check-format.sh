#!/usr/bin/env bash
# Checks that every C++ source git tracks (fixtures/ aside) is laid out as .clang-format says, with
# clang-format 14, Debian 12's (installed when missing; another version may lay out a line
# differently). Prints each file that differs with the first lines of the difference, and exits 1
# when there is one.
#   scripts/check-format.sh         check
#   scripts/check-format.sh --fix   rewrite the files that differ in place
set -euo pipefail
cd "$(dirname "$0")/.."
format=clang-format-14
command -v "$format" >/dev/null || scripts/apt-install.sh clang-format-14
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' | grep -v '^fixtures/')
if [ "${1:-}" = --fix ]; then
  "$format" -i "${files[@]}"
  echo "check-format: laid out ${#files[@]} files"
  exit 0
fi
differing=0
for f in "${files[@]}"; do
  if ! difference=$("$format" "$f" | diff -u "$f" -); then
    echo "$difference" | head -20
    differing=$((differing + 1))
  fi
done
if [ "$differing" -gt 0 ]; then
  echo "check-format: $differing of ${#files[@]} files differ from .clang-format's layout (scripts/check-format.sh --fix)" >&2
  exit 1
fi
echo "check-format: every C++ source follows .clang-format (${#files[@]} files)"
