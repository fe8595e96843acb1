# Two runs of `gizmo run --json` must print the same JSON apart from wall_seconds:
#   cmake -DGIZMO=exe -P compare_runs.cmake -- first-arguments... --vs second-arguments...
# The same arguments twice test determinism; two board files test that they mean the same board.
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/gizmo_cli.cmake)

gizmo_script_args(args)
list(FIND args "--vs" split)
if(split EQUAL -1)
  message(FATAL_ERROR "compare_runs.cmake: the arguments of the two runs are separated by --vs")
endif()
list(SUBLIST args 0 ${split} first)
math(EXPR start "${split} + 1")
list(SUBLIST args ${start} -1 second)

foreach(run IN ITEMS first second)
  gizmo_run(RUN ${${run}})
  if(NOT RUN_EXIT STREQUAL "0")
    gizmo_fail("the ${run} run should exit with 0")
  endif()
  gizmo_check_run_json("${RUN_STDOUT}")
  gizmo_without_wall_seconds(${run}_json "${RUN_STDOUT}")
endforeach()

if(NOT first_json STREQUAL second_json)
  string(JOIN " " a ${first})
  string(JOIN " " b ${second})
  message(FATAL_ERROR "the two runs differ (apart from wall_seconds)\n"
                      "--- gizmo ${a}\n${first_json}--- gizmo ${b}\n${second_json}---")
endif()
