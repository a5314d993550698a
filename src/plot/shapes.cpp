// The scene as generic shapes (polygons and polylines in machine
// coordinates) that every renderer draws without knowing what they are.
//
// To draw a new kind of scene object (a part, a gauge, a stylus), add one
// function here that turns it into shapes with an Ink of its own (add the
// Ink and its style to the table in model.cpp) and call it from
// scene_shapes(). Nothing in svg.cpp or the page's script changes.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "plot/model.hpp"

namespace skipnc::plot {
namespace {

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

}  // namespace

std::vector<Shape> scene_shapes(const machine::Scene& scene, const config::MachineConfig& m,
                                const std::array<int, 3>& xyz, const Box3& extent) {
  std::vector<Shape> out;
  const Frame3 f = frame_of(extent);
  for (const auto& t : scene.triggers) add_trigger(t, m, xyz, f, out);
  for (const auto& s : scene.stops) add_stop(s, m, xyz, f, out);
  return out;
}

}  // namespace skipnc::plot
