#include "kernel/kernel_config.hpp"

#include <cmath>

namespace skipnc::kernel {

KernelConfig kernel_config(const config::MachineConfig& m) {
  KernelConfig k;
  k.clock.period_ns = m.period_ns;
  k.limits.axis_count = m.axis_count();
  k.limits.period_s = k.clock.period_s();
  double max_feed = 0.0;
  for (int i = 0; i < m.axis_count(); ++i) {
    const auto& a = m.axes[static_cast<std::size_t>(i)];
    auto& l = k.limits.axes[static_cast<std::size_t>(i)];
    l.max_velocity_mm_s = a.max_feed_mm_min / 60.0;
    l.rapid_mm_s = a.rapid_mm_min / 60.0;
    l.max_accel_mm_s2 = a.accel_mm_s2;
    max_feed = std::fmax(max_feed, a.max_feed_mm_min);
  }
  k.limits.max_feed_mm_s = max_feed / 60.0;
  k.in_position_mm = m.in_position_mm;
  // The faults the kernel checks in its tick: the stroke ends (a command
  // exactly on an end is inside), an excess following error beyond any lag
  // the axis shows at its rapid rate (1.5 v / kp + 1 mm; an ideal servo has
  // none), and the in-position timeout.
  for (int i = 0; i < m.axis_count(); ++i) {
    const auto& a = m.axes[static_cast<std::size_t>(i)];
    const auto k_i = static_cast<std::size_t>(i);
    k.faults.stroke_min[k_i] = a.min_mm - 1e-9;
    k.faults.stroke_max[k_i] = a.max_mm + 1e-9;
    k.faults.excess_error[k_i] =
        a.kp_per_s > 0.0 ? 1.5 * a.rapid_mm_min / 60.0 / a.kp_per_s + 1.0 : FaultLimits::kNone;
  }
  k.faults.in_position_timeout_s = m.in_position_timeout_s;
  return k;
}

}  // namespace skipnc::kernel
