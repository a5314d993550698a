// Kernel::push on a full queue: refused, seen by the caller, and nothing
// changed (the queued moves, the tags, the skip block's state).
#include <gtest/gtest.h>

#include "config/machine_config.hpp"
#include "kernel/kernel.hpp"
#include "kernel/kernel_config.hpp"
#include "support/axes.hpp"

namespace skipnc {
namespace {

using test::at_x;

kernel::KernelConfig small_queue() {
  kernel::KernelConfig cfg = kernel::kernel_config(*config::builtin_machine("mill3"));
  cfg.queue_capacity = 4;
  return cfg;
}

TEST(KernelQueue, PushOnAFullQueueIsRefusedAndChangesNothing) {
  kernel::Kernel k(small_queue());
  k.set_position(AxisVec{});
  for (int i = 1; i <= 4; ++i) {
    ASSERT_TRUE(k.can_push());
    ASSERT_TRUE(
        k.push({canon::Feed{at_x(10.0 * i), 1200.0, false}, static_cast<std::uint32_t>(i)}));
  }
  EXPECT_FALSE(k.can_push());
  EXPECT_FALSE(k.can_accept());
  EXPECT_EQ(k.next_tag(), 5U);

  canon::Skip s;
  s.target = at_x(100.0);
  s.feed_mm_per_min = 100.0;
  s.spec.input_count = 1;
  s.spec.inputs[0] = canon::SignalAddr{'X', 0, 4};
  EXPECT_FALSE(k.push({s, 5}));
  EXPECT_FALSE(k.push({canon::Dwell{1.0}, 6}));
  EXPECT_EQ(k.next_tag(), 5U) << "a refused command gets no tag";
  EXPECT_FALSE(k.skip().active) << "a refused skip does not start a skip block";

  // The four moves run as queued, and nothing after them.
  kernel::TickInput in;
  kernel::TickOutput out;
  std::uint32_t last_tag = 0;
  for (int i = 0; i < 100000 && !k.idle(); ++i) {
    in.actual = out.commanded;
    k.tick(in, out);
    EXPECT_GE(out.tag, last_tag);
    last_tag = out.tag;
  }
  ASSERT_TRUE(k.idle());
  EXPECT_EQ(last_tag, 4U);
  EXPECT_EQ(k.command(), at_x(40.0));
  EXPECT_TRUE(k.can_push());
}

TEST(KernelQueue, ATickThatEndsASegmentMakesRoom) {
  kernel::Kernel k(small_queue());
  k.set_position(AxisVec{});
  for (int i = 1; i <= 4; ++i) {
    ASSERT_TRUE(k.push({canon::Feed{at_x(0.01 * i), 1200.0, false}, 1}));
  }
  ASSERT_FALSE(k.can_push());
  kernel::TickInput in;
  kernel::TickOutput out;
  for (int i = 0; i < 1000 && !k.can_push(); ++i) k.tick(in, out);
  ASSERT_TRUE(k.can_push());
  EXPECT_TRUE(k.push({canon::Feed{at_x(1.0), 1200.0, false}, 1}));
}

}  // namespace
}  // namespace skipnc
