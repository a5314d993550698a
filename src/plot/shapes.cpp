// The scene as generic shapes (polygons and polylines in machine
// coordinates) that every renderer draws without knowing what they are:
// trigger and stop planes, parts (boxes, vertical cylinders, spheres,
// half-spaces; bores and pockets as dashed outlines), the stock (its box,
// and after a run its deepest cut) and the tool setter.
//
// To draw a new kind of scene object (a part, a gauge, a stylus), add one
// function here that turns it into shapes with an Ink of its own (add the
// Ink and its style to the table in model.cpp) and call it from
// scene_shapes(). Nothing in svg.cpp or the page's script changes.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "machine/geometry.hpp"
#include "plot/model.hpp"

namespace skipnc::plot {
namespace {

double dot3(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// Which of x/y/z (0..2) is machine axis `axis`; -1 when it is none of them.
int slot_of(const std::array<int, 3>& xyz, int axis) {
  for (int k = 0; k < 3; ++k) {
    if (xyz[static_cast<std::size_t>(k)] == axis) return k;
  }
  return -1;
}

struct Frame3 {
  Box3 box;            // the extent with a margin
  double hatch = 1.0;  // length of hatch strokes, mm
};

Frame3 frame_of(const Box3& extent) {
  double span = 0.0;
  for (int k = 0; k < 3; ++k) span = std::max(span, extent.hi[k] - extent.lo[k]);
  const double pad = 0.2 * span;
  Frame3 f;
  for (int k = 0; k < 3; ++k) {
    f.box.lo[k] = extent.lo[k] - pad;
    f.box.hi[k] = extent.hi[k] + pad;
  }
  f.hatch = 0.03 * span;
  return f;
}

// A rectangle in the plane {p[k] = at}, over the frame's other two sides.
Shape plane(int k, double at, const Frame3& f, Ink ink, std::string label, std::string note) {
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  Shape s;
  s.kind = Shape::Kind::kPolygon;
  s.ink = ink;
  s.normal_axis = k;
  s.label = std::move(label);
  s.note = std::move(note);
  for (const auto& [ua, ub] :
       {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}}) {
    Vec3 p;
    p[k] = at;
    p[a] = ua != 0 ? f.box.hi[a] : f.box.lo[a];
    p[b] = ub != 0 ? f.box.hi[b] : f.box.lo[b];
    s.pts.push_back(p);
  }
  return s;
}

// Short strokes on the solid side of a stop, along both in-plane directions,
// so that the stop reads as a wall in the views that see it edge-on.
Shape hatch(int k, double at, bool solid_below, const Frame3& f, Ink ink) {
  Shape s;
  s.kind = Shape::Kind::kSegments;
  s.ink = ink;
  const double dk = solid_below ? -f.hatch : f.hatch;
  for (int along : {(k + 1) % 3, (k + 2) % 3}) {
    const int other = 3 - k - along;
    const double lo = f.box.lo[along], hi = f.box.hi[along];
    const double step = (hi - lo) / 24.0;
    const double mid = 0.5 * (f.box.lo[other] + f.box.hi[other]);
    for (int i = 0; i <= 24; ++i) {
      Vec3 p0, p1;
      p0[k] = at;
      p0[along] = lo + step * i;
      p0[other] = mid;
      p1 = p0;
      p1[k] = at + dk;
      p1[along] = p0[along] - step * 0.8;
      s.pts.push_back(p0);
      s.pts.push_back(p1);
    }
  }
  return s;
}

void add_trigger(const machine::Trigger& t, const config::MachineConfig& m,
                 const std::array<int, 3>& xyz, const Frame3& f, std::vector<Shape>& out) {
  const int k = slot_of(xyz, t.axis);
  if (k < 0) return;  // a rotary or extra axis: shown in the scope only
  const char a = m.axes[static_cast<std::size_t>(t.axis)].name;
  const std::string cond = fmt::format("{} {} {}", a, t.decreasing ? "<" : ">", num(t.at, 3));
  out.push_back(plane(k, t.at, f, Ink::kTrigger, fmt::format("{} on while {}", t.signal_name, cond),
                      fmt::format("{} trigger {}{}", t.signal_name, a, num(t.at, 3))));
}

void add_stop(const machine::Stop& st, const config::MachineConfig& m,
              const std::array<int, 3>& xyz, const Frame3& f, std::vector<Shape>& out) {
  const int k = slot_of(xyz, st.axis);
  if (k < 0) return;
  const char a = m.axes[static_cast<std::size_t>(st.axis)].name;
  // decreasing: motion toward smaller coordinates is blocked (solid below).
  out.push_back(plane(k, st.at, f, Ink::kStop,
                      fmt::format("stop: {} {} {}", a, st.decreasing ? ">=" : "<=", num(st.at, 3)),
                      fmt::format("stop {}{}", a, num(st.at, 3))));
  out.push_back(hatch(k, st.at, st.decreasing, f, Ink::kStop));
  out.back().normal_axis = k;
  out.back().in_iso = false;  // strokes seen at a slant read as noise
}

constexpr int kCircleSteps = 48;

Vec3 v3(const machine::geo::Vec3& p) {
  return Vec3{p.x, p.y, p.z};
}

Shape polygon(std::vector<Vec3> pts, Ink ink, std::string label = {}) {
  Shape s;
  s.kind = Shape::Kind::kPolygon;
  s.ink = ink;
  s.pts = std::move(pts);
  s.label = std::move(label);
  return s;
}

// A circle in the plane spanned by unit vectors a and b, around c.
std::vector<Vec3> circle(const Vec3& c, const Vec3& a, const Vec3& b, double r) {
  std::vector<Vec3> pts;
  for (int i = 0; i < kCircleSteps; ++i) {
    const double t = 2.0 * std::numbers::pi * i / kCircleSteps;
    const double ca = std::cos(t) * r, sb = std::sin(t) * r;
    pts.push_back(
        Vec3{c.x + a.x * ca + b.x * sb, c.y + a.y * ca + b.y * sb, c.z + a.z * ca + b.z * sb});
  }
  return pts;
}

// A box: its six faces. A hole is drawn as outlines only.
void add_box(Vec3 lo, Vec3 hi, Ink ink, std::string label, std::vector<Shape>& out) {
  auto corner = [&](int i) {
    return Vec3{(i & 1) != 0 ? hi.x : lo.x, (i & 2) != 0 ? hi.y : lo.y, (i & 4) != 0 ? hi.z : lo.z};
  };
  static constexpr int kFaces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& f : kFaces) {
    out.push_back(polygon({corner(f[0]), corner(f[1]), corner(f[2]), corner(f[3])}, ink, label));
    label.clear();
  }
}

// A vertical cylinder: top and bottom discs, the outline seen from the front
// and the side, and for the isometric view the two vertical edges of its
// silhouette (where the view's right vector is tangent to the circle).
void add_cylinder(double x, double y, double r, double bottom, double top, Ink ink,
                  std::string label, std::vector<Shape>& out) {
  const Vec3 ex{1, 0, 0}, ey{0, 1, 0};
  out.push_back(polygon(circle(Vec3{x, y, top}, ex, ey, r), ink, std::move(label)));
  out.push_back(polygon(circle(Vec3{x, y, bottom}, ex, ey, r), ink));
  for (const bool along_x : {true, false}) {
    Shape side = polygon({}, ink);
    const double dx = along_x ? r : 0.0, dy = along_x ? 0.0 : r;
    side.pts = {Vec3{x - dx, y - dy, bottom}, Vec3{x + dx, y + dy, bottom},
                Vec3{x + dx, y + dy, top}, Vec3{x - dx, y - dy, top}};
    side.in_iso = false;
    out.push_back(std::move(side));
  }
  Shape edges;
  edges.kind = Shape::Kind::kSegments;
  edges.ink = ink;
  edges.only_iso = true;
  const double k = r / std::sqrt(2.0);
  for (const double sgn : {1.0, -1.0}) {
    edges.pts.push_back(Vec3{x + sgn * k, y - sgn * k, bottom});
    edges.pts.push_back(Vec3{x + sgn * k, y - sgn * k, top});
  }
  out.push_back(std::move(edges));
}

void add_sphere(const Vec3& c, double r, Ink ink, std::string label, std::vector<Shape>& out) {
  const Vec3 ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  for (const auto& [a, b] : {std::pair{ex, ey}, std::pair{ex, ez}, std::pair{ey, ez}}) {
    Shape s = polygon(circle(c, a, b, r), ink, std::move(label));
    s.in_iso = false;
    out.push_back(std::move(s));
    label.clear();
  }
  // Seen from the isometric direction the outline is a circle in the view plane.
  const double u = 1.0 / std::sqrt(2.0), w = 1.0 / std::sqrt(6.0);
  Shape iso = polygon(circle(c, Vec3{u, u, 0}, Vec3{-w, w, 2 * w}, r), ink);
  iso.only_iso = true;
  out.push_back(std::move(iso));
}

// A half-space: its boundary plane, cut to the frame (a polygon of up to six
// corners where the plane crosses the frame's edges).
void add_half_space(const machine::geo::Shape& h, const Frame3& f, Ink ink, std::string label,
                    std::vector<Shape>& out) {
  const Vec3 n = v3(h.normal), p0 = v3(h.center);
  auto side = [&](const Vec3& p) {
    return (p.x - p0.x) * n.x + (p.y - p0.y) * n.y + (p.z - p0.z) * n.z;
  };
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i) {
    for (int k = 0; k < 3; ++k) {
      const int j = i | (1 << k);
      if (j == i) continue;
      const Vec3 a{(i & 1) != 0 ? f.box.hi.x : f.box.lo.x, (i & 2) != 0 ? f.box.hi.y : f.box.lo.y,
                   (i & 4) != 0 ? f.box.hi.z : f.box.lo.z};
      const Vec3 b{(j & 1) != 0 ? f.box.hi.x : f.box.lo.x, (j & 2) != 0 ? f.box.hi.y : f.box.lo.y,
                   (j & 4) != 0 ? f.box.hi.z : f.box.lo.z};
      const double sa = side(a), sb = side(b);
      if ((sa < 0) == (sb < 0) || sa == sb) continue;
      const double t = sa / (sa - sb);
      pts.push_back(Vec3{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t});
    }
  }
  if (pts.size() < 3) return;
  // Order the corners around their centre, in the plane.
  Vec3 c;
  for (const auto& p : pts) c = Vec3{c.x + p.x, c.y + p.y, c.z + p.z};
  c = Vec3{c.x / static_cast<double>(pts.size()), c.y / static_cast<double>(pts.size()),
           c.z / static_cast<double>(pts.size())};
  const Vec3 a = std::fabs(n.x) < 0.9 ? Vec3{0, -n.z, n.y} : Vec3{-n.z, 0, n.x};  // not along n
  const Vec3 b{n.y * a.z - n.z * a.y, n.z * a.x - n.x * a.z, n.x * a.y - n.y * a.x};
  std::sort(pts.begin(), pts.end(), [&](const Vec3& p, const Vec3& q) {
    const Vec3 dp{p.x - c.x, p.y - c.y, p.z - c.z}, dq{q.x - c.x, q.y - c.y, q.z - c.z};
    return std::atan2(dot3(dp, b), dot3(dp, a)) < std::atan2(dot3(dq, b), dot3(dq, a));
  });
  out.push_back(polygon(std::move(pts), ink, std::move(label)));
}

