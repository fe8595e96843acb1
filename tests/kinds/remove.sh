#!/usr/bin/env bash
# docs/design.md's "Taking a kind out", followed on a copy of the tree: the kind STEM (default
# booster) leaves by its own files and its line in the kind list, and nothing else. Its own files
# are its three kind files (core, verify, drawing), its example board and its behaviour class
# (core/include/gizmo/core/gizmos/STEM.hpp) when no file outside its own and the tests includes it.
# The copy's gizmo command must then build with no other edit, run every remaining kind's example
# board, read a board with the kind as one with a command it does not know (the line left out, with
# a warning naming file, line and command), and refuse a log that the tree's gizmo recorded on such
# a board rather than read it as something else. The tree itself is the kind added back: its files
# and its line.
# Usage: tests/kinds/remove.sh [STEM] [WORK_DIR] (default build/kind-removal: the copy in
# WORK_DIR/src, built in its build/release). The tree's gizmo (build/release/cli/gizmo) records the
# log; it is built first when missing.
set -euo pipefail
cd "$(dirname "$0")/../.."
stem=${1:-booster}
work=${2:-build/kind-removal}
mkdir -p "$work"
work=$(cd "$work" && pwd)
src=$work/src
list=core/include/gizmo/core/kinds/kind_list.hpp
line=$(grep -n "^ *X([A-Za-z0-9_]*, *$stem) *\\\\\\{0,1\\} *\$" "$list" | cut -d: -f1)
[ -n "$line" ] || { echo "remove.sh: no kind with stem '$stem' in $list" >&2; exit 1; }
name=$(sed -n "${line}s/^ *X(\\([A-Za-z0-9_]*\\),.*/\\1/p" "$list")

rm -rf "$src"
mkdir -p "$src"
git ls-files -z | tar --null -T - -cf - | tar -xf - -C "$src"

own=(core/include/gizmo/core/kinds/$stem.hpp verify/src/kinds/$stem.hpp cli/kinds/$stem.hpp
  fixtures/boards/gizmos/$stem.txt)
class=core/include/gizmo/core/gizmos/$stem.hpp
if [ -f "$class" ]; then
  users=$(cd "$src" && grep -rl --include='*.hpp' --include='*.cpp' "gizmos/$stem.hpp" core cli verify replay web |
    grep -v -x -F -e "$class" -e "${own[0]}" -e "${own[1]}" -e "${own[2]}" || true)
  if [ -z "$users" ]; then own+=("$class"); else echo "kind removal: $class stays, included by: $users" >&2; fi
fi
for f in "${own[@]}"; do
  [ -f "$src/$f" ] || { echo "remove.sh: $f is not in the tree" >&2; exit 1; }
  rm "$src/$f"
done
# Its line out of the list; a last line leaves its continuation to the line before.
if sed -n "${line}p" "$list" | grep -q '\\ *$'; then
  sed -i "${line}d" "$src/$list"
else
  sed -i "${line}d" "$src/$list"
  sed -i "$((line - 1))s/ *\\\\ *\$//" "$src/$list"
fi
echo "kind removal: $name out: $list's line $line and ${#own[@]} files of its own (${own[*]})" >&2

scripts/setup.sh
tree_gizmo=build/release/cli/gizmo
[ -x "$tree_gizmo" ] || { (cmake --preset release >/dev/null) && cmake --build build/release --target gizmo; }
(cd "$src" && cmake --preset release -DGIZMO_BUILD_TESTS=OFF -DGIZMO_BUILD_BENCH=OFF >/dev/null)
build=$src/build/release
cmake --build "$build" --target gizmo
gizmo=$build/cli/gizmo

# Every remaining kind's example board runs.
count=0
for board in "$src"/fixtures/boards/gizmos/*.txt; do
  "$gizmo" run "$board" --time 2 >/dev/null 2>"$work/err.txt" || { cat "$work/err.txt" >&2; exit 1; }
  count=$((count + 1))
done
echo "kind removal: the copy's gizmo ran the $count remaining kinds' example boards" >&2

# A board with the kind is read as any board with a command of another program that the reader
# does not know: its line left out, with a warning that names the file, the line and the command.
board=fixtures/boards/gizmos/$stem.txt
command=$(sed -n 's/^ *\([A-Za-z]*\) .*/\1/p' "$board" | grep -v -x -e Ball -e Connect -e KeyConnect -e Gravity -e Friction -e Rotate | head -n 1)
"$gizmo" run "$board" --time 1 >/dev/null 2>"$work/err.txt"
grep -q "$(basename "$board"):[0-9]*:[0-9]*: warning: '$command' is not a command" "$work/err.txt" || {
  cat "$work/err.txt" >&2
  echo "remove.sh: the copy's gizmo read $board without a warning that names the line of '$command'" >&2
  exit 1
}
echo "kind removal: its board read without it: $(grep "'$command'" "$work/err.txt" | cut -c1-160)…" >&2
# A log that the tree's gizmo recorded on that board is refused at its header, before any record:
# read otherwise, every gizmo id after the kind's line would name another gizmo.
"$tree_gizmo" record "$board" --time 2 -o "$work/$stem.gzlog" >/dev/null 2>&1
for view in replay dump; do
  if "$gizmo" "$view" "$work/$stem.gzlog" >"$work/out.txt" 2>"$work/err.txt"; then
    echo "remove.sh: the copy's gizmo $view took a log of a board with a $name" >&2
    exit 1
  fi
  grep -q "does not read the log's board as written" "$work/err.txt" && [ ! -s "$work/out.txt" ] || {
    cat "$work/err.txt" >&2
    echo "remove.sh: the copy's gizmo $view did not refuse the log at its header, or printed output" >&2
    exit 1
  }
done
echo "kind removal: its log refused: $(tail -n 1 "$work/err.txt" | cut -c1-160)…" >&2
echo "kind removal: passed (the $name taken out by its own files and one line)" >&2
