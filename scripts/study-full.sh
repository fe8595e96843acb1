#!/usr/bin/env bash
# The full speed/accuracy study with its Kernels part (docs/verification.md, "Kernels"): builds
# gizmo and gizmo_bench (release preset), runs the benchmarks the study charts with JSON output
# into OUT/bench.json, then `gizmo study --bench OUT/bench.json --out OUT`.
#   scripts/study-full.sh [--quick] [OUT] [-- GIZMO_BENCH_OPTION...]
# OUT defaults to study-full. --quick makes both small: `gizmo study --quick`, and one repetition
# of each benchmark at a short minimum time. Options after -- go to gizmo_bench after the
# defaults (3 repetitions, the charted benchmarks only), so they can override them.
# Example: scripts/study-full.sh study-full -- --benchmark_repetitions=5
set -euo pipefail
cd "$(dirname "$0")/.."

quick=()
bench=(--benchmark_repetitions=3)
if [ $# -gt 0 ] && [ "$1" = "--quick" ]; then
  quick=(--quick)
  bench=(--benchmark_repetitions=1 --benchmark_min_time=0.05)
  shift
fi
out=study-full
if [ $# -gt 0 ] && [ "$1" != "--" ]; then
  out=$1
  shift
fi
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
[ -e "$out" ] && [ ! -d "$out" ] && { echo "study-full: $out exists and is not a folder" >&2; exit 2; }

scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release --target gizmo gizmo_bench

# The benchmarks first, while nothing else of ours loads the machine; only those the study charts
# (time of impact, the event loop, recording and replaying, certification).
mkdir -p "$out"
echo "study-full: gizmo_bench into $out/bench.json" >&2
build/release/bench/gizmo_bench --benchmark_filter='TimeOfImpact|^BM_Spec|^BM_Crowded|^BM_CertifyRatio' \
  "${bench[@]}" --benchmark_out="$out/bench.json" --benchmark_out_format=json "$@" >&2
echo "study-full: gizmo study ${quick[*]} --bench $out/bench.json --out $out" >&2
exec build/release/cli/gizmo study "${quick[@]}" --bench "$out/bench.json" --out "$out"
