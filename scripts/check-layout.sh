#!/usr/bin/env bash
# Checks the rules of .editorconfig on every text file git tracks outside fixtures/ (data kept as it
# was written): LF line ends, a final newline, no trailing white space, no tab indents (tabs only in
# .tsv data). Prints each breach as FILE:LINE: what it is, and exits 1 when there is one.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -d '' files < <(git ls-files -z | grep -zv '^fixtures/')
breaches=$(
  {
    grep -nIP '\r$' "${files[@]}" | sed 's/^\([^:]*:[0-9]*\):.*/\1: a CRLF line end/' || true
    grep -nIP '[ \t]+$' "${files[@]}" | sed 's/^\([^:]*:[0-9]*\):.*/\1: trailing white space/' || true
    grep -nIP '^\t' "${files[@]}" | grep -v '^[^:]*\.tsv:' | sed 's/^\([^:]*:[0-9]*\):.*/\1: a tab indent/' || true
    for f in "${files[@]}"; do
      if [ -s "$f" ] && grep -Iq . "$f" && [ -n "$(tail -c1 "$f")" ]; then echo "$f: no newline at the end"; fi
    done
  }
)
if [ -n "$breaches" ]; then
  echo "$breaches"
  echo "check-layout: the files above break .editorconfig" >&2
  exit 1
fi
echo "check-layout: every tracked text file follows .editorconfig (${#files[@]} files)"
