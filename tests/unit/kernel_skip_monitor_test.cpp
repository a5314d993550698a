// The kernel's skip monitor on its own: the test is the machine. It feeds
// the actual position (= the command: an ideal servo), a motor torque and
// input edges with their instants, and reads what the kernel does.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "config/machine_config.hpp"
#include "kernel/kernel.hpp"
#include "kernel/kernel_config.hpp"
#include "sim/simulator.hpp"

namespace skipnc {
namespace {

constexpr canon::SignalAddr kSkip{'X', 0, 4};

class Bench {
 public:
  Bench() : k_(make_config()) { k_.set_position(AxisVec{}); }

  // A G31 along X to `x` at `feed` (mm/min), input X0.4.
  void skip(double x, double feed, canon::SkipSpec spec) {
    canon::Skip s;
    s.target[0] = x;
    s.feed_mm_per_min = feed;
    spec.input_count = 1;
    spec.inputs[0] = kSkip;
    s.spec = spec;
    ASSERT_TRUE(k_.push(canon::Stamped{s, 1}));
  }
  // One period; `edges` happen inside it; the torque of X is `torque_x`.
  const kernel::TickOutput& tick(std::vector<kernel::SignalEdge> edges = {},
                                 double torque_x = 0.0) {
    in_.actual = out_.commanded;
    in_.torque_pct = AxisVec{};
    in_.torque_pct[0] = torque_x;
    in_.edge_count = 0;
    for (const auto& e : edges) in_.edges[static_cast<std::size_t>(in_.edge_count++)] = e;
    k_.tick(in_, out_);
    return out_;
  }
  kernel::Kernel& kernel() { return k_; }

