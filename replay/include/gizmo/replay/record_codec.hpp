#pragma once
// The records of a chunk, both ways: RecordEncoder turns the board's reports into bytes and
// RecordDecoder turns bytes back into decisions. They mirror each other line by line, so they
// live together; docs/replay-format.md describes the same bytes in prose.
//
// Both keep the same small context, reset at every chunk's keyframe: the current time (times
// are written against it), the next sequence number (events are named by their distance from
// it) and the last position and velocity written (outcomes are written against them).
#include <array>
#include <limits>
#include <optional>
#include <unordered_map>

#include "gizmo/core/board/board_state.hpp"
#include "gizmo/core/board/observer.hpp"
#include "gizmo/core/board/physics_params.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/log_format.hpp"
#include "gizmo/replay/scalar_codec.hpp"

namespace gizmo::replay {

// Which of a, b and feature an event of each kind uses (the others are −1), as a mask of these
// bits. A table, not a switch: the encoder asks once per scheduled event.
inline constexpr std::uint8_t kFieldA = 1, kFieldB = 2, kFieldFeature = 4, kAllFields = 7;
inline constexpr std::array<std::uint8_t, kEventKindCount> kScheduledFields = [] {
  std::array<std::uint8_t, kEventKindCount> fields{};
  for (int k = 0; k < kEventKindCount; ++k) {
    switch (static_cast<EventKind>(k)) {
      case EventKind::Collision:
      case EventKind::Leave: fields[std::size_t(k)] = kAllFields; break;
      case EventKind::Input: fields[std::size_t(k)] = kFieldB | kFieldFeature; break;
      case EventKind::EndOfTick: fields[std::size_t(k)] = 0; break;
      default: fields[std::size_t(k)] = kFieldA; break;
    }
  }
  return fields;
}();
inline std::uint8_t scheduledFields(EventKind k) { return kScheduledFields[static_cast<std::size_t>(k)]; }
// Whether the short form (only the fields its kind uses) holds the event: it sets no other.
template <class Real>
bool shortFormHolds(const Event<Real>& e, std::uint8_t uses) {
  const unsigned set = unsigned(e.a != kNoGizmo) | unsigned(e.b != kNoGizmo) << 1 | unsigned(e.feature != -1) << 2;
  return (set & ~unsigned(uses)) == 0;
}

template <class Real>
struct RecordContext {
  Real now{0};
  std::uint64_t nextSequence = 0;
  Vec2<Real> lastPosition, lastVelocity;
  Real maxTick{0}, frictionStep{0};

  void reset(const Real& time, std::uint64_t sequence) {
    now = time;
    nextSequence = sequence;
    lastPosition = lastVelocity = Vec2<Real>();
  }
};

// One record being written. For fixed-width scalars a record's largest size is known, so room
// is claimed once and every byte is stored without further checks; MPFR values, whose size is
// not known in advance, go through the writer and the room is claimed again after each.
template <class Real>
class RecordOut {
 public:
  static constexpr std::size_t kScalar = kMaxCompactBytes<Real>;
  RecordOut(ByteWriter& w, std::size_t room) : w_(w), room_(room), p_(w.claim(room)) {}
  ~RecordOut() { w_.commit(p_); }
  RecordOut(const RecordOut&) = delete;
  RecordOut& operator=(const RecordOut&) = delete;

  void u8(std::uint8_t v) { *p_++ = v; }
  void varint(std::uint64_t v) { p_ = detail::putVarint(p_, v); }
  void svarint(std::int64_t v) { varint(detail::zigzag(v)); }
  void scalar(const Real& value, const Real& base) {
    if constexpr (kScalar > 0) {
      p_ = putScalar(p_, value, base);
    } else {
      w_.commit(p_);
      writeScalar(w_, value, base);
      p_ = w_.claim(room_);
    }
  }
  void vec(const Vec2<Real>& v, const Vec2<Real>& base) {
    scalar(v.x, base.x);
    scalar(v.y, base.y);
  }

