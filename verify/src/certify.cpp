// certifyRun / certifyLog: the double run re-simulated with an observer that, after each executed
// event, copies the state in force until the next one; each executed event is then settled by
// the ladder against the state copied before it. This file runs the core's double code and
// never computes with intervals (so it is built without -frounding-math and never rounds upward).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gizmo/core/gizmos/absorber.hpp"
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/polygonal_gizmo.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/verify/certify.hpp"
#include "gizmo/verify/certify_ladder.hpp"

namespace gizmo::verify {

using namespace detail;

std::string uncertifiedReasonName(UncertifiedReason r) {
  switch (r) {
    case UncertifiedReason::SwingingFlipper: return "swinging flipper";
    case UncertifiedReason::TurningSpinner: return "turning spinner";
    case UncertifiedReason::Undecided: return "undecided";
  }
  return "?";
}

ExactBound exactBound(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", v);
  return ExactBound{v, buf};
}

std::uint64_t CertifyReport::certified() const {
  std::uint64_t n = 0;
  for (std::uint64_t c : certifiedAtRung) n += c;
  return n;
}

std::uint64_t CertifyReport::provenTies() const {
  std::uint64_t n = 0;
  for (const TieDecision& t : ties) n += t.proven ? 1 : 0;
  return n;
}

namespace {

BoardLayout layoutOf(GameBoard<double>& board) {
  BoardLayout layout;
  layout.model = board.params().model;
  layout.ballRadius = kBallRadius;
  const std::size_t n = board.gizmoCount();
  layout.ballIndex.assign(n, -1);
  layout.cells.assign(std::size_t(BoardLayout::kCells * BoardLayout::kCells), {});
  for (std::size_t id = 0; id < n; ++id) {
    const AbstractGizmo<double>& g = board.gizmo(GizmoId(id));
    LayoutGizmo L;
    L.id = GizmoId(id);
    L.name = g.name();
    L.bounds = g.bounds();
    if (g.asBall()) {
      L.kind = LayoutKind::Ball;
      layout.ballIndex[id] = std::int32_t(layout.balls.size());
      layout.balls.push_back(GizmoId(id));
    } else if (const auto* flipper = dynamic_cast<const Flipper<double>*>(&g)) {
      L.kind = LayoutKind::Flipper;
      const GizmoSpec s = g.spec();
      const FlipperLayout f = flipperLayout(s.type, s.orientation);
      L.pivot = flipper->axisAt(0.0).pivot;
      L.restQuarter = f.restQuarter;
      L.endQuarter = f.endQuarter;
      L.forwardSign = f.forwardSign;
    } else if (dynamic_cast<const Spinner<double>*>(&g)) {
      L.kind = LayoutKind::Spinner;
      const GizmoSpec s = g.spec();
      L.pivot = Vec2<double>(double(s.x + 1), double(s.y + 1));
    } else if (const auto* shaped = dynamic_cast<const AbstractGizmoWithPolygonalGeometry<double>*>(&g)) {
      L.shape = shaped->shape();
      L.kind = LayoutKind::FixedShape;
      if (dynamic_cast<const Absorber<double>*>(&g)) {
        L.kind = LayoutKind::Absorber;
        const GizmoSpec s = g.spec();
        L.rect = {double(s.x), double(s.y), double(s.width), double(s.height)};
      }
    } else {
      // A gizmo of a class of its own that neither swings nor turns keeps its outline at rest,
      // which its kind's file gives (KindCore::addRestShape): empty for the spawner, which nothing
      // meets, and a new still kind's outline however its class holds it.
      L.shape = restShape<double>(g.spec());
    }
    if (id != 0 && L.kind != LayoutKind::Ball) {  // the walls are checked against every ball
      auto cell = [](double v) { return std::clamp(int(std::floor(v)), 0, BoardLayout::kCells - 1); };
      for (int y = cell(L.bounds.lo.y); y <= cell(L.bounds.hi.y); ++y)
        for (int x = cell(L.bounds.lo.x); x <= cell(L.bounds.hi.x); ++x)
          layout.cells[std::size_t(y * BoardLayout::kCells + x)].push_back(GizmoId(id));
    }
    layout.gizmos.push_back(std::move(L));
  }
  // Each pair's collider as the board fixes it: asked in id order (GameBoard::rebuild).
  for (GizmoId ball : layout.balls) {
    std::vector<GizmoId> row(n, kNoGizmo);
    for (std::size_t g = 0; g < n; ++g) {
      if (GizmoId(g) == ball) continue;
      const GizmoId lo = std::min(GizmoId(g), ball), hi = std::max(GizmoId(g), ball);
      const PairRole r = formPair(board.gizmo(lo), board.gizmo(hi));
      if (r != PairRole::None) row[g] = r == PairRole::FirstCollides ? lo : hi;
    }
    layout.collider.push_back(std::move(row));
  }
  return layout;
}

class CertifyingObserver final : public BoardObserver<double> {
 public:
  CertifyingObserver(GameBoard<double>& board, const CertifyOptions& options, CertifyReport& report)
      : board_(board), options_(options), report_(report), layout_(layoutOf(board)), ladder_(layout_, options) {
    report_.model = std::string(motionModelName(layout_.model));
    report_.rungBits.push_back(53);
    for (long b : options.mpfiBits) report_.rungBits.push_back(b);
    report_.rungBits.push_back(0);  // the exact step
    report_.certifiedAtRung.assign(report_.rungBits.size(), 0);
  }

