#pragma once
// The Box2D side of box2d_mapping.hpp: parts made into Box2D shapes. This header includes
// Box2D; only the bridge's own sources (verify/src/box2d_*.cpp) use it.
#include <box2d/b2_time_of_impact.h>  // box2d.h does not include it
#include <box2d/box2d.h>

#include <memory>

#include "gizmo/verify/box2d_mapping.hpp"

namespace gizmo::verify {

inline b2Vec2 toBox2d(const Vec2<double>& p) { return b2Vec2(static_cast<float>(p.x), static_cast<float>(p.y)); }
inline Vec2<double> fromBox2d(const b2Vec2& p) { return Vec2<double>(p.x, p.y); }

// The Box2D shape of one part, in the frame the part is given in.
std::unique_ptr<b2Shape> makeBox2dShape(const Box2dPart& part);

}  // namespace gizmo::verify
