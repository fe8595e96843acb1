#!/usr/bin/env bash
# Installs what `gizmo crosscheck --engine box2d-v3` runs: node and npm (Debian's nodejs and npm,
# when there is no node or npm on the PATH) and the box2d3-wasm package in verify/box2d3, at the
# version its package.json pins and with the integrity hash its package-lock.json holds (`npm ci`).
# Non-interactive and idempotent: when that version is installed it only checks and returns.
#   scripts/setup-box2d3.sh
set -euo pipefail
scripts="$(cd "$(dirname "$0")" && pwd)"
dir="$scripts/../verify/box2d3"

if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  echo "setup-box2d3: installing nodejs npm" >&2
  "$scripts/apt-install.sh" nodejs npm
fi

wanted=$(node -p 'require(process.argv[1]).dependencies["box2d3-wasm"]' "$dir/package.json")
installed=$(node -p 'try { require(process.argv[1]).version } catch { "" }' "$dir/node_modules/box2d3-wasm/package.json")
[ "$installed" = "$wanted" ] && exit 0

echo "setup-box2d3: installing box2d3-wasm $wanted" >&2
for try in 1 2 3; do
  (cd "$dir" && npm ci --no-audit --no-fund --ignore-scripts) >&2 && exit 0
  [ "$try" -lt 3 ] && { echo "setup-box2d3: npm ci failed (try $try of 3); again in 20 s" >&2; sleep 20; }
done
echo "setup-box2d3: could not install box2d3-wasm $wanted" >&2
exit 1
