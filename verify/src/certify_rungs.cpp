// The rungs of the ladder: the kernel instantiated with the double intervals (under one
// upward-rounding scope per decision) and with MPFI. Built with -frounding-math (verify/CMakeLists.txt).
#include "gizmo/verify/certify_decider.hpp"
#include "gizmo/verify/certify_ladder.hpp"
#include "gizmo/verify/interval.hpp"
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

LadderResult Ladder::settle(const BoardSnapshot& snapshot, const DecisionInput& input) {
  LadderResult result;
  {
    UpwardRounding upward;  // once per decision, never per operation
    result.outcome = fast_->decider.decide(snapshot, input);
  }
  if (settled(result.outcome)) return result;
  int rung = 0;
  for (long bits : options_.mpfiBits) {
    ++rung;
    MpfiInterval::setWorkingBits(bits);
    Decider<MpfiInterval> decider(layout_, limitsFor(bits));
    result.outcome = decider.decide(snapshot, input);
    result.rung = rung;
    result.bits = bits;
    if (settled(result.outcome)) return result;
  }
  return result;
}

}  // namespace gizmo::verify::detail
