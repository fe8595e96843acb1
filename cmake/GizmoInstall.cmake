# Installation: the static libraries gizmo_core, gizmo_io and gizmo_replay with their headers,
# the `gizmo` command, and a CMake package so that `find_package(gizmo)` gives gizmo::core,
# gizmo::io and gizmo::replay (docs/library.md). Paths are relative to the prefix, so an installation can be moved.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GIZMO_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/gizmo)

# EXPORT_NAME (core, io, replay) plus the namespace give the same names as the ALIAS targets in the build.
install(TARGETS gizmo_core gizmo_io gizmo_replay EXPORT gizmoTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS gizmo RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# Every public header; the src folders hold the private ones.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/include/ ${PROJECT_SOURCE_DIR}/core/io/include/
                  ${PROJECT_SOURCE_DIR}/replay/include/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")
# and the core's generated header of every kind's file (cmake/GizmoKinds.cmake).
install(FILES ${GIZMO_GENERATED_DIR}/core/gizmo/core/kinds/all_kinds.hpp
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/gizmo/core/kinds)

install(EXPORT gizmoTargets
  NAMESPACE gizmo::
  DESTINATION ${GIZMO_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/gizmoConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/gizmoConfig.cmake
  INSTALL_DESTINATION ${GIZMO_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/gizmoConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/gizmoConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/gizmoConfigVersion.cmake
  DESTINATION ${GIZMO_INSTALL_CMAKEDIR})
