#!/usr/bin/env bash
# The play page's tests in headless Chromium (docs/play.md): writes the page of the spec example
# (flippers and an absorber), of the crowded board (100 balls) and of the spawners' board (balls
# added as it plays) with BUILD_DIR's gizmo and the
# play module of WASM_BUILD_DIR, plays each with real key events or touches (play_game.mjs),
# takes a log over in the page (take_over.mjs), lets the module's memory run short
# (memory_short.mjs) and checks the saved logs natively. Installs chromium and chromium-driver when missing. Usage:
#   tests/browser/play/run.sh [BUILD_DIR [WASM_BUILD_DIR]]   (defaults: build/release, build/cross-wasm32)
# CI runs it after `scripts/dev cross-check`, which leaves the wasm32 build in place. Pages, logs
# and screenshots land in BUILD_DIR/play-tests/CASE/.
set -euo pipefail
cd "$(dirname "$0")/../../.."
build=${1:-build/release}
wasm=${2:-build/cross-wasm32}
gizmo="$build/cli/gizmo"
module="$wasm/web/gizmo-play.js"
[ -x "$gizmo" ] || { echo "play tests: no $gizmo (build it first: scripts/dev test)" >&2; exit 2; }
[ -f "$module" ] || { echo "play tests: no $module (build it first: scripts/dev play-module)" >&2; exit 2; }
scripts/setup-browser.sh driver
gizmo=$(cd "$(dirname "$gizmo")" && pwd)/gizmo
out=$(cd "$build" && pwd)/play-tests

play_case() {  # NAME BOARD SCENARIO
  local dir="$out/$1"
  rm -rf "$dir"
  mkdir -p "$dir"
  "$gizmo" play "$2" -o "$dir/game.html" --module "$module"
  node tests/browser/play/play_game.mjs "$3" "$gizmo" "$dir/game.html" "$dir"
}
play_case spec_example_keys fixtures/boards/spec-example.txt keys
play_case crowded_30s fixtures/boards/play/crowded-100-balls.txt crowded
# A long game of the crowded board at 64×, 60 s of board time: the recording's memory bounded.
play_case crowded_long fixtures/boards/play/crowded-100-balls.txt long
# The crowded board at 64× in a page whose module may grow to 18 MB only (PAGE#max-memory=18):
# its memory runs short within seconds; the page stops, saves the game cut off after its last
# complete chunk, and the native reader reads it up to there.
dir="$out/memory_short"
rm -rf "$dir"
mkdir -p "$dir"
"$gizmo" play fixtures/boards/play/crowded-100-balls.txt -o "$dir/game.html" --module "$module"
node tests/browser/play/memory_short.mjs "$gizmo" "$dir/game.html" 18 "$dir"
# Spawners: each space bar press adds a ball, and a sink feeds a ball back; the game's balls grow.
play_case spawner_keys fixtures/boards/gizmos/spawner.txt keys
# The spec example played with a finger on the page's key buttons (touch events).
play_case spec_example_touch fixtures/boards/spec-example.txt touch
# A log recorded natively, opened in the page, scrubbed, taken over, played, rewound and saved.
dir="$out/take_over"
rm -rf "$dir"
mkdir -p "$dir"
"$gizmo" record fixtures/boards/spec-example.txt --keys fixtures/keys/flippers.keys --time 12 --max-tick 0.01 \
  -o "$dir/parent.gzlog" >/dev/null
"$gizmo" play fixtures/boards/gizmos/spawner.txt -o "$dir/game.html" --module "$module"
node tests/browser/play/take_over.mjs "$gizmo" "$dir/game.html" "$dir/parent.gzlog" "$dir"
