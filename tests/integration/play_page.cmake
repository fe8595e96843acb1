# Checks on the page `gizmo play` writes, without a browser or the real play module (the browser
# tests in tests/browser/play/ play real pages):
#   cmake -DGIZMO=exe -DOUTPUT=file -DEXIT=code [-DSTDERR=regex] [-DCONTAINS=regex]
#         -P play_page.cmake -- play-arguments...
# EXIT 0: the page exists, holds the module given, the shared drawing, run data and timeline, the
# controls that open and take over a log and the key buttons' place, and loads nothing (no
# network address, external script, style sheet or unfilled marker). Any other EXIT: the command
# failed with it, said why on stderr (matching STDERR) and left no file, not even a partial one.
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/../support/written_file_checks.cmake)
gizmo_write_checked(play)
file(READ ${OUTPUT} text)
gizmo_check_parts("${text}" "<canvas id=\"board\"" "<script id=\"game-data\" type=\"application/json\">{\"format\":1"
                  "GizmoPlayModule" "const BoardView = " "BoardView.drawGizmo(" "const RunData = " "RunData.loadRun("
                  "const TimelineView = " "TimelineView.draw(" "<input id=\"open-log\" type=\"file\""
                  "<button id=\"take-over\"" "<button id=\"rewind\"" "<div id=\"touch-keys\"")
gizmo_check_self_contained("${text}")
