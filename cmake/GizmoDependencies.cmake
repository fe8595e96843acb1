# Every third-party library comes from Debian 12's packages (scripts/setup.sh installs them).
if(GIZMO_PORTABLE)
  include(${CMAKE_CURRENT_LIST_DIR}/GizmoPortableDependencies.cmake)
  return()
endif()
# The minimum Boost version is also written into the installed gizmoConfig.cmake.
set(GIZMO_BOOST_MIN_VERSION 1.74)
find_package(Boost ${GIZMO_BOOST_MIN_VERSION} REQUIRED)
find_package(PkgConfig REQUIRED)
# Boost's float128 includes <quadmath.h>, which only GCC's own include directory holds; clang
# does not search it. Searched after every other directory, that directory supplies this header
# and nothing clang has itself (core/CMakeLists.txt adds it to gizmo::core).
set(GIZMO_QUADMATH_INCLUDE_DIR "")
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  include(CheckIncludeFileCXX)
  check_include_file_cxx(quadmath.h GIZMO_CLANG_FINDS_QUADMATH)
  if(NOT GIZMO_CLANG_FINDS_QUADMATH)
    execute_process(COMMAND gcc -print-file-name=include OUTPUT_VARIABLE GIZMO_QUADMATH_INCLUDE_DIR
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT EXISTS "${GIZMO_QUADMATH_INCLUDE_DIR}/quadmath.h")
      message(FATAL_ERROR "clang needs GCC's quadmath.h (for Boost's float128); install gcc")
    endif()
  endif()
endif()
pkg_check_modules(GMP REQUIRED IMPORTED_TARGET gmp)
pkg_check_modules(MPFR REQUIRED IMPORTED_TARGET mpfr)
find_package(pugixml REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json REQUIRED)
if(GIZMO_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(GIZMO_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
# MPFI (interval arithmetic over MPFR, for certified decisions) ships no CMake or pkg-config file.
find_path(GIZMO_MPFI_INCLUDE_DIR mpfi.h REQUIRED)
find_library(GIZMO_MPFI_LIBRARY mpfi REQUIRED)
if(NOT TARGET gizmo_mpfi)
  add_library(gizmo_mpfi INTERFACE IMPORTED)
  set_target_properties(gizmo_mpfi PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${GIZMO_MPFI_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${GIZMO_MPFI_LIBRARY};PkgConfig::MPFR;PkgConfig::GMP")
endif()
# The Box2D bridge of gizmo::verify (docs/verification.md, "Cross-checking against Box2D").
find_package(box2d REQUIRED)
if(GIZMO_BUILD_TESTS)
  find_package(rapidcheck REQUIRED)  # targets rapidcheck and rapidcheck_gtest, no namespace
endif()
