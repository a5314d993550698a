#include "machine/stock.hpp"

#include <algorithm>
#include <cmath>

namespace skipnc::machine::geo {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Cells per side: the fewest of at most `cell` mm (a side a hair over a
// whole number of cells, by rounding, does not get one more). A double: the
// scene checks the count before a grid is made, whatever the numbers.
double cells_on(double side, double cell) noexcept {
  return std::max(1.0, std::ceil(side / cell - 1e-9));
}

// The part [t0, t1] of [0, 1] in which a + t (b - a) lies in [lo, hi] on one
// axis; false when none.
bool clip(double a, double b, double lo, double hi, double& t0, double& t1) noexcept {
  const double w = b - a;
  if (w == 0.0) return a >= lo && a <= hi && t0 <= t1;
  double ta = (lo - a) / w, tb = (hi - a) / w;
  if (ta > tb) std::swap(ta, tb);
  t0 = std::max(t0, ta);
  t1 = std::min(t1, tb);
  return t0 <= t1;
}

}  // namespace

double Stock::cell_count(Vec3 lo, Vec3 hi, double cell) noexcept {
  return cells_on(hi.x - lo.x, cell) * cells_on(hi.y - lo.y, cell);
}

Stock::Stock(Vec3 lo, Vec3 hi, double cell)
    : lo_(lo),
      hi_(hi),
      nx_(static_cast<int>(std::min(cells_on(hi.x - lo.x, cell), 1e9))),
      ny_(static_cast<int>(std::min(cells_on(hi.y - lo.y, cell), 1e9))),
      dx_((hi.x - lo.x) / nx_),
      dy_((hi.y - lo.y) / ny_),
      tops_(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), hi.z) {}

void Stock::reset() noexcept {
  std::fill(tops_.begin(), tops_.end(), hi_.z);
}

bool Stock::span(double a, double b, bool on_y, int& first, int& last) const noexcept {
  const double lo = on_y ? lo_.y : lo_.x, hi = on_y ? hi_.y : hi_.x;
  const double d = on_y ? dy_ : dx_;
  const int n = on_y ? ny_ : nx_;
  if (!(b >= lo && a <= hi)) return false;
  const double fa = std::floor((std::max(a, lo) - lo) / d);
  const double fb = std::floor((std::min(b, hi) - lo) / d);
  first = std::clamp(static_cast<int>(fa) - 1, 0, n - 1);
  last = std::clamp(static_cast<int>(fb) + 1, 0, n - 1);
  return true;
}

double Stock::cut(Vec3 a, Vec3 b, double radius) noexcept {
  if (empty() || !(radius > 0.0)) return 0.0;
  int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
  if (!span(std::min(a.x, b.x) - radius, std::max(a.x, b.x) + radius, false, i0, i1) ||
      !span(std::min(a.y, b.y) - radius, std::max(a.y, b.y) + radius, true, j0, j1) ||
      std::min(a.z, b.z) >= hi_.z) {
    return 0.0;
  }
  const double wx = b.x - a.x, wy = b.y - a.y, wz = b.z - a.z;
  // |c - (a + s w)|^2 <= r^2 on the XY plane: A s^2 + B s + C <= 0.
  const double qa = wx * wx + wy * wy;
  double removed = 0.0;
  for (int j = j0; j <= j1; ++j) {
    const double cy = 0.5 * (y0(j) + y1(j));
    for (int i = i0; i <= i1; ++i) {
      const double cx = 0.5 * (x0(i) + x1(i));
      const double mx = a.x - cx, my = a.y - cy;
      const double qc = mx * mx + my * my - radius * radius;
      double s0 = 0.0, s1 = 1.0;
      if (qa > 0.0) {
        const double qb = 2.0 * (mx * wx + my * wy);
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc < 0.0) continue;
        const double root = std::sqrt(disc);
        s0 = std::max(0.0, (-qb - root) / (2.0 * qa));
        s1 = std::min(1.0, (-qb + root) / (2.0 * qa));
        if (s0 > s1) continue;
      } else if (qc > 0.0) {
        continue;
      }
      // Z is linear along the path: its lowest value while the cell is
      // under the tool is at one end of that stretch.
      const double z = std::max(lo_.z, std::min(a.z + wz * s0, a.z + wz * s1));
      double& top = top_at(i, j);
      if (z < top) {
        removed += (top - z) * (x1(i) - x0(i)) * (y1(j) - y0(j));
        top = z;
      }
    }
  }
  return removed;
}

double Stock::removed_volume() const noexcept {
  double v = 0.0;
  for (int j = 0; j < ny_; ++j) {
    for (int i = 0; i < nx_; ++i) v += (hi_.z - top(i, j)) * (x1(i) - x0(i)) * (y1(j) - y0(j));
  }
  return v;
}

