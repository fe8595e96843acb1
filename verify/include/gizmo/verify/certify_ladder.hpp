#pragma once
// The escalation ladder for one decision: the double intervals first, then MPFI at each
// precision of CertifyOptions::mpfiBits, until a rung certifies the decision or proves it
// wrong. Its interface holds no interval type, so that callers need no -frounding-math.
#include <memory>

#include "gizmo/verify/certify.hpp"
#include "gizmo/verify/certify_state.hpp"

namespace gizmo::verify::detail {

struct LadderResult {
  RungOutcome outcome;
  int rung = 0;     // the rung that settled it (0: the double intervals), or the last one tried
  long bits = 53;   // that rung's precision
};

class Ladder {
 public:
  Ladder(const BoardLayout& layout, const CertifyOptions& options);
  ~Ladder();
  Ladder(const Ladder&) = delete;
  Ladder& operator=(const Ladder&) = delete;

  LadderResult settle(const BoardSnapshot& snapshot, const DecisionInput& input);

 private:
  struct Fast;  // the double-interval decider, built once
  const BoardLayout& layout_;
  CertifyOptions options_;
  std::unique_ptr<Fast> fast_;
};

}  // namespace gizmo::verify::detail
