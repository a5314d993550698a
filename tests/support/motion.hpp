// Shared set-up of the motion tests (planner, interpolator, machine): a
// 3-axis mill's limits and a short way to write an X Y Z position.
#pragma once

#include "core/axes.hpp"
#include "planner/planner.hpp"

namespace skipnc::test {

// X Y Z: 20 m/min cutting feed, 500 mm/s rapid, 2000 mm/s^2, 1 ms period.
inline planner::Limits mill_limits() {
  planner::Limits lim;
  lim.axis_count = 3;
  for (auto& a : lim.axes) {
    a.max_velocity_mm_s = 20000.0 / 60.0;
    a.rapid_mm_s = 500.0;
    a.max_accel_mm_s2 = 2000.0;
  }
  lim.period_s = 0.001;
  lim.max_feed_mm_s = 20000.0 / 60.0;
  return lim;
}

inline AxisVec xyz(double x, double y, double z) {
  AxisVec v;
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

}  // namespace skipnc::test