void add_part(const machine::geo::Part& part, const Frame3& f, std::vector<Shape>& out) {
  std::string label = part.name;
  for (const auto& s : part.solids) {
    switch (s.kind) {
      case machine::geo::ShapeKind::kBox:
        add_box(v3(s.lo), v3(s.hi), Ink::kPart, label, out);
        break;
      case machine::geo::ShapeKind::kCylinder:
        add_cylinder(s.lo.x, s.lo.y, s.radius, s.lo.z, s.hi.z, Ink::kPart, label, out);
        break;
      case machine::geo::ShapeKind::kSphere:
        add_sphere(v3(s.center), s.radius, Ink::kPart, label, out);
        break;
      case machine::geo::ShapeKind::kHalfSpace:
        add_half_space(s, f, Ink::kPart, label, out);
        break;
    }
    label.clear();
  }
  // Holes: bores run "without limit" in Z; they are drawn over the part's
  // height (the frame's when the part has no bounded solid).
  double zlo = 1e300, zhi = -1e300;
  for (const auto& sd : part.solids) {
    if (sd.kind == machine::geo::ShapeKind::kBox || sd.kind == machine::geo::ShapeKind::kCylinder) {
      zlo = std::min(zlo, sd.lo.z);
      zhi = std::max(zhi, sd.hi.z);
    } else if (sd.kind == machine::geo::ShapeKind::kSphere) {
      zlo = std::min(zlo, sd.center.z - sd.radius);
      zhi = std::max(zhi, sd.center.z + sd.radius);
    }
  }
  if (zlo > zhi) {
    zlo = f.box.lo.z;
    zhi = f.box.hi.z;
  }
  for (const auto& h : part.holes) {
    const double lo = std::max(h.lo.z, zlo), hi = std::min(h.hi.z, zhi);
    if (lo >= hi) continue;
    if (h.kind == machine::geo::ShapeKind::kCylinder) {
      add_cylinder(h.lo.x, h.lo.y, h.radius, lo, hi, Ink::kHole, "", out);
    } else if (h.kind == machine::geo::ShapeKind::kBox) {
      add_box(Vec3{h.lo.x, h.lo.y, lo}, Vec3{h.hi.x, h.hi.y, hi}, Ink::kHole, "", out);
    }
  }
}

}  // namespace

