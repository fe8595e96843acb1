// Every kind in the registry (core/include/gizmo/core/kinds/kind_list.hpp), walked from the list
// rather than by name: its example board (fixtures/boards/gizmos/STEM.txt) read, written and read
// again in both formats, built and run, its rows complete, and the fuzz generator making it. A kind
// added to the list is tested here without a test of its own (docs/design.md, "Adding a gizmo").
#include <gtest/gtest.h>

#include <array>
#include <ostream>
#include <string>

#include "gizmo/core/board/build_board.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "gizmo/core/gizmos/absorber.hpp"
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/io/text_reader.hpp"
#include "gizmo/io/xml_reader.hpp"
#include "gizmo/verify/fuzz/run_generator.hpp"
#include "support/paths.hpp"

namespace gizmo {
namespace {

struct KindCase {
  GizmoType type;
  std::string stem;
};

void PrintTo(const KindCase& k, std::ostream* os) { *os << k.stem; }

std::vector<KindCase> everyKind() {
  std::vector<KindCase> kinds;
#define GIZMO_KIND_CASE(Name, stem) kinds.push_back({GizmoType::Name, #stem});
  GIZMO_KINDS(GIZMO_KIND_CASE)
#undef GIZMO_KIND_CASE
  return kinds;
}

class EveryKind : public ::testing::TestWithParam<KindCase> {
 protected:
  // The kind's example board: one gizmo of the kind at least, and a ball.
  BoardSpec example() const {
    const std::string path = test::fixturePath("boards/gizmos/" + GetParam().stem + ".txt");
    BoardSpec board = io::readBoardFile(path).board;
    return board;
  }
  const GizmoSpec* gizmoOfKind(const BoardSpec& board) const {
    for (const GizmoSpec& g : board.gizmos)
      if (g.type == GetParam().type) return &g;
    return nullptr;
  }
};

TEST_P(EveryKind, HasAnExampleBoardWithIt) {
  const BoardSpec board = example();
  ASSERT_NE(gizmoOfKind(board), nullptr) << "fixtures/boards/gizmos/" << GetParam().stem << ".txt has no "
                                         << gizmoKind(GetParam().type).word;
  EXPECT_FALSE(board.balls.empty());
}

TEST_P(EveryKind, ItsRowIsCompleteAndItsNamesAreItsOwn) {
  const GizmoKindInfo& k = gizmoKind(GetParam().type);
  EXPECT_EQ(k.type, GetParam().type);
  for (std::string_view name : {k.textCommand, k.textUsage, k.xmlElement, k.word, k.drawing})
    EXPECT_FALSE(name.empty());
  EXPECT_EQ(k.textUsage.substr(0, k.textCommand.size()), k.textCommand);
  for (const GizmoKindInfo& other : kGizmoKinds) {
    if (other.type == k.type) continue;
    EXPECT_NE(other.textCommand, k.textCommand);
    EXPECT_NE(other.xmlElement, k.xmlElement);
    EXPECT_NE(other.drawing, k.drawing);
  }
}

TEST_P(EveryKind, TextBoardRoundTrips) {
  const BoardSpec board = example();
  const std::string text = io::writeTextBoard(board);
  EXPECT_NE(text.find(std::string(gizmoKind(GetParam().type).textCommand) + " "), std::string::npos);
  const BoardSpec again = io::readTextBoard(text, "written.txt").board;
  EXPECT_EQ(io::writeTextBoard(again), text);
  ASSERT_NE(gizmoOfKind(again), nullptr);
}

TEST_P(EveryKind, XmlBoardRoundTrips) {
  const BoardSpec board = example();
  const std::string xml = io::writeXmlBoard(board);
  EXPECT_NE(xml.find("<" + std::string(gizmoKind(GetParam().type).xmlElement) + " "), std::string::npos);
  const BoardSpec again = io::readXmlBoard(xml, "written.xml").board;
  EXPECT_EQ(io::writeXmlBoard(again), xml);
  EXPECT_EQ(io::writeTextBoard(again), io::writeTextBoard(board));
}

TEST_P(EveryKind, BuildsAndRuns) {
  RunRequest request;
  request.board = example();
  request.duration = 2;
  const RunSummary run = simulate<double>(request);
  EXPECT_NEAR(run.time, 2.0, 1e-9);
  EXPECT_GT(run.total, 0u);
  // The board built the kind's gizmo, and it has the kind's outline (restShape).
  const auto board = buildBoard<double>(request.board, PhysicsParams<double>{});
  bool found = false;
  for (GizmoId id = 0; id < GizmoId(board->gizmoCount()); ++id)
    found = found || board->gizmo(id).kind() == gizmoKindOf(GetParam().type);
  EXPECT_TRUE(found);
}

// Its entries that say what its gizmo does are what the shared code relies on (kinds/kind_core.hpp):
// a kind that swings builds a Flipper, one that turns a Spinner, a still one neither, and a gizmo
// of it reports its kind's motion; one that holds the balls placed inside it builds an Absorber,
// which holds them at the start.
TEST_P(EveryKind, ItsEntriesAreWhatItsGizmoIs) {
  const auto board = buildBoard<double>(example(), PhysicsParams<double>{});
  const KindMotion motion = gizmoKind(GetParam().type).motion;
  const bool holds = gizmoKind(GetParam().type).holdsPlacedBalls;
  int seen = 0;
  for (GizmoId id = 0; id < GizmoId(board->gizmoCount()); ++id) {
    const AbstractGizmo<double>& g = board->gizmo(id);
    if (g.kind() != gizmoKindOf(GetParam().type)) continue;
    ++seen;
    EXPECT_EQ(motionOf(g.kind()), motion);
    EXPECT_EQ(dynamic_cast<const Flipper<double>*>(&g) != nullptr, motion == KindMotion::Swings) << g.name();
    EXPECT_EQ(dynamic_cast<const Spinner<double>*>(&g) != nullptr, motion == KindMotion::Turns) << g.name();
    EXPECT_EQ(dynamic_cast<const Absorber<double>*>(&g) != nullptr, holds) << g.name();
  }
  EXPECT_GT(seen, 0);
  EXPECT_EQ(motionOf(GizmoKind::Ball), KindMotion::Still);
  EXPECT_EQ(motionOf(GizmoKind::OuterWalls), KindMotion::Still);
}

TEST_P(EveryKind, TheGeneratorMakesIt) {
  for (std::uint64_t seed = 1; seed <= 400; ++seed)
    for (const GizmoSpec& g : verify::fuzz::generateRun(seed, verify::fuzz::kMaxSize).board.gizmos)
      if (g.type == GetParam().type) return;
  ADD_FAILURE() << "no generated board of seeds 1 to 400 has a " << gizmoKind(GetParam().type).word;
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryKind, ::testing::ValuesIn(everyKind()),
                         [](const ::testing::TestParamInfo<KindCase>& info) { return info.param.stem; });

// GizmoType and GizmoKind are generated from the list in its order (GizmoKind after its Ball and
// OuterWalls): the tables indexed by them (kGizmoKinds, motionOf) rely on it.
TEST(KindRegistry, ValuesFollowTheList) {
  int i = 0;
#define GIZMO_KIND_VALUE(Name, stem)                                         \
  EXPECT_EQ(static_cast<int>(GizmoType::Name), i) << #Name;                  \
  EXPECT_EQ(static_cast<int>(gizmoKindOf(GizmoType::Name)), i + 2) << #Name; \
  ++i;
  GIZMO_KINDS(GIZMO_KIND_VALUE)
#undef GIZMO_KIND_VALUE
  EXPECT_EQ(i, kGizmoTypeCount);
}

// Each rule's code is in logs (docs/replay-format.md, the model rules' table): the board's own
// rules and the kinds' (declared by their behaviour classes, named by their kinds' files) keep
// the codes that logs written before hold, and the names that `gizmo dump` prints and `--only`
// takes.
TEST(KindRegistry, RuleCodesAreTheLogs) {
  const std::array<std::string_view, kModelRuleCodeCount> names = {
      "friction",        "contact-begin", "contact-end",   "minimum-bounce", "wedged",     "flipper-blocked",
      "captured",        "released",      "jammed",        "boosted",        "teleported", "sunk",
      "spinner-blocked", "spawned",       "spawn-blocked", "settled"};
  for (int code = 0; code < kModelRuleCodeCount; ++code)
    EXPECT_EQ(modelRuleName(static_cast<ModelRule>(code)), names[code]) << "code " << code;
  EXPECT_EQ(modelRuleName(static_cast<ModelRule>(kModelRuleCodeCount)), "");
}

}  // namespace
}  // namespace gizmo
