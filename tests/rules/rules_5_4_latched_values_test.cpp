// skip-rules.md 5.4: latched values (rules 21-26).
#include <gtest/gtest.h>

#include <cmath>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

constexpr double kUm = 1e-6;

void g54(config::MachineConfig& m, double x, double y, double z) {
  m.work_offsets[1][0] = x;
  m.work_offsets[1][1] = y;
  m.work_offsets[1][2] = z;
}

TEST(Rules, rule_21_5061_to_5063_hold_the_workpiece_position_of_each_axis) {
  // G54 = (100, 50, -20). The probe moves diagonally in X and Y; X0.4 turns
  // on when the machine X passes 112.5.
  const Outcome o = Rig()
                        .machine([](config::MachineConfig& m) { g54(m, 100.0, 50.0, -20.0); })
                        .trigger("X0.4", 'X', 112.5, false)
                        .run(
                            "G21 G90 G54 G0 X0 Y0 Z5.\n"
                            "G31 X20. Y40. F300.\n"
                            "M30\n");
  ASSERT_TRUE(o.completed());
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.var(5061), 12.5, kUm) << "axis 1";
  EXPECT_NEAR(o.var(5062), 25.0, kUm) << "axis 2: on the line, 40/20 * 12.5";
  EXPECT_NEAR(o.var(5063), 5.0, kUm) << "axis 3 did not move";
  EXPECT_NEAR(o.skip().machine_position[0], 112.5, kUm);
  EXPECT_NEAR(o.skip().machine_position[1], 75.0, kUm);
}

// Machine setting [latch] servo_delay_compensation: the stored position is
// the axis's actual position at the signal (on) or the command's (off),
// which runs ahead of the axis by the servo lag v/kp (10/30 mm at F600).
TEST(Rules, rule_21_servo_delay_compensation_is_a_machine_setting) {
  const char* program = "G21 G90 G54 G31 Z-10. F600.\nM30\n";
  const Outcome on = Rig()
                         .machine([](config::MachineConfig& m) { m.servo_delay_comp = true; })
                         .trigger("X0.4", 'Z', -3.0)
                         .run(program);
  const Outcome off = Rig()
                          .machine([](config::MachineConfig& m) { m.servo_delay_comp = false; })
                          .trigger("X0.4", 'Z', -3.0)
                          .run(program);
  ASSERT_TRUE(on.skip().triggered);
  ASSERT_TRUE(off.skip().triggered);
  EXPECT_NEAR(on.var(5063), -3.0, kUm);
  EXPECT_NEAR(off.var(5063), -3.0 - 10.0 / 30.0, 1e-3);
}

