#pragma once
#include <cstdint>
#include <string_view>

namespace gizmo {

// Rules that the models apply beyond plain reflection (docs/physics.md §6: each is a recorded
// decision).
enum class ModelRule : std::uint8_t {
  FrictionApplied,  // the friction law applied to a ball (ballistic: at a friction tick)
  ContactBegin,     // a slow ball pressed onto a segment starts sliding along it
  ContactEnd,       // it leaves that segment (end reached, or pushed off)
  MinimumBounce,    // a slow hit on a round feature leaves at the minimum bounce speed
  Wedged,           // a slow ball pressed onto a second surface while sliding comes to rest
  FlipperBlocked,   // a flipper pinching a ball stops where it is
  Captured,         // an absorber captured a ball
  Released,         // an absorber fired a ball
  Jammed,           // too many hits at one instant: this one leaves no rebound (see docs/physics.md)
  Boosted,          // a booster doubled a ball's speed
  Teleported,       // a teleporter moved a ball to its exit
  Sunk,             // a sink took a ball out of play
  SpinnerBlocked,   // a spinner pinching a ball stops where it stands
  Spawned,          // a spawner put a ball at its centre (the other gizmo: that ball)
  SpawnBlocked,     // a spawner acted with no room at its centre, or no ball to be had
  Settled,          // a ball slower than restSpeed on a level surface stops (docs/physics.md, "Piles")
};
// The last rule: a log's rule value above it is refused. A rule is four bits of a record's tag
// (replay/record_codec.hpp), so Settled is the last that fits without a new record kind.
inline constexpr ModelRule kLastModelRule = ModelRule::Settled;

inline std::string_view modelRuleName(ModelRule r) {
  switch (r) {
    case ModelRule::FrictionApplied: return "friction";
    case ModelRule::ContactBegin: return "contact-begin";
    case ModelRule::ContactEnd: return "contact-end";
    case ModelRule::MinimumBounce: return "minimum-bounce";
    case ModelRule::Wedged: return "wedged";
    case ModelRule::FlipperBlocked: return "flipper-blocked";
    case ModelRule::Captured: return "captured";
    case ModelRule::Released: return "released";
    case ModelRule::Jammed: return "jammed";
    case ModelRule::Boosted: return "boosted";
    case ModelRule::Teleported: return "teleported";
    case ModelRule::Sunk: return "sunk";
    case ModelRule::SpinnerBlocked: return "spinner-blocked";
    case ModelRule::Spawned: return "spawned";
    case ModelRule::SpawnBlocked: return "spawn-blocked";
    case ModelRule::Settled: return "settled";
  }
  return "?";
}

}  // namespace gizmo
