// skip-rules.md 5.5: stopping and the next block (rules 27-32).
#include <gtest/gtest.h>

#include <cmath>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

constexpr double kPeriod = 0.001;
constexpr double kAccel = 2000.0;  // mill3, every axis

struct StopCase {
  const char* dialect;
  const char* param;  // "" or a --param setting
  bool decelerates;
};

class StopRule : public ::testing::TestWithParam<StopCase> {};

TEST_P(StopRule, rule_27_stop_position_against_the_latched_position) {
  const StopCase& c = GetParam();
  const double feed = 3000.0, v = feed / 60.0;
  Rig r(c.dialect);
  r.machine(ideal_servo).trigger("X0.4", 'X', 23.4567, false);
  if (*c.param != '\0') r.param(c.param);
  // The Fanuc SKF = 1 case accelerates at the start: the trigger is far
  // enough for the full feed.
  const Outcome o = r.run("G21 G90 G54 G31 X80. F3000.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().position[0], 23.4567, kUm);
  const double past = o.skip().end_position[0] - o.skip().position[0];
  if (c.decelerates) {
    EXPECT_NEAR(past, v * v / (2.0 * kAccel), v * kPeriod) << "linear deceleration";
  } else {
    EXPECT_GE(past, 0.0);
    EXPECT_LE(past, v * kPeriod + kUm) << "immediate stop: within one period of travel";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Settings, StopRule,
    ::testing::Values(StopCase{"fanuc", "6200#7=0", false}, StopCase{"fanuc", "6200#7=1", true},
                      StopCase{"mitsubishi", "", false}, StopCase{"nct", "", true},
                      StopCase{"compass", "", true}),
    [](const auto& case_info) {
      const StopCase& c = case_info.param;
      return std::string(c.dialect) + (*c.param != '\0' ? (c.decelerates ? "_skf1" : "_skf0") : "");
    });

TEST(Rules, rule_28_nct_next_interpolation_starts_from_the_end_point_not_the_latch) {
  const Outcome o = Rig("nct")
                        .machine(ideal_servo)
                        .trigger("X0.4", 'X', 20.0, false)
                        .run(
                            "G21 G90 G54 G31 X80. F3000.\n"
                            "#100 = #5001\n#101 = #5061\n"
                            "G91 G1 X10. F1000.\n"
                            "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  const double v = 50.0;
  EXPECT_GT(o.var(100) - o.var(101), v * v / (2 * kAccel) - v * kPeriod);
  EXPECT_NEAR(o.r.final_work[0], o.var(100) + 10.0, kUm) << "from #5001";
}

TEST(Rules, rule_29_incremental_next_block_starts_where_motion_stopped) {
  // mill3_lowgain's servo lags v/kp = 0.56 mm at F1000: the axis comes to rest past
  // the latch, and the increment counts from there.
  const Outcome o = Rig("fanuc")
                        .trigger("X0.4", 'Z', -3.0)
                        .run("G21 G90 G54 G31 Z-10. F1000.\nG91 G1 Z5. F500.\nM30\n");
  ASSERT_TRUE(o.completed());
  const double stop = o.skip().end_position[2];
  EXPECT_NEAR(o.skip().position[2], -3.0, kUm);
  EXPECT_LT(stop, -3.5) << "the stop is measurably past the latch";
  EXPECT_NEAR(o.r.final_work[2], stop + 5.0, kUm);
}

TEST(Rules, rule_30_absolute_one_axis_next_block_moves_only_that_axis) {
  const Outcome o = Rig("fanuc")
                        .trigger("X0.4", 'X', 12.0, false)
                        .traced()
                        .run("G21 G90 G54 G31 X50. Y50. F600.\nG1 Y0 F600.\nM30\n");
  ASSERT_TRUE(o.completed());
  const double stop_x = o.skip().end_position[0];
  EXPECT_NEAR(o.r.final_work[0], stop_x, kUm) << "X stays at the skip stop position";
  EXPECT_NEAR(o.r.final_work[1], 0.0, kUm);
  for (const auto& s : o.trace) {
    if (s.line == 2) {
      EXPECT_NEAR(s.cmd[0], stop_x, kUm);
    }
  }
}

TEST(Rules, rule_31_absolute_two_axes_next_block_is_a_straight_line_from_the_stop) {
  const Outcome o = Rig("fanuc")
                        .trigger("X0.4", 'X', 12.0, false)
                        .traced()
                        .run("G21 G90 G54 G31 X50. Y50. F600.\nG1 X40. Y-10. F600.\nM30\n");
  ASSERT_TRUE(o.completed());
  const double x0 = o.skip().end_position[0], y0 = o.skip().end_position[1];
  int n = 0;
  for (const auto& s : o.trace) {
    if (s.line != 2) continue;
    ++n;
    // Collinear with (x0, y0) -> (40, -10).
    const double cross = (s.cmd[0] - x0) * (-10.0 - y0) - (s.cmd[1] - y0) * (40.0 - x0);
    EXPECT_NEAR(cross, 0.0, 1e-6);
  }
  EXPECT_GT(n, 100);
  EXPECT_NEAR(o.r.final_work[0], 40.0, kUm);
  EXPECT_NEAR(o.r.final_work[1], -10.0, kUm);
}

TEST(Rules, rule_32_compass_g31_blocks_the_next_block_until_active_is_reset) {
  const Outcome o = Rig("compass")
                        .trigger("X0.4", 'X', 5.0, false)
                        .traced()
                        .run("G21 G90 G54 G1 X1. F600.\nG31 X20.\nG1 Y5.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  double active_from = -1, recorded_at = -1, done_at = -1, next_at = -1;
  for (const auto& s : o.trace) {
    if (s.hs.active && active_from < 0) active_from = s.t;
    if (s.hs.recorded && recorded_at < 0) recorded_at = s.t;
    if (s.hs.done && done_at < 0) done_at = s.t;
    if (s.line == 3 && next_at < 0) next_at = s.t;
  }
  ASSERT_GT(active_from, 0.0);
  ASSERT_GT(recorded_at, active_from);
  EXPECT_GE(done_at, recorded_at) << "positions recorded before the block is done";
  EXPECT_GT(next_at, done_at) << "the next block moves only after Active is reset";
  // While Active, the command never leaves the line of the G31 move.
  for (const auto& s : o.trace) {
    if (s.hs.active) {
      EXPECT_NEAR(s.cmd[1], 0.0, kUm);
    }
  }
}

}  // namespace
}  // namespace skipnc::rules
