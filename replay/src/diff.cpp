// Where two logs part (replay.hpp: diffLogs). Two decisions are alike when they are the same
// kind of decision about the same gizmos and events; between logs of one scalar their values
// must also be equal to the last bit, between different scalars their differences are measured.
#include <cmath>
#include <cstdio>
#include <deque>

#include "gizmo/replay/chunk.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/replay.hpp"

namespace gizmo::replay {
namespace {

bool sameValue(const Exact& a, const Exact& b, bool exact) { return exact ? a.text == b.text : true; }

// Empty when alike, else what differs.
std::string difference(const DecisionView& x, const DecisionView& y, bool exact) {
  if (x.type != y.type) return "a different decision";
  if (x.kind != y.kind || x.a != y.a || x.b != y.b || x.feature != y.feature || x.sequence != y.sequence)
    return "a different event";
  if (x.gizmo != y.gizmo || x.other != y.other || x.key != y.key || x.direction != y.direction || x.rule != y.rule)
    return "different gizmos, keys or rules";
  if (!sameValue(x.time, y.time, exact) || !sameValue(x.eventTime, y.eventTime, exact)) return "a different time";
  if (x.balls.size() != y.balls.size()) return "different balls changed";
  for (std::size_t i = 0; i < x.balls.size(); ++i) {
    const BallView &p = x.balls[i], &q = y.balls[i];
    if (p.ball != q.ball) return "different balls changed";
    if (!sameValue(p.x, q.x, exact) || !sameValue(p.y, q.y, exact)) return "a different position";
    if (!sameValue(p.vxBefore, q.vxBefore, exact) || !sameValue(p.vyBefore, q.vyBefore, exact))
      return "a different velocity before";
    if (!sameValue(p.vx, q.vx, exact) || !sameValue(p.vy, q.vy, exact)) return "a different velocity after";
  }
  return {};
}

void measure(const DecisionView& x, const DecisionView& y, DiffReport& r) {
  r.maxTimeDifference = std::max(r.maxTimeDifference, std::abs(x.eventTime.value - y.eventTime.value));
  for (std::size_t i = 0; i < x.balls.size(); ++i)
    r.maxPositionDifference = std::max(r.maxPositionDifference, std::hypot(x.balls[i].x.value - y.balls[i].x.value,
                                                                           x.balls[i].y.value - y.balls[i].y.value));
}

void count(std::vector<std::pair<std::string, std::pair<std::uint64_t, std::uint64_t>>>& counts, const DecisionView& d,
           bool second) {
  std::string key(decisionTypeName(d.type));
  if (d.type == DecisionType::Executed) key += " " + std::string(eventKindName(d.kind));
  auto it = std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == key; });
  if (it == counts.end()) it = counts.insert(counts.end(), {key, {0, 0}});
  ++(second ? it->second.second : it->second.first);
}

// Where two logs' comparison starts: at the start for two ordinary logs; where the later one
// starts when one is a branch of the other or both are branches of one parent (their decisions
// before that are the parent's). A branch compared with a log it was not taken from is refused.
struct CommonStart {
  std::uint64_t decision = 0;
  double time = -1;
};
std::uint64_t firstDecision(const OpenedLog& log, double* time) {
  if (!log.header.parent || log.reader.chunks().empty()) return 0;
  ChunkPreamble p;
  readPreamble(log.reader.chunkPayload(0), p);
  *time = p.time;
  return p.decisionsDone;
}
CommonStart commonStart(const OpenedLog& a, const OpenedLog& b, std::vector<std::string>& notes) {
  if (!a.header.parent && !b.header.parent) return {};
  auto branchOf = [](const OpenedLog& branch, const OpenedLog& parent) {
    return branch.header.parent && branch.header.parent->parentDigest == parent.reader.fileDigest();
  };
  CommonStart start;
  double timeA = -1, timeB = -1;
  const std::uint64_t fromA = firstDecision(a, &timeA), fromB = firstDecision(b, &timeB);
  if (branchOf(b, a)) {
    notes.push_back("the second log is a branch of the first at event " + std::to_string(b.header.parent->event) +
                    "; they are compared from where it starts, decision " + std::to_string(fromB));
  } else if (branchOf(a, b)) {
    notes.push_back("the first log is a branch of the second at event " + std::to_string(a.header.parent->event) +
                    "; they are compared from where it starts, decision " + std::to_string(fromA));
  } else if (a.header.parent && b.header.parent && a.header.parent->parentDigest == b.header.parent->parentDigest) {
    notes.push_back("the logs are branches of one log, at events " + std::to_string(a.header.parent->event) + " and " +
                    std::to_string(b.header.parent->event) + "; they are compared from where the later starts");
  } else {
    const OpenedLog& branch = b.header.parent ? b : a;
    char digest[17];
    std::snprintf(digest, sizeof digest, "%016llx",
                  static_cast<unsigned long long>(branch.header.parent->parentDigest));
    throw BranchError(std::string(b.header.parent ? "the second" : "the first") + " log is a branch of another log " +
                      "(digest " + digest + "), not of the " + (b.header.parent ? "first" : "second") +
                      ": a branch is compared only with its parent or a branch of the same parent");
  }
  start.decision = std::max(fromA, fromB);
  start.time = std::max(timeA, timeB);
  return start;
}

}  // namespace