  void eventScheduled(const Event<double>& e) override {
    if (!snapshotTaken_) takeSnapshot();  // the state at the start, before any event
    live_.push_back(e);
  }
  void eventRemoved(const Event<double>& e) override { forget(e); }
  // The events already queued where the run starts (a branch log's keyframe).
  void adoptQueue(const std::vector<Event<double>>& queued) { live_.insert(live_.end(), queued.begin(), queued.end()); }

  void eventExecuted(const Event<double>& e, const EventOutcome<double>&) override {
    forget(e);
    if (options_.maxEvents != 0 && report_.decisions >= options_.maxEvents) return;
    if (!snapshotTaken_) takeSnapshot();
    DecisionInput in;
    in.eventIndex = report_.decisions;
    in.executed = e;
    for (const Event<double>& pending : live_) {
      if (isRootKind(pending.kind)) continue;
      if (!in.hasNextScheduled || runsBefore(pending, in.nextScheduled)) in.nextScheduled = pending;
      in.hasNextScheduled = true;
    }
    record(ladder_.settle(snapshot_, in), in);
    ++report_.decisions;
    takeSnapshot();  // what is in force until the next event
  }

 private:
  void takeSnapshot() {
    snapshotTaken_ = true;
    // A spawner added a ball: it joins the layout (ids never move, so the rest is as it was).
    if (board_.gizmoCount() != layout_.gizmos.size()) {
      layout_ = layoutOf(board_);
      ladder_.layoutChanged();
    }
    BoardSnapshot& s = snapshot_;
    s.now = board_.now();
    s.balls.resize(layout_.balls.size());
    for (std::size_t i = 0; i < layout_.balls.size(); ++i) {
      const Ball<double>& b = *board_.gizmo(layout_.balls[i]).asBall();
      BallSnapshot& out = s.balls[i];
      out.id = b.id();
      out.captured = b.captured();
      out.t0 = b.anchorTime();
      const Trajectory<double> t = b.trajectoryAt(b.anchorTime());  // τ = 0: the anchor, exactly
      out.p = t.p;
      out.v = t.v;
      out.a = t.a;
      out.contactGizmo = kNoGizmo;
      out.skippedFeatures.clear();
      if (const auto& c = b.contact()) {
        out.contactGizmo = c->gizmo;
        out.contactA = c->segment.a;
        out.contactB = c->segment.b;
        // What shapeTimeOfImpact leaves out for this ball: the segment and the circles capping it.
        const Shape<double>* shape = shapeOf(c->gizmo);
        out.skippedFeatures.push_back(c->feature);
        if (shape && std::size_t(c->feature) < shape->segments.size()) {
          const SegmentFeature<double>& seg = shape->segments[std::size_t(c->feature)];
          for (std::size_t k = 0; k < shape->circles.size(); ++k)
            if (capsEndOf(shape->circles[k], seg))
              out.skippedFeatures.push_back(std::int32_t(shape->segments.size() + k));
        }
      }
    }
    // Overwritten in place: the copies reuse the vectors' storage, so a snapshot allocates
    // nothing once the run is under way.
    std::size_t flippers = 0, spinners = 0, absorbers = 0;
    for (const LayoutGizmo& g : layout_.gizmos) {
      if (g.kind == LayoutKind::Flipper) {
        const auto& f = static_cast<const Flipper<double>&>(board_.gizmo(g.id));
        if (s.flippers.size() <= flippers) s.flippers.emplace_back();
        FlipperSnapshot& fs = s.flippers[flippers++];
        fs.id = g.id;
        fs.swinging = f.swinging();
        if (!fs.swinging) fs.still = f.stillShape();
        else swingOf(f, g, fs);
      } else if (g.kind == LayoutKind::Spinner) {
        const auto& spinner = static_cast<const Spinner<double>&>(board_.gizmo(g.id));
        if (s.spinners.size() <= spinners) s.spinners.emplace_back();
        SpinnerSnapshot& ss = s.spinners[spinners++];
        ss.id = g.id;
        ss.turning = spinner.turning();
        if (!ss.turning) ss.still = spinner.stillShape();
        else turnOf(spinner, ss);
      } else if (g.kind == LayoutKind::Absorber) {
        const auto& a = static_cast<const Absorber<double>&>(board_.gizmo(g.id));
        if (s.absorbers.size() <= absorbers) s.absorbers.emplace_back();
        AbsorberSnapshot& as = s.absorbers[absorbers++];
        as.id = g.id;
        as.firedInside = a.firedStillInside();
      }
    }
  }

