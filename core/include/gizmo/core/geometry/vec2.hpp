#pragma once
// A 2-D vector over any scalar of the ladder. Board coordinates: x right, y down.
#include "gizmo/core/math/scalar.hpp"

namespace gizmo {

template <class Real>
struct Vec2 {
  Real x{0}, y{0};

  Vec2() = default;
  Vec2(const Real& x_, const Real& y_) : x(x_), y(y_) {}

  friend Vec2 operator+(const Vec2& a, const Vec2& b) { return Vec2(a.x + b.x, a.y + b.y); }
  friend Vec2 operator-(const Vec2& a, const Vec2& b) { return Vec2(a.x - b.x, a.y - b.y); }
  friend Vec2 operator-(const Vec2& a) { return Vec2(-a.x, -a.y); }
  friend Vec2 operator*(const Real& s, const Vec2& a) { return Vec2(s * a.x, s * a.y); }
  friend Vec2 operator*(const Vec2& a, const Real& s) { return Vec2(a.x * s, a.y * s); }
  Vec2& operator+=(const Vec2& b) {
    x += b.x;
    y += b.y;
    return *this;
  }
  Vec2& operator-=(const Vec2& b) {
    x -= b.x;
    y -= b.y;
    return *this;
  }
  friend bool operator==(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
};

template <class Real>
inline Real dot(const Vec2<Real>& a, const Vec2<Real>& b) {
  return a.x * b.x + a.y * b.y;
}
// z of the 3-D cross product: positive when b is clockwise of a on screen (y down).
template <class Real>
inline Real cross(const Vec2<Real>& a, const Vec2<Real>& b) {
  return a.x * b.y - a.y * b.x;
}
template <class Real>
inline Real lengthSquared(const Vec2<Real>& a) {
  return dot(a, a);
}
template <class Real>
inline Real length(const Vec2<Real>& a) {
  return sqrtOf(dot(a, a));
}
// a turned a quarter clockwise on screen: (x, y) → (−y, x).
template <class Real>
inline Vec2<Real> perpendicular(const Vec2<Real>& a) {
  return Vec2<Real>(-a.y, a.x);
}

template <class Real>
inline Vec2<Real> toReal(const Vec2<double>& v) {
  return Vec2<Real>(fromDouble<Real>(v.x), fromDouble<Real>(v.y));
}

}  // namespace gizmo
