// Program frame -> work frame (see transform.hpp).
#include "interpreter/transform.hpp"

#include <cmath>
#include <numbers>

namespace skipnc::interp::xform {

std::array<double, 2> cos_sin_deg(double deg) noexcept {
  const double turns = deg / 90.0;
  if (turns == std::trunc(turns)) {
    // Exact quarter turns: cos 90 is 0, not 6e-17.
    constexpr std::array<std::array<double, 2>, 4> kQuarter{{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
    const auto q = static_cast<long long>(turns);
    return kQuarter[static_cast<std::size_t>(((q % 4) + 4) % 4)];
  }
  const double rad = deg * std::numbers::pi / 180.0;
  return {std::cos(rad), std::sin(rad)};
}

namespace {

Point apply(const Transform& t, Point p, bool vector) {
  for (std::size_t i = 0; i < 3; ++i) {
    const double mc = vector ? 0.0 : t.mirror_center[i];
    if (t.mirror[i]) p[i] = 2.0 * mc - p[i];
    const double sc = vector ? 0.0 : t.scale_center[i];
    p[i] = sc + (p[i] - sc) * t.scale[i];
  }
  if (t.rotating) {
    const auto [c, s] = cos_sin_deg(t.angle_deg);
    const double cx = vector ? 0.0 : t.rotation_center[0];
    const double cy = vector ? 0.0 : t.rotation_center[1];
    const double dx = p[0] - cx, dy = p[1] - cy;
    p[0] = cx + c * dx - s * dy;
    p[1] = cy + s * dx + c * dy;
  }
  return p;
}

}  // namespace

Point to_work(const Transform& t, const Point& program) noexcept {
  return apply(t, program, false);
}

Point vector_to_work(const Transform& t, const Point& v) noexcept {
  return apply(t, v, true);
}

Point to_program(const Transform& t, const Point& work) noexcept {
  Point p = work;
  if (t.rotating) {
    const auto [c, s] = cos_sin_deg(t.angle_deg);
    const double dx = p[0] - t.rotation_center[0], dy = p[1] - t.rotation_center[1];
    p[0] = t.rotation_center[0] + c * dx + s * dy;
    p[1] = t.rotation_center[1] - s * dx + c * dy;
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const double sc = t.scale_center[i];
    if (t.scale[i] != 0.0) p[i] = sc + (p[i] - sc) / t.scale[i];
    if (t.mirror[i]) p[i] = 2.0 * t.mirror_center[i] - p[i];
  }
  return p;
}

std::array<double, 2> polar_to_xy(const std::array<double, 2>& center, double radius,
                                  double angle_deg) noexcept {
  const auto [c, s] = cos_sin_deg(angle_deg);
  return {center[0] + radius * c, center[1] + radius * s};
}

}  // namespace skipnc::interp::xform
