#pragma once
// What the replay log's uses share (recording.cpp, decision_stream.cpp, seeking.cpp,
// replaying.cpp): decisions and balls as views with exact values, the bound on a run's queue that
// the chunk reader enforces, the log's parameters and header, and the dispatch on the log's
// scalar. Private to gizmo::replay.
#include <string>
#include <vector>

#include "gizmo/core/std_compat.hpp"
#include "gizmo/replay/chunk.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/log_header.hpp"
#include "gizmo/replay/replay.hpp"

namespace gizmo::replay::detail {

template <class Real>
Exact exact(const Real& x) {
  return Exact{toDouble(x), exactText(x)};
}

// A ball as an executed event left it: where it was hit, its velocity before and after.
template <class Real>
BallView ballView(const BallChange<Real>& c, const std::vector<std::string>& names) {
  return BallView{c.ball,
                  gizmoName(names, c.ball),
                  exact(c.position.x),
                  exact(c.position.y),
                  exact(c.velocityAfter.x),
                  exact(c.velocityAfter.y),
                  exact(c.velocityBefore.x),
                  exact(c.velocityBefore.y)};
}

template <class Real>
DecisionView viewOf(const Decision<Real>& d, std::uint64_t index, std::uint64_t eventIndex,
                    const std::vector<std::string>& names) {
  DecisionView v;
  v.index = index;
  v.eventIndex = eventIndex;
  v.type = d.type;
  v.time = exact(d.time);
  if (d.type == DecisionType::Scheduled || d.type == DecisionType::Removed || d.type == DecisionType::Executed)
    v.eventTime = exact(d.event.time);
  v.kind = d.event.kind;
  v.a = d.event.a;
  v.b = d.event.b;
  v.feature = d.event.feature;
  v.sequence = d.event.sequence;
  for (const BallChange<Real>& c : d.outcome.balls()) v.balls.push_back(ballView(c, names));
  v.gizmo = d.gizmo;
  v.other = d.other;
  v.key = d.key;
  v.direction = d.direction;
  v.rule = d.rule;
  return v;
}

// The most events the run's queue can hold at once (docs/replay-format.md): one per ball and
// gizmo or ball it can meet, a ball's own few, a flipper stop each, the end of the tick and the
// inputs. The reader refuses a log that claims more, so that it never holds more than a real
// run could make it hold.
inline std::size_t maxQueued(const OpenedLog& log) {
  const std::size_t balls = log.request.board.balls.size(), gizmos = log.gizmoNames.size();
  return (balls + 1) * (gizmos + 8) + log.request.keys.size() + 64;
}

template <class Real>
PhysicsParams<Real> paramsOf(const OpenedLog& log) {
  return readParams<Real>(log.header.params);
}

// The header frame's payload for a run of `request` on `board`.
template <class Real>
std::vector<std::uint8_t> headerBytes(const RunRequest& request, const PrecisionChoice& precision,
                                      const GameBoard<Real>& board, const std::vector<std::string>& boardWarnings,
                                      const std::optional<BranchOrigin>& parent = std::nullopt) {
  LogHeader h = headerFor(request, precisionName(precision), scalarName<Real>(), scalarFormat<Real>(),
                          paramBytes(board.params()));
  h.boardWarnings = boardWarnings;
  h.parent = parent;
  return encodeHeader(h);
}

template <class F>
decltype(auto) withLogScalar(const OpenedLog& log, F&& f) {
  return withRecordablePrecision(log.precision, [&]<class Real>() -> decltype(auto) {
    if (scalarName<Real>() != log.header.scalar)
      throw FormatError("the log was made with " + log.header.scalar + ", this build computes " + scalarName<Real>(),
                        0);
    if (scalarFormat<Real>() != log.header.format)
      throw FormatError("the log's " + log.header.scalar + " is " + log.header.format + ", this build's " +
                            scalarName<Real>() + " is " + scalarFormat<Real>() +
                            ": the formats differ, so the log cannot be replayed here",
                        0);
    return f.template operator()<Real>();
  });
}

}  // namespace gizmo::replay::detail
