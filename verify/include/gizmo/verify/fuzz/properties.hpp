#pragma once
// The properties that `gizmo fuzz` and the property tests check on generated runs, by name. Each
// takes one run and says whether it holds, and if not, why (with exact values).
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "gizmo/core/run/run.hpp"

namespace gizmo::verify::fuzz {

struct PropertyResult {
  bool holds = true;
  std::string message;          // why not, when it does not hold
  std::uint64_t fingerprint = 0;  // a digest of what the check saw: equal runs, equal fingerprints
};

struct Property {
  std::string_view name;
  std::string_view summary;
  PropertyResult (*check)(const RunRequest& run);
};

// no-tunnelling, energy, event-queue (invariants.hpp, double precision), replay-identity,
// round-trip, models-agree.
std::span<const Property> allProperties();
const Property* findProperty(std::string_view name);
// "no-tunnelling, energy, …": for help texts and error messages.
std::string propertyNames();

// The run that models-agree compares: the same board with gravity 0 and friction 0.
RunRequest withoutForces(const RunRequest& run);

}  // namespace gizmo::verify::fuzz
