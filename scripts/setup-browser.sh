#!/usr/bin/env bash
# Installs Debian's chromium for the browser tests (tests/browser), when it is missing; with the
# argument `driver`, also Debian's chromium-driver (chromedriver, built from the same chromium
# release), which the play page's tests drive the browser with (tests/browser/play/); and Debian's
# nodejs, which runs those tests' drivers and the player's state check under node
# (tests/integration/player_state.mjs).
# Non-interactive and idempotent: when everything asked for is there it only checks and returns.
set -euo pipefail

packages=()
have_browser=false
for browser in chromium chromium-browser; do
  command -v "$browser" >/dev/null 2>&1 && have_browser=true
done
$have_browser || packages+=(chromium)
[ "${1:-}" = driver ] && ! command -v chromedriver >/dev/null 2>&1 && packages+=(chromium-driver)
command -v node >/dev/null 2>&1 || packages+=(nodejs)
[ ${#packages[@]} -eq 0 ] && exit 0

echo "setup-browser: installing ${packages[*]}" >&2
exec "$(dirname "$0")/apt-install.sh" "${packages[@]}"
