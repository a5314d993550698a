// Shapes (boxes, cylinders, spheres, half-spaces), their signed distances,
// columns against columns, and the roots of polynomials on an interval.
#include "machine/geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "machine/geometry_math.hpp"
#include "machine/mesh.hpp"

namespace skipnc::machine::geo {

namespace {

// Interval of t where alpha + beta t >= 0, intersected into [lo, hi].
void clip_linear(double alpha, double beta, double& lo, double& hi) noexcept {
  if (beta == 0.0) {
    if (alpha < 0.0) lo = kInf;
    return;
  }
  const double t = -alpha / beta;
  if (beta > 0.0) {
    lo = std::max(lo, t);
  } else {
    hi = std::min(hi, t);
  }
}

}  // namespace

Shape make_box(Vec3 lo, Vec3 hi) {
  Shape s;
  s.kind = ShapeKind::kBox;
  s.lo = Vec3{std::min(lo.x, hi.x), std::min(lo.y, hi.y), std::min(lo.z, hi.z)};
  s.hi = Vec3{std::max(lo.x, hi.x), std::max(lo.y, hi.y), std::max(lo.z, hi.z)};
  s.center = (s.lo + s.hi) * 0.5;
  return s;
}

Shape make_cylinder(double x, double y, double radius, double bottom, double top) {
  Shape s;
  s.kind = ShapeKind::kCylinder;
  s.lo = Vec3{x, y, std::min(bottom, top)};
  s.hi = Vec3{x, y, std::max(bottom, top)};
  s.center = Vec3{x, y, (bottom + top) * 0.5};
  s.radius = radius;
  return s;
}

Shape make_sphere(Vec3 center, double radius) {
  Shape s;
  s.kind = ShapeKind::kSphere;
  s.center = center;
  s.radius = radius;
  return s;
}

Shape make_half_space(Vec3 point, Vec3 normal) {
  Shape s;
  s.kind = ShapeKind::kHalfSpace;
  s.center = point;
  const double l = length(normal);
  s.normal = l > 0.0 ? normal * (1.0 / l) : Vec3{0, 0, 1};
  return s;
}

double signed_distance(const Shape& s, Vec3 p) noexcept {
  switch (s.kind) {
    case ShapeKind::kBox: {
      const double qx = std::fabs(p.x - s.center.x) - (s.hi.x - s.lo.x) * 0.5;
      const double qy = std::fabs(p.y - s.center.y) - (s.hi.y - s.lo.y) * 0.5;
      const double qz = std::fabs(p.z - s.center.z) - (s.hi.z - s.lo.z) * 0.5;
      const double out = length(Vec3{std::max(qx, 0.0), std::max(qy, 0.0), std::max(qz, 0.0)});
      return out + std::min(std::max({qx, qy, qz}), 0.0);
    }
    case ShapeKind::kCylinder: {
      const double dr = hypot2(p.x - s.lo.x, p.y - s.lo.y) - s.radius;
      const double dz = std::max(s.lo.z - p.z, p.z - s.hi.z);
      return hypot2(std::max(dr, 0.0), std::max(dz, 0.0)) + std::min(std::max(dr, dz), 0.0);
    }
    case ShapeKind::kSphere:
      return length(p - s.center) - s.radius;
    case ShapeKind::kHalfSpace:
      return dot(p - s.center, s.normal);
  }
  return kInf;
}

double column_overlap(const Column& a, const Column& b) noexcept {
  const double vertical = std::min(a.top, b.top) - std::max(a.bottom, b.bottom);
  const double radial = a.radius + b.radius - hypot2(a.x - b.x, a.y - b.y);
  return std::min(radial, vertical);
}

bool column_first_overlap(const Column& a, Vec3 move, const Column& b, double depth,
                          double& t) noexcept {
  if (column_overlap(a, b) >= depth) return false;  // already in: no new contact
  if (a.top - a.bottom < depth || b.top - b.bottom < depth) return false;
  double lo = 0.0, hi = 1.0;
  // Vertical: a.top + mz t - b.bottom >= depth and b.top - a.bottom - mz t >= depth.
  clip_linear(a.top - b.bottom - depth, move.z, lo, hi);
  clip_linear(b.top - a.bottom - depth, -move.z, lo, hi);
  // Radial: |u0 + w t| <= a.r + b.r - depth.
  const double reach = a.radius + b.radius - depth;
  if (reach <= 0.0) return false;
  const double ux = a.x - b.x, uy = a.y - b.y;
  const double qa = move.x * move.x + move.y * move.y;
  const double qb = 2.0 * (ux * move.x + uy * move.y);
  const double qc = ux * ux + uy * uy - reach * reach;
  if (qa == 0.0) {
    if (qc > 0.0) return false;
  } else {
    double t1 = 0.0, t2 = 0.0;
    if (!quadratic(qa, qb, qc, t1, t2)) return false;
    lo = std::max(lo, t1);
    hi = std::min(hi, t2);
  }
  if (!(lo <= hi) || lo > 1.0 || hi < 0.0) return false;
  t = lo;
  return true;
}

int polynomial_roots(const double* c, int n, double lo, double hi, double* roots) noexcept {
  while (n > 0 && c[n] == 0.0) --n;
  if (n <= 0) return 0;
  int count = 0;
  if (n == 1) {
    const double t = -c[0] / c[1];
    if (t >= lo && t <= hi) roots[count++] = t;
    return count;
  }
  if (n == 2) {
    double t1 = 0.0, t2 = 0.0;
    if (!quadratic(c[2], c[1], c[0], t1, t2)) return 0;
    if (t1 >= lo && t1 <= hi) roots[count++] = t1;
    if (t2 >= lo && t2 <= hi && t2 != t1) roots[count++] = t2;
    return count;
  }
  // The derivative's roots split [lo, hi] into pieces where the polynomial
  // is monotonic; each piece holds at most one root, found by bisection.
  std::array<double, 4> d{};
  for (int i = 0; i < n; ++i) d[static_cast<std::size_t>(i)] = (i + 1) * c[i + 1];
  std::array<double, 6> pts{};
  int np = 0;
  pts[static_cast<std::size_t>(np++)] = lo;
  std::array<double, 4> crit{};
  const int nc = polynomial_roots(d.data(), n - 1, lo, hi, crit.data());
  for (int i = 0; i < nc; ++i)
    pts[static_cast<std::size_t>(np++)] = crit[static_cast<std::size_t>(i)];
  pts[static_cast<std::size_t>(np++)] = hi;
  auto add = [&](double t) {
    if (count > 0 && roots[count - 1] == t) return;
    if (count < n) roots[count++] = t;
  };
  for (int i = 0; i + 1 < np; ++i) {
    double x0 = pts[static_cast<std::size_t>(i)], x1 = pts[static_cast<std::size_t>(i + 1)];
    double f0 = horner(c, n, x0);
    const double f1 = horner(c, n, x1);
    if (f0 == 0.0) {
      add(x0);
      continue;
    }
    if (f1 == 0.0) {
      if (i + 2 == np) add(x1);
      continue;
    }
    if ((f0 < 0.0) == (f1 < 0.0)) continue;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (x0 + x1);
      if (mid <= x0 || mid >= x1) break;
      const double fm = horner(c, n, mid);
      if (fm == 0.0) {
        x0 = x1 = mid;
        break;
      }
      if ((fm < 0.0) == (f0 < 0.0)) {
        x0 = mid;
        f0 = fm;
      } else {
        x1 = mid;
      }
    }
    add(0.5 * (x0 + x1));
  }
  return count;
}

