# Our run against Box2D's path, end to end (docs/render.md, "Our run against Box2D's"):
#   cmake -DGIZMO=exe -DWORK=dir -DBOARD=board -DOTHER_BOARD=board -P render_box2d_path.cmake
# `gizmo crosscheck --path-out` writes a path file that reads back as documented; `gizmo render
# --compare` draws it over a log of the same board and marks where the runs part, at the same
# moment as `--compare box2d:STEP`, which runs Box2D in the command; a path of another board, a
# damaged path file, one cut off, and --path-out with two step sizes are refused with exit code 2,
# a message naming the file (and line), and no page left behind.
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/gizmo_cli.cmake)
foreach(required GIZMO WORK BOARD OTHER_BOARD)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "render_box2d_path.cmake needs -D${required}=…")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(TIME 2)

# Runs gizmo and checks its exit code.
macro(expect_exit code)
  gizmo_run(RUN ${ARGN})
  if(NOT RUN_EXIT EQUAL ${code})
    gizmo_fail("expected exit code ${code}")
  endif()
endmacro()

# A refused render: exit 2, stderr matching `pattern`, no page and no temporary file.
function(expect_refused page pattern)
  file(REMOVE ${page})
  expect_exit(2 ${ARGN})
  if(NOT RUN_STDERR MATCHES "${pattern}")
    gizmo_fail("stderr should match '${pattern}'")
  endif()
  file(GLOB leftovers ${page} ${page}.partial-*)
  if(leftovers)
    gizmo_fail("a refused render left ${leftovers}")
  endif()
endfunction()

# --- The path file.
set(path ${WORK}/box2d.path)
expect_exit(0 crosscheck ${BOARD} --time ${TIME} --dt 1/240 --path-out ${path})
if(NOT RUN_STDOUT MATCHES "path +[^\n]*box2d\\.path")
  gizmo_fail("the report should name the path file")
endif()
file(STRINGS ${path} lines)
list(LENGTH lines count)
list(GET lines 0 magic)
list(GET lines 7 balls)
list(GET lines 8 samples)
math(EXPR last "${count} - 1")
list(GET lines ${last} end)
if(NOT magic STREQUAL "gizmo-path 1" OR NOT samples STREQUAL "samples" OR NOT end STREQUAL "end")
  message(FATAL_ERROR "${path} is not laid out as documented:\n${magic}\n…\n${samples}\n…\n${end}")
endif()
# One line per ball per step, from time 0 to the end: 2 s at 1/240 s is 480 steps.
string(REGEX REPLACE "^balls " "" ball_names "${balls}")
string(REPLACE " " ";" ball_names "${ball_names}")
list(LENGTH ball_names ball_count)
math(EXPR expected "9 + 481 * ${ball_count} + 1")
if(NOT count EQUAL expected)
  message(FATAL_ERROR "${path} has ${count} lines, not ${expected} (481 samples of ${ball_count} balls)")
endif()
set(at 1)
foreach(key engine board keys model dt time)
  list(GET lines ${at} line)
  if(NOT line MATCHES "^${key} .")
    message(FATAL_ERROR "${path}: line ${at} + 1 should be '${key} …', not '${line}'")
  endif()
  math(EXPR at "${at} + 1")
endforeach()
list(GET lines 2 board_line)
list(GET lines 9 first_sample)
if(NOT board_line MATCHES "^board [0-9a-f]+ spec-example\\.txt$" OR NOT first_sample MATCHES "^0 [A-Za-z0-9_]+ [-0-9.e]+ [-0-9.e]+$")
  message(FATAL_ERROR "${path}: unexpected lines\n${board_line}\n${first_sample}")
endif()

# --- Our run against it.
set(log ${WORK}/ours.gzlog)
expect_exit(0 record ${BOARD} --time ${TIME} -o ${log})
set(page ${WORK}/vs-box2d.html)
expect_exit(0 render ${log} -o ${page} --compare ${path})
if(NOT RUN_STDOUT MATCHES "ours\\.gzlog parts from box2d\\.path at t = ")
  gizmo_fail("render should say where the runs part")
