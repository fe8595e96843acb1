#!/usr/bin/env bash
# Installs Debian's chromium for the browser tests (tests/browser), when it is missing.
# Non-interactive and idempotent: when chromium is there it only checks and returns.
set -euo pipefail

for browser in chromium chromium-browser; do
  command -v "$browser" >/dev/null 2>&1 && exit 0
done

echo "setup-browser: installing chromium" >&2
run_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }
export DEBIAN_FRONTEND=noninteractive
run_root apt-get update -qq
run_root apt-get install -y -qq --no-install-recommends chromium >&2
