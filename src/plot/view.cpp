#include "plot/view.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skipnc::plot {

Frame fit_view(const ViewDef& v, const Box3& e, double x, double y, double w, double h,
               double margin_px) {
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (int c = 0; c < 8; ++c) {
    const Vec3 p{(c & 1) != 0 ? e.hi.x : e.lo.x, (c & 2) != 0 ? e.hi.y : e.lo.y,
                 (c & 4) != 0 ? e.hi.z : e.lo.z};
    const double pu = dot(p, v.u), pv = dot(p, v.v);
    u0 = std::min(u0, pu);
    u1 = std::max(u1, pu);
    v0 = std::min(v0, pv);
    v1 = std::max(v1, pv);
  }
  const double iw = std::max(1.0, w - 2 * margin_px), ih = std::max(1.0, h - 2 * margin_px);
  const double su = std::max(u1 - u0, 1e-6), sv = std::max(v1 - v0, 1e-6);
  const double mm_per_px = std::max(su / iw, sv / ih);
  const double cu = 0.5 * (u0 + u1), cv = 0.5 * (v0 + v1);
  Frame f;
  f.x = x;
  f.y = y;
  f.w = w;
  f.h = h;
  f.u0 = cu - 0.5 * w * mm_per_px;
  f.u1 = cu + 0.5 * w * mm_per_px;
  f.v0 = cv - 0.5 * h * mm_per_px;
  f.v1 = cv + 0.5 * h * mm_per_px;
  return f;
}

double nice_step(double span, int target) {
  if (!(span > 0.0) || !std::isfinite(span)) return 1.0;
  const double raw = span / std::max(1, target);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double m = raw / p;
  return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * p;
}

double next_nice_step(double step) {
  if (!(step > 0.0) || !std::isfinite(step)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  const double m = step / p;
  return (m < 1.5 ? 2.0 : m < 3.5 ? 5.0 : 10.0) * p;
}

namespace {

double seg_dist(const Pt& p, const Pt& a, const Pt& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = a.x + t * dx - p.x, ey = a.y + t * dy - p.y;
  return std::sqrt(ex * ex + ey * ey);
}

}  // namespace

std::vector<Pt> simplify(const std::vector<Pt>& pts, double tol) {
  if (pts.size() < 3) return pts;
  std::vector<char> keep(pts.size(), 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, pts.size() - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double worst = -1.0;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = seg_dist(pts[i], pts[a], pts[b]);
      if (d > worst) {
        worst = d;
        at = i;
      }
    }
    if (worst > tol) {
      keep[at] = 1;
      stack.emplace_back(a, at);
      stack.emplace_back(at, b);
    }
  }
  std::vector<Pt> out;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (keep[i] != 0) out.push_back(pts[i]);
  }
  return out;
}

std::optional<std::pair<Pt, Pt>> clip_segment(Pt a, Pt b, const Box2& r) {
  double t0 = 0.0, t1 = 1.0;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - r.x, r.x + r.w - a.x, a.y - r.y, r.y + r.h - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return std::nullopt;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) return std::nullopt;
  }
  return std::pair{Pt{a.x + t0 * dx, a.y + t0 * dy}, Pt{a.x + t1 * dx, a.y + t1 * dy}};
}

constexpr double kCell = 6.0;

LabelPlacer::LabelPlacer(Box2 clip)
    : clip_(clip),
      cols_(std::max(1, static_cast<int>(std::ceil(clip.w / kCell)))),
      rows_(std::max(1, static_cast<int>(std::ceil(clip.h / kCell)))),
      grid_(static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_), 0) {}

void LabelPlacer::line(Pt a, Pt b) {
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const int n = static_cast<int>(std::min(2000.0, std::ceil(len / (kCell / 2))));
  for (int i = 0; i <= n; ++i) {
    const double f = n > 0 ? static_cast<double>(i) / n : 0.0;
    const double cx = std::floor((a.x + (b.x - a.x) * f - clip_.x) / kCell);
    const double cy = std::floor((a.y + (b.y - a.y) * f - clip_.y) / kCell);
    if (cx < 0 || cy < 0 || cx >= cols_ || cy >= rows_) continue;
    grid_[static_cast<std::size_t>(cy) * static_cast<std::size_t>(cols_) +
          static_cast<std::size_t>(cx)] = 1;
  }
}

bool LabelPlacer::on_line(const Box2& b) const {
  const int x0 = std::max(0, static_cast<int>(std::floor((b.x - clip_.x) / kCell)));
  const int x1 = std::min(cols_ - 1, static_cast<int>(std::floor((b.x + b.w - clip_.x) / kCell)));
  const int y0 = std::max(0, static_cast<int>(std::floor((b.y - clip_.y) / kCell)));
  const int y1 = std::min(rows_ - 1, static_cast<int>(std::floor((b.y + b.h - clip_.y) / kCell)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (grid_[static_cast<std::size_t>(y) * static_cast<std::size_t>(cols_) +
                static_cast<std::size_t>(x)] != 0) {
        return true;
      }
    }
  }
  return false;
}

Box2 LabelPlacer::place(double ax, double ay, double w, double h, bool& leader) {
  struct Cand {
    double dx, dy;
  };
  // Beside the anchor first, then on rings further out (with a leader line).
  std::vector<Cand> cands{{8, -h / 2}, {-8 - w, -h / 2}, {6, -6 - h},
                          {6, 6},      {-6 - w, -6 - h}, {-6 - w, 6}};
  const std::size_t near = cands.size();
  for (double r : {26.0, 42.0, 58.0, 76.0, 96.0}) {
    for (int k = 0; k < 12; ++k) {
      const double a = k * std::numbers::pi / 6.0;
      const double cx = ax + r * std::cos(a), cy = ay - r * std::sin(a);
      cands.push_back({cx - ax + (std::cos(a) >= 0 ? 0.0 : -w), cy - ay - h / 2});
    }
  }
  auto clamp_box = [&](Box2 b) {
    b.x = std::clamp(b.x, clip_.x + 2, std::max(clip_.x + 2, clip_.x + clip_.w - b.w - 2));
    b.y = std::clamp(b.y, clip_.y + 2, std::max(clip_.y + 2, clip_.y + clip_.h - b.h - 2));
    return b;
  };
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t i = 0; i < cands.size(); ++i) {
      const Box2 b = clamp_box(Box2{ax + cands[i].dx, ay + cands[i].dy, w, h});
      if (std::any_of(used_.begin(), used_.end(), [&](const Box2& u) { return u.overlaps(b); }))
        continue;
      if (pass == 0 && on_line(b)) continue;
      used_.push_back(b);
      leader = i >= near;
      return b;
    }
  }
  // Every place of the view on a grid of half a label's height, the one
  // nearest to the anchor; none free: no label (labels never stack).
  std::optional<Box2> best;
  double best_d = 0.0;
  const double step = std::max(4.0, h / 2);
  for (double y = clip_.y + 2; y + h <= clip_.y + clip_.h - 2; y += step) {
    for (double x = clip_.x + 2; x + w <= clip_.x + clip_.w - 2; x += step) {
      const Box2 b{x, y, w, h};
      if (std::any_of(used_.begin(), used_.end(), [&](const Box2& u) { return u.overlaps(b); }))
        continue;
      const double d = std::hypot(x + w / 2 - ax, y + h / 2 - ay);
      if (!best || d < best_d) {
        best = b;
        best_d = d;
      }
    }
  }
  leader = best.has_value();
  if (!best) return Box2{ax, ay, 0, 0};
  used_.push_back(*best);
  return *best;
}

}  // namespace skipnc::plot
