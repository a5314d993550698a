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

Matrix axis_angle(const Point& axis, double angle_deg) noexcept {
  // Rodrigues: m = c I + s [n]x + (1 - c) n n^T, n the unit vector.
  const double len = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  Matrix m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  if (len == 0.0) return m;
  const Point n{axis[0] / len, axis[1] / len, axis[2] / len};
  const auto [c, s] = cos_sin_deg(angle_deg);
  const Matrix cross{{{0, -n[2], n[1]}, {n[2], 0, -n[0]}, {-n[1], n[0], 0}}};
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      m[i][j] = (i == j ? c : 0.0) + s * cross[i][j] + (1.0 - c) * n[i] * n[j];
    }
  }
  return m;
}

Matrix turn_xyz(double da_deg, double db_deg, double dc_deg) noexcept {
  const Matrix x = axis_angle({1, 0, 0}, da_deg), y = axis_angle({0, 1, 0}, db_deg),
               z = axis_angle({0, 0, 1}, dc_deg);
  auto mul = [](const Matrix& a, const Matrix& b) {
    Matrix m{};
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 3; ++j) {
        for (std::size_t k = 0; k < 3; ++k) m[i][j] += a[i][k] * b[k][j];
      }
    }
    return m;
  };
  return mul(z, mul(y, x));
}

bool keeps_z(const Matrix& m) noexcept {
  return m[2][0] == 0.0 && m[2][1] == 0.0 && m[0][2] == 0.0 && m[1][2] == 0.0;
}

bool Transform::tilted() const noexcept {
  if (!spatial) return false;
  if (spatial->setting_error && !keeps_z(spatial->setting_turn)) return true;
  for (int k = 0; k < spatial->conversions; ++k) {
    if (!keeps_z(spatial->conversion[static_cast<std::size_t>(k)].m)) return true;
  }
  return false;
}

Transform with_spatial(Transform t, const Spatial& s) {
  t.spatial = s.conversions > 0 || s.setting_error ? std::make_shared<const Spatial>(s) : nullptr;
  return t;
}

namespace {

// p -> c + m (p - c), or m^T for the inverse; without c for a vector.
Point convert(const Conversion& k, const Point& p, bool vector, bool inverse) {
  const Point c = vector ? Point{} : k.center;
  const Point d{p[0] - c[0], p[1] - c[1], p[2] - c[2]};
  Point out = c;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) out[i] += (inverse ? k.m[j][i] : k.m[i][j]) * d[j];
  }
  return out;
}

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
  // The last conversion is the innermost: the program frame is its frame.
  if (!t.spatial) return p;
  const Spatial& sp = *t.spatial;
  for (int k = sp.conversions - 1; k >= 0; --k) {
    p = convert(sp.conversion[static_cast<std::size_t>(k)], p, vector, false);
  }
  if (sp.setting_error) {
    p = convert(Conversion{sp.setting_turn, {}}, p, false, false);
    if (!vector) {
      for (std::size_t i = 0; i < 3; ++i) p[i] += sp.setting_shift[i];
    }
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
  if (t.spatial) {
    const Spatial& sp = *t.spatial;
    if (sp.setting_error) {
      for (std::size_t i = 0; i < 3; ++i) p[i] -= sp.setting_shift[i];
      p = convert(Conversion{sp.setting_turn, {}}, p, false, true);
    }
    for (int k = 0; k < sp.conversions; ++k) {
      p = convert(sp.conversion[static_cast<std::size_t>(k)], p, false, true);
    }
  }
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