 private:
  ByteWriter& w_;
  std::size_t room_;
  std::uint8_t* p_;
};

template <class Real>
class RecordEncoder {
  using Out = RecordOut<Real>;
  static constexpr std::size_t kScalar = Out::kScalar, kVarint = kMaxVarintBytes;

 public:
  RecordEncoder(ByteWriter& out, const PhysicsParams<Real>& params) : out_(out) {
    c_.maxTick = params.maxTick;
    c_.frictionStep = params.frictionStep;
  }
  void reset(const Real& now, std::uint64_t nextSequence) {
    c_.reset(now, nextSequence);
    held_.clear();
    impliedFriction_.reset();
    rulesAfterFriction_.clear();
    nowPlusTick_ = c_.now + c_.maxTick;
    lastFrictionK_ = lastTickK_ = 0;  // a chunk's bytes depend on nothing before its keyframe
  }

  void scheduled(const Event<Real>& e) {
    flushHeld();
    ++records_;
    if (e.sequence != c_.nextSequence) throw std::logic_error("replay: events scheduled out of sequence");
    ++c_.nextSequence;
    const std::uint8_t uses = scheduledFields(e.kind);
    const bool fits = shortFormHolds(e, uses);
    const std::uint8_t written = fits ? uses : kAllFields;
    std::uint8_t tag = static_cast<std::uint8_t>(e.kind);
    if (!fits) tag |= kScheduledAllFields;
    std::int64_t k = 0;
    const TimeForm form = timeForm(e, k);
    Out o(out_, 1 + 4 * kVarint + kScalar);
    o.u8(static_cast<std::uint8_t>(tag | (static_cast<std::uint8_t>(form) << 3)));
    if (written & kFieldA) o.svarint(e.a);
    if (written & kFieldB) o.svarint(e.b);
    if (written & kFieldFeature) o.svarint(e.feature);
    if (form == TimeForm::FrictionGrid || form == TimeForm::TickGrid) o.varint(std::uint64_t(k));
    if (form == TimeForm::Explicit) o.scalar(e.time, c_.now);
  }

  void removed(const Event<Real>& e) {
    flushHeld();
    ++records_;
    const std::uint64_t d = distance(e);
    Out o(out_, 1 + kVarint);
    if (d < 15) {
      o.u8(static_cast<std::uint8_t>(static_cast<std::uint8_t>(RecordType::Removed) | d));
    } else {
      o.u8(static_cast<std::uint8_t>(RecordType::Removed) | 15);
      o.varint(d - 15);
    }
  }

  void executed(const Event<Real>& e, const EventOutcome<Real>& outcome) {
    if (e.kind == EventKind::FrictionTick) {
      if (!impliedFriction_ || impliedFriction_->ball != e.a || !sameEncoding(impliedFriction_->time, e.time))
        throw std::logic_error("replay: a friction tick without its friction rule");
      impliedFriction_.reset();
      writeRulesAfterFriction();
    }
    setNow(e.time);
    ++records_;
    const std::span<const BallChange<Real>> changes = outcome.balls();
    bool forA = false, forB = false;
    std::size_t i = 0;
    if (i < changes.size() && changes[i].ball == e.a) forA = true, ++i;
    if (i < changes.size() && changes[i].ball == e.b) forB = true, ++i;
    if (i != changes.size()) throw std::logic_error("replay: an outcome for a ball the event does not name");
    const std::uint64_t d = distance(e);
    std::uint8_t tag = static_cast<std::uint8_t>(RecordType::Executed);
    if (forA) tag |= 8;
    if (forB) tag |= 4;
    {
      Out o(out_, 1 + kVarint + 12 * kScalar);
      o.u8(static_cast<std::uint8_t>(tag | (d < 3 ? d : 3)));
      if (d >= 3) o.varint(d - 3);
      for (const BallChange<Real>& ch : changes) {
        o.vec(ch.position, c_.lastPosition);
        o.vec(ch.velocityBefore, c_.lastVelocity);
        o.vec(ch.velocityAfter, ch.velocityBefore);
        c_.lastPosition = ch.position;
        c_.lastVelocity = ch.velocityAfter;
      }
    }
    flushHeld();  // what the event did, after the event
  }

