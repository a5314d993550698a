// The control's own variables #3001-#3005 (sysvars.cpp read_control /
// write_control): the two timers, kept as the base a write sets, and
// #3003-#3005, kept for reading back (the simulation has no operator panel
// for them to act on). Held by the interpreter as one member.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "interpreter/variables.hpp"

namespace skipnc::interp {

struct ControlVariables {
  double timer_ms_base = 0.0;      // #3001 = time - base (milliseconds)
  double timer_h_base = 0.0;       // #3002 = time - base (hours)
  std::array<Value, 3> control{};  // #3003 #3004 #3005

  // #3001 and #3002 at `time_s` seconds of the run.
  Value timer_ms(double time_s) const noexcept {
    return Value::of(std::floor(time_s * 1000.0 - timer_ms_base) + 0.0);
  }
  Value timer_h(double time_s) const noexcept {
    return Value::of(time_s / 3600.0 - timer_h_base + 0.0);
  }
  // Writing #3001 or #3002 at `time_s`: the timer reads `v` from then on.
  void set_timer_ms(double time_s, double v) noexcept { timer_ms_base = time_s * 1000.0 - v; }
  void set_timer_h(double time_s, double v) noexcept { timer_h_base = time_s / 3600.0 - v; }
  // #3003 + i.
  Value& at(int i) noexcept { return control[static_cast<std::size_t>(i)]; }
  const Value& at(int i) const noexcept { return control[static_cast<std::size_t>(i)]; }
};

}  // namespace skipnc::interp
