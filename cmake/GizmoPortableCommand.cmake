# The portable `gizmo` command's link step (included from cli/CMakeLists.txt).
if(EMSCRIPTEN)
  # cli/gizmo.js runs under node with the arguments and the file system of a native command:
  # NODERAWFS gives it the real file system; SINGLE_FILE puts the .wasm inside the .js (Node 20's
  # fetch cannot load this emscripten's separate file); EXIT_RUNTIME makes main's return value
  # the process's exit code and flushes the output; a board run may need more than the initial
  # 16 MiB of memory.
  target_link_options(gizmo PRIVATE -sNODERAWFS=1 -sSINGLE_FILE=1 -sEXIT_RUNTIME=1 -sALLOW_MEMORY_GROWTH=1
                                    -sENVIRONMENT=node)
endif()

# BUILD/gizmo-run runs the command on this machine with the arguments given: natively, or through
# the target's emulator (qemu-user, node). scripts/dev cross-check calls every target through it.
list(JOIN CMAKE_CROSSCOMPILING_EMULATOR " " GIZMO_RUNNER)
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/gizmo-run
     CONTENT "#!/bin/sh\nexec ${GIZMO_RUNNER} $<TARGET_FILE:gizmo> \"$@\"\n"
     FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
