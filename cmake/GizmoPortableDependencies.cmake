# The portable build's libraries (docs/determinism.md): pugixml where the target has it (Debian's
# multiarch libpugixml-dev:ARCH; scripts/setup-cross.sh installs it), and the header-only CLI11
# and nlohmann-json, the same files for every target.
find_package(pugixml QUIET)
# A Linux cross target's command is linked statically (cmake/toolchains/linux-cross.cmake).
if(CMAKE_CROSSCOMPILING AND NOT EMSCRIPTEN AND TARGET pugixml::static)
  set_target_properties(pugixml::pugixml PROPERTIES INTERFACE_LINK_LIBRARIES pugixml::static)
endif()
if(NOT TARGET pugixml::pugixml)
  message(STATUS "gizmo: no pugixml for this target, so this build reads text boards only")
endif()

if(EMSCRIPTEN)
  # emscripten has a system root of its own, and the host's /usr/include must not be searched
  # (its C library headers are not emscripten's): the two header-only libraries are reached
  # through a folder that holds links to them and nothing else.
  set(GIZMO_HOST_HEADERS ${CMAKE_BINARY_DIR}/host-headers)
  foreach(library CLI nlohmann)
    find_path(GIZMO_${library}_DIR ${library} PATHS /usr/include NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH REQUIRED)
    file(MAKE_DIRECTORY ${GIZMO_HOST_HEADERS})
    file(CREATE_LINK ${GIZMO_${library}_DIR}/${library} ${GIZMO_HOST_HEADERS}/${library} SYMBOLIC)
  endforeach()
  add_library(CLI11::CLI11 INTERFACE IMPORTED)
  add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
  set_target_properties(CLI11::CLI11 nlohmann_json::nlohmann_json PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES ${GIZMO_HOST_HEADERS})
else()
  find_package(CLI11 REQUIRED)
  find_package(nlohmann_json REQUIRED)
endif()
