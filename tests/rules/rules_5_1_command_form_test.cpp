// skip-rules.md 5.1: command form and modality (rules 1-6).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

constexpr double kUm = 1e-6;

// Highest path feed (mm/min) the trace shows on a source line.
double max_feed_on(const Outcome& o, std::uint32_t line) {
  double f = 0.0;
  for (const auto& s : o.trace) {
    if (s.line == line) f = std::max(f, s.feed_mm_min);
  }
  return f;
}

TEST(Rules, rule_01_g31_is_one_shot_next_block_in_previous_motion_modal_without_monitoring) {
  // X0.4 is on while X > 15. The G31 block ends at X10 without it; the next
  // block (no G31) moves on in the G00 modal from before and crosses the
  // trigger without any skip.
  const Outcome o = Rig()
                        .trigger("X0.4", 'X', 15.0, false)
                        .traced()
                        .run(
                            "G21 G90 G54 G0 X0 Y0 Z0\n"
                            "G31 X10. F100.\n"
                            "X20.\n"
                            "M30\n");
  ASSERT_TRUE(o.completed());
  ASSERT_EQ(o.skip_count(), 1U);
  EXPECT_FALSE(o.skip().triggered);
  EXPECT_NEAR(o.r.final_work[0], 20.0, kUm);
  EXPECT_NEAR(max_feed_on(o, 2), 100.0, 1e-6);
  EXPECT_GT(max_feed_on(o, 3), 1000.0) << "line 3 runs as a rapid (G00 modal)";
}

TEST(Rules, rule_02_g31_interpolates_a_straight_line_like_g01) {
  const Outcome o = Rig().traced().run("G21 G90 G54 G0 X0 Y0 Z0\nG31 X30. Y40. F600.\nM30\n");
  ASSERT_TRUE(o.completed());
  int inside = 0;
  for (const auto& s : o.trace) {
    if (s.line != 2 || s.cmd[0] <= 0.0 || s.cmd[0] >= 30.0) continue;
    ++inside;
    EXPECT_NEAR(s.cmd[1] * 3.0, s.cmd[0] * 4.0, 1e-9) << "on the line from (0,0) to (30,40)";
  }
  EXPECT_GT(inside, 4000);  // 50 mm at 10 mm/s
  EXPECT_NEAR(max_feed_on(o, 2), 600.0, 1e-6) << "F is the path feed";
  EXPECT_NEAR(o.r.final_work[0], 30.0, kUm);
  EXPECT_NEAR(o.r.final_work[1], 40.0, kUm);
}

TEST(Rules, rule_03_g31_axis_words_follow_g90_g91) {
  const Outcome o = Rig().run(
      "G21 G90 G54 G0 X10. Y0 Z0\n"
      "G91 G31 X-5. F500.\n"
      "G90 G31 X-5. F500.\n"
      "M30\n");
  ASSERT_TRUE(o.completed());
  ASSERT_EQ(o.skip_count(), 2U);
  EXPECT_NEAR(o.skip(0).position[0], 5.0, kUm) << "incremental: 10 - 5";
  EXPECT_NEAR(o.skip(1).position[0], -5.0, kUm) << "absolute";
}

class AllDialects : public ::testing::TestWithParam<const char*> {};

TEST_P(AllDialects, rule_04_inactive_input_block_ends_at_its_programmed_end_point) {
  const Outcome o =
      Rig(GetParam()).run("G21 G90 G54 G0 X0 Y0 Z0\nG31 X12.5 Y-3. Z-4. F300.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_EQ(o.skip_count(), 1U);
  EXPECT_FALSE(o.skip().triggered);
  EXPECT_NEAR(o.skip().end_position[0], 12.5, kUm);
  EXPECT_NEAR(o.skip().end_position[1], -3.0, kUm);
  EXPECT_NEAR(o.skip().end_position[2], -4.0, kUm);
  EXPECT_NEAR(o.skip().position[2], -4.0, kUm) << "no signal: the programmed end point is stored";
}

TEST_P(AllDialects, rule_05_active_input_discards_the_rest_and_runs_the_next_block) {
  const Outcome o = Rig(GetParam())
                        .trigger("X0.4", 'Z', -3.0)
                        .run("G21 G90 G54 G0 X0 Y0 Z0\nG31 Z-10. F300.\nG91 G1 X5. F500.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_EQ(o.skip_count(), 1U);
  EXPECT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().position[2], -3.0, kUm);
  EXPECT_GT(o.skip().end_position[2], -3.2) << "the rest of the move to Z-10 is discarded";
  EXPECT_NEAR(o.r.final_work[0], 5.0, kUm) << "the next block ran";
  EXPECT_NEAR(o.r.final_work[2], o.skip().end_position[2], kUm);
}

INSTANTIATE_TEST_SUITE_P(Dialects, AllDialects,
                         ::testing::Values("fanuc", "nct", "mitsubishi", "compass", "haas"),
                         [](const auto& case_info) { return std::string(case_info.param); });

struct CompAlarm {
  const char* dialect;
  int number;
  const char* code;
};

class CutterComp : public ::testing::TestWithParam<CompAlarm> {};

TEST_P(CutterComp, rule_06_g31_in_g41_g42_is_refused_with_the_dialects_alarm) {
  const CompAlarm& c = GetParam();
  // Mitsubishi has no F fallback without #1174: F is in the block.
  const Outcome o = Rig(c.dialect).run(
      "G21 G90 G54 G0 X0 Y0 Z0\n"
      "G41 D1 G1 X10. F100.\n"
      "G31 Z-10. F100.\n"
      "M30\n");
  EXPECT_EQ(o.r.status, sim::RunStatus::kAlarm);
  EXPECT_EQ(o.alarm_id(), AlarmId::kSkipInCutterComp);
  EXPECT_EQ(o.alarm_number(), c.number);
  EXPECT_EQ(o.alarm_code(), c.code);
  EXPECT_EQ(o.alarm_line(), 3U);
  EXPECT_EQ(o.skip_count(), 0U);
  // After G40 the same block runs.
  const Outcome ok = Rig(c.dialect).run(
      "G21 G90 G54 G0 X0 Y0 Z0\n"
      "G41 D1 G1 X10. F100.\n"
      "G40 G1 X20.\n"
      "G31 Z-1. F100.\n"
      "M30\n");
  EXPECT_TRUE(ok.completed()) << ok.alarm_code();
}

INSTANTIATE_TEST_SUITE_P(
    Dialects, CutterComp,
    ::testing::Values(CompAlarm{"fanuc", 35, "PS0035"}, CompAlarm{"mitsubishi", 608, "P608"},
                      CompAlarm{"nct", 9030, "SN9030"}, CompAlarm{"compass", 9030, "SN9030"}),
    [](const auto& case_info) { return std::string(case_info.param.dialect); });

}  // namespace
}  // namespace skipnc::rules
