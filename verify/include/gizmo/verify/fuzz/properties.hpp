#pragma once
// The properties that `gizmo fuzz` and the property tests check on generated runs, by name. Each
// takes one run and says whether it holds, and if not, why (with exact values).
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/core/math/precision.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/fuzz/invariants.hpp"

namespace gizmo::verify::fuzz {

struct PropertyResult {
  bool holds = true;
  std::string message;            // why not, when it does not hold
  std::uint64_t fingerprint = 0;  // a digest of what the check saw: equal runs, equal fingerprints
  // The board time by which it was seen not to hold, where the property can say (the
  // invariants); a failure's log need not go further than the tick that holds it.
  std::optional<double> failedAt = std::nullopt;
};

struct Property {
  std::string_view name;
  std::string_view summary;
  // A function rather than a pointer, so that a property may hold what it checks against (the
  // user's expectations: expectationsProperty in expectations.hpp). `scalar` is Double or
  // LongDouble: the invariants and replay-identity run in it; round-trip has no scalar, and
  // models-agree and the expectations judge double runs (their tolerances are double's).
  std::function<PropertyResult(const RunRequest& run, Precision scalar)> check;
  std::optional<Invariant> invariant = std::nullopt;  // the invariant it checks, for those that are one
};

// no-tunnelling, energy, event-queue (invariants.hpp, double precision), replay-identity,
// round-trip, models-agree.
std::span<const Property> allProperties();
const Property* findProperty(std::string_view name);
// "no-tunnelling, energy, …": for help texts and error messages.
std::string propertyNames();

// Each property's result on one run, in order; a property that throws does not hold ("threw: …").
// The invariants among them are checked together, in one run under one checker: the checker only
// watches and keeps each invariant's first violation, so each gets the result it would get alone,
// for one simulation instead of one each (a campaign's cases spend most of their time simulating).
std::vector<PropertyResult> checkProperties(std::span<const Property* const> properties, const RunRequest& run,
                                            Precision scalar = Precision::Double);

// The run that models-agree compares: the same board with gravity 0 and friction 0.
RunRequest withoutForces(const RunRequest& run);

// One physical decision of a run, as models-agree compares them: collisions, leaves, flipper
// stops and inputs (with the balls they changed), triggers, actions and model rules.
struct PhysicalDecision {
  std::string what;
  std::int32_t feature = -1;  // of a collision
  double time = 0;
  std::vector<double> values;  // positions and velocities after
  bool negligible = false;     // a hit that changed no velocity by more than the tolerance
  bool grazing = false;        // a hit closing no faster than the tolerances let the runs differ
  bool consequence = false;    // a trigger, action or model rule: reported while the event that caused it runs
};

// A trigger, action or model rule ("trigger 2 -> 7", "captured 1 4") at time t.
inline PhysicalDecision consequenceAt(std::string what, double time) {
  PhysicalDecision d{std::move(what), -1, time, {}};
  d.consequence = true;
  return d;
}

// models-agree's judgement of the two models' decisions (docs/fuzzing.md, "When the models may
// part"): they agree, or part where rounding may part them, or one takes a different decision
// while the states agree.
PropertyResult compareModelDecisions(std::vector<PhysicalDecision> classic, std::vector<PhysicalDecision> ballistic);

}  // namespace gizmo::verify::fuzz
