// The Material against a moving ball: the first contact along its path
// (a hot path: every feature near the probe, every servo period).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "machine/geometry.hpp"
#include "machine/geometry_math.hpp"
#include "machine/mesh.hpp"

namespace skipnc::machine::geo {

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

// The contact of the ball at instant t touching the feature at `point`,
// if that point is on the part's surface (valid).
inline bool Material::accept_contact(const Feature& f, Vec3 a, Vec3 b, double t, Vec3 point,
                                     Contact& c) const noexcept {
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
}

// A vertical wall (cylinder or bore): the centre comes to the wall's radius
// plus (outer) or minus (inner) the ball's, in XY.
inline bool Material::wall_contact(const Feature& f, Vec3 a, Vec3 b, double radius,
                                   Contact& c) const noexcept {
  const Vec3 w = b - a;
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
  return accept_contact(f, a, b, t, point, c);
}

// A straight edge: its line between the ends, or one of its ends, first.
inline bool Material::segment_contact(const Feature& f, Vec3 a, Vec3 b, double radius,
                                      Contact& c) const noexcept {
  const Vec3 e0 = f.q - f.p;
  const double len = length(e0);
  if (len == 0.0) return false;
  const Vec3 e = e0 * (1.0 / len);
  double best = kInf;
  Contact bc;
  double t = 0.0, s = 0.0;
  if (line_root(f.p, e, len, a, b, radius, t, s) && accept_contact(f, a, b, t, f.p + e * s, c)) {
    best = t;
    bc = c;
  }
  for (Vec3 end : {f.p, f.q}) {
    if (point_root(end, a, b, radius, t) && t < best && accept_contact(f, a, b, t, end, c)) {
      best = t;
      bc = c;
    }
  }
  if (best == kInf) return false;
  c = bc;
  return true;
}

// A horizontal circular edge (a rim): the torus about it, a quartic in t.
inline bool Material::circle_contact(const Feature& f, Vec3 a, Vec3 b, double radius,
                                     Contact& c) const noexcept {
  // (|m|^2 + R^2 - rho^2)^2 - 4 R^2 |m_xy|^2 = 0: the torus about the rim.
  const Vec3 w = b - a;
  const Vec3 m = a - f.p;
  const double A = dot(w, w), B = 2.0 * dot(m, w), C = dot(m, m);
  const double qa = w.x * w.x + w.y * w.y, qb = 2.0 * (m.x * w.x + m.y * w.y),
               qc = m.x * m.x + m.y * m.y;
  const double K = f.r * f.r - radius * radius, R4 = 4.0 * f.r * f.r;
  const double CK = C + K;
  const double poly[5] = {CK * CK - R4 * qc, 2.0 * B * CK - R4 * qb, B * B + 2.0 * A * CK - R4 * qa,
                          2.0 * A * B, A * A};
  double roots[4];
  const int n = polynomial_roots(poly, 4, 0.0, 1.0, roots);
  for (int i = 0; i < n; ++i) {
    const double t = roots[i];
    const double before = i == 0 ? 0.5 * t : 0.5 * (roots[i - 1] + t);
    const double after = i + 1 < n ? 0.5 * (t + roots[i + 1]) : 0.5 * (t + 1.0);
    if (!(horner(poly, 4, before) > 0.0 || t == 0.0) || !(horner(poly, 4, after) < 0.0)) continue;
    const Vec3 centre = lerp(a, b, t);
    const double dx = centre.x - f.p.x, dy = centre.y - f.p.y;
    const double dxy = hypot2(dx, dy);
    const Vec3 point = dxy > 0.0 ? Vec3{f.p.x + dx * f.r / dxy, f.p.y + dy * f.r / dxy, f.p.z}
                                 : Vec3{f.p.x + f.r, f.p.y, f.p.z};
    if (std::fabs(length(centre - point) - radius) > 1e-6 * (1.0 + radius)) continue;
    if (accept_contact(f, a, b, t, point, c)) return true;
  }
  return false;
}

bool Material::contact_with(const Feature& f, Vec3 a, Vec3 b, double radius,
                            Contact& c) const noexcept {
  switch (f.kind) {
    case FeatureKind::kPlane: {
      double t = 0.0;
      if (!plane_root(f.p, f.n, a, b, radius, t)) return false;
      return accept_contact(f, a, b, t, lerp(a, b, t) - f.n * radius, c);
    }
    case FeatureKind::kOuterWall:
    case FeatureKind::kInnerWall:
      return wall_contact(f, a, b, radius, c);
    case FeatureKind::kSegment:
      return segment_contact(f, a, b, radius, c);
    case FeatureKind::kBall: {
      double t = 0.0;
      if (!point_root(f.p, a, b, f.r + radius, t)) return false;
      const Vec3 centre = lerp(a, b, t);
      return accept_contact(f, a, b, t, f.p + (centre - f.p) * (f.r / (f.r + radius)), c);
    }
    case FeatureKind::kCircle:
      return circle_contact(f, a, b, radius, c);
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

}  // namespace skipnc::machine::geo
