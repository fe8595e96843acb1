#!/usr/bin/env bash
# Fuzzes the replay log reader with libFuzzer (tests/fuzz/log_reader_fuzz.cpp): scripts/fuzz-run.sh
# for the one target log_reader, kept for its old command line.
#   scripts/fuzz-log-reader.sh [SECONDS] [-- LIBFUZZER_OPTION...]
# e.g. FUZZ_SEED=7 scripts/fuzz-log-reader.sh 600 -- -jobs=2 -workers=2
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=()
if [ $# -gt 0 ] && [ "$1" != "--" ]; then
  case "$1" in
    ''|*[!0-9]*) echo "fuzz-log-reader: SECONDS must be a whole number, not '$1'" >&2; exit 2 ;;
  esac
  seconds=("$1")
  shift
fi
exec scripts/fuzz-run.sh "${seconds[@]}" log_reader "$@"
