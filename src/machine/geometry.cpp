#include "machine/geometry.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "machine/mesh.hpp"

namespace skipnc::machine::geo {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
// A contact point is on a surface when its signed distance is within this.
constexpr double kOnSurface = 1e-7;

double hypot2(double x, double y) noexcept {
  return std::sqrt(x * x + y * y);
}

// Roots of a t^2 + b t + c = 0, smaller first. False without real roots or
// when the equation does not depend on t.
bool quadratic(double a, double b, double c, double& t1, double& t2) noexcept {
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

double horner(const double* c, int n, double t) noexcept {
  double v = c[n];
  for (int i = n - 1; i >= 0; --i) v = v * t + c[i];
  return v;
}

bool in_unit(double t) noexcept {
  return t >= 0.0 && t <= 1.0;
}

// The closed-form roots every contact below is made of, for a ball whose
// centre moves from a to b (t in [0, 1]). Each gives the instant the ball
// starts to touch (is entering), not the one it leaves.

// The centre comes within `reach` of point p: the smaller root.
bool point_root(Vec3 p, Vec3 a, Vec3 b, double reach, double& t) noexcept {
  const Vec3 w = b - a, m = a - p;
  double t1 = 0.0, t2 = 0.0;
  if (!quadratic(dot(w, w), 2.0 * dot(m, w), dot(m, m) - reach * reach, t1, t2)) return false;
  t = t1;
  return in_unit(t1);
}

// The centre comes to `radius` in front of the plane through p with unit
// normal n, from in front of it.
bool plane_root(Vec3 p, Vec3 n, Vec3 a, Vec3 b, double radius, double& t) noexcept {
  const double s0 = dot(a - p, n), s1 = dot(b - p, n);
  if (!(s0 >= radius && s1 <= radius && s1 < s0)) return false;
  t = (s0 - radius) / (s0 - s1);
  return true;
}

// The centre comes within `radius` of the line through p along unit e, its
// foot on the line at s in [0, len] from p (an edge without its ends).
bool line_root(Vec3 p, Vec3 e, double len, Vec3 a, Vec3 b, double radius, double& t,
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

// A 2-D curve of a vertical surface: a line n.p = d (n unit) or a circle.
struct Curve2 {
  bool circle = false;
  double nx = 0.0, ny = 0.0, d = 0.0;  // line
  double cx = 0.0, cy = 0.0, r = 0.0;  // circle
};

Curve2 line2(double nx, double ny, double d) {
  Curve2 c;
  c.nx = nx;
  c.ny = ny;
  c.d = d;
  return c;
}
Curve2 circle2(double cx, double cy, double r) {
  Curve2 c;
  c.circle = true;
  c.cx = cx;
  c.cy = cy;
  c.r = r;
  return c;
}

// The vertical surfaces of a shape as XY curves.
void vertical_curves(const Shape& s, std::vector<Curve2>& out) {
  switch (s.kind) {
    case ShapeKind::kBox:
      out.push_back(line2(1, 0, s.lo.x));
      out.push_back(line2(1, 0, s.hi.x));
      out.push_back(line2(0, 1, s.lo.y));
      out.push_back(line2(0, 1, s.hi.y));
      break;
    case ShapeKind::kCylinder:
      out.push_back(circle2(s.lo.x, s.lo.y, s.radius));
      break;
    case ShapeKind::kHalfSpace:
      if (std::fabs(s.normal.z) < 1e-12) {
        const double h = hypot2(s.normal.x, s.normal.y);
        out.push_back(line2(s.normal.x / h, s.normal.y / h,
                            (s.normal.x * s.center.x + s.normal.y * s.center.y) / h));
      }
      break;
    case ShapeKind::kSphere:
      break;
  }
}

// Points where two XY curves cross (at most 2).
int intersect2(const Curve2& a, const Curve2& b, double* xs, double* ys) {
  if (!a.circle && !b.circle) {
    const double det = a.nx * b.ny - a.ny * b.nx;
    if (std::fabs(det) < 1e-12) return 0;
    xs[0] = (a.d * b.ny - a.ny * b.d) / det;
    ys[0] = (a.nx * b.d - a.d * b.nx) / det;
    return 1;
  }
  if (a.circle && b.circle) {
    const double dx = b.cx - a.cx, dy = b.cy - a.cy;
    const double dd = hypot2(dx, dy);
    if (dd < 1e-12 || dd > a.r + b.r || dd < std::fabs(a.r - b.r)) return 0;
    const double along = (a.r * a.r - b.r * b.r + dd * dd) / (2.0 * dd);
    const double h = std::sqrt(std::max(0.0, a.r * a.r - along * along));
    const double mx = a.cx + dx * along / dd, my = a.cy + dy * along / dd;
    xs[0] = mx - dy * h / dd;
    ys[0] = my + dx * h / dd;
    xs[1] = mx + dy * h / dd;
    ys[1] = my - dx * h / dd;
    return 2;
  }
  const Curve2& l = a.circle ? b : a;
  const Curve2& c = a.circle ? a : b;
  const double off = l.d - (l.nx * c.cx + l.ny * c.cy);
  if (std::fabs(off) >= c.r) return 0;
  const double fx = c.cx + l.nx * off, fy = c.cy + l.ny * off;
  const double h = std::sqrt(c.r * c.r - off * off);
  xs[0] = fx - l.ny * h;
  ys[0] = fy + l.nx * h;
  xs[1] = fx + l.ny * h;
  ys[1] = fy - l.nx * h;
  return 2;
}

// The vertical extent of a shape (half-spaces and spheres included).
void z_range(const Shape& s, double& lo, double& hi) {
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

// Overlap of a column with a solid: the smaller of the radial and vertical
// overlaps (boxes, cylinders), the penetration (spheres, half-spaces).
double column_shape_overlap(const Column& c, const Shape& s) noexcept {
  switch (s.kind) {
    case ShapeKind::kBox: {
      const double vertical = std::min(c.top, s.hi.z) - std::max(c.bottom, s.lo.z);
      const double dx = std::max({s.lo.x - c.x, 0.0, c.x - s.hi.x});
      const double dy = std::max({s.lo.y - c.y, 0.0, c.y - s.hi.y});
      double radial;
      if (dx == 0.0 && dy == 0.0) {
        radial = c.radius + std::min({c.x - s.lo.x, s.hi.x - c.x, c.y - s.lo.y, s.hi.y - c.y});
      } else {
        radial = c.radius - hypot2(dx, dy);
      }
      return std::min(radial, vertical);
    }
    case ShapeKind::kCylinder: {
      const double vertical = std::min(c.top, s.hi.z) - std::max(c.bottom, s.lo.z);
      const double radial = c.radius + s.radius - hypot2(c.x - s.lo.x, c.y - s.lo.y);
      return std::min(radial, vertical);
    }
    case ShapeKind::kSphere: {
      const double zc = std::clamp(s.center.z, c.bottom, c.top);
      const double dxy = std::max(0.0, hypot2(c.x - s.center.x, c.y - s.center.y) - c.radius);
      return s.radius - hypot2(dxy, s.center.z - zc);
    }
    case ShapeKind::kHalfSpace: {
      const double z = s.normal.z > 0.0 ? c.bottom : c.top;
      const double low =
          dot(Vec3{c.x, c.y, z} - s.center, s.normal) - c.radius * hypot2(s.normal.x, s.normal.y);
      return -low;
    }
  }
  return 0.0;
}

// Is the column, over the height it shares with `solid`, inside `hole`?
bool column_in_hole(const Column& c, const Shape& solid, const Shape& hole, double tol) noexcept {
  double slo = 0.0, shi = 0.0;
  z_range(solid, slo, shi);
  const double lo = std::max(c.bottom, slo), hi = std::min(c.top, shi);
  if (lo < hole.lo.z - tol || hi > hole.hi.z + tol) return false;
  if (hole.kind == ShapeKind::kCylinder) {
    return hypot2(c.x - hole.lo.x, c.y - hole.lo.y) + c.radius <= hole.radius + tol;
  }
  return c.x - c.radius >= hole.lo.x - tol && c.x + c.radius <= hole.hi.x + tol &&
         c.y - c.radius >= hole.lo.y - tol && c.y + c.radius <= hole.hi.y + tol;
}

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

// --- Material ---------------------------------------------------------------

Material::Material(std::vector<Part> parts) : parts_(std::move(parts)) {
  for (std::size_t p = 0; p < parts_.size(); ++p) {
    start_.push_back(parts_[p].place);
    if (parts_[p].rotary.turns()) turning_.push_back(p);
  }
  for (int p = 0; p < static_cast<int>(parts_.size()); ++p) {
    const Part& part = parts_[static_cast<std::size_t>(p)];
    PartBounds b;
    b.begin = features_.size();
    for (int s = 0; s < static_cast<int>(part.solids.size()); ++s) add_solid_features(p, s);
    for (int h = 0; h < static_cast<int>(part.holes.size()); ++h) {
      add_hole_features(p, h);
      for (int s = 0; s < static_cast<int>(part.solids.size()); ++s) add_rims(p, h, s);
    }
    b.end = features_.size();
    b.lo = Vec3{kInf, kInf, kInf};
    b.hi = Vec3{-kInf, -kInf, -kInf};
    const auto grow = [&](Vec3 lo, Vec3 hi) {
      b.lo = Vec3{std::fmin(b.lo.x, lo.x), std::fmin(b.lo.y, lo.y), std::fmin(b.lo.z, lo.z)};
      b.hi = Vec3{std::fmax(b.hi.x, hi.x), std::fmax(b.hi.y, hi.y), std::fmax(b.hi.z, hi.z)};
    };
    for (const Shape& s : part.solids) {
      switch (s.kind) {
        case ShapeKind::kBox:
          grow(s.lo, s.hi);
          break;
        case ShapeKind::kCylinder:
          grow(Vec3{s.lo.x - s.radius, s.lo.y - s.radius, s.lo.z},
               Vec3{s.hi.x + s.radius, s.hi.y + s.radius, s.hi.z});
          break;
        case ShapeKind::kSphere:
          grow(s.center - Vec3{s.radius, s.radius, s.radius},
               s.center + Vec3{s.radius, s.radius, s.radius});
          break;
        case ShapeKind::kHalfSpace:
          b.bounded = false;
          break;
      }
    }
    bounds_.push_back(b);
    world_.push_back(world_box(part, b));
  }
  // The box that holds every part, when each part has one.
  all_.valid = true;
  all_.lo = Vec3{kInf, kInf, kInf};
  all_.hi = Vec3{-kInf, -kInf, -kInf};
  for (const WorldBox& w : world_) {
    all_.valid = all_.valid && w.valid;
    all_.lo =
        Vec3{std::min(all_.lo.x, w.lo.x), std::min(all_.lo.y, w.lo.y), std::min(all_.lo.z, w.lo.z)};
    all_.hi =
        Vec3{std::max(all_.hi.x, w.hi.x), std::max(all_.hi.y, w.hi.y), std::max(all_.hi.z, w.hi.z)};
  }
}

// Does the column miss the box?
bool Material::misses(const WorldBox& w, const Column& c) noexcept {
  return w.valid &&
         (c.x + c.radius < w.lo.x || c.x - c.radius > w.hi.x || c.y + c.radius < w.lo.y ||
          c.y - c.radius > w.hi.y || c.top < w.lo.z || c.bottom > w.hi.z);
}

// The machine-frame box that holds the part's solids and meshes (the corners
// of their part-frame box, placed); none for a part that turns or is unbounded.
Material::WorldBox Material::world_box(const Part& part, const PartBounds& b) noexcept {
  WorldBox w;
  w.valid = b.bounded && !part.rotary.turns();
  if (!w.valid) return w;
  w.lo = Vec3{kInf, kInf, kInf};
  w.hi = Vec3{-kInf, -kInf, -kInf};
  const auto add = [&](Vec3 lo, Vec3 hi) {
    if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)) return;  // empty
    for (unsigned c = 0; c < 8; ++c) {
      const Vec3 q =
          part.place.to_machine(Vec3{(c & 1U) != 0U ? hi.x : lo.x, (c & 2U) != 0U ? hi.y : lo.y,
                                     (c & 4U) != 0U ? hi.z : lo.z});
      w.lo = Vec3{std::min(w.lo.x, q.x), std::min(w.lo.y, q.y), std::min(w.lo.z, q.z)};
      w.hi = Vec3{std::max(w.hi.x, q.x), std::max(w.hi.y, q.y), std::max(w.hi.z, q.z)};
    }
  };
  add(b.lo, b.hi);
  for (const auto& mesh : part.meshes) add(mesh->bounds().lo, mesh->bounds().hi);
  return w;
}

// Can nothing within the box lo..hi (part frame) reach the part's solids?
bool Material::beyond(const PartBounds& b, Vec3 lo, Vec3 hi) const noexcept {
  return b.bounded && (lo.x > b.hi.x || hi.x < b.lo.x || lo.y > b.hi.y || hi.y < b.lo.y ||
                       lo.z > b.hi.z || hi.z < b.lo.z);
}

void Material::add_solid_features(int part, int solid) {
  const Shape& s = parts_[static_cast<std::size_t>(part)].solids[static_cast<std::size_t>(solid)];
  const FeatureMaker fm{features_, part, solid, false};
  switch (s.kind) {
    case ShapeKind::kBox: {
      fm.plane(s.lo, {-1, 0, 0});
      fm.plane(s.hi, {1, 0, 0});
      fm.plane(s.lo, {0, -1, 0});
      fm.plane(s.hi, {0, 1, 0});
      fm.plane(s.lo, {0, 0, -1});
      fm.plane(s.hi, {0, 0, 1});
      std::array<Vec3, 8> corner{};
      for (unsigned i = 0; i < 8; ++i) {
        corner[i] = Vec3{(i & 1U) ? s.hi.x : s.lo.x, (i & 2U) ? s.hi.y : s.lo.y,
                         (i & 4U) ? s.hi.z : s.lo.z};
      }
      for (unsigned i = 0; i < 8; ++i) {
        for (unsigned bit = 1; bit < 8; bit <<= 1U) {
          if ((i & bit) != 0U) continue;
          Feature f = fm.make(FeatureKind::kSegment);
          f.p = corner[i];
          f.q = corner[i | bit];
          features_.push_back(f);
        }
      }
      break;
    }
    case ShapeKind::kCylinder: {
      Feature wall = fm.make(FeatureKind::kOuterWall);
      wall.p = s.lo;
      wall.r = s.radius;
      features_.push_back(wall);
      fm.plane(s.hi, {0, 0, 1});
      fm.plane(s.lo, {0, 0, -1});
      for (double z : {s.lo.z, s.hi.z}) {
        Feature rim = fm.make(FeatureKind::kCircle);
        rim.p = Vec3{s.lo.x, s.lo.y, z};
        rim.r = s.radius;
        features_.push_back(rim);
      }
      break;
    }
    case ShapeKind::kSphere: {
      Feature f = fm.make(FeatureKind::kBall);
      f.p = s.center;
      f.r = s.radius;
      features_.push_back(f);
      break;
    }
    case ShapeKind::kHalfSpace:
      fm.plane(s.center, s.normal);
      break;
  }
}

void Material::add_hole_features(int part, int hole) {
  const Shape& h = parts_[static_cast<std::size_t>(part)].holes[static_cast<std::size_t>(hole)];
  const FeatureMaker fm{features_, part, hole, true};
  // The walls face into the hole: material is outside it.
  if (h.kind == ShapeKind::kCylinder) {
    Feature wall = fm.make(FeatureKind::kInnerWall);
    wall.p = h.lo;
    wall.r = h.radius;
    features_.push_back(wall);
  } else {
    fm.plane(h.lo, {1, 0, 0});
    fm.plane(h.hi, {-1, 0, 0});
    fm.plane(h.lo, {0, 1, 0});
    fm.plane(h.hi, {0, -1, 0});
  }
  fm.plane(h.lo, {0, 0, 1});   // floor
  fm.plane(h.hi, {0, 0, -1});  // ceiling
}

// The convex edges a hole makes where it leaves a solid: rims at the solid's
// horizontal faces, and vertical lines where its walls meet the solid's.
void Material::add_rims(int part, int hole, int solid) {
  const Part& pt = parts_[static_cast<std::size_t>(part)];
  const Shape& h = pt.holes[static_cast<std::size_t>(hole)];
  const Shape& s = pt.solids[static_cast<std::size_t>(solid)];
  const FeatureMaker fm{features_, part, hole, true};
  std::array<double, 2> levels{};
  int nl = 0;
  if (s.kind == ShapeKind::kBox || s.kind == ShapeKind::kCylinder) {
    levels[0] = s.lo.z;
    levels[1] = s.hi.z;
    nl = 2;
  } else if (s.kind == ShapeKind::kHalfSpace && std::fabs(std::fabs(s.normal.z) - 1.0) < 1e-12) {
    levels[0] = s.center.z;
    nl = 1;
  }
  for (int i = 0; i < nl; ++i) {
    const double z = levels[static_cast<std::size_t>(i)];
    if (!(z > h.lo.z && z < h.hi.z)) continue;
    if (h.kind == ShapeKind::kCylinder) {
      Feature rim = fm.make(FeatureKind::kCircle);
      rim.p = Vec3{h.lo.x, h.lo.y, z};
      rim.r = h.radius;
      features_.push_back(rim);
    } else {
      const std::array<Vec3, 4> c{Vec3{h.lo.x, h.lo.y, z}, Vec3{h.hi.x, h.lo.y, z},
                                  Vec3{h.hi.x, h.hi.y, z}, Vec3{h.lo.x, h.hi.y, z}};
      for (std::size_t k = 0; k < 4; ++k) {
        Feature e = fm.make(FeatureKind::kSegment);
        e.p = c[k];
        e.q = c[(k + 1) % 4];
        features_.push_back(e);
      }
    }
  }
  std::vector<Curve2> sc, hc;
  vertical_curves(s, sc);
  vertical_curves(h, hc);
  double slo = 0.0, shi = 0.0;
  z_range(s, slo, shi);
  const double zlo = std::max(slo, h.lo.z), zhi = std::min(shi, h.hi.z);
  if (!(zlo < zhi)) return;
  for (const Curve2& a : sc) {
    for (const Curve2& b : hc) {
      double xs[2], ys[2];
      const int n = intersect2(a, b, xs, ys);
      for (int k = 0; k < n; ++k) {
        Feature e = fm.make(FeatureKind::kSegment);
        e.p = Vec3{xs[k], ys[k], zlo};
        e.q = Vec3{xs[k], ys[k], zhi};
        features_.push_back(e);
      }
    }
  }
}

bool Material::valid(const Feature& f, Vec3 q) const noexcept {
  const Part& pt = parts_[static_cast<std::size_t>(f.part)];
  if (!f.of_hole) {
    const Shape& s = pt.solids[static_cast<std::size_t>(f.owner)];
    if (std::fabs(signed_distance(s, q)) > kOnSurface) return false;
    for (const Shape& h : pt.holes) {
      if (signed_distance(h, q) < -kOnSurface) return false;
    }
    return true;
  }
  const Shape& h = pt.holes[static_cast<std::size_t>(f.owner)];
  if (std::fabs(signed_distance(h, q)) > kOnSurface) return false;
  bool in_solid = false;
  for (const Shape& s : pt.solids) {
    if (signed_distance(s, q) <= kOnSurface) {
      in_solid = true;
      break;
    }
  }
  if (!in_solid) return false;
  for (std::size_t j = 0; j < pt.holes.size(); ++j) {
    if (static_cast<int>(j) != f.owner && signed_distance(pt.holes[j], q) < -kOnSurface)
      return false;
  }
  return true;
}

bool Material::contact_with(const Feature& f, Vec3 a, Vec3 b, double radius,
                            Contact& c) const noexcept {
  const Vec3 w = b - a;
  auto accept = [&](double t, Vec3 point) {
    const Vec3 centre = lerp(a, b, t);
    if (!valid(f, point)) return false;
    Vec3 n = centre - point;
    const double l = length(n);
    n = l > 0.0 ? n * (1.0 / l) : Vec3{0, 0, 1};
    c.t = t;
    c.point = point;
    c.normal = n;
    c.part = f.part;
    return true;
  };
  switch (f.kind) {
    case FeatureKind::kPlane: {
      double t = 0.0;
      if (!plane_root(f.p, f.n, a, b, radius, t)) return false;
      return accept(t, lerp(a, b, t) - f.n * radius);
    }
    case FeatureKind::kOuterWall:
    case FeatureKind::kInnerWall: {
      const bool outer = f.kind == FeatureKind::kOuterWall;
      const double reach = outer ? f.r + radius : f.r - radius;
      if (reach <= 0.0) return false;
      const double ux = a.x - f.p.x, uy = a.y - f.p.y;
      double t1 = 0.0, t2 = 0.0;
      const double qa = w.x * w.x + w.y * w.y;
      if (qa == 0.0) return false;
      if (!quadratic(qa, 2.0 * (ux * w.x + uy * w.y), ux * ux + uy * uy - reach * reach, t1, t2)) {
        return false;
      }
      const double t = outer ? t1 : t2;
      if (!in_unit(t)) return false;
      const Vec3 centre = lerp(a, b, t);
      const double k = f.r / reach;
      const Vec3 point{f.p.x + (centre.x - f.p.x) * k, f.p.y + (centre.y - f.p.y) * k, centre.z};
      return accept(t, point);
    }
    case FeatureKind::kSegment: {
      const Vec3 e0 = f.q - f.p;
      const double len = length(e0);
      if (len == 0.0) return false;
      const Vec3 e = e0 * (1.0 / len);
      double best = kInf;
      Contact bc;
      double t = 0.0, s = 0.0;
      if (line_root(f.p, e, len, a, b, radius, t, s) && accept(t, f.p + e * s)) {
        best = t;
        bc = c;
      }
      for (Vec3 end : {f.p, f.q}) {
        if (point_root(end, a, b, radius, t) && t < best && accept(t, end)) {
          best = t;
          bc = c;
        }
      }
      if (best == kInf) return false;
      c = bc;
      return true;
    }
    case FeatureKind::kBall: {
      double t = 0.0;
      if (!point_root(f.p, a, b, f.r + radius, t)) return false;
      const Vec3 centre = lerp(a, b, t);
      return accept(t, f.p + (centre - f.p) * (f.r / (f.r + radius)));
    }
    case FeatureKind::kCircle: {
      // (|m|^2 + R^2 - rho^2)^2 - 4 R^2 |m_xy|^2 = 0: the torus about the rim.
      const Vec3 m = a - f.p;
      const double A = dot(w, w), B = 2.0 * dot(m, w), C = dot(m, m);
      const double qa = w.x * w.x + w.y * w.y, qb = 2.0 * (m.x * w.x + m.y * w.y),
                   qc = m.x * m.x + m.y * m.y;
      const double K = f.r * f.r - radius * radius, R4 = 4.0 * f.r * f.r;
      const double CK = C + K;
      const double poly[5] = {CK * CK - R4 * qc, 2.0 * B * CK - R4 * qb,
                              B * B + 2.0 * A * CK - R4 * qa, 2.0 * A * B, A * A};
      double roots[4];
      const int n = polynomial_roots(poly, 4, 0.0, 1.0, roots);
      for (int i = 0; i < n; ++i) {
        const double t = roots[i];
        const double before = i == 0 ? 0.5 * t : 0.5 * (roots[i - 1] + t);
        const double after = i + 1 < n ? 0.5 * (t + roots[i + 1]) : 0.5 * (t + 1.0);
        if (!(horner(poly, 4, before) > 0.0 || t == 0.0) || !(horner(poly, 4, after) < 0.0))
          continue;
        const Vec3 centre = lerp(a, b, t);
        const double dx = centre.x - f.p.x, dy = centre.y - f.p.y;
        const double dxy = hypot2(dx, dy);
        const Vec3 point = dxy > 0.0 ? Vec3{f.p.x + dx * f.r / dxy, f.p.y + dy * f.r / dxy, f.p.z}
                                     : Vec3{f.p.x + f.r, f.p.y, f.p.z};
        if (std::fabs(length(centre - point) - radius) > 1e-6 * (1.0 + radius)) continue;
        if (accept(t, point)) return true;
      }
      return false;
    }
  }
  return false;
}

void Material::set_turns(const double* before, const double* after) noexcept {
  for (const std::size_t p : turning_) {
    const Rotary& r = parts_[p].rotary;
    start_[p] = r.at(before[r.axis]);
    parts_[p].place = r.at(after[r.axis]);
  }
}

bool Material::first_contact(Vec3 a, Vec3 b, double radius, Contact& out,
                             bool backward) const noexcept {
  bool found = false;
  Contact c;
  // A part on a turning table stands at start_ when the period starts and
  // at place when it ends: each end of the ball's segment is moved into the
  // part's frame at its own instant.
  const auto local = [&](std::size_t p, Vec3& la, Vec3& lb) {
    const Placement& end = parts_[p].place;
    const Placement& start = start_[p];
    la = (backward ? end : start).to_local(a);
    lb = (backward ? start : end).to_local(b);
  };
  for (std::size_t p = 0; p < parts_.size(); ++p) {
    const PartBounds& pb = bounds_[p];
    if (pb.begin == pb.end) continue;
    // Each feature in its part's frame: a and b are moved there, the contact
    // is moved back. A part whose box the swept ball cannot reach is passed.
    const Placement& pl = parts_[p].place;
    Vec3 la, lb;
    local(p, la, lb);
    const Vec3 r{radius, radius, radius};
    const Vec3 lo{std::fmin(la.x, lb.x), std::fmin(la.y, lb.y), std::fmin(la.z, lb.z)};
    const Vec3 hi{std::fmax(la.x, lb.x), std::fmax(la.y, lb.y), std::fmax(la.z, lb.z)};
    if (beyond(pb, lo - r, hi + r)) continue;
    for (std::size_t i = pb.begin; i < pb.end; ++i) {
      const Feature& f = features_[i];
      if (contact_with(f, la, lb, radius, c) && (!found || c.t < out.t)) {
        out = c;
        out.point = pl.to_machine(c.point);
        out.normal = pl.turn(c.normal);
        found = true;
      }
    }
  }
  for (std::size_t p = 0; p < parts_.size(); ++p) {
    const Part& part = parts_[p];
    if (part.meshes.empty()) continue;
    Vec3 la, lb;
    local(p, la, lb);
    for (const auto& mesh : part.meshes) {
      double t = 0.0;
      Vec3 point, normal;
      if (mesh->first_contact(la, lb, radius, t, point, normal) && (!found || t < out.t)) {
        out =
            Contact{t, part.place.to_machine(point), part.place.turn(normal), static_cast<int>(p)};
        found = true;
      }
    }
  }
  return found;
}

double Material::feature_distance(const Feature& f, Vec3 p, Vec3& closest) const noexcept {
  switch (f.kind) {
    case FeatureKind::kPlane: {
      const double s = dot(p - f.p, f.n);
      if (s < 0.0) return kInf;
      closest = p - f.n * s;
      return s;
    }
    case FeatureKind::kOuterWall:
    case FeatureKind::kInnerWall: {
      const double dx = p.x - f.p.x, dy = p.y - f.p.y;
      const double dxy = hypot2(dx, dy);
      const bool outer = f.kind == FeatureKind::kOuterWall;
      if (outer ? dxy < f.r : dxy > f.r) return kInf;
      closest = dxy > 0.0 ? Vec3{f.p.x + dx * f.r / dxy, f.p.y + dy * f.r / dxy, p.z}
                          : Vec3{f.p.x + f.r, f.p.y, p.z};
      return std::fabs(dxy - f.r);
    }
    case FeatureKind::kSegment: {
      const Vec3 e = f.q - f.p;
      const double ee = dot(e, e);
      const double s = ee > 0.0 ? std::clamp(dot(p - f.p, e) / ee, 0.0, 1.0) : 0.0;
      closest = f.p + e * s;
      return length(p - closest);
    }
    case FeatureKind::kBall: {
      const Vec3 d = p - f.p;
      const double l = length(d);
      if (l < f.r) return kInf;
      closest = l > 0.0 ? f.p + d * (f.r / l) : f.p;
      return l - f.r;
    }
    case FeatureKind::kCircle: {
      const double dx = p.x - f.p.x, dy = p.y - f.p.y;
      const double dxy = hypot2(dx, dy);
      closest = dxy > 0.0 ? Vec3{f.p.x + dx * f.r / dxy, f.p.y + dy * f.r / dxy, f.p.z}
                          : Vec3{f.p.x + f.r, f.p.y, f.p.z};
      return length(p - closest);
    }
  }
  return kInf;
}

double Material::part_sdf(const Part& part, Vec3 p) const noexcept {
  double solid = kInf;
  for (const Shape& s : part.solids) solid = std::min(solid, signed_distance(s, p));
  double hole = kInf;
  for (const Shape& h : part.holes) hole = std::min(hole, signed_distance(h, p));
  return std::max(solid, -hole);
}

double Material::distance(Vec3 p, double cap) const noexcept {
  double best = cap;
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const Part& part = parts_[i];
    const Vec3 q = part.place.to_local(p);
    // Inside a solid only within the box that holds them.
    if (!part.solids.empty() && !beyond(bounds_[i], q, q) && part_sdf(part, q) < 0.0) return 0.0;
    for (const auto& mesh : part.meshes) {
      if (mesh->inside(q)) return 0.0;
      best = std::min(best, mesh->surface_distance(q, best));
    }
  }
  Vec3 q;
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const PartBounds& pb = bounds_[i];
    if (pb.begin == pb.end) continue;
    const Vec3 lp = parts_[i].place.to_local(p);
    // Nothing of the part is nearer than `best` when its box, grown by best,
    // does not hold the point.
    if (best < kInf && beyond(pb, lp - Vec3{best, best, best}, lp + Vec3{best, best, best})) {
      continue;
    }
    for (std::size_t fi = pb.begin; fi < pb.end; ++fi) {
      const Feature& f = features_[fi];
      const double d = feature_distance(f, lp, q);
      if (d < best && valid(f, q)) best = d;
    }
  }
  return best;
}

