// The kernel's own fault checks (issue 19): a caller that drives the kernel
// from its own servo loop gets the stroke limits, the excess following error
// and the in-position timeout without the simulator. Limits from the
// built-in mill3 (X -500..500 mm, rapid 30000 mm/min, kp 50/s) through
// kernel_config().
#include <gtest/gtest.h>

#include <cmath>

#include "config/machine_config.hpp"
#include "kernel/kernel.hpp"
#include "kernel/kernel_config.hpp"
#include "support/axes.hpp"

namespace skipnc {
namespace {

using test::at_x;

kernel::KernelConfig mill3() {
  return kernel::kernel_config(*config::builtin_machine("mill3"));
}

TEST(KernelFault, ACommandBeyondTheStrokeIsNeverGivenAndTheKernelHolds) {
  kernel::Kernel k(mill3());
  k.set_position(at_x(490.0));
  ASSERT_TRUE(k.push({canon::Feed{at_x(520.0), 1200.0, false}, 7}));
  kernel::TickInput in;
  kernel::TickOutput out;
  double last = 490.0;
  int ticks = 0;
  // An ideal drive: the axis is where it was commanded.
  for (; ticks < 5000 && !out.fault; ++ticks) {
    in.actual = out.commanded;
    if (ticks == 0) in.actual = at_x(490.0);
    k.tick(in, out);
    if (!out.fault) last = out.commanded[0];
  }
  ASSERT_TRUE(out.fault);
  EXPECT_EQ(out.fault.kind, kernel::Fault::Kind::kStrokeLimit);
  EXPECT_EQ(out.fault.axis, 0);
  EXPECT_GT(out.fault.value, 500.0);
  EXPECT_NEAR(out.fault.limit, 500.0, 1e-6);
  // The command given is the last one inside the stroke, and it stays there.
  EXPECT_LE(out.commanded[0], 500.0 + 1e-9);
  EXPECT_EQ(out.commanded[0], last);
  for (int i = 0; i < 10; ++i) {
    k.tick(in, out);
    EXPECT_EQ(out.commanded[0], last);
    EXPECT_EQ(out.fault.kind, kernel::Fault::Kind::kStrokeLimit);
  }
  // A reset (set_position) clears it.
  k.set_position(at_x(0.0));
  EXPECT_FALSE(k.fault());
}

TEST(KernelFault, AnAxisFarBehindItsCommandIsAnExcessError) {
  const kernel::KernelConfig cfg = mill3();
  // 1.5 times the lag at rapid (500 mm/s, kp 50/s) plus 1 mm.
  const double limit = 1.5 * 500.0 / 50.0 + 1.0;
  EXPECT_DOUBLE_EQ(cfg.faults.excess_error[0], limit);
  kernel::Kernel k(cfg);
  k.set_position(at_x(0.0));
  ASSERT_TRUE(k.push({canon::Rapid{at_x(400.0)}, 3}));
  kernel::TickInput in;
  kernel::TickOutput out;
  // The axis does not move (held by something the kernel cannot see): the
  // following error grows with the command until it passes the limit.
  double commanded = 0.0;
  for (int i = 0; i < 5000 && !out.fault; ++i) {
    in.actual = at_x(0.0);
    k.tick(in, out);
    if (!out.fault) commanded = out.commanded[0];
  }
  ASSERT_TRUE(out.fault);
  EXPECT_EQ(out.fault.kind, kernel::Fault::Kind::kExcessError);
  EXPECT_EQ(out.fault.axis, 0);
  EXPECT_GT(out.fault.value, limit);
  EXPECT_LE(out.fault.value, commanded + 1e-9);
  EXPECT_DOUBLE_EQ(out.fault.limit, limit);
}

TEST(KernelFault, ALockedAxisHasNoFollowingErrorToCheck) {
  kernel::Kernel k(mill3());
  k.set_position(at_x(0.0));
  AxisMask x;
  x.set(0);
  k.set_locked_axes(x);
  ASSERT_TRUE(k.push({canon::Rapid{at_x(400.0)}, 3}));
  kernel::TickInput in;
  kernel::TickOutput out;
  for (int i = 0; i < 3000; ++i) {
    in.actual = at_x(0.0);  // machine lock: the axis stays
    k.tick(in, out);
    ASSERT_FALSE(out.fault) << "tick " << i;
  }
}

TEST(KernelFault, AnAxisHeldShortOfItsCommandAtRestTimesOut) {
  kernel::KernelConfig cfg = mill3();
  cfg.faults.in_position_timeout_s = 0.5;
  kernel::Kernel k(cfg);
  k.set_position(at_x(0.0));
  ASSERT_TRUE(k.push({canon::Feed{at_x(10.0), 600.0, false}, 4}));
  kernel::TickInput in;
  kernel::TickOutput out;
  std::int64_t ticks = 0;
  std::int64_t at_rest = -1;
  for (; ticks < 10000 && !out.fault; ++ticks) {
    // A stop holds the axis at X9.
    in.actual = at_x(std::fmin(out.commanded[0], 9.0));
    k.tick(in, out);
    if (at_rest < 0 && out.commanded[0] == 10.0) at_rest = ticks;
  }
  ASSERT_TRUE(out.fault);
  EXPECT_EQ(out.fault.kind, kernel::Fault::Kind::kInPositionTimeout);
  EXPECT_EQ(out.fault.axis, 0);
  EXPECT_NEAR(out.fault.value, 1.0, 1e-9);
  // About 0.5 s after the command came to rest.
  EXPECT_NEAR(static_cast<double>(ticks - at_rest) * 0.001, 0.5, 0.005);
}

}  // namespace
}  // namespace skipnc