bool box_first_contact(Vec3 lo, Vec3 hi, Vec3 a, Vec3 b, double radius, Contact& out) noexcept {
  double best = kInf;
  Vec3 at;
  auto take = [&](double t, Vec3 point) {
    if (t < best) {
      best = t;
      at = point;
    }
  };
  auto coord = [](Vec3& v, int k) -> double& { return k == 0 ? v.x : k == 1 ? v.y : v.z; };
  double t = 0.0, s = 0.0;
  for (int k = 0; k < 3; ++k) {
    // Faces: the contact point must lie on the face (its two other sides).
    for (const bool high : {false, true}) {
      Vec3 n;
      coord(n, k) = high ? 1.0 : -1.0;
      if (!plane_root(high ? hi : lo, n, a, b, radius, t)) continue;
      Vec3 q = lerp(a, b, t) - n * radius;
      bool on = true;
      for (int j = 1; j < 3; ++j) {
        const int o = (k + j) % 3;
        on = on && coord(q, o) >= coord(lo, o) - kOnSurface &&
             coord(q, o) <= coord(hi, o) + kOnSurface;
      }
      if (on) take(t, q);
    }
    // The four edges along axis k.
    Vec3 e;
    coord(e, k) = 1.0;
    const double len = coord(hi, k) - coord(lo, k);
    for (unsigned i = 0; i < 4; ++i) {
      Vec3 p = lo;
      coord(p, (k + 1) % 3) = (i & 1U) != 0U ? coord(hi, (k + 1) % 3) : coord(lo, (k + 1) % 3);
      coord(p, (k + 2) % 3) = (i & 2U) != 0U ? coord(hi, (k + 2) % 3) : coord(lo, (k + 2) % 3);
      if (line_root(p, e, len, a, b, radius, t, s)) take(t, p + e * s);
    }
  }
  for (unsigned i = 0; i < 8; ++i) {
    const Vec3 p{(i & 1U) != 0U ? hi.x : lo.x, (i & 2U) != 0U ? hi.y : lo.y,
                 (i & 4U) != 0U ? hi.z : lo.z};
    if (point_root(p, a, b, radius, t)) take(t, p);
  }
  if (best == kInf) return false;
  Vec3 n = lerp(a, b, best) - at;
  const double l = length(n);
  out = Contact{best, at, l > 0.0 ? n * (1.0 / l) : Vec3{0, 0, 1}, -1};
  return true;
}

}  // namespace skipnc::machine::geo
