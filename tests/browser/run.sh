#!/usr/bin/env bash
# The browser checks of the replay player on a build: installs Chromium when it is missing, then
# runs every case of cases.cmake with that build's gizmo. Usage: tests/browser/run.sh [BUILD_DIR]
# (default build/release). Screenshots and pages land in BUILD_DIR/browser-tests/CASE/.
set -euo pipefail
cd "$(dirname "$0")/../.."
[ -d "${1:-build/release}" ] || { echo "run.sh: no build folder ${1:-build/release} (build first: scripts/dev test)" >&2; exit 2; }
build=$(cd "${1:-build/release}" && pwd)
gizmo="$build/cli/gizmo"
[ -x "$gizmo" ] || { echo "run.sh: no $gizmo (build it first: scripts/dev test)" >&2; exit 2; }
scripts/setup-browser.sh
# cases.cmake calls gizmo_browser_test(NAME settings...); here each call runs the check at once.
driver=$(mktemp)
trap 'rm -f "$driver"' EXIT
cat >"$driver" <<CMAKE
function(gizmo_browser_test name)
  set(defs)
  foreach(setting \${ARGN})
    list(APPEND defs -D\${setting})
  endforeach()
  message(STATUS "browser check \${name}")
  execute_process(COMMAND \${CMAKE_COMMAND} -DGIZMO=$gizmo -DWORK_DIR=$build/browser-tests/\${name} \${defs}
                          -P $PWD/tests/browser/player_seek.cmake RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "browser check \${name} failed")
  endif()
endfunction()
include($PWD/tests/browser/cases.cmake)
CMAKE
cmake -P "$driver"