  // The swing's anchor, exactly as the flipper holds it (its saved state starts with t0, s0). A
  // swing that starts back from the end position starts from that exact quarter turn: the core
  // snapped the flipper to it when the forward swing stopped.
  void swingOf(const Flipper<double>& f, const LayoutGizmo& g, FlipperSnapshot& out) {
    savedState_.reals.clear();
    savedState_.ints.clear();
    f.saveState(savedState_);
    const double t0 = savedState_.reals.at(0), s0 = savedState_.reals.at(1);
    const bool fromEnd = s0 == Flipper<double>::swingTime();
    out.quarter = fromEnd ? g.endQuarter : g.restQuarter;
    out.offset = fromEnd ? 0.0 : s0;
    out.t0 = t0;
    out.turn = g.forwardSign * f.direction();
  }

  // The turn's anchor, exactly as the spinner holds it (its saved state: t0, phase; quarter).
  void turnOf(const Spinner<double>& spinner, SpinnerSnapshot& out) {
    savedState_.reals.clear();
    savedState_.ints.clear();
    spinner.saveState(savedState_);
    out.t0 = savedState_.reals.at(0);
    out.phase = savedState_.reals.at(1);
    out.quarter = int(savedState_.ints.at(0));
  }

  void forget(const Event<double>& e) {
    for (std::size_t i = 0; i < live_.size(); ++i)
      if (live_[i].sequence == e.sequence) {
        live_[i] = live_.back();
        live_.pop_back();
        return;
      }
  }

  const Shape<double>* shapeOf(GizmoId id) const {
    const AbstractGizmo<double>& g = board_.gizmo(id);
    if (const auto* f = dynamic_cast<const Flipper<double>*>(&g)) return &f->stillShape();
    if (const auto* s = dynamic_cast<const Spinner<double>*>(&g)) return &s->stillShape();
    if (const auto* p = dynamic_cast<const AbstractGizmoWithPolygonalGeometry<double>*>(&g)) return &p->shape();
    return nullptr;
  }

  std::string nameOf(GizmoId id) const {
    return id >= 0 && std::size_t(id) < layout_.gizmos.size() ? layout_.gizmos[std::size_t(id)].name : "-";
  }

  EventRef refOf(const EventKey& k) const {
    EventRef r{k.kind, k.a, k.b, k.feature, std::string(eventKindName(k.kind))};
    switch (k.kind) {
      case EventKind::Collision:
        r.description += " " + nameOf(k.a) + "/" + nameOf(k.b) + " feature " + std::to_string(k.feature);
        break;
      case EventKind::Leave: r.description += " " + nameOf(k.b) + " leaves " + nameOf(k.a); break;
      case EventKind::Input:
        r.description += " key " + std::to_string(k.feature) + (k.b == int(KeyDirection::Down) ? " down" : " up");
        break;
      case EventKind::EndOfTick: break;
      default: r.description += " " + nameOf(k.a); break;
    }
    return r;
  }

