#!/usr/bin/env bash
# Checks an input of the simulator's libFuzzer target (tests/fuzz/simulation_fuzz.cpp: a header
# line "run MODEL MAX_TICK DURATION", a key script, a line "board", a text board) with
# `gizmo fuzz --check`, one invariant property at a time, after writing its board and key script
# as files beside each other in DIR (default: a temporary folder, removed afterwards).
#   scripts/simulation-fuzz-check.sh GIZMO INPUT [DIR]
# Example: scripts/simulation-fuzz-check.sh build/release/cli/gizmo build/fuzz/fuzz-artifacts/simulation-crash-… out
# Exit code: gizmo's (0 every property holds, 1 one fails, 2 bad input).
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 GIZMO INPUT [DIR]" >&2; exit 2; }
gizmo=$1 input=$2 dir=${3:-}
if [ -z "$dir" ]; then
  dir=$(mktemp -d -t gizmo-simulation-check.XXXXXX)
  trap 'rm -rf "$dir"' EXIT
fi
mkdir -p "$dir"
read -r word model tick duration < <(head -n 1 "$input")
[ "$word" = run ] || { echo "$input: the first line is not 'run MODEL MAX_TICK DURATION'" >&2; exit 2; }
grep -qx board "$input" || { echo "$input: no line 'board'" >&2; exit 2; }
awk 'NR > 1 && $0 == "board" { exit } NR > 1' "$input" > "$dir/keys.txt"
awk 'seen; $0 == "board" && NR > 1 { seen = 1 }' "$input" > "$dir/board.txt"
echo "$gizmo fuzz --check $dir/board.txt --keys $dir/keys.txt --model $model --max-tick $tick --time $duration" >&2
code=0
for property in no-tunnelling energy event-queue; do
  "$gizmo" fuzz --property "$property" --check "$dir/board.txt" --keys "$dir/keys.txt" --model "$model" \
    --max-tick "$tick" --time "$duration" || code=$?
done
exit $code
