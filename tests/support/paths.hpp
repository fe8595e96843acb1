#pragma once
// Where the tests and benchmarks find the files they read. The folders are compiled into one small
// source (paths.cpp, given them by CMake) rather than into a -D of every test source: an absolute
// path inside a -D would keep ccache from reusing those objects in a clone in another folder
// (cmake/GizmoCompilerCache.cmake).
#include <string>

namespace gizmo::test {

// The repository's fixtures/ folder, e.g. fixturePath("boards/spec-example.txt").
std::string fixturesDir();
std::string fixturePath(const std::string& relative);

// The real-board collection, read where it lies beside the source tree (../shared/boards/real);
// a clone on its own does not have it (docs/board-files.md §7, "Boards of other Gizmoball programs").
std::string realBoardsDir();

}  // namespace gizmo::test
