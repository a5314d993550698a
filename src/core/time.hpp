// Servo time. A tick is one servo period; time is an integer tick count, and
// a time inside a tick is the tick plus a fraction in [0, 1). Seconds are
// derived from ticks by one multiplication, never accumulated.
#pragma once

#include <cstdint>

namespace skipnc {

using Tick = std::int64_t;

struct ServoClock {
  std::int64_t period_ns = 1'000'000;

  constexpr double period_s() const noexcept { return static_cast<double>(period_ns) * 1e-9; }
  constexpr double seconds(Tick t) const noexcept {
    return static_cast<double>(t) * static_cast<double>(period_ns) * 1e-9;
  }
  // A point inside tick `t`: `frac` of the way from t-1 to t (frac in (0, 1]).
  constexpr double seconds(Tick t, double frac) const noexcept {
    return (static_cast<double>(t - 1) + frac) * static_cast<double>(period_ns) * 1e-9;
  }
};

}  // namespace skipnc
