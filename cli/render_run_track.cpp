// One log read into the arrays the pictures and the player draw from (see render_run_track.hpp).
#include "render_run_track.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include <stdexcept>
#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/gizmo_kinds.hpp"
#include "gizmo/core/gizmos/absorber.hpp"
#include "gizmo/core/gizmos/flipper.hpp"
#include "gizmo/core/gizmos/sink.hpp"
#include "gizmo/core/gizmos/spawner.hpp"
#include "gizmo/core/gizmos/spinner.hpp"
#include "gizmo/core/gizmos/teleporter.hpp"

namespace gizmo::cli {
namespace {

Vec2<double> vec(const replay::Exact& x, const replay::Exact& y) { return Vec2<double>(x.value, y.value); }

}  // namespace

RunTrack trackRun(const replay::OpenedLog& log, double tolerance) {
  RunTrack track;
  track.model = log.header.model;
  track.precision = log.header.precision;
  track.duration = log.header.duration;
  track.tolerance = tolerance;
  track.truncation = log.reader.truncation();
  track.gizmoNames = log.gizmoNames;

  // The board as built at time 0: its parameters, and each ball's first state (a ball placed at
  // rest in an absorber starts held there).
  const std::unique_ptr<GameBoard<double>> board =
      buildBoard<double>(log.request.board, paramsFor<double>(log.request));
  const PhysicsParams<double>& params = board->params();
  std::map<GizmoId, std::size_t> ballIndex;
  std::vector<BallPathBuilder> builders;
  // A branch log starts from its first keyframe: each ball and flipper as it left them, and its
  // events are numbered from there.
  std::optional<replay::StartView> branchStart;
  if (log.reader.isBranch()) branchStart = replay::startView(log);
  const std::uint64_t firstEvent = branchStart ? branchStart->events : 0;
  track.startTime = branchStart ? branchStart->time : 0.0;
  track.firstEvent = firstEvent;
  if (branchStart) {
    for (const replay::StartView::Ball& b : branchStart->balls) {
      PathPiece start;
      start.t0 = branchStart->time;
      start.p = Vec2<double>(b.x, b.y);
      start.v = Vec2<double>(b.vx, b.vy);
      start.a = Vec2<double>(b.ax, b.ay);
      start.logged = true;
      ballIndex[b.id] = builders.size();
      builders.emplace_back(track.model, params, tolerance, start, b.captured);
      track.balls.push_back(BallTrack{b.id, replay::gizmoName(log.gizmoNames, b.id), {}});
    }
  }
  for (GizmoId id : branchStart ? std::vector<GizmoId>{} : board->ballIds()) {
    const Ball<double>& ball = *board->gizmo(id).asBall();
    PathPiece start;
    start.p = ball.positionAt(0);
    start.v = ball.velocityAt(0);
    start.a = ball.acceleration();
    start.logged = true;
    ballIndex[id] = builders.size();
    builders.emplace_back(track.model, params, tolerance, start, ball.captured());
    track.balls.push_back(BallTrack{id, ball.name(), {}});
  }
  std::map<GizmoId, FlipperSwings> flippers;
  // Anchors from the start are anchored where the run starts (the page takes their time from there).
  if (branchStart)
    for (const replay::StartView::Swing& f : branchStart->flippers) {
      const double s = std::clamp(f.s0 + f.direction * (track.startTime - f.t0), 0.0, Flipper<double>::swingTime());
      flippers.emplace(f.id, FlipperSwings(SwingAnchor{-1, track.startTime, s, f.direction}, f.lastDirection));
    }
  // A spinner's turning as the player draws it: the seconds it has turned (its angle over its rate,
  // within a quarter turn, as the cross looks the same a quarter on), anchored at each action.
  std::map<GizmoId, std::vector<SwingAnchor>> spinners;
  std::map<GizmoId, Vec2<double>> hold;     // where a gizmo that captures balls holds them
  std::map<GizmoId, Vec2<double>> spawnAt;  // where a gizmo that spawns balls puts them
  const std::vector<GizmoSpec>& specs = log.request.board.gizmos;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const GizmoId id = static_cast<GizmoId>(i + 1);  // 0 is the outer walls
    if (id >= static_cast<GizmoId>(log.gizmoNames.size()) || log.gizmoNames[std::size_t(id)] != specs[i].name)
      throw std::runtime_error("the log's gizmo names do not follow its board");
    const KindMotion motion = gizmoKind(specs[i].type).motion;
    if (motion == KindMotion::Swings) flippers[id];
    if (motion == KindMotion::Turns) spinners[id] = {SwingAnchor{-1, 0, 0, 0}};
    const AbstractGizmo<double>& gizmo = board->gizmo(id);
    if (const std::optional<Vec2<double>> p = gizmo.heldBallPosition()) hold[id] = *p;
    if (const std::optional<Vec2<double>> p = gizmo.spawnPosition()) spawnAt[id] = *p;
  }
  // A branch log's spinners as its first keyframe left them: the seconds turned past a quarter.
  if (branchStart)
    for (const replay::StartView::Turn& t : branchStart->spinners)
      spinners[t.id] = {SwingAnchor{-1, track.startTime,
                                    std::fmod(t.phase / kSpinnerTurnRate + (t.turning ? track.startTime - t.t0 : 0.0),
                                              std::acos(-1.0) / 2 / kSpinnerTurnRate),
                                    t.turning ? 1 : 0}};
  auto builderOf = [&](GizmoId id) -> BallPathBuilder* {
    const auto it = ballIndex.find(id);
    return it == ballIndex.end() ? nullptr : &builders[it->second];
  };

