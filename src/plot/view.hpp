// Screen geometry for the SVG writer: fitting a view to a rectangle, tick
// steps, line simplification and label placement. The page's script does
// the same with the same rules (assets/plot_views.js).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "plot/model.hpp"

namespace skipnc::plot {

inline double dot(const Vec3& a, const Vec3& b) noexcept {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// The world window (u0..u1, v0..v1, mm) shown in the pixel rectangle
// (x, y, w, h); v grows upwards, pixels downwards.
struct Frame {
  double x = 0, y = 0, w = 1, h = 1;
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  double px(double u) const noexcept { return x + (u - u0) / (u1 - u0) * w; }
  double py(double v) const noexcept { return y + (v1 - v) / (v1 - v0) * h; }
};

// Fits the extent's eight corners, projected, into the rectangle with the
// same scale on both screen axes and `margin_px` free on every side.
Frame fit_view(const ViewDef& v, const Box3& extent, double x, double y, double w, double h,
               double margin_px);

// A round step (1, 2 or 5 x 10^n) giving about `target` intervals over span.
double nice_step(double span, int target);
// The next larger round step: 1 -> 2 -> 5 -> 10 (x 10^n).
double next_nice_step(double step);

struct Pt {
  double x = 0, y = 0;
};
// Douglas-Peucker: drops points closer than tol to the simplified line.
// Keeps the first and the last point.
std::vector<Pt> simplify(const std::vector<Pt>& pts, double tol);

struct Box2 {
  double x = 0, y = 0, w = 0, h = 0;
  bool overlaps(const Box2& o) const noexcept {
    return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
  }
};

// The part of segment a-b inside the rectangle (Liang-Barsky), if any.
std::optional<std::pair<Pt, Pt>> clip_segment(Pt a, Pt b, const Box2& r);

// Greedy label placement: beside the anchor, then on rings further out
// (with a leader line). A place that covers no other label and no drawn line
// wins, then one that covers no label. Lines are kept in a grid of 6 px cells.
class LabelPlacer {
 public:
  explicit LabelPlacer(Box2 clip);
  void block(Box2 b) { used_.push_back(b); }
  // Marks the cells a drawn line crosses.
  void line(Pt a, Pt b);
  // The label's box; `leader` is true when it sits away from the anchor.
  // Never over another label or marker: beside the anchor, on rings
  // further out, else the free place of the view nearest to it; with none
  // left, an empty box (w = 0): the label is not drawn (its marker keeps
  // the text as a tooltip).
  Box2 place(double ax, double ay, double w, double h, bool& leader);

 private:
  bool on_line(const Box2& b) const;
  Box2 clip_;
  std::vector<Box2> used_;
  int cols_ = 1, rows_ = 1;
  std::vector<unsigned char> grid_;
};

// Approximate width of a text in px (sans-serif).
inline double text_width(const std::string& s, double font_px) noexcept {
  return 0.6 * font_px * static_cast<double>(s.size());
}

}  // namespace skipnc::plot
