#include "support/paths.hpp"

namespace gizmo::test {

std::string fixturesDir() { return GIZMO_FIXTURES_DIR; }
std::string fixturePath(const std::string& relative) { return fixturesDir() + "/" + relative; }
std::string realBoardsDir() { return GIZMO_REAL_BOARDS_DIR; }

}  // namespace gizmo::test
