#include "gizmo/verify/box2d_shapes.hpp"

#include <stdexcept>

namespace gizmo::verify {

std::unique_ptr<b2Shape> makeBox2dShape(const Box2dPart& part) {
  switch (part.kind) {
    case Box2dPart::Kind::Polygon: {
      auto polygon = std::make_unique<b2PolygonShape>();
      std::vector<b2Vec2> points;
      for (const Vec2<double>& p : part.points) points.push_back(toBox2d(p));
      if (points.size() < 3 || points.size() > b2_maxPolygonVertices)
        throw std::invalid_argument("a Box2D polygon needs 3 to 8 vertices");
      polygon->Set(points.data(), static_cast<int32>(points.size()));  // Box2D orders them itself
      return polygon;
    }
    case Box2dPart::Kind::Edge: {
      auto edge = std::make_unique<b2EdgeShape>();
      edge->SetTwoSided(toBox2d(part.points.at(0)), toBox2d(part.points.at(1)));
      return edge;
    }
    case Box2dPart::Kind::Circle: {
      auto circle = std::make_unique<b2CircleShape>();
      circle->m_p = toBox2d(part.centre);
      circle->m_radius = static_cast<float>(part.radius);
      return circle;
    }
  }
  throw std::invalid_argument("unknown Box2D part");
}

}  // namespace gizmo::verify