  // The board reports what an event does (triggers, actions, inputs, rules) while it runs and
  // the event itself when it is done. These reports are held and written after the event's
  // record, which sets the current time they share; only a report that is not followed by its
  // event needs a time record of its own.
  void trigger(const Real& t, GizmoId source, GizmoId target) {
    ++records_;
    Out o(hold(t), 1 + 2 * kVarint);
    o.u8(static_cast<std::uint8_t>(RecordType::Trigger));
    o.svarint(source);
    o.svarint(target);
  }
  void action(const Real& t, GizmoId target) {
    ++records_;
    Out o(hold(t), 1 + kVarint);
    o.u8(static_cast<std::uint8_t>(RecordType::Action));
    o.svarint(target);
  }
  void input(const Real& t, int key, KeyDirection d) {
    ++records_;
    Out o(hold(t), 1 + kVarint);
    o.u8(static_cast<std::uint8_t>(static_cast<std::uint8_t>(RecordType::Input) | (d == KeyDirection::Up)));
    o.svarint(key);
  }
  // The board applies the friction rule at every friction tick, and only there: the reader puts
  // that rule back after the tick's record, so it is not written (a friction tick without it is
  // a broken promise of the board's, and stops the recording). Rules the tick applies after it
  // (Settled) wait until it is known whether the friction rule was implied, and follow it.
  // Reports held from an earlier time are written first: the board reports what a gizmo started
  // in an instant released once the instant is over, after its last event, and the next event
  // may be a friction tick with nothing scheduled or removed in between.
  void rule(const Real& t, ModelRule r, GizmoId g, GizmoId other) {
    ++records_;
    if (r == ModelRule::FrictionApplied && other == kNoGizmo && !impliedFriction_) {
      if (held_.size() > 0 && !sameEncoding(t, heldTime_)) flushHeld();
      if (held_.size() == 0) {
        impliedFriction_ = ImpliedFriction{g, t};
        return;
      }
    }
    if (impliedFriction_ && sameEncoding(t, impliedFriction_->time)) {
      rulesAfterFriction_.push_back(PendingRule{r, g, other, t});
      return;
    }
    writeRule(hold(t), r, g, other);
  }
  void tick(const Real& t) {
    flushHeld();
    at(t);
    ++records_;
    out_.u8(static_cast<std::uint8_t>(RecordType::Tick));
  }
  // Writes whatever is held (before a chunk is closed).
  void flush() { flushHeld(); }
  // Records made so far (held ones included), over all chunks: what the reader numbers.
  std::uint64_t records() const { return records_; }

 private:
  std::uint64_t distance(const Event<Real>& e) const {
    if (e.sequence >= c_.nextSequence) throw std::logic_error("replay: an event that was never scheduled");
    return c_.nextSequence - 1 - e.sequence;
  }

  static void writeRule(ByteWriter& w, ModelRule r, GizmoId g, GizmoId other) {
    Out o(w, 1 + 2 * kVarint);
    o.u8(static_cast<std::uint8_t>(static_cast<std::uint8_t>(RecordType::Rule) | static_cast<std::uint8_t>(r)));
    o.svarint(g);
    o.svarint(other);
  }
  // A friction rule that turns out not to belong to a friction tick is written like any rule.
  void writeImpliedFriction() {
    const ImpliedFriction f = *impliedFriction_;
    impliedFriction_.reset();
    heldTime_ = f.time;
    writeRule(held_, ModelRule::FrictionApplied, f.ball, kNoGizmo);
    writeRulesAfterFriction();
  }
  // Held like any rule, at the friction's time (the reader gives them that time).
  void writeRulesAfterFriction() {
    for (const PendingRule& p : rulesAfterFriction_) writeRule(hold(p.time), p.rule, p.gizmo, p.other);
    rulesAfterFriction_.clear();
  }

