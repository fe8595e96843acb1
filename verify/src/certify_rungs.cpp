// The rungs of the ladder: the kernel instantiated with the double intervals (under one
// upward-rounding scope per decision) and with MPFI, then the exact step. Built with
// -frounding-math (verify/CMakeLists.txt).
#include "gizmo/verify/certify_decider.hpp"
#include "gizmo/verify/certify_exact.hpp"
#include "gizmo/verify/certify_ladder.hpp"
#include "gizmo/verify/interval_trig.hpp"  // before the kernel: its sin and cos of Interval
#include "gizmo/verify/mpfi_interval.hpp"

namespace gizmo::verify::detail {

namespace {
// Higher precision buys narrower pieces: more subdivisions and bisections are worth it there.
SearchLimits limitsFor(long bits) {
  SearchLimits l;
  l.pieces = bits <= 53 ? 48 : int(4 * bits);
  l.narrowingSteps = int(bits + 16);
  return l;
}

bool settled(const RungOutcome& o) { return o.verdict != Verdict::Undecided; }
}  // namespace

struct Ladder::Fast {
  explicit Fast(const BoardLayout& layout) : decider(build(layout)) {}
  static Decider<Interval> build(const BoardLayout& layout) {
    UpwardRounding upward;  // the fixed geometry is enclosed with the same rounding
    return Decider<Interval>(layout, limitsFor(53));
  }
  Decider<Interval> decider;
};

Ladder::Ladder(const BoardLayout& layout, const CertifyOptions& options)
    : layout_(layout), options_(options), fast_(std::make_unique<Fast>(layout)) {}
Ladder::~Ladder() = default;

void Ladder::layoutChanged() { fast_ = std::make_unique<Fast>(layout_); }

LadderResult Ladder::settle(const BoardSnapshot& snapshot, const DecisionInput& input) {
  LadderResult result;
  {
    UpwardRounding upward;  // once per decision, never per operation
    result.outcome = fast_->decider.decide(snapshot, input);
  }
  // A genuine tie never parts at any precision: try to prove it exactly as soon as the events
  // overlap, rather than after every MPFI rung has failed to part them. The exact step runs in
  // rationals, outside the upward-rounding scope.
  if (settled(result.outcome) || provenTie(snapshot, input, result.outcome)) return result;
  int rung = 0;
  for (long bits : options_.mpfiBits) {
    ++rung;
    MpfiInterval::setWorkingBits(bits);
    Decider<MpfiInterval> decider(layout_, limitsFor(bits));
    result.outcome = decider.decide(snapshot, input);
    result.rung = rung;
    result.bits = bits;
    if (settled(result.outcome) || provenTie(snapshot, input, result.outcome)) return result;
  }
  // Still overlapping at the top: two different roots closer than the intervals can part are
  // ordered exactly, where the gaps are polynomials.
  if (std::optional<RungOutcome> exact = settleExactly(layout_, snapshot, input, result.outcome, true)) {
    result.outcome = std::move(*exact);
    result.rung = rung + 1;
    result.bits = 0;
  }
  return result;
}

bool Ladder::provenTie(const BoardSnapshot& snapshot, const DecisionInput& input, RungOutcome& outcome) const {
  std::optional<RungOutcome> exact = settleExactly(layout_, snapshot, input, outcome, false);
  if (!exact || exact->verdict != Verdict::Tie) return false;
  outcome = std::move(*exact);
  return true;
}

}  // namespace gizmo::verify::detail
