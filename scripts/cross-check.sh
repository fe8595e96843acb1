#!/usr/bin/env bash
# scripts/dev cross-check [TARGET...]: one log, every machine (docs/determinism.md). For each
# target (default: all), builds the portable set (scripts/dev cross TARGET), then for every golden
# log of fixtures/logs/golden.txt whose scalar format the target computes:
#   1. the target replays the committed log, recorded by another machine: identical;
#   2. the target records the same run: the same bytes as the committed log;
#   3. the host's build replays the target's log: identical (where the host computes its format).
# A golden log of another format must be refused by the target (exit 2, "formats differ"): it is
# counted as such, not compared. A difference prints the target and the first decision where the
# logs part (index, board time, both decisions in hex floats), and the check exits 1. At the end,
# one table: target, logs compared, identical, build seconds (wall and CPU) and check seconds.
set -uo pipefail
cd "$(dirname "$0")/.."
all="x86_64-gcc-O0 x86_64-gcc-O3 x86_64-clang i686 aarch64 riscv64 ppc64el s390x wasm32"
targets=("$@")
[ ${#targets[@]} -eq 0 ] && read -r -a targets <<< "$all"

# Every target's packages in one install (scripts/setup-cross.sh: nothing to do when they are
# there), then the host's full build: it recorded the golden logs, and it replays what each
# target records.
installStarted=$SECONDS
scripts/setup-cross.sh "${targets[@]}" || { echo "cross-check: installing the targets' packages failed" >&2; exit 1; }
echo "cross-check: packages ready in $((SECONDS - installStarted)) s" >&2
scripts/setup.sh
cmake --preset release >/dev/null && cmake --build --preset release --target gizmo >/dev/null || {
  echo "cross-check: the host build failed" >&2
  exit 1
}
host=build/release/cli/gizmo
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

failed=0
table=()
# The CPU seconds (user + system) of every command this script has waited for so far: a target's
# build measured in them does not depend on what else the machine is doing, as wall seconds do.
# (From the kernel's account of this shell, $$: `times` would count a command substitution's own.)
ticksPerSecond=$(getconf CLK_TCK)
childCpuSeconds() {
  awk -v hz="$ticksPerSecond" '{ printf "%.0f", ($16 + $17) / hz }' "/proc/$$/stat"
}
problem() {  # TARGET TEXT...
  echo "cross-check: $1: ${*:2}" >&2
  failed=1
}

for target in "${targets[@]}"; do
  started=$SECONDS
  cpuStarted=$(childCpuSeconds)
  if ! scripts/cross-build.sh "$target" > "$work/build.log" 2>&1; then
    problem "$target" "the build failed or warned:"
    tail -n 30 "$work/build.log" >&2
    table+=("$target - - - $((SECONDS - started)) - - build-failed")
    continue
  fi
  built=$SECONDS
  buildCpu=$(( $(childCpuSeconds) - cpuStarted ))
  [ "$target" = wasm32 ] && wasmBuilt=1
  run=build/cross-$target/gizmo-run
  compared=0 identical=0 otherFormat=0
  while read -r file board model precision seconds keys recordedOn; do
    [[ -z "$file" || "$file" == \#* ]] && continue
    golden=fixtures/logs/$file
    ours=$work/$target-$file
    # 1. The target replays the committed log, or refuses one of a format it does not compute.
    replayed=$("$run" replay "$golden" 2>&1)
    code=$?
    if [ $code -eq 2 ] && [[ "$replayed" == *"formats differ"* ]]; then
      otherFormat=$((otherFormat + 1))
      continue
    fi
    compared=$((compared + 1))
    same=1
    if [ $code -ne 0 ]; then
      problem "$target" "replaying $file (recorded on $recordedOn) is not identical (exit $code):"$'\n'"$replayed"
      same=0
    fi
    # 2. The target records the run again: the same bytes.
    keyArgs=()
    [ "$keys" = keys ] && keyArgs=(--keys fixtures/keys/flippers.keys)
    if ! "$run" record "fixtures/$board" --model "$model" --precision "$precision" --time "$seconds" \
        "${keyArgs[@]}" -o "$ours" > "$work/record.log" 2>&1; then
      problem "$target" "recording $file failed:"$'\n'"$(cat "$work/record.log")"
      continue
    fi
    if ! cmp -s "$golden" "$ours"; then
      problem "$target" "records $file differently; the first decision where the logs part (first: the" \
        "committed log, second: $target's):"$'\n'"$("$run" diff "$golden" "$ours" --context 0 2>&1)"
      same=0
    fi
    # 3. The host replays the target's log, where it computes the log's format.
    hostReplay=$("$host" replay "$ours" 2>&1)
    code=$?
    if [ $code -ne 0 ] && ! { [ $code -eq 2 ] && [ "$recordedOn" != host ] && [[ "$hostReplay" == *"formats differ"* ]]; }; then
      problem "$target" "the host does not replay $target's $file identically (exit $code):"$'\n'"$hostReplay"
      same=0
    fi
    [ $same -eq 1 ] && identical=$((identical + 1))
  done < fixtures/logs/golden.txt
  verdict=identical
  [ $identical -ne $compared ] && verdict=DIFFERENT
  [ $compared -eq 0 ] && { verdict=nothing-compared; failed=1; }
  table+=("$target $compared $identical $otherFormat $((built - started)) $buildCpu $((SECONDS - built)) $verdict")
done

# The wasm command's speed against native: the spec example over 60 s, run by the host's build
# and by node, back to back (docs/determinism.md, "Figures").
if [ "${wasmBuilt:-0}" = 1 ]; then
  seconds() { local t0 t1; t0=$(date +%s.%N); "$@" > /dev/null 2>&1; t1=$(date +%s.%N); awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }'; }
  native=$(seconds "$host" run --time 60)
  wasm=$(seconds build/cross-wasm32/gizmo-run run --time 60)
  printf 'cross-check: the spec example over 60 s: native %.2f s, wasm32 under node %.2f s: %.2f times native\n' \
    "$native" "$wasm" "$(awk -v w="$wasm" -v n="$native" 'BEGIN { print w / n }')"
fi

echo
# "other format": golden logs of a scalar format the target does not compute, which it refused.
# "build CPU seconds": user + system time of the build's processes, the figure that a loaded
# machine does not inflate (wall seconds on two idle cores are a little over half of it).
printf '%-14s %8s %9s %12s %13s %17s %13s  %s\n' target compared identical "other format" "build seconds" \
  "build CPU seconds" "check seconds" result
for row in "${table[@]}"; do
  read -r t c i o b p s v <<< "$row"
  printf '%-14s %8s %9s %12s %13s %17s %13s  %s\n' "$t" "$c" "$i" "$o" "$b" "$p" "$s" "${v//-/ }"
done
passed=0
for row in "${table[@]}"; do [[ "$row" == *" identical" ]] && passed=$((passed + 1)); done
echo "cross-check: $passed passed, $(( ${#table[@]} - passed )) failed, $SECONDS s in all (packages included)"
exit $failed
