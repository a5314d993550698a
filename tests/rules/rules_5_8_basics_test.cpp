// skip-rules.md 5.8: related basics from the textbook seed (rules 47-49).
#include <gtest/gtest.h>

#include <cmath>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

TEST(Rules, rule_47_g04_x5_calculator_type_decimal_input_is_5_seconds) {
  const Outcome o = Rig().param("3401#0=1").run("G04 X5\nM30\n");
  ASSERT_TRUE(o.completed());
  EXPECT_NEAR(o.r.time_s, 5.0, 0.0025);
}

TEST(Rules, rule_47_g04_x5_ordinary_decimal_input_is_5_milliseconds) {
  const Outcome o = Rig().param("3401#0=0").run("G04 X5\nM30\n");
  ASSERT_TRUE(o.completed());
  EXPECT_NEAR(o.r.time_s, 0.005, 0.0025);
}

TEST(Rules, rule_47_g04_is_one_shot) {
  // The block after the dwell is a move in the G00 modal, not another dwell.
  const Outcome o = Rig().param("3401#0=1").run("G0 X0\nG04 X2.\nX3.\nM30\n");
  ASSERT_TRUE(o.completed());
  EXPECT_NEAR(o.r.final_work[0], 3.0, kUm);
  EXPECT_LT(o.r.time_s, 2.5);
}

// Time (s) at which the commanded position of `axis` first equals `target`.
double arrival(const Outcome& o, int axis, double target) {
  for (const auto& s : o.trace) {
    if (std::fabs(s.cmd[axis] - target) < 1e-12) return s.t;
  }
  return -1.0;
}

TEST(Rules, rule_48_g00_linear_positioning_all_axes_arrive_together) {
  const Outcome o = Rig().param("1401#1=1").traced().run("G21 G90 G0 X100. Y10.\nM30\n");
  ASSERT_TRUE(o.completed());
  EXPECT_NEAR(arrival(o, 1, 10.0), arrival(o, 0, 100.0), 1e-9);
}

TEST(Rules, rule_48_g00_non_linear_positioning_short_axes_arrive_first) {
  const Outcome o = Rig().param("1401#1=0").traced().run("G21 G90 G0 X100. Y10.\nM30\n");
  ASSERT_TRUE(o.completed());
  EXPECT_LT(arrival(o, 1, 10.0) + 0.05, arrival(o, 0, 100.0));
}

TEST(Rules, rule_48_g00_speed_is_not_programmable) {
  const Outcome a = Rig().machine(ideal_servo).run("G21 G90 G0 X100.\nM30\n");
  const Outcome b = Rig().machine(ideal_servo).run("G21 G90 G0 X100. F10.\nM30\n");
  EXPECT_NEAR(a.r.time_s, b.r.time_s, 1e-9);
  // 100 mm with 2000 mm/s^2 never reaches the 500 mm/s rapid: 2 sqrt(100/2000) s.
  EXPECT_NEAR(a.r.time_s, 2.0 * std::sqrt(0.05), 0.003);
}

TEST(Rules, rule_49_g01_f_is_the_path_feed_modal_all_axes_arrive_together) {
  const Outcome o = Rig().traced().run("G21 G90 G1 X30. Y40. F600.\nX0 Y0\nM30\n");
  ASSERT_TRUE(o.completed());
  EXPECT_NEAR(arrival(o, 0, 30.0), arrival(o, 1, 40.0), 1e-9);
  double mid2 = 0.0;
  int n = 0;
  for (const auto& s : o.trace) {
    if (s.line == 2 && s.feed_mm_min > 599.0) {
      mid2 = s.feed_mm_min;
      ++n;
    }
  }
  EXPECT_NEAR(mid2, 600.0, 1e-6) << "F is modal: the second block runs at F600 too";
  EXPECT_GT(n, 4000) << "50 mm at 10 mm/s";
}

}  // namespace
}  // namespace skipnc::rules
