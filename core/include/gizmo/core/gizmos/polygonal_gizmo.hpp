#pragma once
// The seed's AbstractGizmoWithPolygonalGeometry: a fixed shape whose edges and vertices (and,
// for the circle bumper, one round feature) meet the ball. Squares, triangles, circles,
// absorbers and the outer walls share all of it; the absorber overrides only the response.
#include "gizmo/core/geometry/shapes.hpp"
#include "gizmo/core/gizmos/grid_properties.hpp"
#include "gizmo/core/gizmos/shape_collisions.hpp"

namespace gizmo {

template <class Real>
class AbstractGizmoWithPolygonalGeometry : public AbstractGizmo<Real> {
 public:
  CollisionAnswer canCollideWith(const AbstractGizmo<Real>& other) const override {
    return other.asBall() ? CollisionAnswer::CanCollide : CollisionAnswer::NeverCollides;
  }

  std::optional<Contact<Real>> timeUntilCollision(const AbstractGizmo<Real>& other, const Real& now, const Real& limit,
                                                  const PhysicsParams<Real>&) const override {
    const Ball<Real>* ball = other.asBall();
    if (!ball || ball->captured()) return std::nullopt;
    const Trajectory<Real> path = ball->trajectoryAt(now);
    const Real span = limit - now;
    // A fast ball's box in the broad phase covers the board: rule out a shape its path passes
    // far from (the shape lies within half its box's width plus half its height of the centre).
    // Only for a ball that may go farther than a cell: a slower one's box has ruled out what is
    // far, and the test would cost the spec example's 600 s game 1.8% more for nothing.
    if (Real(1) < Real(lengthSquared(path.v) * span * span) &&
        !pathMayComeWithin(path, span, centre_, Real(reach_ + Ball<Real>::radius())))
      return std::nullopt;
    const std::int32_t skip =
        ball->contact() && ball->contact()->gizmo == this->id() ? ball->contact()->feature : std::int32_t{-1};
    const std::optional<FeatureHit<Real>> hit = shapeTimeOfImpact(shape_, path, Ball<Real>::radius(), span, skip);
    if (!hit) return std::nullopt;
    return Contact<Real>{now + hit->tau, hit->feature, EventKind::Collision};
  }

  void collide(AbstractGizmo<Real>& other, const Contact<Real>& contact, BoardAccess<Real>& board) override {
    if (Ball<Real>* ball = other.asBall()) respond(*ball, contact, board);
  }

  Box<Real> bounds() const override { return bounds_; }
  const Shape<Real>& shape() const { return shape_; }
  const Real& coefficient() const { return coefficient_; }

 protected:
  AbstractGizmoWithPolygonalGeometry(std::string name, Shape<Real> shape, const Real& coefficient)
      : AbstractGizmo<Real>(std::move(name)), coefficient_(coefficient) {
    setShape(std::move(shape));
  }

  void setShape(Shape<Real> shape) {
    shape_ = std::move(shape);
    bounds_ = shapeBounds(shape_);
    const Real half = Real(1) / Real(2);
    centre_ = Vec2<Real>(half * (bounds_.lo.x + bounds_.hi.x), half * (bounds_.lo.y + bounds_.hi.y));
    reach_ = half * (Real(bounds_.hi.x - bounds_.lo.x) + Real(bounds_.hi.y - bounds_.lo.y));
  }

  // The reflection; the absorber captures instead.
  virtual void respond(Ball<Real>& ball, const Contact<Real>& contact, BoardAccess<Real>& board) {
    bounceOffShape(shape_, this->id(), coefficient_, ball, contact.feature, board);
  }

 private:
  Shape<Real> shape_;
  Box<Real> bounds_;
  Vec2<Real> centre_;  // of bounds_
  Real reach_{0};      // half its width plus half its height: every point of the shape is this near centre_
  Real coefficient_;
};

// A polygonal gizmo that stands on the grid and is described by a GizmoSpec.
template <class Real>
class GridBumper : public GridPlaced<AbstractGizmoWithPolygonalGeometry<Real>> {
 public:
  explicit GridBumper(const GizmoSpec& spec)
      : GridPlaced<AbstractGizmoWithPolygonalGeometry<Real>>(spec, spec.name, restShape<Real>(spec), Real(1)) {}

  // The centre of the cells it stands on: where a teleporter's pass goes through, where a sink
  // holds the balls it took.
  Vec2<Real> centre() const {
    const GizmoSpec s = this->spec();
    const Real two(2);
    return Vec2<Real>(Real(s.x) + Real(s.width) / two, Real(s.y) + Real(s.height) / two);
  }

  // A bumper only reflects: a ball can lie against it. The kinds built on it that do more (capture,
  // boost, teleport, sink) say otherwise in their own classes.
  const Shape<Real>* restingShape() const override { return &this->shape(); }

  GizmoKind kind() const override { return gizmoKindOf(this->placement().type); }

 protected:
  void placed() override { this->setShape(restShape<Real>(this->placement())); }
};

// Square, circle and triangle bumpers: coefficient 1, a trigger, no action.
template <class Real>
using SquareBumper = GridBumper<Real>;
template <class Real>
using CircleBumper = GridBumper<Real>;
template <class Real>
using TriangleBumper = GridBumper<Real>;

}  // namespace gizmo
