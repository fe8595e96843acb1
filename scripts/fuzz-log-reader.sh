#!/usr/bin/env bash
# Fuzzes the replay log reader with libFuzzer (tests/fuzz/log_reader_fuzz.cpp).
#   scripts/fuzz-log-reader.sh [SECONDS] [-- LIBFUZZER_OPTION...]
# Configures build/fuzz with clang (RelWithDebInfo, ASan+UBSan on the fuzz target), builds
# log_reader_fuzz, and runs it for SECONDS (default 30) over a temporary copy of the seed corpus
# fixtures/logs/corpus, which stays unchanged. Inputs that crash are kept in
# build/fuzz/fuzz-artifacts/. libFuzzer's seed is 1 unless FUZZ_SEED says otherwise (FUZZ_SEED=0:
# libFuzzer picks one and prints it); options after -- go to libFuzzer as they are, e.g.
#   FUZZ_SEED=7 scripts/fuzz-log-reader.sh 600 -- -jobs=2 -workers=2
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=30
if [ $# -gt 0 ] && [ "$1" != "--" ]; then
  seconds=$1
  shift
fi
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
case "$seconds" in
  ''|*[!0-9]*) echo "fuzz-log-reader: SECONDS must be a whole number, not '$seconds'" >&2; exit 2 ;;
esac
seed=${FUZZ_SEED:-1}

scripts/setup.sh
if ! command -v clang++ >/dev/null; then
  echo "fuzz-log-reader: installing clang (libFuzzer comes with it)" >&2
  run_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }
  export DEBIAN_FRONTEND=noninteractive
  run_root apt-get update -qq
  run_root apt-get install -y -qq --no-install-recommends clang >&2
fi

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
CC=clang CXX=clang++ cmake -S . -B build/fuzz "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DGIZMO_BUILD_BENCH=OFF -DGIZMO_BUILD_FUZZERS=ON >/dev/null
cmake --build build/fuzz --target log_reader_fuzz -j "$(nproc)"

corpus=$(mktemp -d "${TMPDIR:-/tmp}/gizmo-fuzz-corpus.XXXXXX")
trap 'rm -rf "$corpus"' EXIT
cp fixtures/logs/corpus/* "$corpus"/
artifacts=build/fuzz/fuzz-artifacts
mkdir -p "$artifacts"

echo "fuzz-log-reader: ${seconds}s, seed $seed, corpus copy in $corpus, crashes to $artifacts/" >&2
build/fuzz/tests/fuzz/log_reader_fuzz -seed="$seed" -max_total_time="$seconds" -timeout=20 \
  -artifact_prefix="$artifacts/" "$@" "$corpus"