endif()
file(READ ${page} html)
if(NOT html MATCHES "\"path\":{\"label\":\"box2d\\.path\",\"engine\":\"Box2D [^\"]*\"[^}]*\"threshold\":0\\.1,\"balls\":\\[{\"name\":")
  message(FATAL_ERROR "${page} holds no Box2D path")
endif()
if(NOT html MATCHES "\"parting\":{\"time\":([0-9.e-]+),\"ball\":")
  message(FATAL_ERROR "${page} marks no parting")
endif()
set(parting_from_file ${CMAKE_MATCH_1})

# Box2D run in the command at the same step size parts at the same step.
set(page_here ${WORK}/vs-box2d-here.html)
expect_exit(0 render ${log} -o ${page_here} --compare box2d:1/240)
file(READ ${page_here} html)
if(NOT html MATCHES "\"parting\":{\"time\":([0-9.e-]+),\"ball\":")
  message(FATAL_ERROR "${page_here} marks no parting")
endif()
if(NOT CMAKE_MATCH_1 STREQUAL parting_from_file)
  message(FATAL_ERROR "box2d:1/240 parts at ${CMAKE_MATCH_1} s, the path file at ${parting_from_file} s")
endif()

# --- Refused: a path of another board, damaged files, bad shortcuts, --path-out with two steps.
set(other ${WORK}/other-board.path)
expect_exit(0 crosscheck ${OTHER_BOARD} --time 0.5 --dt 1/60 --path-out ${other})
set(bad_page ${WORK}/refused.html)
expect_refused(${bad_page} "other-board\\.path: a path of another board" render ${log} -o ${bad_page} --compare ${other})

# A sample whose x is not a number: the message names the file and line 12.
set(damaged ${WORK}/damaged.path)
set(copy ${lines})
list(GET copy 11 sample)
string(REGEX REPLACE " [^ ]+ ([^ ]+)$" " x1.5 \\1" sample "${sample}")
list(REMOVE_AT copy 11)
list(INSERT copy 11 "${sample}")
string(JOIN "\n" text ${copy})
file(WRITE ${damaged} "${text}\n")
expect_refused(${bad_page} "damaged\\.path:12: x 'x1\\.5' is not a finite number"
  render ${log} -o ${bad_page} --compare ${damaged})

# Cut off at a line's end: no 'end' line.
set(cut ${WORK}/cut.path)
list(SUBLIST lines 0 200 head)
string(JOIN "\n" text ${head})
file(WRITE ${cut} "${text}\n")
expect_refused(${bad_page} "cut\\.path:201: the file stops before its 'end' line" render ${log} -o ${bad_page} --compare ${cut})

# Times that go back.
set(backwards ${WORK}/backwards.path)
set(copy ${lines})
list(GET copy 9 first)
list(INSERT copy 12 "${first}")
string(JOIN "\n" text ${copy})
file(WRITE ${backwards} "${text}\n")
expect_refused(${bad_page} "backwards\\.path:13: ball [^ ]+'s times must increase"
  render ${log} -o ${bad_page} --compare ${backwards})

# Neither a log nor a path file.
get_filename_component(other_name ${OTHER_BOARD} NAME)
expect_refused(${bad_page} "${other_name}: neither a replay log nor a path file"
  render ${log} -o ${bad_page} --compare ${OTHER_BOARD})
expect_refused(${bad_page} "box2d:1/0: not a step size" render ${log} -o ${bad_page} --compare box2d:1/0)
expect_exit(2 crosscheck ${BOARD} --time 1 --dt 1/60,1/120 --path-out ${WORK}/two.path)
if(NOT RUN_STDERR MATCHES "--path-out writes the path of one step size" OR EXISTS ${WORK}/two.path)
  gizmo_fail("--path-out with two step sizes should be refused, writing nothing")
endif()