void add_scene_extent(const machine::Scene& scene, Box3& extent) {
  for (const auto& part : scene.probing.parts) {
    // Corners of each shape's box, placed in machine coordinates.
    auto add = [&](double x0, double y0, double z0, double x1, double y1, double z1) {
      for (int i = 0; i < 8; ++i) {
        const machine::geo::Vec3 c{(i & 1) != 0 ? x1 : x0, (i & 2) != 0 ? y1 : y0,
                                   (i & 4) != 0 ? z1 : z0};
        extent.add(v3(part.place.to_machine(c)));
      }
    };
    for (const auto& s : part.solids) {
      switch (s.kind) {
        case machine::geo::ShapeKind::kBox:
          add(s.lo.x, s.lo.y, s.lo.z, s.hi.x, s.hi.y, s.hi.z);
          break;
        case machine::geo::ShapeKind::kCylinder:
          add(s.lo.x - s.radius, s.lo.y - s.radius, s.lo.z, s.hi.x + s.radius, s.hi.y + s.radius,
              s.hi.z);
          break;
        case machine::geo::ShapeKind::kSphere:
          add(s.center.x - s.radius, s.center.y - s.radius, s.center.z - s.radius,
              s.center.x + s.radius, s.center.y + s.radius, s.center.z + s.radius);
          break;
        case machine::geo::ShapeKind::kHalfSpace:
          break;  // unbounded: drawn over what the rest needs
      }
    }
  }
  if (const auto& st = scene.probing.stock) {
    extent.add(v3(st->lo));
    extent.add(v3(st->hi));
  }
  if (const auto& ts = scene.probing.tool_setter) {
    extent.add(Vec3{ts->x - ts->radius, ts->y - ts->radius, ts->top - ts->thickness});
    extent.add(Vec3{ts->x + ts->radius, ts->y + ts->radius, ts->top});
  }
}

