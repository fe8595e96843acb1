# Checks on a file `gizmo render` writes, without a browser (used by tests/integration):
#   cmake -DGIZMO=exe -DOUTPUT=file -DEXIT=code [-DKIND=html|svg] [-DCONTAINS=regex]
#         -P check_rendered_file.cmake -- render-arguments...
# EXIT 0: the file exists and is self-contained (no network address but SVG's namespace name, no
# external script, every template marker filled, no path of this machine). Any other EXIT: the
# command failed with it and left no file, not even a partial one.
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/../support/written_file_checks.cmake)
gizmo_write_checked(render)
file(READ ${OUTPUT} text)
if(KIND STREQUAL "svg")
  string(REPLACE "xmlns=\"http://www.w3.org/2000/svg\"" "" text "${text}")
  if(NOT text MATCHES "^<svg ")
    message(FATAL_ERROR "${OUTPUT} is not an SVG picture")
  endif()
else()
  gizmo_check_parts("${text}" "<canvas id=\"board\"" "<script id=\"run-data\" type=\"application/json\">{\"format\":1")
endif()
gizmo_check_self_contained("${text}")
foreach(arg ${args})
  get_filename_component(dir "${arg}" DIRECTORY)
  if(IS_ABSOLUTE "${dir}")
    string(FIND "${text}" "${dir}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${OUTPUT} names a folder of this machine: ${dir}")
    endif()
  endif()
endforeach()