  ByteWriter& hold(const Real& t) {
    if (impliedFriction_) writeImpliedFriction();
    if (held_.size() > 0 && !sameEncoding(t, heldTime_)) flushHeld();
    heldTime_ = t;
    return held_;
  }
  void flushHeld() {
    if (impliedFriction_) writeImpliedFriction();
    if (held_.size() == 0) return;
    at(heldTime_);
    out_.bytes(held_.bytes().data(), held_.size());
    held_.clear();
  }

  // The reader takes the executed event's time as the current time, bit for bit.
  void setNow(const Real& t) {
    if (sameEncoding(t, c_.now)) return;
    c_.now = t;
    nowPlusTick_ = c_.now + c_.maxTick;
  }
  // Reports carry the time of the event they belong to; anything else is written as a move of
  // the current time first, so that nothing is lost.
  void at(const Real& t) {
    if (sameEncoding(t, c_.now)) return;
    ++records_;
    {
      Out o(out_, 1 + kScalar);
      o.u8(static_cast<std::uint8_t>(RecordType::Time));
      o.scalar(t, c_.now);
    }
    setNow(t);
  }

  TimeForm timeForm(const Event<Real>& e, std::int64_t& k) {
    if (sameEncoding(e.time, c_.now)) return TimeForm::Now;
    if (sameEncoding(e.time, nowPlusTick_)) return TimeForm::NowPlusTick;
    if (e.kind == EventKind::FrictionTick && onGrid(e.time, c_.frictionStep, lastFrictionK_, k))
      return TimeForm::FrictionGrid;
    if (e.kind == EventKind::EndOfTick && onGrid(e.time, c_.maxTick, lastTickK_, k)) return TimeForm::TickGrid;
    return TimeForm::Explicit;
  }
  // Whether t = k·step for a whole k; the k after the last one found is tried first, which
  // spares a division nearly always.
  static bool onGrid(const Real& t, const Real& step, std::int64_t& last, std::int64_t& k) {
    if (sameEncoding(Real(Real(last + 1) * step), t)) {
      k = ++last;
      return true;
    }
    if (!(Real(0) < step) || !(Real(0) <= t)) return false;
    const double q = toDouble(Real(t / step));
    if (!(q < 9.0e15)) return false;
    k = static_cast<std::int64_t>(q + 0.5);
    if (!sameEncoding(Real(Real(k) * step), t)) return false;
    last = k;
    return true;
  }

  ByteWriter& out_;
  RecordContext<Real> c_;
  Real nowPlusTick_{0};
  std::int64_t lastFrictionK_ = 0, lastTickK_ = 0;
  ByteWriter held_;
  Real heldTime_{0};
  struct ImpliedFriction {
    GizmoId ball;
    Real time;
  };
  std::optional<ImpliedFriction> impliedFriction_;
  struct PendingRule {
    ModelRule rule;
    GizmoId gizmo, other;
    Real time;
  };
  std::vector<PendingRule> rulesAfterFriction_;
  std::uint64_t records_ = 0;
};

// One decoded record.
enum class DecisionType : std::uint8_t { Scheduled, Removed, Executed, Trigger, Action, Input, Rule, Tick, Time };

inline std::string_view decisionTypeName(DecisionType t) {
  switch (t) {
    case DecisionType::Scheduled: return "scheduled";
    case DecisionType::Removed: return "removed";
    case DecisionType::Executed: return "executed";
    case DecisionType::Trigger: return "trigger";
    case DecisionType::Action: return "action";
    case DecisionType::Input: return "input";
    case DecisionType::Rule: return "rule";
    case DecisionType::Tick: return "tick";
    case DecisionType::Time: return "time";
  }
  return "?";
}

template <class Real>
struct Decision {
  DecisionType type = DecisionType::Tick;
  Real time{0};                // the board time the decision was made at
  Event<Real> event;           // scheduled, removed, executed
  EventOutcome<Real> outcome;  // executed
  GizmoId gizmo = kNoGizmo;    // trigger: source; action: target; rule: the gizmo
  GizmoId other = kNoGizmo;    // trigger: target; rule: the other gizmo
  int key = 0;
  KeyDirection direction = KeyDirection::Down;
  ModelRule rule = ModelRule::FrictionApplied;
};

template <class Real>
class RecordDecoder {
 public:
  // maxQueued: the most events the board's queue can hold at once; a log that claims more is
  // refused before it can make the reader hold them all.
  RecordDecoder(ByteReader& in, const PhysicsParams<Real>& params, std::size_t maxQueued)
      : in_(in), maxQueued_(maxQueued) {
    c_.maxTick = params.maxTick;
    c_.frictionStep = params.frictionStep;
  }
  // The keyframe's time, its queue and its next sequence number.
  void reset(const Real& now, const std::vector<Event<Real>>& live, std::uint64_t nextSequence) {
    if (live.size() > maxQueued_) throw FormatError("a keyframe with more queued events than the board can hold", 0);
    c_.reset(now, nextSequence);
    live_.clear();
    impliedRule_.reset();
    for (const Event<Real>& e : live) live_.emplace(e.sequence, e);
  }

