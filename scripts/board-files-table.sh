#!/usr/bin/env bash
# Regenerates the real-board table of docs/board-files.md (between its two marker lines) from the
# files in ../shared/boards/real, with the real_boards_survey of a build:
#   scripts/board-files-table.sh build/release
set -euo pipefail
build=${1:?usage: $0 BUILD_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
doc=$root/docs/board-files.md
table=$(mktemp)
trap 'rm -f "$table" "$table.doc"' EXIT
"$build/tests/real_boards/real_boards_survey" "$root/../shared/boards/real" \
  --unlisted "$root/tests/real_boards/unlisted.tsv" --table "$table" ||
  echo "board-files-table: some files broke their kind's expectations (above); the table shows them as they are" >&2
awk -v table="$table" '
  /<!-- real-boards-table:begin -->/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
  /<!-- real-boards-table:end -->/ { skip = 0 }
  !skip { print }' "$doc" > "$table.doc"
mv "$table.doc" "$doc"
