#!/usr/bin/env bash
# Fuzzes with libFuzzer what reads outside input (the replay log reader, the XML and text board
# readers and the key-script reader) and the simulator under its invariants (tests/fuzz/*_fuzz.cpp).
#   scripts/fuzz-run.sh [--ci] [SECONDS] [TARGET...] [-- LIBFUZZER_OPTION...]
# TARGET is log_reader, xml_reader, text_reader, key_script or simulation (default: all five, one
# after the other, SECONDS each; default 30). Configures build/fuzz with clang (RelWithDebInfo, ASan+UBSan on
# the fuzz targets), builds them, and runs each over a temporary copy of its seed corpus from
# fixtures/, which stays unchanged. Inputs that crash, leak or hang (-timeout: 20 s, 10 s for the
# simulator, whose inputs take milliseconds; it also gets tests/fuzz/simulation.dict) are kept in
# build/fuzz/fuzz-artifacts/. libFuzzer's seed is 1 unless FUZZ_SEED says otherwise (FUZZ_SEED=0:
# libFuzzer picks one and prints it).
#   --ci  for .ci/run: without clang, say so and skip instead of installing it; no set-up step.
# Example: FUZZ_SEED=7 scripts/fuzz-run.sh 600 xml_reader -- -jobs=2 -workers=2
set -euo pipefail
cd "$(dirname "$0")/.."

ci=0
[ $# -gt 0 ] && [ "$1" = "--ci" ] && { ci=1; shift; }
seconds=30
if [ $# -gt 0 ] && [[ "$1" =~ ^[0-9]+$ ]]; then
  seconds=$1
  shift
fi
targets=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  case "$1" in
    log_reader|xml_reader|text_reader|key_script|simulation) targets+=("$1") ;;
    *) echo "fuzz-run: unknown target or bad SECONDS '$1' (log_reader, xml_reader, text_reader, key_script, simulation)" >&2; exit 2 ;;
  esac
  shift
done
[ $# -gt 0 ] && shift  # the --
[ ${#targets[@]} -eq 0 ] && targets=(log_reader xml_reader text_reader key_script simulation)
seed=${FUZZ_SEED:-1}

if [ "$ci" = 1 ]; then
  if ! command -v clang++ >/dev/null; then
    echo "fuzz-run: clang is not installed: skipping the libFuzzer runs (the corpus runners ran in ctest)" >&2
    exit 0
  fi
else
  scripts/setup.sh
  if ! command -v clang++ >/dev/null; then
    echo "fuzz-run: installing clang (libFuzzer comes with it)" >&2
    scripts/apt-install.sh clang
  fi
fi

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
CC=clang CXX=clang++ cmake -S . -B build/fuzz "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DGIZMO_UNITY_BUILD=OFF -DGIZMO_PRECOMPILE_HEADERS=OFF \
  -DGIZMO_BUILD_BENCH=OFF -DGIZMO_BUILD_FUZZERS=ON >/dev/null
cmake --build build/fuzz --target "${targets[@]/%/_fuzz}" -j "$(nproc)"

# The seed corpus of a target, from fixtures/, copied into the empty folder $2.
fill_corpus() {
  if [ "$1" = simulation ]; then
    cmake -DFIXTURES=fixtures -DOUT="$2" -P tests/fuzz/simulation_corpus.cmake
    return
  fi
  local i=0 f
  while IFS= read -r f; do cp "$f" "$2/$i-$(basename "$f")"; i=$((i + 1)); done < <(
    case "$1" in
      log_reader) find fixtures/logs/corpus -type f ;;
      xml_reader) find fixtures/boards -type f -name '*.xml' ;;
      text_reader) find fixtures/boards -type f -name '*.txt' ;;
      key_script) find fixtures/keys -type f -name '*.keys' ;;
    esac | sort)
}

artifacts=build/fuzz/fuzz-artifacts
mkdir -p "$artifacts"
corpus=$(mktemp -d -t gizmo-fuzz-corpus.XXXXXX)
trap 'rm -rf "$corpus"' EXIT
for target in "${targets[@]}"; do
  rm -rf "${corpus:?}"/*
  fill_corpus "$target" "$corpus"
  timeout=20 dict=()
  [ "$target" = simulation ] && timeout=10 dict=(-dict=tests/fuzz/simulation.dict)
  echo "fuzz-run: $target for ${seconds}s, seed $seed, $(ls "$corpus" | wc -l) seed inputs, crashes to $artifacts/" >&2
  build/fuzz/tests/fuzz/"$target"_fuzz -seed="$seed" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 \
    -detect_leaks=1 -artifact_prefix="$artifacts/$target-" "${dict[@]}" "$@" "$corpus"
done
