#!/usr/bin/env bash
# The play module's figures (docs/play.md): its core under node against the native core
# (play_speed.mjs), then the play page's simulation time per frame in headless Chromium
# (play_frames.mjs) on the spec example and the crowded board. Usage:
#   bench/play-bench.sh [BUILD_DIR [WASM_BUILD_DIR]]   (defaults: build/release, build/cross-wasm32)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
wasm=${2:-build/cross-wasm32}
gizmo="$build/cli/gizmo"
module="$wasm/web/gizmo-play.js"
[ -x "$gizmo" ] || { echo "play-bench: no $gizmo (build it first: scripts/dev run)" >&2; exit 2; }
[ -f "$module" ] || { echo "play-bench: no $module (build it first: scripts/dev play-module)" >&2; exit 2; }
scripts/setup-browser.sh driver
node bench/play_speed.mjs "$gizmo" "$module"
pages=$(mktemp -d)
trap 'rm -rf "$pages"' EXIT
"$gizmo" play fixtures/boards/spec-example.txt -o "$pages/spec-example.html" --module "$module" >/dev/null
"$gizmo" play fixtures/boards/play/crowded-100-balls.txt -o "$pages/crowded-100-balls.html" --module "$module" >/dev/null
node bench/play_frames.mjs "$pages/spec-example.html" "$pages/crowded-100-balls.html"
