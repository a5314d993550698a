// The buffer stop as the interpreter's caller sees it (issue 14): a block
// that reads a live position after queued motion returns Step::kSync with
// nothing of it done -- no command emitted, no variable written -- and after
// sync() the same block runs with the machine's values. Waiting is a value
// of its own (NeedSync), never an alarm.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "interpreter/interpreter.hpp"
#include "support/interp_mill.hpp"

namespace skipnc::interp {
namespace {

using test::Collect;
using test::Mill;

// Where a Feed command goes, machine coordinates (NaN when `c` is not one).
double feed_target(const canon::Stamped& c, int axis) {
  const auto* f = std::get_if<canon::Feed>(&c.cmd);
  return f ? f->target[axis] : std::nan("");
}

TEST(BufferStop, ALiveReadAfterMotionWaitsAndRunsAgainWithTheMachinesValue) {
  const Mill m;
  auto in = m.start("G21 G90 G54 G1 X10. F1000.\nG1 Y#5021\n#100=#5022\nM30\n");
  ASSERT_TRUE(in);
  Collect out;
  auto st = in->step(out);  // the move
  ASSERT_TRUE(st.has_value()) << st.error().detail;
  ASSERT_EQ(out.cmds.size(), 1U);
  st = in->step(out);  // G1 Y#5021: the move has not run yet
  ASSERT_TRUE(st.has_value()) << "a wait, not an alarm: " << st.error().detail;
  EXPECT_EQ(*st, Step::kSync);
  EXPECT_EQ(out.cmds.size(), 1U) << "nothing of the block emitted";
  // The machine stopped short of the end (as after a feed hold, say).
  SyncState s;
  s.machine_position[0] = 9.5;
  s.actual_position[0] = 9.5;
  ASSERT_TRUE(in->sync(s).has_value());
  st = in->step(out);  // the same block, now with the machine's X
  ASSERT_TRUE(st.has_value()) << st.error().detail;
  ASSERT_EQ(out.cmds.size(), 2U);
  EXPECT_DOUBLE_EQ(feed_target(out.cmds[1], 1), 9.5);
  EXPECT_EQ(out.cmds[1].line, 2U);
  st = in->step(out);  // #100=#5022 waits for the Y move in turn
  ASSERT_TRUE(st.has_value()) << st.error().detail;
  EXPECT_EQ(*st, Step::kSync);
  EXPECT_TRUE(in->read_variable(100)->vacant) << "not assigned before the wait";
  s.machine_position[1] = 9.5;
  s.actual_position[1] = 9.5;
  ASSERT_TRUE(in->sync(s).has_value());
  st = in->step(out);
  ASSERT_TRUE(st.has_value()) << st.error().detail;
  EXPECT_DOUBLE_EQ(in->read_variable(100)->v, 9.5);
}

TEST(BufferStop, AReadWithoutQueuedMotionDoesNotWait) {
  const Mill m;
  auto in = m.start("G21 G90 G54\n#100=#5021\nM30\n");
  ASSERT_TRUE(in);
  Collect out;
  for (int i = 0; i < 2; ++i) {
    auto st = in->step(out);
    ASSERT_TRUE(st.has_value()) << st.error().detail;
    EXPECT_NE(*st, Step::kSync);
  }
  EXPECT_DOUBLE_EQ(in->read_variable(100)->v, 0.0);
}

}  // namespace
}  // namespace skipnc::interp
