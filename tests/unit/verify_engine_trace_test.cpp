// Any engine's run read from a trace and compared by the cross-check's own code
// (docs/verification.md, "Any engine's run"): a trace of the exact motion matches everything; a
// planted miss, a late contact and a path that drifts off are each reported as such; a damaged
// trace is refused with its file, line and what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "gizmo/verify/engine_trace.hpp"
#include "support/board_builder.hpp"

namespace gizmo::verify {
namespace {

// One ball between the side walls at 20 L/s, no gravity, no friction: it meets the right wall at
// x = 19.75 when 0.4875 s have passed, the left one 0.975 s later, and so on.
constexpr double kSpeed = 20, kStartX = 10, kY = 10.5, kStep = 0.01, kEnd = 2;
const double kRightWall = (19.75 - kStartX) / kSpeed, kLeftWall = kRightWall + 19.5 / kSpeed;

BoardSpec board() {
  BoardSpec b = test::emptyBoard(0);
  b.balls.push_back(test::ballAt("B", kStartX, kY, kSpeed, 0));
  return b;
}

RunRequest request() {
  RunRequest r;
  r.board = board();
  r.duration = kEnd;
  return r;
}

// The exact motion: x folded between the walls, the velocity's sign with it.
void exactAt(double t, double& x, double& vx) {
  const double u = std::fmod(kStartX - 0.25 + kSpeed * t, 39.0);
  x = u <= 19.5 ? 0.25 + u : 0.25 + 39 - u;
  vx = u <= 19.5 ? kSpeed : -kSpeed;
}

struct TraceContact {
  double t, x;
};

// A trace of the run at steps of kStep to kEnd + 0.1 s: positions from `path`, and the contacts
// given, each listed with the step that it falls in.
std::string traceText(std::vector<TraceContact> contacts,
                      const std::function<void(double, double&, double&, double&)>& path) {
  std::ostringstream out;
  out.precision(17);
  out << R"({"format":"gizmo-trace","version":1,"engine":"exact by hand","contacts":true})" << '\n';
  std::size_t next = 0;
  for (int k = 0; double(k) * kStep <= kEnd + 0.1; ++k) {
    const double t = double(k) * kStep;
    double x = 0, y = 0, vx = 0;
    path(t, x, y, vx);
    out << R"({"t":)" << t << R"(,"balls":{"B":{"x":)" << x << R"(,"y":)" << y << R"(,"vx":)" << vx
        << R"(,"vy":0}},"contacts":[)";
    for (bool first = true; next < contacts.size() && contacts[next].t <= t; ++next, first = false)
      out << (first ? "" : ",") << R"({"t":)" << contacts[next].t << R"(,"ball":"B","other":"OuterWalls","x":)"
          << contacts[next].x << R"(,"y":)" << kY << "}";
    out << "]}\n";
  }
  return out.str();
}

void exactPath(double t, double& x, double& y, double& vx) {
  exactAt(t, x, vx);
  y = kY;
}

StepComparison compare(const std::string& text) {
  std::istringstream in(text);
  const EngineTrace trace = readEngineTrace(in, "t.jsonl", board(), kEnd);
  EXPECT_EQ(trace.engine, "exact by hand");
  const CrosscheckReport report = crosscheckRuns(request(), {trace.run});
  EXPECT_EQ(report.ourCollisions, 2u);  // the two walls within 2 s
  return report.steps.at(0);
}

TEST(EngineTrace, ExactRunMatchesEveryCollision) {
  const StepComparison c = compare(traceText({{kRightWall, 19.75}, {kLeftWall, 0.25}}, exactPath));
  EXPECT_EQ(c.matched, 2u);
  EXPECT_EQ(c.missedByThem, 0u);
  EXPECT_EQ(c.missedByUs, 0u);
  EXPECT_LT(c.maxTimeError, 1e-12);
  EXPECT_LT(c.maxPositionError, 1e-12);
  EXPECT_LT(c.maxDivergence, 1e-12);
  EXPECT_FALSE(c.parting);
  EXPECT_NEAR(c.dt, kStep, 1e-12);
}

// The engine "forgot" the left wall: our hit there is the one it missed.
TEST(EngineTrace, PlantedMissIsTheFirstUnmatched) {
  const StepComparison c = compare(traceText({{kRightWall, 19.75}}, exactPath));
  EXPECT_EQ(c.matched, 1u);
  EXPECT_EQ(c.missedByThem, 1u);
  EXPECT_EQ(c.missedByUs, 0u);
  ASSERT_TRUE(c.firstUnmatched);
  EXPECT_EQ(c.firstUnmatched->side, "ours");
  EXPECT_EQ(c.firstUnmatched->collision.other, kOuterWallsName);
  EXPECT_NEAR(c.firstUnmatched->collision.time, kLeftWall, 1e-12);
}

// The engine reports the right wall 3 ms late: still matched, with that time error.
TEST(EngineTrace, LateContactIsATimeError) {
  const StepComparison c = compare(traceText({{kRightWall + 0.003, 19.75}, {kLeftWall, 0.25}}, exactPath));
  EXPECT_EQ(c.matched, 2u);
  EXPECT_EQ(c.missedByThem + c.missedByUs, 0u);
  EXPECT_NEAR(c.maxTimeError, 0.003, 1e-12);
  EXPECT_NEAR(c.meanTimeError, 0.0015, 1e-12);
}

// The engine's ball drifts down at 0.45 L/s: the paths part at the first of our tick boundaries
// (every 0.05 s) past 0.1 L apart, 0.25 s, where the mpfr:256 run is with us.
TEST(EngineTrace, DriftPartsThePathsAndMpfrSidesWithUs) {
  const auto drifting = [](double t, double& x, double& y, double& vx) {
    exactAt(t, x, vx);
    y = kY + 0.45 * t;
  };
  const StepComparison c = compare(traceText({{kRightWall, 19.75}, {kLeftWall, 0.25}}, drifting));
  ASSERT_TRUE(c.parting);
  EXPECT_NEAR(c.parting->time, 0.25, 1e-12);
  EXPECT_EQ(c.parting->agreesWith, "ours");
  EXPECT_LT(c.parting->oursOff, 1e-12);
  EXPECT_NEAR(c.parting->theirsOff, 0.1125, 1e-9);
  ASSERT_EQ(c.parting->reference.size(), 1u);
  EXPECT_NEAR(c.parting->reference[0].y, kY, 1e-12);
}

// A trace that reports no contacts is compared by its paths alone.
TEST(EngineTrace, WithoutContactsOnlyThePathsAreCompared) {
  std::string text = traceText({}, exactPath);
  text.replace(text.find(R"("contacts":true)"), 15, R"("contacts":false)");
  for (std::size_t at; (at = text.find(R"(,"contacts":[])")) != std::string::npos;) text.erase(at, 14);
  std::istringstream in(text);
  const EngineTrace trace = readEngineTrace(in, "t.jsonl", board(), kEnd);
  const StepComparison c = crosscheckRuns(request(), {trace.run}).steps.at(0);
  EXPECT_FALSE(c.collisionsCompared);
  EXPECT_EQ(c.matched + c.missedByThem + c.missedByUs, 0u);
  EXPECT_LT(c.maxDivergence, 1e-12);
}

struct Damage {
  std::string text;
  std::string message;
};

class DamagedTrace : public testing::TestWithParam<Damage> {};

TEST_P(DamagedTrace, IsRefusedWithFileLineAndWhat) {
  std::istringstream in(GetParam().text);
  try {
    readEngineTrace(in, "t.jsonl", board(), 0.02);
    FAIL() << "accepted:\n" << GetParam().text;
  } catch (const EngineTraceError& e) {
    EXPECT_EQ(std::string(e.what()), GetParam().message);
  }
}

const std::string kHeader = R"({"format":"gizmo-trace","version":1,"engine":"e","contacts":true})"
                            "\n";
const std::string kStart = R"({"t":0,"balls":{"B":{"x":10,"y":10.5,"vx":20,"vy":0}}})"
                           "\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, DamagedTrace,
    testing::Values(
        Damage{"", "t.jsonl: error: the trace is empty: its first line is the header"},
        Damage{R"({"format":"other","version":1,"engine":"e","contacts":true})"
               "\n",
               R"(t.jsonl:1: error: the header's "format" is not "gizmo-trace")"},
        Damage{R"({"format":"gizmo-trace","version":2,"engine":"e","contacts":true})"
               "\n",
               R"(t.jsonl:1: error: the header's "version" is not 1, the version this reader knows)"},
        Damage{R"({"format":"gizmo-trace","version":1,"engine":"e"})"
               "\n",
               R"(t.jsonl:1: error: the header has no "contacts")"},
        Damage{kHeader + "[1, 2]\n", "t.jsonl:2: error: not a JSON object (each line is one JSON object)"},
        Damage{kHeader + "\n", "t.jsonl:2: error: an empty line (each line is one JSON object)"},
        Damage{kHeader + R"({"t":0.01,"balls":{"B":{"x":10,"y":10.5,"vx":20,"vy":0}}})"
                         "\n",
               R"(t.jsonl:2: error: the first step's "t" is 0.01, not 0)"},
        Damage{kHeader + kStart +
                   R"({"t":0,"balls":{"B":{"x":10,"y":10.5,"vx":20,"vy":0}}})"
                   "\n",
               R"(t.jsonl:3: error: "t" 0 is not after the step before, 0)"},
        Damage{kHeader + kStart +
                   R"({"t":0.01,"balls":{}})"
                   "\n",
               R"(t.jsonl:3: error: "balls" has no ball 'B' (every ball of the board, each step))"},
        Damage{kHeader + kStart +
                   R"({"t":0.01,"balls":{"B":{"x":10,"y":10.5,"vx":20,"vy":0},"C":{}}})"
                   "\n",
               R"(t.jsonl:3: error: "balls" names 'C', which is not a ball of the board)"},
        Damage{kHeader + kStart +
                   R"({"t":0.01,"balls":{"B":{"x":"ten","y":10.5,"vx":20,"vy":0}}})"
                   "\n",
               R"(t.jsonl:3: error: ball 'B': "x" is not a number)"},
        Damage{kHeader + kStart +
                   R"({"t":0.01,"balls":{"B":{"x":10,"y":10.5,"vx":20,"vy":0}},"spin":1})"
                   "\n",
               R"(t.jsonl:3: error: the step has an unknown key "spin")"},
        Damage{
            kHeader + kStart +
                R"({"t":0.01,"balls":{"B":{"x":10,"y":10.5,"vx":20,"vy":0}},"contacts":[{"t":0.005,"ball":"B","other":"Q","x":1,"y":1}]})"
                "\n",
            "t.jsonl:3: error: a contact names 'Q', which is not a gizmo, a ball or OuterWalls"},
        Damage{kHeader + kStart +
                   R"({"t":0.01,"balls":{"B":{"x":10.2,"y":10.5,"vx":20,"vy":0}}})"
                   "\n",
               "t.jsonl:3: error: the trace ends at 0.01 s, before the end of the comparison, 0.02 s (--time)"}));

// A trace that says it reports no contacts may not list any.
TEST(EngineTrace, ContactsWhereTheHeaderPromisedNone) {
  std::istringstream in(R"({"format":"gizmo-trace","version":1,"engine":"e","contacts":false})"
                        "\n" +
                        kStart +
                        R"({"t":0.05,"balls":{"B":{"x":11,"y":10.5,"vx":20,"vy":0}},"contacts":[]})"
                        "\n");
  EXPECT_THROW(
      {
        try {
          readEngineTrace(in, "t.jsonl", board(), 0.02);
        } catch (const EngineTraceError& e) {
          EXPECT_STREQ(e.what(), R"(t.jsonl:3: error: the step has an unknown key "contacts")");
          throw;
        }
      },
      EngineTraceError);
}

}  // namespace
}  // namespace gizmo::verify
