// Property: cutter radius compensation keeps the tool at the radius from the
// part. A random convex polygon (5 to 9 corners on a circle 40 to 120 mm
// across; the corners from sharp to nearly straight) is cut round its outside with G41 and a
// random D radius (0.5 to 12 mm), clockwise, so the tool is on the left of
// its travel and every corner is an outer corner: obtuse ones end at the
// intersection of the offset sides, acute ones go round by the two extended
// vectors. On the tool centre path between the end of the start-up and the
// start of the cancel:
//   - no point is nearer the polygon than the radius (no gouge), and
//   - each side's midpoint, moved out by the radius, is on the path (the
//     side is cut at the radius along its length).
// Tolerance: 1e-6 mm (the intersections are solved in double precision from
// coordinates written with 4 decimals).
//
// Seed and count: RC_PARAMS="seed=7 max_success=10000".
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "property/program_gen.hpp"

namespace skipnc::property {
namespace {

constexpr double kTol = 1e-6;

struct P {
  double x, y;
};

double seg_dist(P p, P a, P b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

double poly_dist(P p, const std::vector<P>& poly) {
  double d = 1e300;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    d = std::min(d, seg_dist(p, poly[i], poly[(i + 1) % poly.size()]));
  }
  return d;
}

RC_GTEST_PROP(CutterCompProperty, OutsideOfAConvexPolygonStaysAtTheRadius, ()) {
  const int n = *rc::gen::inRange(5, 10);
  const double size = gen_real(20.0, 60.0);
  const double r = std::round(gen_real(0.5, 12.0) * 1000.0) / 1000.0;
  // Corners on a circle, clockwise, at random gaps of 10 to 100 parts of the
  // turn (no two corners nearer than 4 degrees).
  std::vector<double> gaps;
  double total = 0.0;
  for (int i = 0; i < n; ++i) {
    gaps.push_back(*rc::gen::inRange(10, 101));
    total += gaps.back();
  }
  std::vector<double> ang;
  double turn = gen_real(0.0, 360.0);
  for (double g : gaps) {
    ang.push_back(turn);
    turn -= g / total * 360.0;
  }
  std::vector<P> poly;
  for (double deg : ang) {
    const double t = deg * std::numbers::pi / 180.0;
    poly.push_back({std::round(size * std::cos(t) * 10000.0) / 10000.0,
                    std::round(size * std::sin(t) * 10000.0) / 10000.0});
  }
  // Start-up from outside, along the line from the centre through corner 0.
  std::string prog = "G21 G90 G17 G40 G49 G54 G94\nG10 L12 P1 R" + num(r) + "\n";
  prog += "G0 X" + num(poly[0].x * 3.0, 4) + " Y" + num(poly[0].y * 3.0, 4) + " Z0\n";
  prog += "G41 D1 X" + num(poly[0].x, 4) + " Y" + num(poly[0].y, 4) + "\n";
  prog += "G1 F500.\n";
  for (int i = 1; i <= n; ++i) {
    const P& p = poly[static_cast<std::size_t>(i % n)];
    prog += "X" + num(p.x, 4) + " Y" + num(p.y, 4) + "\n";
  }
  prog += "G40 X" + num(poly[0].x * 3.0, 4) + " Y" + num(poly[0].y * 3.0, 4) + "\nM30\n";
  const Machine m;
  const CanonRun run = canon_of(m, prog);
  RC_ASSERT(!run.alarm);
  // The tool centre path of the contour: from the end of the start-up block
  // (line 4) to the start of the cancel (line 6 + n).
  const auto cancel_line = static_cast<std::uint32_t>(6 + n);
  std::vector<P> path;
  for (const auto& c : run.cmds) {
    const AxisVec* t = nullptr;
    if (const auto* r0 = std::get_if<canon::Rapid>(&c.cmd)) t = &r0->target;
    if (const auto* f = std::get_if<canon::Feed>(&c.cmd)) t = &f->target;
    if (t == nullptr || c.line < 4 || c.line >= cancel_line) continue;
    path.push_back({(*t)[0], (*t)[1]});
  }
  RC_ASSERT(path.size() >= static_cast<std::size_t>(n));
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    for (int k = 0; k <= 20; ++k) {
      const double u = k / 20.0;
      const P q{path[i].x + u * (path[i + 1].x - path[i].x),
                path[i].y + u * (path[i + 1].y - path[i].y)};
      RC_ASSERT(poly_dist(q, poly) >= r - kTol);
    }
  }
  for (int i = 0; i < n; ++i) {
    const P a = poly[static_cast<std::size_t>(i)];
    const P b = poly[static_cast<std::size_t>((i + 1) % n)];
    const double l = std::hypot(b.x - a.x, b.y - a.y);
    // Left of the travel a -> b, the outside of a clockwise polygon.
    const P mid{(a.x + b.x) / 2.0 - (b.y - a.y) / l * r, (a.y + b.y) / 2.0 + (b.x - a.x) / l * r};
    double d = 1e300;
    for (std::size_t j = 0; j + 1 < path.size(); ++j)
      d = std::min(d, seg_dist(mid, path[j], path[j + 1]));
    RC_ASSERT(d <= kTol);
  }
}

}  // namespace
}  // namespace skipnc::property
