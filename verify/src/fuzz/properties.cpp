#include "gizmo/verify/fuzz/properties.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <vector>

#include "gizmo/core/gizmo_kinds.hpp"
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/io/diagnostics.hpp"
#include "gizmo/io/key_script.hpp"
#include "gizmo/io/text_reader.hpp"
#include "gizmo/io/xml_reader.hpp"
#include "gizmo/replay/replay.hpp"
#include "gizmo/verify/fuzz/checker_geometry.hpp"
#include "gizmo/verify/fuzz/invariants.hpp"
#include "gizmo/verify/fuzz/run_description.hpp"

namespace gizmo::verify::fuzz {
namespace {

// FNV-1a, for fingerprints: the same bytes on every machine.
struct Digest {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  void add(const void* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<const unsigned char*>(data)[i]) * 0x100000001b3ULL;
  }
  template <class T>
  void add(const T& value) {
    add(&value, sizeof value);
  }
  void add(const std::string& s) { add(s.data(), s.size()); }
};

// What a run under the invariant checker says of one of the invariants it checked.
PropertyResult invariantResult(const InvariantRun& r, Invariant which) {
  Digest d;
  d.add(r.events);
  d.add(r.energy);
  for (const Violation& v : r.violations)
    if (v.invariant == which) return PropertyResult{false, v.message, d.h, v.time};
  return PropertyResult{true, "", d.h};
}

InvariantRun invariantsIn(Precision scalar, const RunRequest& run, const std::vector<Invariant>& which) {
  return scalar == Precision::LongDouble ? checkInvariants<long double>(run, which)
                                         : checkInvariants<double>(run, which);
}

PropertyResult fromInvariant(const RunRequest& run, Precision scalar, Invariant which) {
  return invariantResult(invariantsIn(scalar, run, {which}), which);
}

PropertyResult noTunnelling(const RunRequest& run, Precision s) {
  return fromInvariant(run, s, Invariant::NoTunnelling);
}
PropertyResult energy(const RunRequest& run, Precision s) { return fromInvariant(run, s, Invariant::Energy); }
PropertyResult eventQueue(const RunRequest& run, Precision s) { return fromInvariant(run, s, Invariant::EventQueue); }

// A log file of its own in the system's temporary folder, removed when done with: the recorder
// writes files, and cases run on many threads (and in many processes) at once.
class TemporaryLog {
 public:
  TemporaryLog() {
    static std::atomic<std::uint64_t> counter{0};
    path_ = (std::filesystem::temp_directory_path() /
             ("gizmo-fuzz-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".gzlog"))
                .string();
  }
  ~TemporaryLog() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  TemporaryLog(const TemporaryLog&) = delete;
  TemporaryLog& operator=(const TemporaryLog&) = delete;
  const std::string& path() const { return path_; }
  std::string bytes() const {
    std::ifstream in(path_, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }

 private:
  std::string path_;
};

PropertyResult replayIdentity(const RunRequest& run, Precision scalar) {
  const PrecisionChoice precision{scalar == Precision::LongDouble ? Precision::LongDouble : Precision::Double, 0};
  TemporaryLog first, second;
  {
    replay::LogWriter sink(first.path());
    replay::recordRun(run, precision, sink);
  }
  {
    replay::LogWriter sink(second.path());
    replay::recordRun(run, precision, sink);
  }
  const std::string bytes = first.bytes();
  Digest d;
  d.add(bytes);
  if (bytes != second.bytes()) return PropertyResult{false, "recording the same run twice gave different logs", d.h};
  const replay::ReplayReport report = replay::replayLog(replay::openLog(first.path()));
  if (!report.identical) {
    std::ostringstream m;
    m << "the replay parts from the log after " << report.decisions << " decisions: " << report.where;
    return PropertyResult{false, m.str(), d.h};
  }
  return PropertyResult{true, "", d.h};
}

PropertyResult roundTrip(const RunRequest& run, Precision) {
  Digest d;
  auto differs = [&](const std::string& format, const std::string& written,
                     io::ReadResult (*read)(std::string_view, const std::string&)) -> std::optional<std::string> {
    d.add(written);
    try {
      const io::ReadResult back = read(written, "written." + format);
      if (const std::optional<std::string> diff = boardDifference(run.board, back.board))
        return "board -> " + format + " -> board changed it: " + *diff;
    } catch (const io::InputError& e) {
      return "the " + format + " the board writer wrote does not read back: " + e.what();
    }
    return std::nullopt;
  };
  if (auto m = differs("xml", io::writeXmlBoard(run.board), &io::readXmlBoard)) return {false, *m, d.h};
  if (auto m = differs("txt", io::writeTextBoard(run.board), &io::readTextBoard)) return {false, *m, d.h};
  // The key script travels with a failing case's board, so it must round-trip too.
  try {
    const std::vector<io::KeyInput> keys = io::readKeyScript(writeKeyScript(run.keys), "written.keys");
    bool same = keys.size() == run.keys.size();
    for (std::size_t i = 0; same && i < keys.size(); ++i)
      same = keys[i].time == run.keys[i].time && keys[i].key == run.keys[i].key &&
             keys[i].direction == run.keys[i].direction;
    if (!same) return {false, "key script -> text -> key script changed it", d.h};
  } catch (const io::InputError& e) {
    return {false, std::string("the key script written does not read back: ") + e.what(), d.h};
  }
  return {true, "", d.h};
}

// How far apart the two models' arithmetic may carry the same straight-line motion: their times
// of impact solve different equations (a linear and a degenerate quadratic), each to a few ulps.
constexpr double kModelTimeTolerance = 1e-9;   // s
constexpr double kModelValueTolerance = 1e-6;  // L and L/s, relative to the value's size (at least 1)

bool withinTolerance(double x, double y) {
  return std::fabs(x - y) <= kModelValueTolerance * std::max(1.0, std::fabs(y));
}

// Whether a hit closed no faster than the models' tolerances let their states differ, so that
// whether it happens at all is rounding's choice. Along an edge that is the velocity tolerance
// (a ball moving along an absorber's top, exactly tangent, is left moving into it at 2e-13 L/s
// by one model's rounding and at 0 by the other's: campaign seed 314159265, case 4834). On
// something round it is far more: a path that passes a round surface of radius R at a tangent
// and lies δ closer to it meets it closing at |v|·sqrt(2δ/(r + R)), so a position within the
// tolerance δ decides whether there is a hit, and how hard (a ball 1.2e-10 L low after a
// negligible hit long before strikes a ball it passes over, closing at 2e-5 of its speed, where
// the other model's passes it: seed 271828182, case 1802).
bool closesWithinTolerance(const Vec2<double>& p, const Vec2<double>& relativeVelocity, const Vec2<double>& n,
                           std::optional<double> roundRadius) {
  const double closing = -dot(relativeVelocity, n);
  const double speed = length(relativeVelocity);
  if (!roundRadius) return closing <= kModelValueTolerance * std::max(1.0, speed);
  const double delta = kModelValueTolerance * std::max({1.0, std::fabs(p.x), std::fabs(p.y)});
  return closing <= speed * std::sqrt(2 * delta / (Ball<double>::radius() + *roundRadius));
}

bool grazes(const GameBoard<double>& board, const Event<double>& e, const EventOutcome<double>& o) {
  if (e.kind != EventKind::Collision) return false;
  if (o.count == 2) {  // two balls
    const BallChange<double>& a = o.changes[0];
    const BallChange<double>& b = o.changes[1];
    const Vec2<double> d = a.position - b.position;
    const double len = length(d);
    if (!(len > 0)) return false;
    return closesWithinTolerance(a.position, a.velocityBefore - b.velocityBefore, Vec2<double>(d.x / len, d.y / len),
                                 Ball<double>::radius());
  }
  const GizmoId g = GizmoId(e.a);
  if (o.count != 1 || g < 0 || std::size_t(g) >= board.gizmoCount() || g == board.outerWallsId()) return false;
  if (board.gizmo(g).asBall()) return false;
  const GizmoSpec spec = board.gizmo(g).spec();
  const BallChange<double>& ball = o.changes[0];
  std::optional<GizmoTouch> touch;
  const KindMotion motion = gizmoKind(spec.type).motion;
  if (motion == KindMotion::Swings) {
    // A still flipper is a capsule like any other round-ended shape: a ball passing its tip at a
    // tangent, rounding's hair closer in one model, is struck in that model only (campaign seed
    // 667430151, case 4778: a ball lifted 1e-7 L/s off its line by rounding amplified in a row
    // of balls dips 7.5e-11 L into a flipper's tip in one run and 3.7e-11 L in the other, around
    // the graze's 5.8e-11 L; exactly, it is tangent). A swinging flipper's surface moves, and its
    // hits are not judged here, but for its pivot's cap, which turns in place: a still circle (seed
    // 2612061514, case 1695: a ball at 5000 L/s passing a swinging flipper's pivot at a tangent,
    // 1.2e-10 L closer in the ballistic run, glanced off it there and not in the classic run).
    const auto* flipper = dynamic_cast<const Flipper<double>*>(&board.gizmo(g));
    if (!flipper) return false;
    const SwingingAxis<double> axis = flipper->axisAt(e.time);
    const Vec2<double> tip = axis.pivot + axis.length * axis.direction(0.0);
    touch = touchOnCapsule(axis.pivot, tip, axis.radius, ball.position);
    const bool onPivotCap = nearestPointOnSegment(ball.position, axis.pivot, tip) == axis.pivot;
    if (flipper->swinging() && !onPivotCap) return false;
  } else if (motion == KindMotion::Turns) {
    // A still spinner is two crossed capsules, judged like a still flipper on the nearer one; a
    // turning one is not judged.
    const auto* spinner = dynamic_cast<const Spinner<double>*>(&board.gizmo(g));
    if (!spinner || spinner->turning()) return false;
    double nearest = 0;
    for (int k = 0; k < 2; ++k) {
      const SwingingAxis<double> arm = spinner->armAt(k, e.time);
      const Vec2<double> reach = arm.length * arm.direction(0.0);
      const Vec2<double> from = arm.pivot - reach, to = arm.pivot + reach;
      const double distance = length(Vec2<double>(ball.position - nearestPointOnSegment(ball.position, from, to)));
      if (k == 0 || distance < nearest) {
        nearest = distance;
        touch = touchOnCapsule(from, to, arm.radius, ball.position);
      }
    }
  } else {
    touch = touchOnGizmo(spec, ball.position);
  }
  if (!touch) return false;
  return closesWithinTolerance(ball.position, ball.velocityBefore, touch->normal,
                               touch->round ? std::optional<double>(touch->radius) : std::nullopt);
}

// The physical decisions of a run, for comparing the two models. Bookkeeping (recalculations,
// ends of ticks) is where the models legitimately differ.
class PhysicalTrace final : public BoardObserver<double> {
 public:
  explicit PhysicalTrace(const GameBoard<double>& board) : board_(board) {}
  std::vector<PhysicalDecision> decisions;
  void eventExecuted(const Event<double>& e, const EventOutcome<double>& o) override {
    if (e.kind == EventKind::Recalculate || e.kind == EventKind::EndOfTick || e.kind == EventKind::FrictionTick) return;
    // Without the sequence number: the models' bookkeeping events take different numbers.
    PhysicalDecision d{std::string(eventKindName(e.kind)) + " a=" + std::to_string(e.a) + " b=" + std::to_string(e.b),
                       e.feature,
                       e.time,
                       {}};
    bool changedNothing = e.kind == EventKind::Collision;
    for (const BallChange<double>& c : o.balls()) {
      d.values.insert(d.values.end(), {c.position.x, c.position.y, c.velocityAfter.x, c.velocityAfter.y});
      changedNothing = changedNothing && withinTolerance(c.velocityBefore.x, c.velocityAfter.x) &&
                       withinTolerance(c.velocityBefore.y, c.velocityAfter.y);
    }
    d.negligible = changedNothing;
    d.grazing = grazes(board_, e, o);
    decisions.push_back(std::move(d));
  }
  void triggerFired(const double& t, GizmoId s, GizmoId g) override {
    decisions.push_back(consequenceAt("trigger " + std::to_string(s) + " -> " + std::to_string(g), t));
  }
  void actionPerformed(const double& t, GizmoId g) override {
    decisions.push_back(consequenceAt("action " + std::to_string(g), t));
  }
  void modelRuleApplied(const double& t, ModelRule r, GizmoId g, GizmoId o) override {
    decisions.push_back(
        consequenceAt(std::string(modelRuleName(r)) + " " + std::to_string(g) + " " + std::to_string(o), t));
  }

 private:
  const GameBoard<double>& board_;
};

// Whether two decisions agree in their numbers: time, and the balls' positions and velocities.
bool closeEnough(const PhysicalDecision& x, const PhysicalDecision& y) {
  if (!(std::fabs(x.time - y.time) <= kModelTimeTolerance) || x.values.size() != y.values.size()) return false;
  for (std::size_t k = 0; k < x.values.size(); ++k)
    if (!withinTolerance(x.values[k], y.values[k])) return false;
  return true;
}

// The same decision: the same event or rule on the same gizmos, at the same time. A polygon's
// edge and the vertex at its end touched at one point are one contact with one normal: which
// feature index a model names for it is a tie broken by rounding, and only a different outcome
// makes it a different decision.
bool sameDecision(const PhysicalDecision& x, const PhysicalDecision& y) {
  return x.what == y.what && (x.feature == y.feature || closeEnough(x, y)) && x.values.size() == y.values.size() &&
         std::fabs(x.time - y.time) <= kModelTimeTolerance;
}

// The two models must take the same decision whenever their states agree. Rounding differences
// (a few ulps per event) are amplified by every collision between balls or with a round feature
// (a dispersing billiard: roughly by travel/radius each time), so after enough of them the runs
// part in their numbers, and from there they may legitimately decide differently. What must never
// happen is a different decision from states that still agree: that is a model disagreeing.
PropertyResult modelsAgree(const RunRequest& original, Precision) {
  RunRequest run = withoutForces(original);
  std::vector<PhysicalDecision> decisions[2];
  const MotionModel models[2] = {MotionModel::Classic, MotionModel::Ballistic};
  for (int i = 0; i < 2; ++i) {
    run.model = models[i];
    try {
      const std::unique_ptr<GameBoard<double>> board = prepareRun<double>(run);
      PhysicalTrace trace(*board);
      board->setObserver(&trace);
      continueRun(*board, run, 0);
      board->setObserver(nullptr);
      decisions[i] = std::move(trace.decisions);
    } catch (const std::exception& e) {
      return {false, std::string(motionModelName(models[i])) + " run stopped: " + e.what(), 0};
    }
  }
  return compareModelDecisions(std::move(decisions[0]), std::move(decisions[1]));
}

}  // namespace

PropertyResult compareModelDecisions(std::vector<PhysicalDecision> c, std::vector<PhysicalDecision> b) {
  Digest digest;
  auto show = [](const PhysicalDecision& d) {
    return d.what + " feature=" + std::to_string(d.feature) + " at t=" + exact(d.time);
  };
  // Decisions less than the time tolerance apart may come in either order: which of two events
  // 1e-14 s apart runs first is decided by the models' rounding. The one that matches is moved
  // up in its run.
  // When the order of two decisions was rounding's, so may be whether the second happens at all:
  // a ball that touches an absorber and a flipper at one instant is captured at once in one run,
  // and struck by the flipper first in the other (campaign seed 20261121, case 140; mpfr:256
  // parts the same way between the two models). A decision that one run lacks, within the time
  // tolerance of such a reordered pair, is that near-tie, and the runs part there.
  std::optional<double> reorderedAt;
  auto matchAhead = [&reorderedAt](std::vector<PhysicalDecision>& run, std::size_t from,
                                   const PhysicalDecision& wanted) {
    for (std::size_t k = from + 1; k < run.size() && run[k].time <= run[from].time + kModelTimeTolerance; ++k)
      if (sameDecision(run[k], wanted)) {
        std::rotate(run.begin() + std::ptrdiff_t(from), run.begin() + std::ptrdiff_t(k),
                    run.begin() + std::ptrdiff_t(k) + 1);
        reorderedAt = wanted.time;
        return true;
      }
    return false;
  };
  auto nearReordered = [&reorderedAt](const PhysicalDecision& d) {
    return reorderedAt && std::fabs(d.time - *reorderedAt) <= kModelTimeTolerance;
  };
  // Triggers, actions and rules are reported while the event that causes them runs, so that
  // event follows them in the trace, at their time.
  auto causedByRoundingHit = [](const std::vector<PhysicalDecision>& run, std::size_t k) {
    if (!run[k].consequence) return false;
    std::size_t m = k + 1;
    while (m < run.size() && run[m].time == run[k].time && run[m].consequence) ++m;
    return m < run.size() && run[m].time == run[k].time && (run[m].negligible || run[m].grazing);
  };
  std::size_t i = 0, j = 0;
  while (i < c.size() && j < b.size()) {
    const bool same = sameDecision(c[i], b[j]);
    // The same event at times further apart than the tolerance: the numbers have parted (at
    // 5000 L/s a position within the value tolerance is a time 2e-9 s off).
    if (!same && c[i].what == b[j].what && c[i].feature == b[j].feature) return {true, "", digest.h};
    if (!same && (nearReordered(c[i]) || nearReordered(b[j]))) return {true, "", digest.h};
    if (same || matchAhead(b, j, c[i]) || matchAhead(c, i, b[j])) {
      digest.add(c[i].what);
      if (!closeEnough(c[i], b[j])) return {true, "", digest.h};  // parted by amplified rounding: compared enough
      ++i;
      ++j;
      continue;
    }
    // A hit that changes no velocity beyond the tolerance (a ball at rest to within rounding
    // touching a surface: a velocity of 1e-13 L/s one way or the other) is not a decision the
    // models must share. But whether and which surface such a ball touches is rounding's
    // choice, and when the hit has consequences, so is everything they lead to: the runs part
    // there. Campaign seed 20261203, case 2382: a ball stopped dead in a corner touches a
    // flipper, firing its trigger, in one model and the square beside it in the other (at
    // mpfr:256 too). Seed 314159265, case 4834: a ball stopped dead by a head-on hit, tangent
    // to an absorber's top, is 8e-15 L into it in one model and left moving into it at 8e-11
    // L/s by the hit's rounding, so that model captures it (exactly, it touches and stays out).
    if (causedByRoundingHit(c, i) || causedByRoundingHit(b, j)) return {true, "", digest.h};
    if (c[i].negligible) {
      ++i;
      continue;
    }
    if (b[j].negligible) {
      ++j;
      continue;
    }
    // A hit that closed no faster than the tolerances let the states differ, in one run only:
    // whether it happens was rounding's choice, and the runs part there.
    if (c[i].grazing || b[j].grazing) return {true, "", digest.h};
    // Two different decisions less than the time tolerance apart, where taking one precludes the
    // other (a ball captured by an absorber at the instant it touches the bumper beside it): a
    // near-tie that the models' rounding breaks. The runs part there legitimately.
    if (std::fabs(c[i].time - b[j].time) <= kModelTimeTolerance) return {true, "", digest.h};
    return {false,
            "decision " + std::to_string(i) + " differs while the states agree: classic " + show(c[i]) +
                ", ballistic " + show(b[j]),
            digest.h};
  }
  while (i < c.size() && c[i].negligible) ++i;
  while (j < b.size() && b[j].negligible) ++j;
  if ((i < c.size() && nearReordered(c[i])) || (j < b.size() && nearReordered(b[j]))) return {true, "", digest.h};
  auto partsHere = [&](const std::vector<PhysicalDecision>& run, std::size_t k) {
    return k < run.size() && (run[k].grazing || causedByRoundingHit(run, k));
  };
  if (partsHere(c, i) || partsHere(b, j)) return {true, "", digest.h};
  if (i < c.size() || j < b.size())
    return {false,
            "classic made " + std::to_string(c.size()) + " physical decisions, ballistic " + std::to_string(b.size()) +
                (i < c.size() ? "; classic's next: " + show(c[i]) : "; ballistic's next: " + show(b[j])),
            digest.h};
  return {true, "", digest.h};
}

std::span<const Property> allProperties() {
  // Built on first use: a std::function is not constant, and no static initialiser may meet it unbuilt.
  static const Property all[] = {
      {"no-tunnelling", "no ball inside a gizmo or beyond a wall, at every event and between events", &noTunnelling,
       Invariant::NoTunnelling},
      {"energy",
       "energy rises only by what moving surfaces and the gizmos' rules supply (a shot, a spawn, a boost, a "
       "teleport); friction ticks slow balls",
       &energy, Invariant::Energy},
      {"event-queue", "time never goes back; the queue holds exactly the pending events; every moving ball is covered",
       &eventQueue, Invariant::EventQueue},
      {"replay-identity", "recording twice gives the same log, and replaying it gives the same decisions",
       &replayIdentity},
      {"round-trip", "board -> XML -> board and board -> text -> board give the same board; key scripts too",
       &roundTrip},
      {"models-agree", "with gravity and friction 0, classic and ballistic make the same decisions", &modelsAgree},
  };
  return all;
}

std::vector<PropertyResult> checkProperties(std::span<const Property* const> properties, const RunRequest& run,
                                            Precision scalar) {
  auto threw = [](const std::exception& e) { return PropertyResult{false, std::string("threw: ") + e.what(), 0}; };
  std::vector<Invariant> invariants;
  for (const Property* p : properties)
    if (p->invariant) invariants.push_back(*p->invariant);
  std::optional<InvariantRun> watched;
  std::optional<PropertyResult> watchThrew;
  if (invariants.size() > 1) {
    try {
      watched = invariantsIn(scalar, run, invariants);
    } catch (const std::exception& e) {
      watchThrew = threw(e);
    }
  }
  std::vector<PropertyResult> results;
  for (const Property* p : properties) {
    if (p->invariant && watchThrew) {
      results.push_back(*watchThrew);
    } else if (p->invariant && watched) {
      results.push_back(invariantResult(*watched, *p->invariant));
    } else {
      try {
        results.push_back(p->check(run, scalar));
      } catch (const std::exception& e) {
        results.push_back(threw(e));
      }
    }
  }
  return results;
}

const Property* findProperty(std::string_view name) {
  for (const Property& p : allProperties())
    if (p.name == name) return &p;
  return nullptr;
}

std::string propertyNames() {
  std::string s;
  for (const Property& p : allProperties()) s += (s.empty() ? "" : ", ") + std::string(p.name);
  return s;
}

RunRequest withoutForces(const RunRequest& run) {
  RunRequest r = run;
  r.board.gravity = 0;
  r.board.mu = r.board.mu2 = 0;
  return r;
}

}  // namespace gizmo::verify::fuzz
