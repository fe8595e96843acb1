#pragma once
#include <cstdint>
#include <string_view>

namespace gizmo {

// A rule that a model applies beyond plain reflection (docs/physics.md §6: each is a recorded
// decision). Its value is its code in logs: four bits of a record's tag (replay/record_codec.hpp),
// so codes run from 0 to 15 and never change meaning.
//
// The enumerators are the board's own rules, which any ball meets whatever the gizmos. A rule that
// only one kind of gizmo records belongs to that kind: its behaviour class declares it (as
// `AbsorberRule::Captured` in gizmos/absorber.hpp) and its kind's file names it (`rules`,
// kinds/kind_core.hpp); the kinds' registry checks at compile time that no two rules share a code
// or a name (gizmo_kinds.hpp). The codes the kinds hold today: 5 flipper-blocked, 6 captured,
// 7 released, 9 boosted, 10 teleported, 11 sunk, 12 spinner-blocked, 13 spawned, 14 spawn-blocked.
enum class ModelRule : std::uint8_t {
  FrictionApplied = 0,  // the friction law applied to a ball (ballistic: at a friction tick)
  ContactBegin = 1,     // a slow ball pressed onto a segment starts sliding along it
  ContactEnd = 2,       // it leaves that segment (end reached, or pushed off)
  MinimumBounce = 3,    // a slow hit on a round feature leaves at the minimum bounce speed
  Wedged = 4,           // a slow ball pressed onto a second surface while sliding comes to rest
  Jammed = 8,           // too many hits at one instant: this one leaves no rebound (see docs/physics.md)
  Settled = 15,         // a ball slower than restSpeed on a level surface stops (docs/physics.md, "Piles")
};

// How many codes a record can hold; a code that no rule has is refused in a log.
inline constexpr int kModelRuleCodeCount = 16;

// The name of one of the board's own rules; empty for any other code.
constexpr std::string_view boardRuleName(ModelRule r) {
  switch (r) {
    case ModelRule::FrictionApplied: return "friction";
    case ModelRule::ContactBegin: return "contact-begin";
    case ModelRule::ContactEnd: return "contact-end";
    case ModelRule::MinimumBounce: return "minimum-bounce";
    case ModelRule::Wedged: return "wedged";
    case ModelRule::Jammed: return "jammed";
    case ModelRule::Settled: return "settled";
  }
  return {};
}

// The name of any rule, the board's or a kind's (core/src/kind_registry.cpp, which sees every
// kind); empty for a code that no rule has.
std::string_view modelRuleName(ModelRule r);

}  // namespace gizmo
