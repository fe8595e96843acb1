// The core's lookups of a kind's data that the low headers declare (board_spec.hpp, shapes.hpp,
// board/model_rule.hpp): they are defined here, where every kind's file is included, because each
// kind's file includes its gizmo's class, and the classes include those headers. gizmo_kinds.hpp
// checks every kind's file against CoreKindEntry.
#include <array>

#include "gizmo/core/gizmo_kinds.hpp"

namespace gizmo {

int ownSide(GizmoType t) { return gizmoKind(t).side; }

bool isDiscGizmo(GizmoType t) { return gizmoKind(t).disc; }

namespace {

// Every code's name: the board's rules', then the kinds' (gizmo_kinds.hpp checks that they agree).
constexpr std::array<std::string_view, kModelRuleCodeCount> ruleNames() {
  std::array<std::string_view, kModelRuleCodeCount> names{};
  for (int code = 0; code < kModelRuleCodeCount; ++code) names[code] = boardRuleName(static_cast<ModelRule>(code));
  forEachKind([&]<GizmoType T>(KindTag<T>) {
    for (const KindRule& k : KindCore<T>::rules) names[static_cast<int>(k.rule)] = k.name;
  });
  return names;
}

constexpr std::array<std::string_view, kModelRuleCodeCount> kRuleNames = ruleNames();

}  // namespace

std::string_view modelRuleName(ModelRule r) {
  const int code = static_cast<int>(r);
  return code < kModelRuleCodeCount ? kRuleNames[code] : std::string_view();
}

}  // namespace gizmo
