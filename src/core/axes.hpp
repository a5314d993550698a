// Axis arrays: one value per machine axis, in a fixed-capacity array so that
// nothing on the servo path allocates.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

namespace skipnc {

inline constexpr int kMaxAxes = 8;

struct AxisVec {
  std::array<double, kMaxAxes> v{};

  constexpr double& operator[](int i) noexcept { return v[static_cast<std::size_t>(i)]; }
  constexpr double operator[](int i) const noexcept { return v[static_cast<std::size_t>(i)]; }

  constexpr AxisVec& operator+=(const AxisVec& o) noexcept {
    for (int i = 0; i < kMaxAxes; ++i) (*this)[i] += o[i];
    return *this;
  }
  constexpr AxisVec& operator-=(const AxisVec& o) noexcept {
    for (int i = 0; i < kMaxAxes; ++i) (*this)[i] -= o[i];
    return *this;
  }
  constexpr AxisVec& operator*=(double k) noexcept {
    for (auto& x : v) x *= k;
    return *this;
  }
  friend constexpr AxisVec operator+(AxisVec a, const AxisVec& b) noexcept { return a += b; }
  friend constexpr AxisVec operator-(AxisVec a, const AxisVec& b) noexcept { return a -= b; }
  friend constexpr AxisVec operator*(AxisVec a, double k) noexcept { return a *= k; }
  friend constexpr AxisVec operator*(double k, AxisVec a) noexcept { return a *= k; }
  friend constexpr bool operator==(const AxisVec&, const AxisVec&) = default;
};

// Euclidean length over the first `count` axes.
inline double norm(const AxisVec& a, int count) noexcept {
  double s = 0.0;
  for (int i = 0; i < count; ++i) s += a[i] * a[i];
  return std::sqrt(s);
}

// Linear interpolation a + (b - a) * f over every axis.
constexpr AxisVec lerp(const AxisVec& a, const AxisVec& b, double f) noexcept {
  AxisVec r;
  for (int i = 0; i < kMaxAxes; ++i) r[i] = a[i] + (b[i] - a[i]) * f;
  return r;
}

// A set of axes, one bit per axis index.
struct AxisMask {
  unsigned bits = 0;
  constexpr bool has(int i) const noexcept { return (bits >> i) & 1U; }
  constexpr void set(int i) noexcept { bits |= 1U << i; }
  constexpr bool empty() const noexcept { return bits == 0; }
  constexpr int count() const noexcept {
    int n = 0;
    for (unsigned b = bits; b != 0; b &= b - 1) ++n;
    return n;
  }
  friend constexpr bool operator==(AxisMask, AxisMask) = default;
};

}  // namespace skipnc
