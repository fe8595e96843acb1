# What makes a build from scratch fast on two cores: precompiled headers and unity groups. Both
# pay off where nothing is cached; neither changes what is compiled, only how often the same
# headers are parsed and the same inline functions optimized.
#
# Precompiled headers: nearly every source includes gizmo/core/math/scalar.hpp, and with it the
# four Boost.Multiprecision backends, which cost about 2 s of compiling per source at -O3 before a
# line of ours is read (2.5 s for scalar.hpp alone against 0.5 s for the standard headers it
# uses). Parsed once per target instead, a build from scratch spends that once per target.
#
# Both stay on under ccache (cmake/GizmoCompilerCache.cmake sets the sloppiness that lets it cache
# a source compiled with a precompiled header). A unity group is compiled again whenever one of its
# sources changes, which an edit-and-rebuild cycle feels: GIZMO_UNITY_BUILD=OFF for such work.
# The asan preset and the libFuzzer build (scripts/fuzz-run.sh) turn both off: they compile
# every source on its own, so a header that a source forgot to include cannot hide behind a
# neighbour in its unity group, and clang is not given g++'s precompiled-header workaround.
set(GIZMO_FRESH_BUILD_DEFAULT ON)
# The portable build (docs/determinism.md) has none of the Boost headers below to precompile.
set(GIZMO_PRECOMPILE_DEFAULT ${GIZMO_FRESH_BUILD_DEFAULT})
if(GIZMO_PORTABLE)
  set(GIZMO_PRECOMPILE_DEFAULT OFF)
endif()
option(GIZMO_PRECOMPILE_HEADERS "Precompile the heavy third-party headers once per target"
       ${GIZMO_PRECOMPILE_DEFAULT})
option(GIZMO_UNITY_BUILD "Compile each unity group of sources as one translation unit"
       ${GIZMO_FRESH_BUILD_DEFAULT})

# Third-party headers only, so that editing gizmo's own headers never rebuilds a precompiled one.
set(GIZMO_PRECOMPILED_HEADERS
  <algorithm> <map> <memory> <optional> <stdexcept> <string> <vector>
  <boost/math/constants/constants.hpp>
  <boost/multiprecision/cpp_bin_float.hpp>
  <boost/multiprecision/float128.hpp>
  <boost/multiprecision/gmp.hpp>
  <boost/multiprecision/mpfr.hpp>)

# gizmo_precompiled_header_warnings(TARGET):
# g++ 12 does not keep `#pragma GCC diagnostic` in a precompiled header (GCC PR 64117, fixed in
# g++ 13), and libstdc++ 12 turns three warnings off that way around std::string's copies, where
# g++ 12 gives false positives for `"text" + std::string` (the family of PR 105651). A target with
# a precompiled header turns those three off itself; builds without one (ccache, clang, g++ 13)
# keep them.
function(gizmo_precompiled_header_warnings target)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-array-bounds -Wno-stringop-overflow -Wno-stringop-overread)
  endif()
endfunction()

# gizmo_precompile_headers(TARGET [HEADER...]): TARGET's sources are compiled with the headers
# above and the extra HEADERs (e.g. <nlohmann/json.hpp>) precompiled. Building a precompiled
# header costs about as much as compiling four sources' includes (10 to 13 s, and each source
# then loads its 240 MB), so only targets of several sources that include the heavy headers are
# given one of their own; the smaller ones reuse one (gizmo_reuse_precompiled_header below).
# TARGET must link Boost and MPFR (gizmo::core does).
function(gizmo_precompile_headers target)
  if(GIZMO_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE ${GIZMO_PRECOMPILED_HEADERS} ${ARGN})
    gizmo_precompiled_header_warnings(${target})
  endif()
endfunction()

# gizmo_unity_group(TARGET GROUP SOURCE...): TARGET's SOURCEs are compiled as one translation unit
# (CMake's unity build, GROUP mode), so the headers they share, and the inline functions of those
# headers that each would optimize again (std::string's, nlohmann::json's, the core's), cost once.
# A group holds sources of one purpose; sources named in no group are compiled alone, the
# heaviest ones (one scalar's instantiations each) so that both cores stay busy. Two sources whose
# file-local helpers share a name cannot be in one group.
function(gizmo_unity_group target group)
  if(GIZMO_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
    set_source_files_properties(${ARGN} PROPERTIES UNITY_GROUP ${group})
  endif()
endfunction()

# gizmo_shared_precompiled_header(NAME LIBS lib... HEADERS header...): the headers above and the
# HEADERs precompiled once, in NAME (an object library of one empty source, linked to LIBS so that
# it is compiled with the flags of the targets that reuse it), for targets too small to pay for a
# precompiled header of their own. gizmo_reuse_precompiled_header(TARGET NAME) compiles TARGET's
# sources with it. The test programs each hold a few sources that include GoogleTest's and the
# Boost headers: one header for all of them costs 8 s of compiling and saves about 2 to 3 s of
# every test source (docs/design.md, "Building from scratch").
function(gizmo_shared_precompiled_header name)
  if(NOT GIZMO_PRECOMPILE_HEADERS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "LIBS;HEADERS" ${ARGN})
  set(anchor ${CMAKE_CURRENT_BINARY_DIR}/${name}_anchor.cpp)
  file(CONFIGURE OUTPUT ${anchor} CONTENT "// The translation unit that ${name}'s precompiled header is built for.\n")
  add_library(${name} OBJECT ${anchor})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS})
  gizmo_precompile_headers(${name} ${ARG_HEADERS})
endfunction()

# gizmo_reuse_precompiled_header(TARGET NAME): TARGET's sources are compiled with NAME's precompiled
# header (NAME is gizmo_core, or made by gizmo_shared_precompiled_header). TARGET must be compiled
# with the same language flags: g++ refuses a header built with others, and -Winvalid-pch, which
# CMake adds, says so. Measured on a build from scratch with two jobs (ninja on the objects alone):
# gizmo_io and gizmo_replay 50 s -> 41 s with gizmo_core's; the fuzz corpus runners, the
# real-board survey and gizmo_bench 65 s -> 47 s with gizmo_core's; the test programs 224 s ->
# 166 s with gizmo_test_pch (its own 8 s included).
function(gizmo_reuse_precompiled_header target name)
  if(GIZMO_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} REUSE_FROM ${name})
    gizmo_precompiled_header_warnings(${target})
  endif()
endfunction()