  // A teleport is reported before its event's record, which gives the ball where it touched the
  // teleporter: the ball is moved to the exit once that record is read.
  std::map<GizmoId, const Teleporter<double>*> teleported;
  std::int64_t event = -1;
  auto note = [&](const replay::DecisionView& d, std::int32_t x, std::int32_t y) {
    if (event < 0) return;  // nothing reports before the first event
    track.notes.push_back(EventNote{static_cast<std::uint32_t>(event), static_cast<std::uint8_t>(d.type),
                                    static_cast<std::uint8_t>(d.rule), x, y});
  };
  replay::DecisionStream stream(log);
  while (const std::optional<replay::DecisionView> d = stream.next()) {
    const double now = d->time.value;
    switch (d->type) {
      case replay::DecisionType::Executed: {
        if (d->eventIndex != firstEvent + track.eventTime.size())
          throw std::runtime_error("the log's events are not numbered in order");
        event = static_cast<std::int64_t>(d->eventIndex - firstEvent);
        track.eventTime.push_back(now);
        track.eventKind.push_back(static_cast<std::uint8_t>(d->kind));
        track.eventA.push_back(d->a);
        track.eventB.push_back(d->b);
        track.eventFeature.push_back(d->feature);
        for (BallPathBuilder& b : builders) b.step(event, now);
        for (const replay::BallView& b : d->balls)
          if (BallPathBuilder* builder = builderOf(b.ball))
            builder->logged(event, now, vec(b.x, b.y), vec(b.vxBefore, b.vyBefore), vec(b.vx, b.vy));
        for (const replay::BallView& b : d->balls)
          if (const auto it = teleported.find(b.ball); it != teleported.end()) {
            if (BallPathBuilder* builder = builderOf(b.ball))
              builder->released(event, now, it->second->exitPosition(vec(b.x, b.y)), vec(b.vx, b.vy));
            teleported.erase(it);
          }
        if (d->kind == EventKind::Collision)
          for (const replay::BallView& b : d->balls) track.collisionPoints.push_back(vec(b.x, b.y));
        if (d->kind == EventKind::FlipperStop && flippers.count(d->a)) flippers[d->a].stopped(event, now);
        break;
      }
      case replay::DecisionType::Action:
        if (flippers.count(d->gizmo)) flippers[d->gizmo].action(event, now);
        if (const auto it = spinners.find(d->gizmo); it != spinners.end()) {
          const SwingAnchor last = it->second.back();
          const double quarter = std::acos(-1.0) / 2 / kSpinnerTurnRate;
          const double turned = std::fmod(last.s0 + last.direction * (now - last.t0), quarter);
          it->second.push_back(SwingAnchor{event, now, turned, last.direction == 0 ? 1 : 0});
        }
        note(*d, d->gizmo, -1);
        break;
      case replay::DecisionType::Trigger: note(*d, d->gizmo, d->other); break;
      case replay::DecisionType::Input: note(*d, d->key, d->direction == KeyDirection::Up ? 1 : 0); break;
      case replay::DecisionType::Rule: {
        BallPathBuilder* ball = builderOf(d->other);
        // A sunk ball is held at the sink's centre for good, as a captured one at its absorber's corner.
        const bool held = d->rule == AbsorberRule::Captured || d->rule == SinkRule::Sunk;
        if (held && ball && hold.count(d->gizmo)) ball->captured(event, now, hold[d->gizmo]);
        if (d->rule == AbsorberRule::Released && ball && hold.count(d->gizmo))
          ball->released(event, now, hold[d->gizmo], Absorber<double>::fireVelocity());
        if (d->rule == TeleporterRule::Teleported)
          if (const auto* t = dynamic_cast<const Teleporter<double>*>(&board->gizmo(d->gizmo)))
            teleported[d->other] = t;
        if (d->rule == FlipperRule::Blocked && flippers.count(d->gizmo)) flippers[d->gizmo].blocked(event, now);
        if (d->rule == SpawnerRule::Spawned && spawnAt.count(d->gizmo)) {
          // A ball a sink held comes back; a new one starts its track here, at rest.
          const Vec2<double> p = spawnAt[d->gizmo];
          if (ball) {
            ball->released(event, now, p, Vec2<double>());
          } else if (d->other > 0) {
            PathPiece start;
            start.event = event;
            start.t0 = now;
            start.p = p;
            start.a = track.model == MotionModel::Ballistic ? Vec2<double>(0, params.gravity) : Vec2<double>();
            start.logged = true;
            ballIndex[d->other] = builders.size();
            builders.emplace_back(track.model, params, tolerance, start, false);
            track.balls.push_back(BallTrack{d->other, spawnedBallName(d->other, log.gizmoNames), {}});
          }
        }
        // Every friction tick implies its friction rule: noting it would only repeat the event.
        if (d->rule != ModelRule::FrictionApplied) note(*d, d->gizmo, d->other);
        break;
      }
      default: break;  // scheduling, ticks and time moves draw nothing
    }
  }
  track.endTime = track.eventTime.empty() ? track.startTime : track.eventTime.back();

  // The state after the last event settles each ball's last piece.
  std::optional<replay::StateView> end;
  try {
    replay::SeekTarget target;
    target.events = firstEvent + track.eventTime.size();
    end = replay::seekLog(log, target);
  } catch (const std::exception&) {
    end.reset();  // a log cut off inside its first chunk: the last pieces keep their default
  }
  for (std::size_t i = 0; i < builders.size(); ++i) {
    std::optional<Vec2<double>> velocity;
    if (end)
      for (const replay::BallView& b : end->balls)
        if (b.name == track.balls[i].name) velocity = vec(b.vx, b.vy);
    track.balls[i].pieces = builders[i].finish(track.endTime, velocity);
  }
  for (auto& [id, swings] : flippers) track.flippers[id] = swings.visibleAnchors(tolerance, track.endTime);
  for (auto& [id, anchors] : spinners) track.flippers[id] = anchors;  // drawn from the same anchors
  return track;
}

}  // namespace gizmo::cli