bool Stock::first_contact(Vec3 a, Vec3 b, double radius, Contact& out) const noexcept {
  if (empty()) return false;
  // Only the stretch of the segment within the stock's box grown by the
  // radius can touch (a long ray, as the reach check casts, crosses a few
  // rows of cells, not the whole grid).
  double t0 = 0.0, t1 = 1.0;
  if (!clip(a.x, b.x, lo_.x - radius, hi_.x + radius, t0, t1) ||
      !clip(a.y, b.y, lo_.y - radius, hi_.y + radius, t0, t1) ||
      !clip(a.z, b.z, lo_.z - radius, hi_.z + radius, t0, t1)) {
    return false;
  }
  const Vec3 ca = lerp(a, b, t0), cb = lerp(a, b, t1);
  int j0 = 0, j1 = 0;
  if (!span(std::min(ca.y, cb.y) - radius, std::max(ca.y, cb.y) + radius, true, j0, j1)) {
    return false;
  }
  bool found = false;
  Contact c;
  for (int j = j0; j <= j1; ++j) {
    // The stretch whose ball reaches this row, and the cells it spans.
    double r0 = t0, r1 = t1;
    if (!clip(a.y, b.y, y0(j) - radius, y1(j) + radius, r0, r1)) continue;
    const Vec3 pa = lerp(a, b, r0), pb = lerp(a, b, r1);
    int i0 = 0, i1 = 0;
    if (!span(std::min(pa.x, pb.x) - radius, std::max(pa.x, pb.x) + radius, false, i0, i1)) {
      continue;
    }
    const double zlow = std::min(pa.z, pb.z) - radius;
    for (int i = i0; i <= i1; ++i) {
      const double top = this->top(i, j);
      if (!(top > lo_.z) || zlow > top) continue;
      if (box_first_contact({x0(i), y0(j), lo_.z}, {x1(i), y1(j), top}, a, b, radius, c) &&
          (!found || c.t < out.t)) {
        out = c;
        found = true;
      }
    }
  }
  return found;
}

double Stock::clearance(Vec3 p) const noexcept {
  return empty() ? kInf : box_distance(lo_, hi_, p);
}

double Stock::distance(Vec3 p, double cap) const noexcept {
  if (empty()) return cap;
  const double bound = box_distance(lo_, hi_, p);
  if (bound >= cap) return cap;
  // Every cell outside a window of half-width w about p is farther than w:
  // search a window, and widen it once to the nearest distance found when
  // that is more than w.
  double w = std::isfinite(cap) ? cap : bound + std::max(dx_, dy_);
  for (;;) {
    double best = kInf;
    int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
    if (span(p.x - w, p.x + w, false, i0, i1) && span(p.y - w, p.y + w, true, j0, j1)) {
      for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
          const double top = this->top(i, j);
          if (!(top > lo_.z)) continue;
          best = std::min(best, box_distance({x0(i), y0(j), lo_.z}, {x1(i), y1(j), top}, p));
        }
      }
    }
    const bool whole = p.x - w <= lo_.x && p.x + w >= hi_.x && p.y - w <= lo_.y && p.y + w >= hi_.y;
    if (best <= w || whole || std::isfinite(cap)) return std::min(best, cap);
    w = std::isfinite(best) ? best : 2.0 * w;
  }
}

double Stock::depth(Vec3 p) const noexcept {
  if (empty() || p.x <= lo_.x || p.x >= hi_.x || p.y <= lo_.y || p.y >= hi_.y || p.z <= lo_.z) {
    return 0.0;
  }
  const int i = std::clamp(static_cast<int>((p.x - lo_.x) / dx_), 0, nx_ - 1);
  const int j = std::clamp(static_cast<int>((p.y - lo_.y) / dy_), 0, ny_ - 1);
  const double top = this->top(i, j);
  if (p.z >= top) return 0.0;
  // To the cell's top, the bottom or the box's sides: an estimate next to
  // lower cells, as Material::depth is next to holes.
  return std::min({top - p.z, p.z - lo_.z, p.x - lo_.x, hi_.x - p.x, p.y - lo_.y, hi_.y - p.y});
}

bool Stock::column_hits(const Column& c, double tol) const noexcept {
  if (empty() || c.bottom >= hi_.z - tol || c.top <= lo_.z + tol) return false;
  int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
  if (!span(c.x - c.radius, c.x + c.radius, false, i0, i1) ||
      !span(c.y - c.radius, c.y + c.radius, true, j0, j1)) {
    return false;
  }
  for (int j = j0; j <= j1; ++j) {
    const double dy = 0.5 * (y0(j) + y1(j)) - c.y;
    for (int i = i0; i <= i1; ++i) {
      const double dx = 0.5 * (x0(i) + x1(i)) - c.x;
      const double radial = c.radius - std::sqrt(dx * dx + dy * dy);
      const double vertical = std::min(c.top, top(i, j)) - std::max(c.bottom, lo_.z);
      if (radial > tol && vertical > tol) return true;
    }
  }
  return false;
}

bool Solids::first_contact(Vec3 a, Vec3 b, double radius, Contact& out,
                           bool backward) const noexcept {
  bool found = material_->first_contact(a, b, radius, out, backward);
  Contact c;
  if (stock_ != nullptr && stock_->first_contact(a, b, radius, c) && (!found || c.t < out.t)) {
    out = c;
    found = true;
  }
  return found;
}

double Solids::distance(Vec3 p, double cap) const noexcept {
  const double d = material_->distance(p, cap);
  return stock_ != nullptr && d > 0.0 ? stock_->distance(p, d) : d;
}

double Solids::clearance(Vec3 p) const noexcept {
  const double d = material_->clearance(p);
  return stock_ != nullptr ? std::min(d, stock_->clearance(p)) : d;
}

double Solids::depth(Vec3 p) const noexcept {
  const double d = material_->depth(p);
  return stock_ != nullptr ? std::max(d, stock_->depth(p)) : d;
}

}  // namespace skipnc::machine::geo