double Material::clearance(Vec3 p) const noexcept {
  if (turns()) return 0.0;
  double best = kInf;
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const Part& part = parts_[i];
    const PartBounds& pb = bounds_[i];
    const Vec3 q = part.place.to_local(p);
    if (pb.begin != pb.end || !part.solids.empty()) {
      if (!pb.bounded) return 0.0;
      best = std::min(best, box_distance(pb.lo, pb.hi, q));
    }
    for (const auto& mesh : part.meshes) {
      best = std::min(best, box_distance(mesh->bounds().lo, mesh->bounds().hi, q));
    }
  }
  return best;
}

double Material::depth(Vec3 p) const noexcept {
  double d = 0.0;
  for (const Part& part : parts_) d = std::max(d, part_depth(part, part.place.to_local(p)));
  return d;
}

// How deep a point of the part's frame is in the part (0 outside).
double Material::part_depth(const Part& part, Vec3 q) const noexcept {
  double d = part.solids.empty() ? 0.0 : std::max(0.0, -part_sdf(part, q));
  for (const auto& mesh : part.meshes) {
    if (mesh->inside(q)) d = std::max(d, mesh->surface_distance(q));
  }
  return d;
}

// A vertical column against a part tilted about X or Y: in the part's frame
// the column leans, and no closed form here solves a leaning cylinder against
// the features. Its volume is sampled instead: rings of points (centre, half
// and full radius, 16 round) at most 0.25 mm apart along the axis, over the
// length that the part's box can hold. Crash detection, not a latch: a
// contact between two samples is found a little late, by at most
// r (1 - cos(pi / 16)) = 0.019 r across and 0.25 mm along the axis.
bool Material::leaning_column_hits(std::size_t p, const Column& world, double tol) const noexcept {
  const Part& part = parts_[p];
  const PartBounds& pb = bounds_[p];
  const Placement& pl = part.place;
  const double h = world.top - world.bottom;
  // The part's box (solids and meshes) in machine coordinates limits the
  // length to sample; a half-space leaves it whole.
  double lo = 0.0, hi = h;
  if (pb.bounded) {
    double zmin = kInf, zmax = -kInf;
    const auto span = [&](Vec3 blo, Vec3 bhi) {
      if (blo.x > bhi.x) return;  // empty
      for (int c = 0; c < 8; ++c) {
        const Vec3 corner{(c & 1) != 0 ? bhi.x : blo.x, (c & 2) != 0 ? bhi.y : blo.y,
                          (c & 4) != 0 ? bhi.z : blo.z};
        const double z = pl.to_machine(corner).z;
        zmin = std::min(zmin, z);
        zmax = std::max(zmax, z);
      }
    };
    span(pb.lo, pb.hi);
    for (const auto& mesh : part.meshes) span(mesh->bounds().lo, mesh->bounds().hi);
    lo = std::max(lo, zmin - world.bottom);
    hi = std::min(hi, zmax - world.bottom);
    if (lo > hi) return false;
  }
  const int steps = std::max(1, static_cast<int>(std::ceil((hi - lo) / 0.25)));
  for (int i = 0; i <= steps; ++i) {
    const double z = world.bottom + lo + (hi - lo) * i / steps;
    if (part_depth(part, pl.to_local(Vec3{world.x, world.y, z})) > tol) return true;
    for (const double rr : {0.5 * world.radius, world.radius}) {
      for (int k = 0; k < 16; ++k) {
        const double a = 2.0 * kPi * k / 16.0;
        const Vec3 q{world.x + rr * std::cos(a), world.y + rr * std::sin(a), z};
        if (part_depth(part, pl.to_local(q)) > tol) return true;
      }
    }
  }
  return false;
}