void add_stock_cut(const sim::StockResult& st, const machine::Scene& scene,
                   std::vector<Shape>& out) {
  if (!scene.probing.stock) return;
  const auto& spec = *scene.probing.stock;
  // A staircase per side view: each column of cells at its lowest top. Seen
  // from above it lies on the box's edge, so only the side views show it.
  auto profile = [&](const std::vector<double>& edges, const std::vector<double>& lowest,
                     bool along_x) {
    Shape s;
    s.kind = Shape::Kind::kPolyline;
    s.ink = Ink::kStock;
    s.in_iso = false;
    auto at = [&](double u, double z) {
      return along_x ? Vec3{u, spec.lo.y, z} : Vec3{spec.lo.x, u, z};
    };
    for (std::size_t i = 0; i < lowest.size(); ++i) {
      s.pts.push_back(at(edges[i], lowest[i]));
      s.pts.push_back(at(edges[i + 1], lowest[i]));
    }
    out.push_back(std::move(s));
  };
  if (st.removed_mm3 <= 0.0) return;
  profile(st.x_edges, st.lowest_along_x, true);
  profile(st.y_edges, st.lowest_along_y, false);
}

std::vector<Shape> scene_shapes(const machine::Scene& scene, const config::MachineConfig& m,
                                const std::array<int, 3>& xyz, const Box3& extent) {
  std::vector<Shape> out;
  const Frame3 f = frame_of(extent);
  for (const auto& t : scene.triggers) add_trigger(t, m, xyz, f, out);
  for (const auto& s : scene.stops) add_stop(s, m, xyz, f, out);
  for (const auto& part : scene.probing.parts) {
    // Shapes are drawn in the part's frame, then placed (a scene [[frame]]).
    const std::size_t first = out.size();
    add_part(part, f, out);
    if (part.place.turned() || !(part.place.origin == machine::geo::Vec3{})) {
      for (std::size_t i = first; i < out.size(); ++i) {
        for (auto& p : out[i].pts) p = v3(part.place.to_machine({p.x, p.y, p.z}));
        // A face keeps its machine axis only while the turn keeps that axis.
        if (part.place.turned() && (out[i].normal_axis != 2 || !part.place.upright())) {
          out[i].normal_axis = -1;
        }
      }
    }
  }
  if (const auto& st = scene.probing.stock) {
    // Its ink has no fill: an outline, with the cut drawn over it.
    add_box(v3(st->lo), v3(st->hi), Ink::kStock, "stock", out);
  }
  if (const auto& ts = scene.probing.tool_setter) {
    add_cylinder(ts->x, ts->y, ts->radius, ts->top - ts->thickness, ts->top, Ink::kSetter,
                 "tool setter " + ts->signal_name, out);
  }
  return out;
}

}  // namespace skipnc::plot
