// Servo time. A tick is one servo period; time is an integer tick count, and
// a time inside a tick is the tick plus a fraction in [0, 1). Seconds are
// derived from ticks by one multiplication, never accumulated.
#pragma once

#include <cstdint>

namespace skipnc {

using Tick = std::int64_t;

struct ServoClock {
  std::int64_t period_ns = 1'000'000;

  constexpr double period_s() const noexcept { return static_cast<double>(period_ns) / 1e9; }
  // t * period is an exact integer of nanoseconds (below 2^53 for any run);
  // one correctly rounded division turns it into seconds, so 1833 ticks of
  // 1 ms read as 1.833, not 1.8330000000000002.
  constexpr double seconds(Tick t) const noexcept {
    return static_cast<double>(t * period_ns) / 1e9;
  }
  // A point inside tick `t`: `frac` of the way from t-1 to t (frac in (0, 1]).
  constexpr double seconds(Tick t, double frac) const noexcept {
    return (static_cast<double>((t - 1) * period_ns) + frac * static_cast<double>(period_ns)) / 1e9;
  }
};

}  // namespace skipnc
