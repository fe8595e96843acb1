# The consumer test: install gizmo's build tree into a fresh prefix, then configure, build and
# run tests/consumer against it, as a project outside gizmo would.
#   cmake -DGIZMO_BUILD_DIR=... -DWORK_DIR=... -DGENERATOR=... -DMAKE_PROGRAM=... -DBUILD_TYPE=...
#         -DCXX_COMPILER=... -P run.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var GIZMO_BUILD_DIR WORK_DIR GENERATOR MAKE_PROGRAM CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run.cmake: -D${var}=... is required")
  endif()
endforeach()
set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
# From scratch every time, so that a file missing from the install rules cannot hide behind an
# earlier run.
file(REMOVE_RECURSE ${WORK_DIR})

execute_process(COMMAND ${CMAKE_COMMAND} --install ${GIZMO_BUILD_DIR} --prefix ${prefix}
                OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
foreach(f include/gizmo/core/board/game_board.hpp include/gizmo/io/board_file.hpp)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "the installation lacks ${f}")
  endif()
endforeach()
# The installed command runs (the built-in board needs no other file).
execute_process(COMMAND ${prefix}/bin/gizmo run --time 1 OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)

# The consumer sees the gizmo of this prefix only: no package registry, no other prefixes.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR} -B ${build} -G ${GENERATOR}
                        -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
                        -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_PREFIX_PATH=${prefix}
                        -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
                OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
file(STRINGS ${build}/CMakeCache.txt found REGEX "^gizmo_DIR:")
string(FIND "${found}" "=${prefix}/" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the consumer found gizmo outside the test prefix: ${found}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${build} COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${build}/gizmo_consumer COMMAND_ERROR_IS_FATAL ANY)
