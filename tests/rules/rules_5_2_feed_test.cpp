// skip-rules.md 5.2: feed, override, dry run (rules 7-12).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

// The path feed (mm/min) the trace shows in the middle of a source line's motion.
double cruise_feed_on(const Outcome& o, std::uint32_t line) {
  std::vector<double> f;
  for (const auto& s : o.trace) {
    if (s.line == line && s.feed_mm_min > 0.0) f.push_back(s.feed_mm_min);
  }
  return f.empty() ? 0.0 : f[f.size() / 2];
}

// The feed of the first full servo period of a line's motion. (The period
// in which a block begins still runs at the previous block's override and
// dry-run scale: the time scale is set once per period.)
double first_feed_on(const Outcome& o, std::uint32_t line) {
  bool seen = false;
  for (const auto& s : o.trace) {
    if (s.line != line || s.feed_mm_min <= 0.0) continue;
    if (seen) return s.feed_mm_min;
    seen = true;
  }
  return 0.0;
}

TEST(Rules, rule_07_mitsubishi_f_in_the_block_is_used_and_the_modal_f_is_kept) {
  const Outcome o = Rig("mitsubishi")
                        .traced()
                        .run(
                            "G21 G90 G54 G1 X1. F300.\n"
                            "G31 X20. F100.\n"
                            "G1 X30.\n"
                            "#100 = #4109\n"
                            "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(cruise_feed_on(o, 2), 100.0, 1e-6) << "G31 runs at its own F";
  EXPECT_NEAR(cruise_feed_on(o, 3), 300.0, 1e-6) << "the next G01 keeps the F from before";
  EXPECT_NEAR(o.var(100), 300.0, 1e-9) << "#4109 (modal F) is not updated by G31";
}

TEST(Rules, rule_07_mitsubishi_no_f_uses_parameter_1174_skip_f) {
  const Outcome o = Rig("mitsubishi")
                        .param("1174=250")
                        .traced()
                        .run("G21 G90 G54 G1 X1. F300.\nG31 X20.\nG1 X30.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(cruise_feed_on(o, 2), 250.0, 1e-6);
  EXPECT_NEAR(cruise_feed_on(o, 3), 300.0, 1e-6);
}

TEST(Rules, rule_08_mitsubishi_no_f_and_skip_f_zero_is_p603) {
  const Outcome o = Rig("mitsubishi").run("G21 G90 G54 G1 X1. F300.\nG31 X20.\nM30\n");
  EXPECT_EQ(o.r.status, sim::RunStatus::kAlarm);
  EXPECT_EQ(o.alarm_number(), 603);
  EXPECT_EQ(o.alarm_code(), "P603");
  EXPECT_EQ(o.alarm_line(), 2U);
}

TEST(Rules, rule_09_nct_skipf_0_uses_the_specified_or_modal_f) {
  const Outcome o = Rig("nct")
                        .param("90101=0")
                        .param("90102=40")
                        .traced()
                        .run("G21 G90 G54 G1 X1. F300.\nG31 X20.\nG31 X40. F150.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(cruise_feed_on(o, 2), 300.0, 1e-6) << "modal F";
  EXPECT_NEAR(cruise_feed_on(o, 3), 150.0, 1e-6) << "specified F";
}

TEST(Rules, rule_09_nct_skipf_1_uses_g31fd_whatever_f_says) {
  const Outcome o = Rig("nct")
                        .param("90101=1")
                        .param("90102=40")
                        .traced()
                        .run("G21 G90 G54 G1 X1. F300.\nG31 X5.\nG31 X10. F150.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(cruise_feed_on(o, 2), 40.0, 1e-6);
  EXPECT_NEAR(cruise_feed_on(o, 3), 40.0, 1e-6);
}

TEST(Rules, rule_10_compass_f_omitted_uses_the_last_non_rapid_feed) {
  // The F12000 of the G0 block (as in the manual's example) is a rapid's.
  const char* program = "G21 G90 G54 G1 X1. F300.\nG0 X2. F12000.\nG31 X20.\nM30\n";
  const Outcome o = Rig("compass").traced().run(program);
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(cruise_feed_on(o, 3), 300.0, 1e-6);
  // The Fanuc rule for comparison: the modal F, whichever block set it.
  const Outcome f = Rig("fanuc").traced().run(program);
  ASSERT_TRUE(f.completed());
  EXPECT_NEAR(cruise_feed_on(f, 3), 12000.0, 1e-6);
}

// Override 50 % and dry run at 3000 mm/min from the start.
const char* kOperatorScene = "[[operator]]\nat_time = 0.0\noverride = 50\ndry_run = true\n";

TEST(Rules, rule_11_skf_0_override_dry_run_and_acceleration_do_not_act_on_g31) {
  const Outcome o = Rig("fanuc")
                        .param("6200#7=0")
                        .param("1410=3000")
                        .scene(kOperatorScene)
                        .traced()
                        .run("G21 G90 G54 G1 X1. F600.\nG31 X60. F6000.\nG1 X0 F600.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(cruise_feed_on(o, 2), 6000.0, 1e-6) << "override and dry run ignored";
  EXPECT_NEAR(first_feed_on(o, 2), 6000.0, 1e-6) << "no acceleration: F from the first period";
  EXPECT_NEAR(cruise_feed_on(o, 3), 1500.0, 1e-6) << "a G01 block: dry run 3000 x 50 %";
}

TEST(Rules, rule_11_skf_1_override_dry_run_and_acceleration_act_on_g31) {
  const Outcome o = Rig("fanuc")
                        .param("6200#7=1")
                        .param("1410=3000")
                        .scene(kOperatorScene)
                        .traced()
                        .run("G21 G90 G54 G1 X1. F600.\nG31 X60. F6000.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(cruise_feed_on(o, 2), 1500.0, 1e-6) << "dry run 3000 x 50 %";
  EXPECT_LT(first_feed_on(o, 2), 500.0) << "the move accelerates (2000 mm/s^2)";
}

TEST(Rules, rule_11_skf_0_override_zero_does_not_stop_g31) {
  const Outcome o = Rig("fanuc")
                        .scene("[[operator]]\nat_time = 0.0\noverride = 0\n")
                        .run("G21 G90 G54 G31 X5. F600.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.r.final_work[0], 5.0, kUm);
}

TEST(Rules, rule_12_mitsubishi_override_is_100_percent_and_dry_run_is_invalid_in_g31) {
  const Outcome o = Rig("mitsubishi")
                        .param("90013=3000")
                        .scene(kOperatorScene)
                        .traced()
                        .run("G21 G90 G54 G1 X1. F600.\nG31 X60. F6000.\nG1 X0\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(cruise_feed_on(o, 2), 6000.0, 1e-6);
  EXPECT_NEAR(first_feed_on(o, 2), 6000.0, 1e-6) << "(2) no automatic acceleration";
  EXPECT_NEAR(cruise_feed_on(o, 3), 1500.0, 1e-6) << "G01 obeys dry run and override";
}

// The time the commanded X spends at rest inside line 1 while it has not
// reached its end point.
double held_seconds(const Outcome& o, double end_x) {
  double held = 0.0;
  for (std::size_t i = 1; i < o.trace.size(); ++i) {
    const auto& s = o.trace[i];
    if (s.line == 1 && s.cmd[0] == o.trace[i - 1].cmd[0] && s.cmd[0] > 0.0 && s.cmd[0] < end_x) {
      held += 0.001;
    }
  }
  return held;
}

TEST(Rules, rule_12_mitsubishi_feed_hold_and_interlock_still_stop_g31) {
  const Outcome o = Rig("mitsubishi")
                        .scene(
                            "[[operator]]\nat_time = 0.5\nfeed_hold = true\n"
                            "[[operator]]\nat_time = 1.0\nfeed_hold = false\n"
                            "[[operator]]\nat_time = 1.5\ninterlock = true\n"
                            "[[operator]]\nat_time = 2.0\ninterlock = false\n")
                        .traced()
                        .run("G21 G90 G54 G31 X50. F600.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.r.final_work[0], 50.0, kUm) << "the block resumes and ends at its end point";
  EXPECT_NEAR(held_seconds(o, 50.0), 1.0, 0.01) << "0.5 s feed hold + 0.5 s interlock";
  EXPECT_GT(o.r.time_s, 6.0) << "50 mm at 10 mm/s plus 1 s held";
}

TEST(Rules, rule_12_mitsubishi_override_zero_stops_g31) {
  const Outcome o = Rig("mitsubishi")
                        .scene(
                            "[[operator]]\nat_time = 0.5\noverride = 0\n"
                            "[[operator]]\nat_time = 1.5\noverride = 30\n")
                        .traced()
                        .run("G21 G90 G54 G31 X20. F600.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(held_seconds(o, 20.0), 1.0, 0.01) << "stopped while the override is 0 %";
  EXPECT_NEAR(cruise_feed_on(o, 1), 600.0, 1e-6) << "30 % is not applied: fixed at 100 %";
}

TEST(Rules, rule_12_mitsubishi_stroke_end_still_stops_g31) {
  const Outcome o = Rig("mitsubishi").run("G21 G90 G54 G31 X600. F3000.\nM30\n");
  EXPECT_EQ(o.r.status, sim::RunStatus::kAlarm);
  EXPECT_EQ(o.alarm_id(), AlarmId::kStrokeLimit);
  EXPECT_LE(o.r.final_machine[0], 500.0 + 0.05 + kUm) << "stopped at the +X stroke end";
}

}  // namespace
}  // namespace skipnc::rules
