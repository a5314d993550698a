// The Material: the features (faces, walls, edges, rims) of the parts' solids
// and holes, made once from the scene's parts, and the parts' bounds.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "machine/geometry.hpp"
#include "machine/geometry_math.hpp"
#include "machine/mesh.hpp"

namespace skipnc::machine::geo {

namespace {

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

}  // namespace

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

}  // namespace skipnc::machine::geo