  bool atEnd() const { return !impliedRule_ && in_.atEnd(); }

  Decision<Real> next() {
    if (impliedRule_) {
      Decision<Real> d = std::move(*impliedRule_);
      impliedRule_.reset();
      return d;
    }
    Decision<Real> d;
    const std::size_t start = in_.position();
    const std::uint8_t tag = in_.u8();
    if (!(tag & 0x80)) {
      d.type = DecisionType::Scheduled;
      Event<Real>& e = d.event;
      const std::uint8_t kind = tag & 7, form = (tag >> 3) & 7;
      e.kind = static_cast<EventKind>(kind);
      const bool all = tag & kScheduledAllFields;
      const std::uint8_t uses = scheduledFields(e.kind), written = all ? kAllFields : uses;
      if (written & kFieldA) e.a = gizmoId();
      if (written & kFieldB) e.b = gizmoId();
      if (written & kFieldFeature) e.feature = static_cast<std::int32_t>(bounded(INT32_MIN, INT32_MAX));
      // Every event has one spelling: the full form only for an event its kind's short form
      // cannot hold.
      if (all && shortFormHolds(e, uses))
        throw FormatError("an event written in full that its short form holds", start);
      switch (static_cast<TimeForm>(form)) {
        case TimeForm::Now: e.time = c_.now; break;
        case TimeForm::NowPlusTick: e.time = c_.now + c_.maxTick; break;
        case TimeForm::FrictionGrid: e.time = Real(grid()) * c_.frictionStep; break;
        case TimeForm::TickGrid: e.time = Real(grid()) * c_.maxTick; break;
        case TimeForm::Explicit: e.time = readScalar<Real>(in_, c_.now); break;
        default: throw FormatError("unknown time form " + std::to_string(form), start);
      }
      if (live_.size() >= maxQueued_) throw FormatError("more queued events than the board can hold", start);
      e.sequence = c_.nextSequence++;
      live_.emplace(e.sequence, e);
      d.time = c_.now;
      return d;
    }
    d.time = c_.now;
    switch (static_cast<RecordType>(tag & 0xF0)) {
      case RecordType::Removed: {
        const std::uint64_t small = tag & 15;
        d.type = DecisionType::Removed;
        d.event = take(small < 15 ? small : longDistance(15), start);
        return d;
      }
      case RecordType::Executed: {
        const std::uint64_t small = tag & 3;
        d.type = DecisionType::Executed;
        d.event = take(small < 3 ? small : longDistance(3), start);
        c_.now = d.time = d.event.time;
        if (tag & 8) readChange(d.outcome, d.event.a);
        if (tag & 4) readChange(d.outcome, d.event.b);
        if (d.event.kind == EventKind::FrictionTick) {  // its friction rule, implied (see the encoder)
          Decision<Real>& r = impliedRule_.emplace();
          r.type = DecisionType::Rule;
          r.time = c_.now;
          r.rule = ModelRule::FrictionApplied;
          r.gizmo = d.event.a;
        }
        return d;
      }
      case RecordType::Trigger:
        if (tag & 15) throw FormatError("bad trigger record", start);
        d.type = DecisionType::Trigger;
        d.gizmo = gizmoId();
        d.other = gizmoId();
        return d;
      case RecordType::Action:
        if (tag & 15) throw FormatError("bad action record", start);
        d.type = DecisionType::Action;
        d.gizmo = gizmoId();
        return d;
      case RecordType::Input:
        if (tag & 14) throw FormatError("bad input record", start);
        d.type = DecisionType::Input;
        d.direction = (tag & 1) ? KeyDirection::Up : KeyDirection::Down;
        d.key = static_cast<int>(bounded(INT32_MIN, INT32_MAX));
        return d;
      case RecordType::Rule:
        if (modelRuleName(static_cast<ModelRule>(tag & 15)).empty()) throw FormatError("unknown model rule", start);
        d.type = DecisionType::Rule;
        d.rule = static_cast<ModelRule>(tag & 15);
        d.gizmo = gizmoId();
        d.other = gizmoId();
        return d;
      case RecordType::Tick:
        if (tag & 15) throw FormatError("bad tick record", start);
        d.type = DecisionType::Tick;
        return d;
      case RecordType::Time:
        if (tag & 15) throw FormatError("bad time record", start);
        d.type = DecisionType::Time;
        c_.now = d.time = readScalar<Real>(in_, c_.now);
        return d;
    }
    throw FormatError("unknown record", start);
  }

