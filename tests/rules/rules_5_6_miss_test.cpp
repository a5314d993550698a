// skip-rules.md 5.6: miss behaviour and special states (rules 33-36).
#include <gtest/gtest.h>

#include <cmath>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

TEST(Rules, rule_33_k1_alarms_when_the_block_ends_without_a_skip) {
  const Outcome o = Rig().run("G21 G90 G54 G31 Z-5. F600. K1\nG1 X5.\nM30\n");
  EXPECT_EQ(o.r.status, sim::RunStatus::kAlarm);
  EXPECT_EQ(o.alarm_id(), AlarmId::kSkipMiss);
  EXPECT_EQ(o.alarm_code(), "SN9032");
  EXPECT_EQ(o.alarm_line(), 1U);
  EXPECT_NEAR(o.r.final_work[0], 0.0, kUm) << "the next block does not run";
  EXPECT_NEAR(o.r.final_work[2], -5.0, kUm);
}

TEST(Rules, rule_33_k0_no_alarm_when_the_block_ends_without_a_skip) {
  const Outcome o = Rig().param("90001=1").run("G21 G90 G54 G31 Z-5. F600. K0\nG1 X5.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.r.final_work[0], 5.0, kUm);
}

TEST(Rules, rule_33_k1_with_a_skip_is_no_alarm) {
  const Outcome o = Rig().trigger("X0.4", 'Z', -2.0).run("G21 G90 G54 G31 Z-5. F600. K1\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_TRUE(o.skip().triggered);
}

TEST(Rules, rule_33_k_omitted_parameter_90001_0_no_alarm) {
  const Outcome o = Rig().param("90001=0").run("G21 G90 G54 G31 Z-5. F600.\nM30\n");
  EXPECT_TRUE(o.completed()) << o.alarm_code();
}

TEST(Rules, rule_33_k_omitted_parameter_90001_1_alarm) {
  const Outcome o = Rig().param("90001=1").run("G21 G90 G54 G31 Z-5. F600.\nM30\n");
  EXPECT_EQ(o.alarm_id(), AlarmId::kSkipMiss);
}

TEST(Rules, rule_33_k_other_than_0_or_1_is_refused) {
  const Outcome o = Rig().run("G21 G90 G54 G31 Z-5. F600. K2\nM30\n");
  EXPECT_EQ(o.alarm_id(), AlarmId::kSkipSyntax);
}

class MissCompletes : public ::testing::TestWithParam<const char*> {};

TEST_P(MissCompletes, rule_34_a_miss_completes_normally_and_the_next_block_runs) {
  const Outcome o = Rig(GetParam()).run("G21 G90 G54 G31 Z-5. F600.\nG91 G1 X5. F600.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_FALSE(o.skip().triggered);
  EXPECT_NEAR(o.r.final_work[0], 5.0, kUm);
  EXPECT_NEAR(o.r.final_work[2], -5.0, kUm);
}

TEST_P(MissCompletes, rule_34_k_is_not_an_address_of_g31_there) {
  const Outcome o = Rig(GetParam()).run("G21 G90 G54 G31 Z-5. F600. K1\nM30\n");
  EXPECT_EQ(o.alarm_id(), AlarmId::kSkipSyntax);
}

INSTANTIATE_TEST_SUITE_P(Dialects, MissCompletes, ::testing::Values("mitsubishi", "compass"),
                         [](const auto& case_info) { return std::string(case_info.param); });

// A pulse on the skip input at 0.2 s, during a 1 s G31 move.
Rig pulse_during(const char* dialect) {
  Rig r(dialect);
  r.pulse("X0.4", 0.2, 0.05);
  return r;
}

TEST(Rules, rule_35_mitsubishi_machine_lock_ignores_the_skip_signal) {
  const Outcome o = pulse_during("mitsubishi")
                        .param("90010=1")
                        .run("G21 G90 G54 G31 Z-10. F600.\n#100=#5063\n#101=#5023\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_FALSE(o.skip().triggered);
  EXPECT_NEAR(o.var(100), -10.0, kUm) << "#5063: the block's end point, as after any miss";
  EXPECT_NEAR(o.var(101), 0.0, kUm) << "#5023: the machine stands still";
  EXPECT_NEAR(o.skip().end_position[2], -10.0, kUm) << "runs to the end of the block";
  EXPECT_NEAR(o.r.final_machine[2], 0.0, kUm)
      << "the report's machine position is where the machine stands (the command moved)";
}

TEST(Rules, rule_35_mitsubishi_z_cancel_ignores_the_skip_for_a_z_only_g31) {
  const Outcome z =
      pulse_during("mitsubishi").param("90011=1").run("G21 G90 G54 G31 Z-10. F600.\nM30\n");
  ASSERT_TRUE(z.completed()) << z.alarm_code();
  EXPECT_FALSE(z.skip().triggered);
  const Outcome xz =
      pulse_during("mitsubishi").param("90011=1").run("G21 G90 G54 G31 X10. Z-10. F600.\nM30\n");
  ASSERT_TRUE(xz.completed()) << xz.alarm_code();
  EXPECT_TRUE(xz.skip().triggered) << "not a Z-only command: the signal counts";
}

TEST(Rules, rule_35_mitsubishi_without_lock_the_pulse_skips) {
  const Outcome o = pulse_during("mitsubishi").run("G21 G90 G54 G31 Z-10. F600.\nM30\n");
  ASSERT_TRUE(o.completed());
  EXPECT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().time_s, 0.2, 1e-9);
}

TEST(Rules, rule_35_fanuc_machine_lock_still_monitors_the_skip_signal) {
  const Outcome o =
      pulse_during("fanuc").param("90010=1").run("G21 G90 G54 G31 Z-10. F600.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_TRUE(o.skip().triggered) << "the manual does not say otherwise";
  EXPECT_NEAR(o.skip().time_s, 0.2, 1e-9);
}

// Machine lock on a control that still monitors the skip: the machine does
// not move, the command does. The skip stores the command at the signal --
// the work position the control counts, as #5043 shows -- while the machine
// coordinates stay where the machine stands (skipnc's decision where no
// manual says: base.toml skip_locked_stores_command). Was: #5063 = 0, the
// machine's position, beside #5043 = -1.99.
TEST(Rules, rule_35_fanuc_machine_lock_stores_the_command_at_the_signal) {
  const char* program = "G21 G90 G54 G31 Z-10. F600.\n#100=#5063\n#101=#5023\n#102=#5043\nM30\n";
  const Outcome o = pulse_during("fanuc").param("90010=1").run(program);
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  // 10 mm/s without acceleration (SKF = 0) for 0.2 s, less the period in
  // which the block starts.
  EXPECT_NEAR(o.var(100), -1.99, kUm);
  EXPECT_NEAR(o.var(101), 0.0, kUm) << "the machine stands still";
  EXPECT_NEAR(o.var(102), -1.99, kUm) << "the work position follows the command";
  const Outcome machine =
      pulse_during("fanuc")
          .param("90010=1")
          .switches([](config::Switches& sw) { sw.skip_locked_stores_command = false; })
          .run(program);
  ASSERT_TRUE(machine.completed()) << machine.alarm_code();
  EXPECT_NEAR(machine.var(100), 0.0, kUm) << "the switch off: where the machine stands";
}

// Z-axis cancel holds Z only: X stores its actual position at the signal
// (servo delay compensated), Z its command.
TEST(Rules, rule_35_fanuc_z_cancel_stores_the_command_of_the_held_axis_only) {
  const Outcome o = pulse_during("fanuc").param("90011=1").run(
      "G21 G90 G54 G31 X10. Z-10. F600.\n#100=#5061\n#101=#5063\n#102=#5021\n#103=#5023\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  // Along X10 Z-10 at 10 mm/s: each axis at 10/sqrt(2) mm/s.
  const double along = 1.99 / std::sqrt(2.0);
  EXPECT_NEAR(o.var(101), -along, kUm) << "Z: the command";
  EXPECT_NEAR(o.var(103), 0.0, kUm) << "Z does not move";
  EXPECT_NEAR(o.var(100), o.skip().machine_position[0], kUm);
  EXPECT_LT(o.var(100), along) << "X: the actual position, behind the command";
  EXPECT_GT(o.var(100), 0.0);
}

void g54_x100(config::MachineConfig& m) {
  m.work_offsets[1][0] = 100.0;
}

TEST(Rules, rule_36_compass_g31_g53_targets_machine_coordinates) {
  const Outcome o =
      Rig("compass").machine(g54_x100).run("G21 G90 G54 G0 X0 Y0 Z0\nG31 G53 X-50. F3000.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.r.final_machine[0], -50.0, kUm);
}

TEST(Rules, rule_36_compass_g31_and_g31_g1_target_the_local_system) {
  const Outcome o = Rig("compass").machine(g54_x100).run(
      "G21 G90 G54 G0 X0 Y0 Z0\nG31 X-50. F3000.\n#100 = #5021\nG31 G1 X-20.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), 50.0, kUm);
  EXPECT_NEAR(o.r.final_machine[0], 80.0, kUm);
}

TEST(Rules, rule_36_g31_g53_is_refused_where_the_manual_has_no_such_form) {
  const Outcome o = Rig("fanuc").run("G21 G90 G54 G31 G53 X-50. F3000.\nM30\n");
  EXPECT_EQ(o.alarm_id(), AlarmId::kSkipSyntax);
}

}  // namespace
}  // namespace skipnc::rules
