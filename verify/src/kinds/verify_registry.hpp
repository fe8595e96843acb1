#pragma once
// Every kind's verify file, and the check that each holds what VerifyKindEntry asks: an
// incomplete file fails to compile with the kind's name and its file in the message.
#include "gizmo/core/kinds/kind_core.hpp"
#include "kinds/all_verify_kinds.hpp"  // generated from the kind list by cmake/GizmoKinds.cmake
#include "kinds/kind_verify.hpp"

namespace gizmo::verify {

#define GIZMO_VERIFY_KIND_IS_COMPLETE(Name, stem)             \
  static_assert(VerifyKindEntry<KindVerify<GizmoType::Name>>, \
                "kind " #Name ": verify/src/kinds/" #stem     \
                ".hpp lacks part of what VerifyKindEntry (verify/src/kinds/kind_verify.hpp) asks");
GIZMO_KINDS(GIZMO_VERIFY_KIND_IS_COMPLETE)
#undef GIZMO_VERIFY_KIND_IS_COMPLETE

// One of a kind's verify facts, read through the kind list's switch: verifyFact(t, [](auto k) {
// return k.restedOnTop; }) with k the kind's KindVerify.
template <class F>
constexpr auto verifyFact(GizmoType t, F&& fact) {
  return visitKind(t, [&]<GizmoType T>(KindTag<T>) { return fact(KindVerify<T>{}); });
}

}  // namespace gizmo::verify