  void record(const LadderResult& result, const DecisionInput& in) {
    const RungOutcome& o = result.outcome;
    // Most decisions are certified and only counted: their names and printed times are not made.
    if (o.verdict == Verdict::Certified) {
      ++report_.certifiedAtRung[std::size_t(result.rung)];
      return;
    }
    const EventRef executed = refOf(keyOf(in.executed));
    const ExactBound time = exactBound(in.executed.time);
    switch (o.verdict) {
      case Verdict::Certified: return;
      case Verdict::Wrong: {
        WrongDecision w;
        w.eventIndex = in.eventIndex;
        w.time = time;
        w.executed = executed;
        w.shouldHaveComeFirst = refOf(o.other);
        if (o.otherIsScheduled) w.shouldHaveComeFirst.description += " at " + exactBound(in.nextScheduled.time).hex;
        w.byAtLeast = exactBound(o.byLo);
        w.byAtMost = exactBound(o.byHi);
        w.explanation = o.explanation;
        w.rungBits = result.bits;
        report_.wrong.push_back(std::move(w));
        return;
      }
      case Verdict::Tie: {
        TieDecision t;
        t.eventIndex = in.eventIndex;
        t.time = time;
        t.executed = executed;
        t.proven = true;
        t.within = exactBound(0.0);
        for (const EventKey& k : o.tiedWith) {
          if (t.other.description.empty()) t.other = refOf(k);
          else t.alsoTied.push_back(refOf(k));
          t.orderFollowed = t.orderFollowed && tieOrderBefore(keyOf(in.executed), k);
        }
        report_.ties.push_back(std::move(t));
        return;
      }
      case Verdict::Undecided: break;
    }
    // Still overlapping at the top rung: a tie if the window is down at that precision's scale.
    const double tieScale = std::ldexp(std::max(1.0, std::abs(in.executed.time)), -int(result.bits / 2));
    if (!(o.window <= tieScale)) {
      uncertified(in, o, executed, time, reasonOf(in, o));
      return;
    }
    TieDecision t;
    t.eventIndex = in.eventIndex;
    t.time = time;
    t.executed = executed;
    t.other = refOf(o.other);
    t.within = exactBound(o.window + 0.0);  // a width of −0 (two equal points) reads as 0
    t.orderFollowed = sameEvent(o.other, keyOf(in.executed)) || tieOrderBefore(keyOf(in.executed), o.other);
    report_.ties.push_back(std::move(t));
  }

  // Why the exact step could not order them: a gap that is not a polynomial (a moving arm's side
  // or tip) among the executed event's and the overlapping ones, or none.
  UncertifiedReason reasonOf(const DecisionInput& in, const RungOutcome& o) const {
    bool flipper = false, spinner = false;
    auto note = [&](GizmoId id) {
      const LayoutKind kind = layout_.gizmos[std::size_t(id)].kind;
      flipper = flipper || kind == LayoutKind::Flipper;
      spinner = spinner || kind == LayoutKind::Spinner;
    };
    if (!o.ownPolynomial) note(in.executed.a);
    for (const Overlap& v : o.overlaps)
      if (!v.polynomial) note(v.key.a);
    if (spinner) return UncertifiedReason::TurningSpinner;
    return flipper ? UncertifiedReason::SwingingFlipper : UncertifiedReason::Undecided;
  }

  void uncertified(const DecisionInput& in, const RungOutcome& o, const EventRef& executed, const ExactBound& time,
                   UncertifiedReason why) {
    ++report_.uncertifiedByReason[std::size_t(why)];
    if (report_.uncertified.size() < 100)
      report_.uncertified.push_back(
          UncertifiedDecision{in.eventIndex, time, executed, why, refOf(o.other), exactBound(o.window)});
  }

  GameBoard<double>& board_;
  const CertifyOptions& options_;
  CertifyReport& report_;
  BoardLayout layout_;
  Ladder ladder_;
  // The queue's live events (a handful: a vector searched by sequence number is cheapest).
  std::vector<Event<double>> live_;
  BoardSnapshot snapshot_;
  bool snapshotTaken_ = false;
  GizmoState<double> savedState_;  // scratch for swingOf and turnOf
};

}  // namespace

// The run from `board` as it stands, `ticksDone` ticks into it (0: as built).
CertifyReport certifyFrom(GameBoard<double>& board, const RunRequest& request, std::uint64_t ticksDone,
                          std::uint64_t eventsDone, const CertifyOptions& options) {
  CertifyReport report;
  CertifyingObserver observer(board, options, report);
  observer.adoptQueue(board.pendingEvents());
  board.setObserver(&observer);
  if (options.maxEvents != 0) board.setRunLimit({eventsDone + options.maxEvents, std::nullopt});
  continueRun(board, request, std::int64_t(ticksDone));
  return report;
}

CertifyReport certifyRun(const RunRequest& request, const CertifyOptions& options) {
  std::unique_ptr<GameBoard<double>> board = prepareRun<double>(request);
  return certifyFrom(*board, request, 0, 0, options);
}

CertifyReport certifyLog(const replay::OpenedLog& log, const CertifyOptions& options) {
  if (log.precision.kind != Precision::Double)
    throw CertifyError("certified decisions need a log of a double run; this log was recorded in " +
                       precisionName(log.precision));
  // A branch log's run starts from its first keyframe.
  replay::RunStartBoard start = replay::startBoardInDouble(log);
  return certifyFrom(*start.board, log.request, start.ticksDone, start.eventsDone, options);
}

}  // namespace gizmo::verify
