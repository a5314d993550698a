// skip-rules.md 5.7: torque limit skip G31 P98/P99 (rules 37-46).
//
// mill3_lowgain (the rigs' machine): kp 30/s, no feedforward, torque = 100 %/mm of following error.
// At F300 (5 mm/s) the free-running lag is 5/30 mm, 16.7 % torque. A [[stop]] at Z-3 holds the
// axis; the command runs on and the torque grows by 500 %/s until it reaches the limit Q.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

Rig against_stop() {
  Rig r("fanuc");
  r.stop('Z', -3.0).traced();
  return r;
}

double max_torque_z(const Outcome& o, std::uint32_t line) {
  double t = 0.0;
  for (const auto& s : o.trace) {
    if (s.line == line) t = std::max(t, std::fabs(s.torque[2]));
  }
  return t;
}

TEST(Rules, rule_37_q_is_the_torque_limit_override) {
  const Outcome o = against_stop().run("G21 G90 G54 G31 P98 Z-10. F300. Q40\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_EQ(o.skip().signal, "TORQUE");
  EXPECT_EQ(o.skip().kind, canon::SkipKind::kTorque);
  EXPECT_NEAR(max_torque_z(o, 1), 40.0, 1e-9) << "the motor torque is limited to Q";
}

TEST(Rules, rule_37_q_omitted_uses_parameter_6280) {
  const Outcome o = against_stop().param("6280=70").run("G21 G90 G54 G31 P98 Z-10. F300.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(max_torque_z(o, 1), 70.0, 1e-9);
}

TEST(Rules, rule_37_q_outside_1_to_300_is_refused) {
  for (const char* q : {"Q0", "Q301"}) {
    const Outcome o = Rig().run(std::string("G21 G90 G54 G31 P98 Z-10. F300. ") + q + "\nM30\n");
    EXPECT_EQ(o.alarm_id(), AlarmId::kTorqueSkipBadQ) << q;
  }
}

TEST(Rules, rule_38_p98_skips_on_the_torque_limit_only_not_on_the_skip_input) {
  const Outcome o =
      against_stop().pulse("X0.4", 0.2, 0.05).run("G21 G90 G54 G31 P98 Z-10. F300. Q40\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_EQ(o.skip().signal, "TORQUE");
  EXPECT_GT(o.skip().time_s, 0.6) << "not at the 0.2 s pulse";
  EXPECT_NEAR(o.var(5063), -3.0, kUm);
}

TEST(Rules, rule_39_p99_skips_on_the_skip_input) {
  const Outcome o =
      against_stop().pulse("X0.4", 0.2, 0.05).run("G21 G90 G54 G31 P99 Z-10. F300. Q40\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_EQ(o.skip().signal, "X0.4");
  EXPECT_NEAR(o.skip().time_s, 0.2, 1e-9);
}

TEST(Rules, rule_39_p99_skips_on_the_torque_limit) {
  const Outcome o = against_stop().run("G21 G90 G54 G31 P99 Z-10. F300. Q40\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_EQ(o.skip().signal, "TORQUE");
}

TEST(Rules, rule_40_p98_p99_with_no_axis_or_two_axes_is_alarm_015) {
  for (const char* block : {"G31 P99 X5. Z-10. F300.", "G31 P98 F300.", "G31 P98 X1. Y1. F300."}) {
    const Outcome o = Rig().run(std::string("G21 G90 G54 ") + block + "\nM30\n");
    EXPECT_EQ(o.alarm_id(), AlarmId::kTorqueSkipAxes) << block;
    EXPECT_EQ(o.alarm_number(), 15) << block;
    EXPECT_EQ(o.alarm_code(), "PS0015") << block;
  }
}

TEST(Rules, rule_41_p98_p99_in_g41_g42_is_refused) {
  const Outcome o = Rig().run("G21 G90 G54 G42 D1 G1 X10. F100.\nG31 P99 Z-10. F300.\nM30\n");
  EXPECT_EQ(o.alarm_id(), AlarmId::kTorqueSkipCutterComp);
  EXPECT_EQ(o.alarm_code(), "PS0035");
  EXPECT_EQ(o.alarm_line(), 2U);
}

TEST(Rules, rule_42_p98_p99_on_an_axis_under_synchronous_control_is_refused) {
  // Parameter 90012: bit 2 = the third axis (Z) is synchronised.
  const Outcome z = Rig().param("90012=4").run("G21 G90 G54 G31 P99 Z-10. F300.\nM30\n");
  EXPECT_EQ(z.alarm_id(), AlarmId::kTorqueSkipSyncAxis);
  const Outcome x = Rig().param("90012=4").run("G21 G90 G54 G31 P99 X-1. F300.\nM30\n");
  EXPECT_TRUE(x.completed()) << x.alarm_code();
}

TEST(Rules, rule_43_after_contact_error_and_torque_grow_and_the_block_ends_from_the_stop) {
  const Outcome o = against_stop().run("G21 G90 G54 G31 P98 Z-10. F300. Q60\nG91 G0 Z5.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  // Contact: the first period the axis stands on the stop.
  std::size_t contact = 0, skip = 0;
  for (std::size_t i = 0; i < o.trace.size(); ++i) {
    if (contact == 0 && o.trace[i].act[2] == -3.0) contact = i;
    if (contact != 0 && skip == 0 && std::fabs(o.trace[i].torque[2]) >= 60.0) skip = i;
  }
  ASSERT_GT(contact, 0U);
  ASSERT_GT(skip, contact + 10) << "the limit is reached some time after contact";
  for (std::size_t i = contact + 1; i <= skip; ++i) {
    const Sample& s = o.trace[i];
    const Sample& p = o.trace[i - 1];
    EXPECT_LT(s.cmd[2], p.cmd[2]) << "the CNC keeps commanding motion, t=" << s.t;
    EXPECT_EQ(s.act[2], -3.0) << "the machine stays at the stop";
    EXPECT_GT(s.act[2] - s.cmd[2], p.act[2] - p.cmd[2]) << "the following error grows";
    EXPECT_GE(std::fabs(s.torque[2]), std::fabs(p.torque[2])) << "the torque grows";
  }
  EXPECT_NEAR(std::fabs(o.trace[skip].torque[2]), 60.0, 1e-9) << "the skip at the limit";
  EXPECT_NEAR(o.skip().time_s, o.trace[skip].t, 1e-9);
  EXPECT_NEAR(o.skip().position[2], -3.0, kUm) << "stored: the mechanical stop position";
  EXPECT_NEAR(o.skip().end_position[2], -3.0, kUm) << "the block ends from the stop";
  EXPECT_NEAR(o.r.final_work[2], 2.0, kUm) << "the next block runs from there";
}

// A 5 ms load of 150 % at 0.2 s on Z: a torque peak, no contact.
Rig peak(const char* delay_ms) {
  Rig r("fanuc");
  r.scene("[[load]]\naxis = \"Z\"\nat_time = 0.2\nduration = 0.005\ntorque = 150\n")
      .param(std::string("6281=") + delay_ms)
      .traced();
  return r;
}

TEST(Rules, rule_44_a_torque_peak_shorter_than_the_6281_delay_does_not_skip) {
  const Outcome o = peak("10").run("G21 G90 G54 G31 P98 Z-2. F300. Q100\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_FALSE(o.skip().triggered);
  EXPECT_NEAR(max_torque_z(o, 1), 100.0, 1e-9) << "the peak did reach the limit";
  EXPECT_NEAR(o.skip().end_position[2], -2.0, kUm);
}

TEST(Rules, rule_44_a_torque_peak_longer_than_the_6281_delay_skips) {
  const Outcome o = peak("3").run("G21 G90 G54 G31 P98 Z-2. F300. Q100\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().time_s, 0.203, 1e-9) << "3 ms after the limit was reached";
}

TEST(Rules, rule_44_against_a_stop_the_skip_comes_6281_ms_after_the_limit) {
  const Outcome fast = against_stop().run("G21 G90 G54 G31 P98 Z-10. F300. Q60\nM30\n");
  const Outcome slow =
      against_stop().param("6281=50").run("G21 G90 G54 G31 P98 Z-10. F300. Q60\nM30\n");
  ASSERT_TRUE(fast.skip().triggered);
  ASSERT_TRUE(slow.skip().triggered);
  EXPECT_NEAR(slow.skip().time_s - fast.skip().time_s, 0.050, 1e-9);
  EXPECT_NEAR(slow.skip().position[2], -3.0, kUm);
}

TEST(Rules, rule_45_k1_applies_to_p98_p99) {
  const Outcome k1 = Rig().run("G21 G90 G54 G31 P99 Z-2. F300. Q40 K1\nM30\n");
  EXPECT_EQ(k1.alarm_id(), AlarmId::kSkipMiss);
  const Outcome k0 = Rig().run("G21 G90 G54 G31 P99 Z-2. F300. Q40 K0\nM30\n");
  EXPECT_TRUE(k0.completed()) << k0.alarm_code();
}

TEST(Rules, rule_46_no_torque_limit_commanded_the_move_runs_on) {
  // Q omitted, 6280 = 0: no limit was commanded. The 150 % peak does not skip.
  const Outcome none = peak("0").param("6280=0").run("G21 G90 G54 G31 P98 Z-2. F300.\nM30\n");
  ASSERT_TRUE(none.completed()) << none.alarm_code();
  EXPECT_FALSE(none.skip().triggered);
  EXPECT_GT(max_torque_z(none, 1), 130.0) << "not limited: 150 % load less the 16.7 % drive";
  const Outcome set = peak("0").param("6280=100").run("G21 G90 G54 G31 P98 Z-2. F300.\nM30\n");
  EXPECT_TRUE(set.skip().triggered);
}

TEST(Rules, rule_46_p99_ended_by_skip_stores_where_the_machine_stopped) {
  // F1000 on mill3_lowgain: the axis lags 0.56 mm and comes to rest past the signal.
  const Outcome o =
      Rig().trigger("X0.4", 'Z', -3.0).run("G21 G90 G54 G31 P99 Z-10. F1000. Q100\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_EQ(o.skip().signal, "X0.4");
  EXPECT_LT(o.skip().end_position[2], -3.5);
  EXPECT_NEAR(o.var(5063), o.skip().end_position[2], kUm) << "not -3, where SKIP came";
  // An ordinary G31 stores where the signal came.
  const Outcome g31 = Rig().trigger("X0.4", 'Z', -3.0).run("G21 G90 G54 G31 Z-10. F1000.\nM30\n");
  EXPECT_NEAR(g31.var(5063), -3.0, kUm);
}

}  // namespace
}  // namespace skipnc::rules