int Material::column_hits(const Column& world, double tol) const noexcept {
  if (misses(all_, world)) return -1;  // most periods: nowhere near any part
  for (std::size_t p = 0; p < parts_.size(); ++p) {
    const Part& part = parts_[p];
    if (misses(world_[p], world)) continue;
    if (!part.place.upright()) {
      if (leaning_column_hits(p, world, tol)) return static_cast<int>(p);
      continue;
    }
    // A vertical column stays vertical in a frame turned about Z.
    const Vec3 foot = part.place.to_local(Vec3{world.x, world.y, world.bottom});
    const Column c{foot.x, foot.y, world.radius, foot.z, foot.z + (world.top - world.bottom)};
    for (const auto& mesh : part.meshes) {
      if (mesh->column_overlap(c) > tol) return static_cast<int>(p);
    }
    // A column beyond the box that holds the solids overlaps none of them.
    if (beyond(bounds_[p], Vec3{c.x - c.radius, c.y - c.radius, c.bottom},
               Vec3{c.x + c.radius, c.y + c.radius, c.top})) {
      continue;
    }
    for (const Shape& s : part.solids) {
      if (column_shape_overlap(c, s) <= tol) continue;
      bool clear = false;
      for (const Shape& h : part.holes) clear = clear || column_in_hole(c, s, h, tol);
      if (!clear) return static_cast<int>(p);
    }
  }
  return -1;
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
