# Every build compiles through ccache when it is installed (scripts/setup.sh installs it), so that
# a second build of the same sources, in this folder or in a clone elsewhere on the machine (CI's
# fresh clone), takes its objects from the cache. GIZMO_CCACHE=OFF compiles without it; a launcher
# given on the command line (-DCMAKE_CXX_COMPILER_LAUNCHER=...) is left as it is.
#
# What makes a clone in another folder hit the cache (docs/design.md, "The compiler cache"):
# - base_dir: ccache rewrites the absolute paths under the source folder that CMake puts on the
#   command line (the source, -I, -include of a precompiled header) into paths relative to the
#   build folder, which are the same in every clone;
# - hash_dir off: the asan build's -g would otherwise put the build folder into every key;
# - no absolute path inside a -D: the tests and benchmarks learn where the fixtures are from one
#   small generated source (tests/support/paths.hpp), the only object a clone compiles again;
# - sloppiness pch_defines,time_macros: what ccache needs to cache a source compiled with a
#   precompiled header (its manual, "Precompiled headers"); nothing here uses __DATE__ or __TIME__,
#   and the precompiled headers hold third-party headers only. include_file_mtime and ctime: a
#   header written by the build just before a source that includes it (the unity sources) is
#   hashed by its content like any other;
# - the inode cache: ccache hashes every file a source includes, and the precompiled header that
#   each source of a target reads is 240 MB; remembered by inode, size and times, it is hashed
#   once per build instead of once per source (a test source's compilation through an empty
#   cache: 1.6 s of CPU over the compiler's own 9.9 s without it, 0.3 s with it).
option(GIZMO_CCACHE "Compile through ccache when it is installed" ON)
if(GIZMO_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(GIZMO_CCACHE_PROGRAM ccache)
  if(GIZMO_CCACHE_PROGRAM)
    set(CMAKE_CXX_COMPILER_LAUNCHER
        ${CMAKE_COMMAND} -E env
        CCACHE_BASEDIR=${CMAKE_SOURCE_DIR}
        CCACHE_NOHASHDIR=1
        CCACHE_INODECACHE=1
        CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
        ${GIZMO_CCACHE_PROGRAM})
  endif()
endif()
