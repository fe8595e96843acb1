#pragma once
// restShape's definition (geometry/shapes.hpp): the outline each kind's file gives. Included by
// the explicit instantiations in core/src only (instantiate.hpp), since every kind's file must be
// included where it is compiled.
#include "gizmo/core/gizmo_kinds.hpp"

namespace gizmo {

template <class Real>
Shape<Real> restShape(const GizmoSpec& g) {
  Shape<Real> s;
  visitKind(g.type, [&]<GizmoType T>(KindTag<T>) { KindCore<T>::template addRestShape<Real>(s, g); });
  return s;
}

}  // namespace gizmo
