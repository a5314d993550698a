// Block rules of the executor: modal-group conflicts and the block as a
// transaction (issue 14).
#include <gtest/gtest.h>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

TEST(Rules, block_two_motion_codes_raise_ps0010_on_fanuc) {
  const Outcome o = Rig("fanuc").run("G21 G90 G0 G1 X1. F100.\nM30\n");
  EXPECT_EQ(o.alarm_id(), AlarmId::kGCodeConflict);
  EXPECT_EQ(o.alarm_code(), "PS0010");
  EXPECT_EQ(o.alarm_line(), 1u);
}

TEST(Rules, block_g90_g91_and_g20_g21_are_refused_on_fanuc) {
  EXPECT_EQ(Rig("fanuc").run("G90 G91 X1.\nM30\n").alarm_code(), "PS0010");
  EXPECT_EQ(Rig("fanuc").run("G20 G21\nM30\n").alarm_code(), "PS0010");
}

TEST(Rules, block_second_one_shot_code_with_g31_is_refused_in_every_dialect) {
  for (const char* d : {"fanuc", "mitsubishi", "nct", "compass"}) {
    EXPECT_EQ(Rig(d).run("G21 G90 F100.\nG04 G31 Z-1.\nM30\n").alarm_id(), AlarmId::kGCodeConflict)
        << d;
    EXPECT_EQ(Rig(d).run("G21 G90 F100.\nG31 G28 Z-1.\nM30\n").alarm_id(), AlarmId::kGCodeConflict)
        << d;
    EXPECT_EQ(Rig(d).run("G21 G90 F100.\nG31 G92 Z-1.\nM30\n").alarm_id(), AlarmId::kGCodeConflict)
        << d;
  }
}

// Mitsubishi M700V programming manual, appendix "Order of G function command
// priority": of two G codes of one group the one commanded last is valid.
TEST(Rules, block_last_code_of_a_group_wins_on_mitsubishi) {
  const Outcome o = Rig("mitsubishi").run("G21 G90 G1 G0 X5. F100.\n#100=#4001\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), 0.0, 1e-9) << "G0 was commanded last";
}

TEST(Rules, block_with_an_alarm_emits_no_spindle_command) {
  const Outcome o = Rig("fanuc").run("G21 G90\nS1000 D999 G1 X1. F100.\nM30\n");
  EXPECT_EQ(o.alarm_code(), "PS0030");
  EXPECT_EQ(o.alarm_line(), 2u);
  EXPECT_NEAR(o.var(4119), 0.0, 1e-9) << "S of the alarmed block not taken";
}

}  // namespace
}  // namespace skipnc::rules
