#pragma once
// The escalation ladder for one decision: the double intervals first, then MPFI at each
// precision of CertifyOptions::mpfiBits, until a rung certifies the decision or proves it
// wrong; overlapping events whose gaps are polynomials are compared exactly (certify_exact.hpp)
// after each rung, which proves genuine ties, and after the last, which also orders roots closer
// than the top rung can part. Its interface holds no interval type, so that callers need no
// -frounding-math.
#include <memory>

#include "gizmo/verify/certify.hpp"
#include "gizmo/verify/certify_state.hpp"

namespace gizmo::verify::detail {

struct LadderResult {
  RungOutcome outcome;
  // The rung that settled it (0: the double intervals; one past the MPFI rungs: the exact step),
  // or the last one tried; and that rung's precision (0: exact).
  int rung = 0;
  long bits = 53;
};

class Ladder {
 public:
  Ladder(const BoardLayout& layout, const CertifyOptions& options);
  ~Ladder();
  Ladder(const Ladder&) = delete;
  Ladder& operator=(const Ladder&) = delete;

  LadderResult settle(const BoardSnapshot& snapshot, const DecisionInput& input);
  // The layout it was built on has changed (a spawner added a ball): the deciders built from it
  // are built again.
  void layoutChanged();

 private:
  // Whether the exact step proves `outcome` (undecided) a tie; it is then replaced by the tie.
  bool provenTie(const BoardSnapshot& snapshot, const DecisionInput& input, RungOutcome& outcome) const;

  struct Fast;  // the double-interval decider, built once
  const BoardLayout& layout_;
  CertifyOptions options_;
  std::unique_ptr<Fast> fast_;
};

}  // namespace gizmo::verify::detail
