#pragma once
// The exact step of the ladder (docs/verification.md, "Ties, proven exactly"): for a decision the
// intervals leave undecided, the executed event and every event overlapping it are roots of gap
// polynomials whose coefficients are rational (the run's doubles are). Two such times are equal
// exactly when their polynomials share that root: with each root isolated (the only root of its
// polynomial in its enclosure, by a Sturm count), the gcd having a root in both enclosures proves
// the tie, and none proves them distinct, which exact bisection then orders. Nothing here uses
// intervals or the rounding mode: this runs in GMP rationals.
#include <optional>

#include "gizmo/verify/certify_state.hpp"

namespace gizmo::verify::detail {

// Settles an undecided outcome exactly: a proven tie (Verdict::Tie, the equal events in
// tiedWith), or, when `orderDistinct`, also Certified or Wrong where the times are proven to
// differ. Nothing when an overlapping event is not a polynomial's proven entry (a swinging
// flipper's side or tip, a search that ran out) or a root cannot be isolated.
std::optional<RungOutcome> settleExactly(const BoardLayout& layout, const BoardSnapshot& snapshot,
                                         const DecisionInput& input, const RungOutcome& undecided, bool orderDistinct);

}  // namespace gizmo::verify::detail
