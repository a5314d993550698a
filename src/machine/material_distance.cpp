// The Material's distances (to the nearest surface, the depth of a point)
// and the tool's column against the parts (every servo period).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "machine/geometry.hpp"
#include "machine/geometry_math.hpp"
#include "machine/mesh.hpp"

namespace skipnc::machine::geo {

namespace {

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

}  // namespace

// Does the column miss the box?
bool Material::misses(const WorldBox& w, const Column& c) noexcept {
  return w.valid &&
         (c.x + c.radius < w.lo.x || c.x - c.radius > w.hi.x || c.y + c.radius < w.lo.y ||
          c.y - c.radius > w.hi.y || c.top < w.lo.z || c.bottom > w.hi.z);
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

}  // namespace skipnc::machine::geo
