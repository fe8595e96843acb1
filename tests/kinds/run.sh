#!/usr/bin/env bash
# docs/design.md's recipe "Adding a gizmo", followed on a copy of the tree so that the recipe stays
# true: a thirteenth kind, the bouncer, that only this trial registers (tests/kinds/bouncer/: its
# core file with its behaviour class, its verify file, its drawing file and its example board), is
# added to the copy by those four files and one line at the end of the kind list, and nothing else.
# The copy is then built (the gizmo command and the verify tests) and must hold the kind everywhere:
# the registry's tests walk it with every other kind (read, written and read again in both formats,
# built and run, its entries true of its gizmo, generated), `gizmo run` simulates its board, `gizmo
# render` draws it in its class, and a fuzz campaign generates boards with it and checks them.
# Usage: tests/kinds/run.sh [WORK_DIR] (default build/kind-trial: the copy in WORK_DIR/src, built in
# its build/release).
set -euo pipefail
cd "$(dirname "$0")/../.."
work=${1:-build/kind-trial}
mkdir -p "$work"
work=$(cd "$work" && pwd)
src=$work/src
trial=tests/kinds/bouncer

# The tracked files as they are in the working tree, copied afresh.
rm -rf "$src"
mkdir -p "$src"
git ls-files -z | tar --null -T - -cf - | tar -xf - -C "$src"

# The recipe: four files of the kind's own, and one line at the end of the list.
cp "$trial/core.hpp" "$src/core/include/gizmo/core/kinds/bouncer.hpp"
cp "$trial/verify.hpp" "$src/verify/src/kinds/bouncer.hpp"
cp "$trial/drawing.hpp" "$src/cli/kinds/bouncer.hpp"
cp "$trial/board.txt" "$src/fixtures/boards/gizmos/bouncer.txt"
list=$src/core/include/gizmo/core/kinds/kind_list.hpp
last=$(grep -n '^ *X([A-Za-z0-9_]*, *[a-z0-9_]*) *$' "$list" | tail -n 1 | cut -d: -f1)
[ -n "$last" ] || { echo "run.sh: no last line X(Name, stem) in kind_list.hpp" >&2; exit 1; }
sed -i "${last}s/\$/ \\\\/" "$list"
sed -i "${last}a\\  X(Bouncer, bouncer)" "$list"
echo "kind trial: the copy's list ends with: $(tail -n 2 "$list" | tr -s ' ' | tr '\n' ' ')" >&2

# The copy's release build, inside the copy as in the tree (the compiler cache sees the same
# relative paths, so a second trial, from any clone, compiles little).
scripts/setup.sh
(cd "$src" && cmake --preset release -DGIZMO_BUILD_TESTS=ON -DGIZMO_BUILD_BENCH=OFF >/dev/null)
build=$src/build/release
cmake --build "$build" --target gizmo verify_tests

# The registry's tests of the new kind (one per entry, named by its stem), and the list's values.
out=$("$build/tests/unit/verify_tests" --gtest_filter='Registry/EveryKind.*/bouncer:KindRegistry.*' 2>&1) || {
  echo "$out" >&2
  exit 1
}
passed=$(echo "$out" | sed -n 's/^\[  PASSED  \] \([0-9]*\) tests\{0,1\}\..*/\1/p')
echo "kind trial: the registry's tests: ${passed:-0} passed" >&2
[ "${passed:-0}" -ge 8 ] || { echo "$out" >&2; echo "run.sh: expected at least 8 registry tests of the bouncer" >&2; exit 1; }

gizmo=$build/cli/gizmo
board=$src/fixtures/boards/gizmos/bouncer.txt
"$gizmo" run "$board" --time 5 >"$work/run.txt"
"$gizmo" render "$board" -o "$work/bouncer.svg"
grep -q 'class="bouncer"' "$work/bouncer.svg" || { echo "run.sh: the picture has no bouncer" >&2; exit 1; }
grep -q '\.bouncer *{[^}]*#2a9d8f' "$work/bouncer.svg" || {
  echo "run.sh: the picture's style sheet does not give the bouncer its colour" >&2
  exit 1
}
# Generated boards with bouncers, every property checked (seed printed, as every campaign's is).
rm -rf "$work/fuzz"
"$gizmo" fuzz --count 60 --seed 13 --jobs 2 --out "$work/fuzz" >&2
echo "kind trial: passed (the bouncer read, written, built, run, drawn, generated and checked)" >&2