TEST(Rules, rule_22_nct_stores_the_position_at_the_signal_or_the_programmed_end_point) {
  const Outcome o = Rig("nct")
                        .trigger("X0.4", 'Z', -3.25)
                        .run(
                            "G21 G90 G54 G0 X0 Y0 Z0\n"
                            "G31 Z-10. F200.\n"
                            "#100 = #5063\n"
                            "G0 Z0\n"
                            "G31 X7.5 F200.\n"
                            "#101 = #5061\n"
                            "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), -3.25, kUm) << "the instant the signal arrived";
  EXPECT_NEAR(o.var(101), 7.5, kUm) << "no signal: the programmed end point";
}

TEST(Rules, rule_23_nct_5061_in_the_work_system_with_g43_length_and_g45_offset) {
  // G54 = (100, 50, -200); H1 = 50 mm length; D1 = 2 mm.
  // G43 H1 Z10.: machine Z = 10 + 50 - 200 = -140.
  // G91 G45 X10. D1: the move is lengthened by 2 mm: machine X = 100 + 12.
  // G90 G31 X30.: X0.4 turns on at machine X 120 -> #5061 = 120 - 100 - 2 = 18.
  const Outcome o = Rig("nct")
                        .machine([](config::MachineConfig& m) {
                          g54(m, 100.0, 50.0, -200.0);
                          m.tool_offsets[1].length_geometry = 50.0;
                          m.tool_offsets[1].radius_geometry = 2.0;
                        })
                        .trigger("X0.4", 'X', 120.0, false)
                        .run(
                            "G21 G90 G54 G0 X0 Y0 Z50.\n"
                            "G43 H1 Z10.\n"
                            "G91 G45 X10. D1\n"
                            "#100 = #5021\n"
                            "G90 G31 X30. F200.\n"
                            "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), 112.0, kUm) << "G45 lengthened the move by D1";
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().machine_position[0], 120.0, kUm);
  EXPECT_NEAR(o.skip().machine_position[2], -140.0, kUm);
  EXPECT_NEAR(o.var(5061), 18.0, kUm);
  EXPECT_NEAR(o.var(5062), 0.0, kUm);
  EXPECT_NEAR(o.var(5063), 10.0, kUm) << "tool tip: G43 length taken into account";
}

TEST(Rules, rule_23_g45_g48_in_absolute_mode_and_with_twice_the_offset) {
  // G90 G45 X10 from X0: 10 + 2; G46 X20: +10 - 2 (shortened); G48 X10:
  // back by 10 - 2*2. The shifts accumulate: +2 -2 +4 = +4 -> machine X 14.
  const Outcome o =
      Rig("nct")
          .machine([](config::MachineConfig& m) { m.tool_offsets[1].radius_geometry = 2.0; })
          .run(
              "G21 G90 G54 G0 X0 Y0 Z0 D1\n"
              "G45 X10.\n#100 = #5021\n"
              "G46 X20.\n#101 = #5021\n"
              "G48 X10.\n#102 = #5021\n"
              "G31 X12. F100.\n"
              "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), 12.0, kUm);
  EXPECT_NEAR(o.var(101), 20.0, kUm);
  EXPECT_NEAR(o.var(102), 14.0, kUm);
  EXPECT_NEAR(o.var(5061), 12.0, kUm) << "no signal: the end point in programmed coordinates";
  EXPECT_NEAR(o.skip().machine_position[0], 16.0, kUm);
}

TEST(Rules, rule_23_g45_is_not_a_code_of_the_fanuc_dialect) {
  const Outcome o = Rig("fanuc").run("G21 G91 G45 X10. D1\nM30\n");
  EXPECT_EQ(o.alarm_id(), AlarmId::kUnknownGCode);
}

// #5001 - #5061 for a G31 at `feed` into a trigger at Z-20 (ideal servo).
double end_minus_latch(double feed) {
  const Outcome o = Rig("nct")
                        .machine(ideal_servo)
                        .trigger("X0.4", 'Z', -20.0)
                        .run(
                            "G21 G90 G54 G0 X0 Y0 Z0\n"
                            "G31 Z-60. F" +
                            std::to_string(feed) +
                            "\n"
                            "#100 = #5001\n#101 = #5061\n#102 = #5003\n#103 = #5063\n"
                            "M30\n");
  EXPECT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(103), -20.0, kUm);
  return o.var(103) - o.var(102);
}

TEST(Rules, rule_24_nct_end_point_5001_differs_from_5061_by_a_distance_growing_with_feed) {
  const double v1 = 500.0 / 60.0, v2 = 2000.0 / 60.0, a = 2000.0, T = 0.001;
  const double d1 = end_minus_latch(500.0);
  const double d2 = end_minus_latch(2000.0);
  EXPECT_GT(d2, d1 * 4.0);
  EXPECT_NEAR(d1, v1 * v1 / (2 * a), v1 * T);
  EXPECT_NEAR(d2, v2 * v2 / (2 * a), v2 * T);
}

TEST(Rules, rule_25_compass_mcs_then_lcs_differ_by_exactly_the_active_offset) {
  const Outcome o = Rig("compass")
                        .machine([](config::MachineConfig& m) { g54(m, 100.0, 50.0, -20.0); })
                        .trigger("X0.4", 'X', 133.3, false)
                        .run(
                            "G21 G90 G54 G0 X0 Y0 Z0\n"
                            "G31 X50. F300.\n"
                            "#101 = #<NC.SysVars.G31.MCS.X>\n"
                            "#102 = # <NC.SysVars.G31.LCS.X>\n"
                            "#103 = #<NC.SysVars.G31.MCS.Y>\n"
                            "#104 = #<NC.SysVars.G31.LCS.Y>\n"
                            "#105 = #<NC.SysVars.G31.MCS.Z> - #<NC.SysVars.G31.LCS.Z>\n"
                            "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(101), 133.3, kUm);
  EXPECT_NEAR(o.var(102), 33.3, kUm);
  EXPECT_NEAR(o.var(103), 50.0, kUm);
  EXPECT_NEAR(o.var(104), 0.0, kUm);
  EXPECT_NEAR(o.var(105), -20.0, kUm);
  // As --var reads them (the name as written, any case).
  EXPECT_NEAR(o.named("NC.SysVars.G31.LCS.X"), 33.3, kUm);
  EXPECT_NEAR(o.named("nc.sysvars.g31.mcs.x"), 133.3, kUm);
}

TEST(Rules, rule_25_compass_fourth_axis_is_aux1) {
  const Outcome o = Rig("compass")
                        .machine([](config::MachineConfig& m) {
                          config::AxisConfig a = m.axes[0];
                          a.name = 'A';
                          m.axes.push_back(a);
                          m.work_offsets[1][3] = 5.0;
                        })
                        .run("G21 G90 G54 G0 X0 Y0 Z0 A0\nG31 A30. F600.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.named("NC.SysVars.G31.MCS.Aux1"), 35.0, kUm);
  EXPECT_NEAR(o.named("NC.SysVars.G31.LCS.Aux1"), 30.0, kUm);
}

TEST(Rules, rule_26_compass_the_latched_lcs_x_brings_the_tool_back) {
  // The manual's example, with a trigger at machine X 61.7 and G54 X10. The
  // manual saves into #1001; skipnc's variable store has #100-#199 and
  // #500-#999 only, so #100 stands in for it.
  const Outcome o = Rig("compass")
                        .machine([](config::MachineConfig& m) { g54(m, 10.0, 0.0, 0.0); })
                        .trigger("X0.4", 'X', 61.7, false)
                        .traced()
                        .run(
                            "N1 G90 G17 G21\n"
                            "N10 G0 X0.0 Y0.0 Z0.0 F12000\n"
                            "N12 G31 X100 F200\n"
                            "#100 = # <NC.SysVars.G31.LCS.X>\n"
                            "N14 G1 Y10 F12000\n"
                            "G1 X0 Y0\n"
                            "G1 X[#100]\n"
                            "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), 51.7, kUm);
  EXPECT_NEAR(o.r.final_work[0], 51.7, kUm);
  EXPECT_NEAR(o.r.final_machine[0], 61.7, kUm) << "where the skip latched";
}

}  // namespace
}  // namespace skipnc::rules
