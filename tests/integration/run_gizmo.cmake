# One run of the `gizmo` command and checks on what it did:
#   cmake -DGIZMO=exe -DEXIT=code [-DSTDOUT=regex] [-DSTDERR=regex] [-DEMPTY_STDOUT=ON]
#         [-DDIAGNOSTICS=file [-DDIAGNOSTICS_MATCH=first|all]] [-DJSON=ON [-DJSON_PRECISION=name]]
#         -P run_gizmo.cmake -- gizmo-arguments...
# DIAGNOSTICS: a fixture's .expected file; stderr's first line (or all of stderr) must be its
# first line (or all of it). JSON: stdout is the output of `gizmo run --json`.
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/gizmo_cli.cmake)

gizmo_script_args(args)
gizmo_run(RUN ${args})

gizmo_check_run(${EXIT} "")
if(EMPTY_STDOUT AND NOT RUN_STDOUT STREQUAL "")
  gizmo_fail("stdout should be empty")
endif()

if(DEFINED DIAGNOSTICS)
  file(READ ${DIAGNOSTICS} expected)
  if(DIAGNOSTICS_MATCH STREQUAL "all")
    set(got "${RUN_STDERR}")
  else()
    string(REGEX REPLACE "\n.*" "" expected "${expected}")
    string(REGEX REPLACE "\n.*" "" got "${RUN_STDERR}")
  endif()
  if(NOT got STREQUAL expected)
    if(DIAGNOSTICS_MATCH STREQUAL "all")
      gizmo_fail("stderr should be exactly\n${expected}")
    else()
      gizmo_fail("stderr's first line should be\n${expected}")
    endif()
  endif()
endif()

if(JSON)
  gizmo_check_run_json("${RUN_STDOUT}")
  if(DEFINED JSON_PRECISION)
    string(JSON precision GET "${RUN_STDOUT}" precision)
    if(NOT precision STREQUAL JSON_PRECISION)
      gizmo_fail("the JSON output's precision should be ${JSON_PRECISION}")
    endif()
  endif()
endif()