 private:
  std::int64_t bounded(std::int64_t lo, std::int64_t hi) {
    const std::size_t at = in_.position();
    const std::int64_t v = in_.svarint();
    if (v < lo || v > hi) throw FormatError("number out of range", at);
    return v;
  }
  GizmoId gizmoId() { return static_cast<GizmoId>(bounded(-1, INT32_MAX)); }
  std::uint64_t longDistance(std::uint64_t from) {
    const std::size_t at = in_.position();
    const std::uint64_t v = in_.varint();
    if (v > std::numeric_limits<std::uint64_t>::max() - from) throw FormatError("event distance out of range", at);
    return from + v;
  }
  std::int64_t grid() {
    const std::size_t at = in_.position();
    const std::uint64_t k = in_.varint();
    if (k >= (std::uint64_t(1) << 53)) throw FormatError("grid index out of range", at);
    return static_cast<std::int64_t>(k);
  }

  Event<Real> take(std::uint64_t distance, std::size_t at) {
    if (distance >= c_.nextSequence) throw FormatError("names an event never scheduled", at);
    auto it = live_.find(c_.nextSequence - 1 - distance);
    if (it == live_.end()) throw FormatError("names an event that is not in the queue", at);
    Event<Real> e = it->second;
    live_.erase(it);
    return e;
  }

  void readChange(EventOutcome<Real>& o, GizmoId ball) {
    BallChange<Real> ch;
    ch.ball = ball;
    ch.position = readVec(c_.lastPosition);
    ch.velocityBefore = readVec(c_.lastVelocity);
    ch.velocityAfter = readVec(ch.velocityBefore);
    c_.lastPosition = ch.position;
    c_.lastVelocity = ch.velocityAfter;
    o.add(ch);
  }
  Vec2<Real> readVec(const Vec2<Real>& base) {
    const Real x = readScalar<Real>(in_, base.x);
    return Vec2<Real>(x, readScalar<Real>(in_, base.y));
  }

  ByteReader& in_;
  std::size_t maxQueued_;
  RecordContext<Real> c_;
  std::unordered_map<std::uint64_t, Event<Real>> live_;
  std::optional<Decision<Real>> impliedRule_;
};

}  // namespace gizmo::replay