DiffReport diffLogs(const OpenedLog& a, const OpenedLog& b, std::size_t context, bool counts) {
  DiffReport r;
  r.sameScalar = a.header.scalar == b.header.scalar;
  // One scalar name in two formats (long-double recorded on x86 and on aarch64): its values
  // are different numbers, and the decisions of two machines are not this tool's to compare.
  if (r.sameScalar && a.header.format != b.header.format)
    throw FormatError("the logs' " + a.header.scalar + " values have different formats (" + a.header.format + ", " +
                          b.header.format + "): logs are compared only within one format",
                      0);
  if (a.header.board != b.header.board) r.notes.push_back("the logs are of different boards");
  if (a.header.model != b.header.model) r.notes.push_back("the logs use different motion models");
  if (!r.sameScalar)
    r.notes.push_back("different scalars (" + a.header.scalar + ", " + b.header.scalar +
                      "): decisions are compared without their values, whose differences are measured");
  if (a.header.keys.size() != b.header.keys.size()) r.notes.push_back("the logs have different key input");

  const CommonStart start = commonStart(a, b, r.notes);
  r.firstDecision = start.decision;
  DecisionStream sa(a, start.time), sb(b, start.time);
  auto from = [&](DecisionStream& s) {
    std::optional<DecisionView> d = s.next();
    while (d && d->index < start.decision) d = s.next();
    return d;
  };
  std::deque<DecisionView> recent;
  for (bool first = true;; first = false) {
    std::optional<DecisionView> x = first ? from(sa) : sa.next(), y = first ? from(sb) : sb.next();
    if (!x && !y) break;
    if (x && y) {
      const std::string why = difference(*x, *y, r.sameScalar);
      if (why.empty()) {
        measure(*x, *y, r);
        ++r.matched;
        if (counts) count(r.counts, *x, false), count(r.counts, *y, true);
        recent.push_back(std::move(*x));
        if (recent.size() > context) recent.pop_front();
        continue;
      }
      r.where = why;
    } else {
      r.where = x ? "the second log ends here" : "the first log ends here";
    }
    r.parted = true;
    r.before.assign(recent.begin(), recent.end());
    r.first = x;
    r.second = y;
    if (counts) {
      if (x) count(r.counts, *x, false);
      if (y) count(r.counts, *y, true);
    }
    // What follows on each side: a few decisions for the reader, or all of them for the counts.
    for (std::optional<DecisionView> d; (d = sa.next());) {
      if (r.afterFirst.size() < context) r.afterFirst.push_back(*d);
      else if (!counts) break;
      if (counts) count(r.counts, *d, false);
    }
    for (std::optional<DecisionView> d; (d = sb.next());) {
      if (r.afterSecond.size() < context) r.afterSecond.push_back(*d);
      else if (!counts) break;
      if (counts) count(r.counts, *d, true);
    }
    break;
  }
  return r;
}

}  // namespace gizmo::replay
