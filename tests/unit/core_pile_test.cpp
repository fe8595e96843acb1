// Piles (docs/physics.md, "Piles"): a bounce too small to rise settleRise is none, friction stops
// a slow ball on a level surface, a ball at rest holds up what falls onto it, and a ball that
// leaves rest wakes what rests on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/board_builder.hpp"

namespace gizmo {
namespace {

using test::ballAt;
using test::build;
using test::emptyBoard;
using test::gizmoAt;
using test::Recorder;

// A board run for `seconds` (ballistic, ticks of 0.05 s unless p says otherwise), its events kept.
struct Watched {
  std::unique_ptr<GameBoard<double>> board;
  Recorder<double> rec;
};
std::unique_ptr<Watched> watch(const BoardSpec& s, const PhysicsParams<double>& p, double seconds) {
  auto w = std::make_unique<Watched>();
  w->board = buildBoard<double>(s, p);
  w->board->setObserver(&w->rec);
  w->board->tick(seconds);
  return w;
}

// A ball dropped onto the floor from `height` (its lowest point above the floor), no friction:
// the first hit is at √(2·25·height) L/s.
std::unique_ptr<Watched> dropOntoTheFloor(double height) {
  BoardSpec s = emptyBoard(25, 0, 0);
  s.balls.push_back(ballAt("B", 10, 19.75 - height));
  return watch(s, PhysicsParams<double>{}, 0.5);
}

TEST(Piles, ABounceThatWouldRiseLessThanSettleRiseIsNone) {
  // At 0.4 L/s a bounce would rise 0.4²/50 = 0.0032 L < settleRise = 0.005 L: the ball lies on
  // the floor from its first hit on.
  auto low = dropOntoTheFloor(0.0032);
  const Ball<double>& b = low->board->ballById(*low->board->find("B"));
  ASSERT_TRUE(b.contact().has_value());
  EXPECT_EQ(low->rec.countRule(ModelRule::ContactBegin), 1);
  EXPECT_EQ(b.velocityAt(low->board->now()), Vec2<double>(0, 0));
  EXPECT_EQ(b.positionAt(low->board->now()).y, 19.75);
  // At 0.6 L/s it would rise 0.0072 L: an elastic bounce, which keeps bouncing without friction.
  auto high = dropOntoTheFloor(0.0072);
  EXPECT_EQ(high->rec.countRule(ModelRule::ContactBegin), 0);
  EXPECT_GE(high->rec.ofKind(EventKind::Collision).size(), 10u);
}

// In the classic model a ball on a floor hops each tick by what the tick's gravity gives it,
// g·dt = 1.25 L/s at the default tick, a bounce that rises 0.031 L: it lies on the floor only
// with ticks below √(2·settleRise/g) = 0.02 s.
TEST(Piles, FrictionStopsASlowBallOnALevelFloor) {
  for (const MotionModel model : {MotionModel::Ballistic, MotionModel::Classic}) {
    BoardSpec s = emptyBoard(25, 0.5, 0.5);
    s.balls.push_back(ballAt("B", 5, 19.75, 0.3, 0));
    const double tick = model == MotionModel::Classic ? 0.01 : 0.05;
    auto board = build(s, model, tick);
    Recorder<double> rec;
    board->setObserver(&rec);
    board->tick(15.0);
    const Ball<double>& b = board->ballById(*board->find("B"));
    EXPECT_EQ(b.velocityAt(board->now()), Vec2<double>(0, 0)) << motionModelName(model);
    EXPECT_TRUE(b.resting()) << motionModelName(model);
    EXPECT_EQ(rec.countRule(ModelRule::Settled), 1) << motionModelName(model);
    // At rest it costs nothing but the board's ticks.
    const std::uint64_t before = board->executedTotal();
    board->tick(10.0);
    EXPECT_EQ(board->executedTotal() - before, std::uint64_t(std::llround(10.0 / tick))) << motionModelName(model);
  }
}

TEST(Piles, ABallOnASlopeNeverSettles) {
  // Gravity along the slope keeps it going: only a level surface stops a slow ball.
  BoardSpec s = emptyBoard(25, 0.5, 0.5);
  s.gizmos.push_back(gizmoAt(GizmoType::Triangle, "T", 10, 10, 90, 1, 1));
  s.balls.push_back(ballAt("B", 10.6, 9.6));
  auto board = build(s, MotionModel::Ballistic);
  Recorder<double> rec;
  board->setObserver(&rec);
  board->tick(3.0);
  EXPECT_EQ(rec.countRule(ModelRule::Settled), 0);
}

// Nine balls dropped into a box three L wide whose floor two triangles narrow to one L, with the
// friction of a real multiball board. (A box whose floor a row of balls fills exactly is the open
// case of docs/physics.md, "Piles".)
template <class Real>
std::unique_ptr<GameBoard<Real>> ballsInABox(double seconds) {
  BoardSpec s = emptyBoard(25, 0.025, 0.025);
  for (int y = 10; y < 20; ++y) {
    s.gizmos.push_back(gizmoAt(GizmoType::Square, "L" + std::to_string(y), 4, y));
    s.gizmos.push_back(gizmoAt(GizmoType::Square, "R" + std::to_string(y), 8, y));
  }
  s.gizmos.push_back(gizmoAt(GizmoType::Triangle, "TL", 5, 19, 0));
  s.gizmos.push_back(gizmoAt(GizmoType::Triangle, "TR", 7, 19, 90));
  for (int i = 0; i < 9; ++i)
    s.balls.push_back(
        ballAt("B" + std::to_string(i), 5.3 + 0.55 * (i % 4), 14.4 + 0.6 * (i / 4), 0.7 - 0.3 * (i % 4), 0));
  auto board = build<Real>(s, MotionModel::Ballistic);
  board->tick(Real(seconds));
  return board;
}

template <class Real>
void expectAPileAtRest(GameBoard<Real>& board) {
  const std::vector<GizmoId>& ids = board.ballIds();
  std::vector<Vec2<double>> p;
  for (GizmoId id : ids) {
    const Ball<Real>& b = board.ballById(id);
    EXPECT_TRUE(b.resting()) << b.name();
    const Vec2<Real> q = b.positionAt(board.now());
    p.emplace_back(toDouble(q.x), toDouble(q.y));
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    int below = 0;
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (i == j) continue;
      const double d = std::hypot(p[i].x - p[j].x, p[i].y - p[j].y);
      EXPECT_GE(d, 0.5 - 1e-9) << "balls " << i << " and " << j << " overlap";
      if (d < 0.5 + 1e-5 && p[j].y > p[i].y) ++below;
    }
    // Nothing hangs in the air: a ball lies low in the box (on its floor or a triangle's slope),
    // or something at rest lies under it.
    EXPECT_TRUE(p[i].y > 18.5 || below > 0)
        << "ball " << i << " at (" << p[i].x << ", " << p[i].y << ") rests on nothing";
    EXPECT_GE(p[i].x, 5.25 - 1e-9);
    EXPECT_LE(p[i].x, 7.75 + 1e-9);
  }
}

TEST(Piles, BallsDroppedIntoABoxComeToRestAndStayAtRest) {
  auto board = ballsInABox<double>(60.0);
  expectAPileAtRest(*board);
  const std::uint64_t before = board->executedTotal();
  board->tick(30.0);
  EXPECT_EQ(board->executedTotal() - before, 600u);  // the board's ticks, nothing else
}

// Two balls at rest on the floor 0.998 L apart (their V has sides 3.6° from level, the shape of a
// floor row with one ball squeezed out of it), and a ball that falls 0.001 L onto one of them,
// 0.001 L from the V's middle: it strikes A 0.002 L from C.
std::unique_ptr<Watched> ballFallingIntoAFlatV(double settleRise) {
  BoardSpec s = emptyBoard(25, 0.025, 0.025);
  s.balls.push_back(ballAt("A", 10.0, 19.75));
  s.balls.push_back(ballAt("C", 10.998, 19.75));
  s.balls.push_back(ballAt("B", 10.498, 19.75 - std::sqrt(0.25 - 0.498 * 0.498) - 0.001));
  PhysicsParams<double> p;
  p.settleRise = settleRise;
  return watch(s, p, 5.0);
}

TEST(Piles, ABallInTheFlatVOfTwoBallsAtRestComesToRest) {
  // Within settleRise of the second ball while it strikes the first, it rests in the V.
  auto v = ballFallingIntoAFlatV(0.005);
  const Ball<double>& b = v->board->ballById(*v->board->find("B"));
  ASSERT_TRUE(b.wedged());
  const Vec2<double> p = b.positionAt(v->board->now());
  EXPECT_EQ(p.x, 10.498);
  EXPECT_NEAR(p.y, 19.75 - std::sqrt(0.25 - 0.498 * 0.498), 1e-12);  // where it struck A
  const std::size_t hits = v->rec.ofKind(EventKind::Collision).size();
  EXPECT_EQ(hits, 3u);  // A and C come to lie on the floor, B to rest on A
  // With settleRise only a minimum bounce's rise (restSpeed²/2|g|, 2·10⁻⁶ L: the reach a V of a
  // gizmo keeps; the settling threshold narrows with it), it strikes side after side far longer.
  auto narrow = ballFallingIntoAFlatV(0.01 * 0.01 / 50);
  EXPECT_GT(narrow->rec.ofKind(EventKind::Collision).size(), 10 * hits);
}

// Squares 2 L apart from y = 12 down, nine balls dropped into them: four fill the floor exactly
// (one is squeezed up out of the row), four stand on them, and both rows would pass momentum
// between the walls across room of 10⁻⁶ L (before the rule for rows: 20 s took over 25 s of wall
// time in the ballistic model).
TEST(Piles, RowsThatFillABoxComeToRest) {
  for (const MotionModel model : {MotionModel::Ballistic, MotionModel::Classic}) {
    BoardSpec s = emptyBoard(25, 0.5, 0.5);
    for (int y = 12; y < 20; ++y) {
      s.gizmos.push_back(gizmoAt(GizmoType::Square, "L" + std::to_string(y), 4, y));
      s.gizmos.push_back(gizmoAt(GizmoType::Square, "R" + std::to_string(y), 7, y));
    }
    for (int i = 0; i < 9; ++i)
      s.balls.push_back(
          ballAt("B" + std::to_string(i), 5.35 + 0.65 * (i % 3), 14.4 + 0.6 * (i / 3), 0.5 - 0.3 * (i % 3), 0));
    PhysicsParams<double> p;
    p.model = model;
    const auto w = watch(s, p, 20.0);
    for (GizmoId id : w->board->ballIds()) EXPECT_TRUE(w->board->ballById(id).resting()) << motionModelName(model);
    EXPECT_LT(w->board->executedTotal(), 40000u) << motionModelName(model);
  }
}

// A row of three balls on the floor against a square, struck by a ball rolling in from open floor
// at 0.3 L/s: the row has no room ahead, but the ball that strikes it has room behind, so the hit
// passes along the row to the square and back, and the striker rolls away as fast as it came.
TEST(Piles, ARowWithRoomBehindTheStrikerPassesTheHitOn) {
  BoardSpec s = emptyBoard(25, 0, 0);
  s.gizmos.push_back(gizmoAt(GizmoType::Square, "Q", 4, 19));  // its face at x = 5
  s.balls.push_back(ballAt("B1", 5.25, 19.75));
  s.balls.push_back(ballAt("B2", 5.75, 19.75));
  s.balls.push_back(ballAt("B3", 6.25, 19.75));
  s.balls.push_back(ballAt("S", 8.0, 19.75, -0.3, 0));
  const auto w = watch(s, PhysicsParams<double>{}, 12.0);
  const Ball<double>& striker = w->board->ballById(*w->board->find("S"));
  EXPECT_NEAR(striker.velocityAt(w->board->now()).x, 0.3, 1e-9);
  EXPECT_EQ(w->rec.countRule(ModelRule::Wedged), 0);
}

// A ball B wedged between a still flipper's side and a triangle's slope, and a ball C that slid
// down the slope onto it and rests in the V of B and the slope: held up by B alone.
TEST(Piles, ABallThatLeavesRestWakesWhatRestsOnIt) {
  BoardSpec s = emptyBoard(25, 0.5, 0.5);
  s.gizmos.push_back(gizmoAt(GizmoType::Triangle, "T", 6, 12, 180));  // slope from (7, 12) down to (6, 13)
  s.gizmos.push_back(gizmoAt(GizmoType::RightFlipper, "F", 4, 11));   // its side at x = 6 while still
  s.balls.push_back(ballAt("B", 6.3, 12.2));
  s.balls.push_back(ballAt("C", 6.7, 11.9));
  s.keyConnections.push_back(KeyConnectSpec{32, KeyDirection::Down, "F", {}});
  auto board = build(s, MotionModel::Ballistic);
  board->tick(19.0);
  const Ball<double>& b = board->ballById(*board->find("B"));
  const Ball<double>& c = board->ballById(*board->find("C"));
  ASSERT_TRUE(b.wedged());
  ASSERT_TRUE(c.wedged());
  const Vec2<double> restB = b.positionAt(board->now()), restC = c.positionAt(board->now());
  EXPECT_NEAR(std::hypot(restC.x - restB.x, restC.y - restB.y), 0.5, 1e-6);
  EXPECT_LT(restC.y, restB.y);
  // The flipper swings away: B falls, and C, which B held up, does not hang in the air.
  board->scheduleInput(20.0, 32, KeyDirection::Down);
  board->tick(1.05);
  EXPECT_FALSE(b.wedged());
  EXPECT_FALSE(c.wedged());
  board->tick(1.0);
  EXPECT_GT(c.positionAt(board->now()).y, restC.y + 0.5);
}

// Rule 4 waits until the instant is over, and a ball back at rest where it rested by then never
// moved. Ball M lies on the floor, C balanced on top of it, and X slides in along the floor into M
// while the jam rule holds (forced here; in campaign seed 2612061238, case 1209, a pile of 51
// balls made it). The jammed hit sends M and X on together at half X's speed. With a square's
// side against M, M's hit on it leaves no rebound and X strikes M again at that instant, which
// rests the pair: M never moved, and C stays at rest. In that case a ball woken so fell back onto
// a spinner 0.78 ns later, whose start struck the first ball out of rest and into it again, for
// ever. Without the square M is still moving when the instant's events are over, and C wakes.
TEST(Piles, ABallStruckOutOfRestAndBackIntoItAtOneInstantWakesNothing) {
  for (const bool squareBesideM : {true, false}) {
    SCOPED_TRACE(squareBesideM ? "a square beside M" : "nothing beside M");
    BoardSpec s = emptyBoard(25, 0, 0);
    if (squareBesideM) s.gizmos.push_back(gizmoAt(GizmoType::Square, "Q", 9, 19));  // its side at x = 10
    s.balls.push_back(ballAt("M", 10.25, 19.75));
    s.balls.push_back(ballAt("C", 10.25, 19.25));
    s.balls.push_back(ballAt("X", 15.0, 19.75, -1, 0));  // touches M at t = 4.25 s
    auto board = build(s, MotionModel::Ballistic);
    board->tick(4.25 - 5e-7);
    const Ball<double>& m = board->ballById(*board->find("M"));
    const Ball<double>& c = board->ballById(*board->find("C"));
    ASSERT_TRUE(m.resting());
    ASSERT_TRUE(c.wedged());
    const Vec2<double> restM = m.positionAt(board->now()), restC = c.positionAt(board->now());
    BoardState<double> jammed = board->saveState();
    jammed.jamWindowStart = jammed.now;
    jammed.collisionsInWindow = 1000;
    board->restoreState(jammed);
    Recorder<double> rec;
    board->setObserver(&rec);
    board->tick(0.5);
    ASSERT_GE(rec.countRule(ModelRule::Jammed), 1);
    const GizmoId cId = *board->find("C");
    const auto wokeC = std::count_if(rec.rules.begin(), rec.rules.end(), [&](const auto& r) {
      return r.first == ModelRule::ContactEnd && r.second == cId;
    });
    if (squareBesideM) {
      EXPECT_EQ(wokeC, 0);
      EXPECT_TRUE(m.resting());
      EXPECT_EQ(m.positionAt(board->now()), restM);
      EXPECT_TRUE(c.wedged());
      EXPECT_EQ(c.positionAt(board->now()), restC);
    } else {
      EXPECT_EQ(wokeC, 1);  // M still moving when the instant's events were over (the jam then rests all three)
    }
  }
}

}  // namespace
}  // namespace gizmo
