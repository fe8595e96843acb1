# `gizmo fuzz` in N shards, merged, against one unsharded run with the same seed: the summary lines
# must be the same (cmake -P; -DGIZMO=the binary -DWORK=a scratch folder -DSHARDS=N, the campaign's
# arguments after --).
include(${CMAKE_CURRENT_LIST_DIR}/../integration/gizmo_cli.cmake)
gizmo_script_args(campaign)
file(REMOVE_RECURSE ${WORK})

# The line that starts with "fuzz: " in `out`.
function(summary_of out var)
  string(REGEX MATCH "fuzz: [^\n]*" line "${out}")
  if(line STREQUAL "")
    gizmo_fail("no summary line")
  endif()
  set(${var} "${line}" PARENT_SCOPE)
endfunction()

gizmo_run(RUN fuzz ${campaign} --out ${WORK}/whole)
if(NOT RUN_EXIT EQUAL 0 AND NOT RUN_EXIT EQUAL 1)
  gizmo_fail("the unsharded campaign failed to run")
endif()
set(wholeExit ${RUN_EXIT})
summary_of("${RUN_STDOUT}" whole)

math(EXPR last "${SHARDS} - 1")
set(dirs "")
foreach(k RANGE ${last})
  gizmo_run(RUN fuzz ${campaign} --shard ${k}/${SHARDS} --out ${WORK}/shard-${k})
  if(NOT RUN_EXIT EQUAL 0 AND NOT RUN_EXIT EQUAL 1)
    gizmo_fail("shard ${k}/${SHARDS} failed to run")
  endif()
  list(APPEND dirs ${WORK}/shard-${k})
endforeach()

gizmo_run(RUN fuzz --merge ${dirs})
summary_of("${RUN_STDOUT}" merged)
if(NOT merged STREQUAL whole)
  gizmo_fail("merged shards: ${merged}\nunsharded:     ${whole}")
endif()
if(NOT RUN_EXIT EQUAL wholeExit)
  gizmo_fail("the merge exits ${RUN_EXIT}, the unsharded run ${wholeExit}")
endif()

# A shard missing is refused.
list(REMOVE_AT dirs 0)
gizmo_run(RUN fuzz --merge ${dirs})
if(NOT RUN_EXIT EQUAL 2 OR NOT RUN_STDERR MATCHES "shard 0 of ${SHARDS} is missing")
  gizmo_fail("a merge without shard 0 should be refused with exit 2")
endif()
file(REMOVE_RECURSE ${WORK})