 private:
  static kernel::KernelConfig make_config() {
    auto m = config::builtin_machine("mill3");
    return kernel::kernel_config(*m);
  }
  kernel::Kernel k_;
  kernel::TickInput in_;
  kernel::TickOutput out_;
};

TEST(KernelSkip, LevelDetectionEndsAtOnceWhenTheInputIsAlreadyActive) {
  Bench b;
  b.kernel().preset_signal(kSkip, true);
  canon::SkipSpec spec;
  spec.edge = false;
  spec.active_at_start_ends = true;
  b.skip(10.0, 600.0, spec);
  for (int i = 0; i < 20 && !b.kernel().skip().done; ++i) b.tick();
  ASSERT_TRUE(b.kernel().skip().done);
  EXPECT_TRUE(b.kernel().skip().triggered);
  EXPECT_LT(b.kernel().skip().stop_position[0], 0.05);
}

TEST(KernelSkip, EdgeDetectionWaitsForANewActiveEdge) {
  Bench b;
  b.kernel().preset_signal(kSkip, true);
  canon::SkipSpec spec;
  spec.edge = true;
  b.skip(10.0, 600.0, spec);
  for (int i = 0; i < 100; ++i) b.tick();
  EXPECT_FALSE(b.kernel().skip().triggered);
  b.tick({kernel::SignalEdge{kSkip, false, 0.5}});  // falling: not the active edge
  EXPECT_FALSE(b.kernel().skip().triggered);
  b.tick({kernel::SignalEdge{kSkip, true, 0.25}});
  ASSERT_TRUE(b.kernel().skip().triggered);
  // 10 mm/s without acceleration, 0.01 mm per period: in the 102nd period
  // the command runs from 1.00 to 1.01 (the first period only starts the
  // move), and the edge a quarter into it is latched at 1.0025.
  EXPECT_NEAR(b.kernel().skip().latch_machine[0], 1.0025, 1e-9);
}

TEST(KernelSkip, HandshakeActiveSkipRecordedDone) {
  Bench b;
  canon::SkipSpec spec;
  b.skip(10.0, 600.0, spec);
  // Seed 003: Active is set at the start of the G31 move, i.e. in the tick
  // whose command starts it.
  EXPECT_TRUE(b.tick().handshake.active) << "Active from the tick that starts the move";
  EXPECT_TRUE(b.tick().handshake.active);
  const auto& hit = b.tick({kernel::SignalEdge{kSkip, true, 0.5}});
  EXPECT_TRUE(hit.handshake.skip);
  EXPECT_TRUE(hit.handshake.recorded) << "exact latch: recorded at once";
  const auto& after = b.tick();
  EXPECT_FALSE(after.handshake.active);
  EXPECT_TRUE(after.handshake.done);
  EXPECT_TRUE(after.handshake.skip) << "stays until the next skip block starts";
}

TEST(KernelSkip, SampledLatchWithDelayRecordsAfterTheDelay) {
  Bench b;
  canon::SkipSpec spec;
  spec.latch = canon::SkipLatch::kSampled;
  spec.latch_delay_s = 0.004;
  b.skip(10.0, 600.0, spec);
  b.tick();
  b.tick();
  const auto hit = b.tick({kernel::SignalEdge{kSkip, true, 0.5}});
  EXPECT_TRUE(hit.handshake.skip);
  EXPECT_FALSE(hit.handshake.recorded);
  int ticks = 0;
  while (!b.tick().handshake.recorded && ticks < 10) ++ticks;
  EXPECT_EQ(ticks, 3) << "recorded in the fourth period after the sample";
}

// The control learns of the signal only after the detection delay: the axes
// keep moving meanwhile, the position stored is the one at the end of the
// delay, and the stop starts there (ideal servo, immediate stop: the axis
// rests where it was latched).
TEST(KernelSkip, SampledLatchWithDelayKeepsMovingUntilTheControlSeesTheSignal) {
  Bench b;
  canon::SkipSpec spec;
  spec.latch = canon::SkipLatch::kSampled;
  spec.latch_delay_s = 0.004;
  b.skip(10.0, 600.0, spec);
  double x = 0.0;
  for (int i = 0; i < 50; ++i) x = b.tick().commanded[0];  // at the feed: 0.01 mm per period
  const double at_sample = x;  // the position at the sample that sees the edge
  for (int i = 0; i < 4; ++i) {
    const double next =
        (i == 0 ? b.tick({kernel::SignalEdge{kSkip, true, 0.5}}) : b.tick()).commanded[0];
    EXPECT_NEAR(next - x, 0.01, 1e-9) << "period " << i << " after the sample";
    x = next;
  }
  for (int i = 0; i < 20 && !b.kernel().skip().done; ++i) b.tick();
  ASSERT_TRUE(b.kernel().skip().done);
  EXPECT_NEAR(b.kernel().skip().latch_machine[0] - at_sample, 0.04, 1e-9)
      << "stored 4 ms (0.04 mm at F600) after the sample";
  EXPECT_NEAR(b.kernel().skip().stop_position[0], b.kernel().skip().latch_machine[0], 1e-9);
}

TEST(KernelSkip, TorqueBelowTheDelayDoesNotSkipAtOrAboveItDoes) {
  Bench b;
  canon::SkipSpec spec;
  spec.kind = canon::SkipKind::kTorque;
  spec.input_count = 0;
  spec.torque_ends = true;
  spec.torque_axis = 0;
  spec.torque_limit_pct = 50.0;
  spec.torque_delay_s = 0.005;
  b.skip(10.0, 600.0, spec);
  b.tick();
  for (int i = 0; i < 5; ++i) b.tick({}, 60.0);  // 5 periods: 4 ms above the limit
  b.tick({}, 10.0);
  EXPECT_FALSE(b.kernel().skip().triggered);
  for (int i = 0; i < 6 && !b.kernel().skip().triggered; ++i) b.tick({}, -55.0);
  ASSERT_TRUE(b.kernel().skip().triggered) << "the sign of the torque does not matter";
  EXPECT_TRUE(b.kernel().skip().torque_reached);
}

TEST(KernelSkip, TorqueLimitIsAnOutputWhileTheTorqueSkipRuns) {
  Bench b;
  canon::SkipSpec spec;
  spec.kind = canon::SkipKind::kTorque;
  spec.torque_ends = true;
  spec.torque_axis = 0;
  spec.torque_limit_pct = 35.0;
  b.skip(10.0, 600.0, spec);
  b.tick();
  const auto running = b.tick();
  EXPECT_EQ(running.torque_limit_pct[0], 35.0);
  EXPECT_TRUE(running.torque_limited);
  b.tick({}, 40.0);
  for (int i = 0; i < 5; ++i) b.tick();
  const auto done = b.tick();
  EXPECT_EQ(done.torque_limit_pct[0], 0.0) << "released when the block is done";
  EXPECT_FALSE(done.torque_limited);
}

TEST(KernelSkip, FixedFeedSkipIgnoresOverrideButNotFeedHold) {
  Bench b;
  kernel::OperatorState op;
  op.override_pct = 50.0;
  b.kernel().set_operator(op);
  canon::SkipSpec spec;
  spec.feed_fixed = true;
  b.skip(10.0, 600.0, spec);
  b.tick();
  EXPECT_NEAR(b.tick().path_speed, 10.0, 1e-9) << "100 %";
  op.feed_hold = true;
  b.kernel().set_operator(op);
  double v = 10.0;
  for (int i = 0; i < 20; ++i) v = b.tick().path_speed;
  EXPECT_EQ(v, 0.0) << "feed hold stops the skip move";
}

TEST(KernelSkip, OverrideActsOnASkipWhoseFeedIsNotFixed) {
  Bench b;
  kernel::OperatorState op;
  op.override_pct = 50.0;
  b.kernel().set_operator(op);
  canon::SkipSpec spec;
  spec.feed_fixed = false;
  b.skip(10.0, 600.0, spec);
  double v = 0.0;
  for (int i = 0; i < 10; ++i) v = b.tick().path_speed;
  EXPECT_NEAR(v, 5.0, 1e-9);
}

TEST(KernelSkip, LockedAxesAreInPositionWhateverTheirActualPosition) {
  auto m = config::builtin_machine("mill3");
  kernel::Kernel k(kernel::kernel_config(*m));
  k.set_position(AxisVec{});
  AxisMask all;
  for (int i = 0; i < 3; ++i) all.set(i);
  k.set_locked_axes(all);
  canon::Skip s;
  s.target[2] = -2.0;
  s.feed_mm_per_min = 600.0;
  s.spec.input_count = 1;
  s.spec.inputs[0] = kSkip;
  s.spec.ignore_inputs = true;
  ASSERT_TRUE(k.push(canon::Stamped{s, 1}));
  kernel::TickInput in;  // the axes never move
  kernel::TickOutput out;
  for (int i = 0; i < 1000 && !k.skip().done; ++i) {
    in.edge_count = 0;
    if (i == 50) {
      in.edges[0] = kernel::SignalEdge{kSkip, true, 0.5};
      in.edge_count = 1;
    }
    k.tick(in, out);
  }
  ASSERT_TRUE(k.skip().done);
  EXPECT_FALSE(k.skip().triggered) << "the input is ignored";
  EXPECT_NEAR(k.skip().stop_position[2], -2.0, 1e-12);
}

}  // namespace
}  // namespace skipnc
