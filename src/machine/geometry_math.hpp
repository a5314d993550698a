// The closed forms the geometry is made of (roots of the ball's path
// against points, planes and lines; a shape's vertical extent), shared by
// geometry.cpp and the Material's files. Internal to the machine stage: not
// installed.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "machine/geometry.hpp"

namespace skipnc::machine::geo {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
// A contact point is on a surface when its signed distance is within this.
constexpr double kOnSurface = 1e-7;

inline double hypot2(double x, double y) noexcept {
  return std::sqrt(x * x + y * y);
}

// Roots of a t^2 + b t + c = 0, smaller first. False without real roots or
// when the equation does not depend on t.
inline bool quadratic(double a, double b, double c, double& t1, double& t2) noexcept {
  if (a == 0.0) {
    if (b == 0.0) return false;
    t1 = t2 = -c / b;
    return true;
  }
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return false;
  const double s = std::sqrt(disc);
  const double q = -0.5 * (b + (b >= 0.0 ? s : -s));
  if (q == 0.0) {
    t1 = t2 = 0.0;
    return true;
  }
  t1 = q / a;
  t2 = c / q;
  if (t1 > t2) std::swap(t1, t2);
  return true;
}

inline double horner(const double* c, int n, double t) noexcept {
  double v = c[n];
  for (int i = n - 1; i >= 0; --i) v = v * t + c[i];
  return v;
}

inline bool in_unit(double t) noexcept {
  return t >= 0.0 && t <= 1.0;
}

// The closed-form roots every contact below is made of, for a ball whose
// centre moves from a to b (t in [0, 1]). Each gives the instant the ball
// starts to touch (is entering), not the one it leaves.

// The centre comes within `reach` of point p: the smaller root.
inline bool point_root(Vec3 p, Vec3 a, Vec3 b, double reach, double& t) noexcept {
  const Vec3 w = b - a, m = a - p;
  double t1 = 0.0, t2 = 0.0;
  if (!quadratic(dot(w, w), 2.0 * dot(m, w), dot(m, m) - reach * reach, t1, t2)) return false;
  t = t1;
  return in_unit(t1);
}

// The centre comes to `radius` in front of the plane through p with unit
// normal n, from in front of it.
inline bool plane_root(Vec3 p, Vec3 n, Vec3 a, Vec3 b, double radius, double& t) noexcept {
  const double s0 = dot(a - p, n), s1 = dot(b - p, n);
  if (!(s0 >= radius && s1 <= radius && s1 < s0)) return false;
  t = (s0 - radius) / (s0 - s1);
  return true;
}

// The centre comes within `radius` of the line through p along unit e, its
// foot on the line at s in [0, len] from p (an edge without its ends).
inline bool line_root(Vec3 p, Vec3 e, double len, Vec3 a, Vec3 b, double radius, double& t,
                      double& s) noexcept {
  const Vec3 w = b - a, m = a - p;
  const Vec3 mp = m - e * dot(m, e), wp = w - e * dot(w, e);
  double t1 = 0.0, t2 = 0.0;
  if (!quadratic(dot(wp, wp), 2.0 * dot(mp, wp), dot(mp, mp) - radius * radius, t1, t2) ||
      !(dot(wp, wp) > 0.0) || !in_unit(t1)) {
    return false;
  }
  t = t1;
  s = dot(lerp(a, b, t1) - p, e);
  return s >= 0.0 && s <= len;
}

// The vertical extent of a shape (half-spaces and spheres included).
inline void z_range(const Shape& s, double& lo, double& hi) {
  switch (s.kind) {
    case ShapeKind::kBox:
    case ShapeKind::kCylinder:
      lo = s.lo.z;
      hi = s.hi.z;
      return;
    case ShapeKind::kSphere:
      lo = s.center.z - s.radius;
      hi = s.center.z + s.radius;
      return;
    case ShapeKind::kHalfSpace:
      lo = -1e9;
      hi = 1e9;
      return;
  }
}

}  // namespace skipnc::machine::geo
