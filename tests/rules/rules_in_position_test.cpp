// Issue 14: the in-position check between blocks, and the position
// variables with or without the tool offsets, as the real control has them.
// mill3_lowgain's servo (the rigs' machine) has no feedforward (kp 30/s): at the end of a rapid the
// axes lag the command by millimetres, so every case here differs from a
// run that does not wait for them.
#include <gtest/gtest.h>

#include <cmath>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

constexpr double kUm = 1e-6;
constexpr double kInPos = 0.0005;  // mill3 in_position_mm

// The input is already on when the G31 starts (the probe touches at Z-3,
// the G00 went to Z-5): level detection ends the block with no motion. The
// G31 starts only once the G00 has settled, so the stored point is its
// start point, not a point of the G00's lag (was -3.6179: the G31 started
// while the axis was still near Z-3.6).
TEST(InPosition, G31AfterARapidStartsFromWhereTheRapidSettled) {
  for (double z : {-5.0, -20.0}) {
    const Outcome o = Rig()
                          .trigger("X0.4", 'Z', -3.0)
                          .run("G21 G90 G54 G0 Z" + std::to_string(z) + "\nG31 Z-30. F100.\nM30\n");
    ASSERT_TRUE(o.completed()) << o.alarm_code();
    ASSERT_TRUE(o.skip().triggered);
    EXPECT_NEAR(o.var(5063), z, kInPos) << "G0 Z" << z;
    EXPECT_NEAR(o.skip().machine_position[2], z, kInPos);
  }
}

// The third case of the issue: a fast touch, a 1 mm G00 back-off, a slow
// touch. The slow G31 starts once the back-off has settled above the
// surface, so it stores the surface itself (was -228.97: the slow G31
// started while the axis still lagged below it, with the input on).
TEST(InPosition, SlowTouchAfterAOneMillimetreBackOffStoresTheSurface) {
  const Outcome o = Rig()
                        .trigger("X0.4", 'Z', -228.87)
                        .run(
                            "G21 G90 G54 G0 Z-200.\nG31 Z-240. F500.\n#100=#5063\nG91 G0 Z1.\n"
                            "G90 G31 Z-240. F20.\n#101=#5063\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_EQ(o.skip_count(), 2U);
  EXPECT_TRUE(o.skip(0).triggered);
  EXPECT_TRUE(o.skip(1).triggered);
  EXPECT_NEAR(o.var(100), -228.87, kUm) << "fast touch";
  EXPECT_NEAR(o.var(101), -228.87, kUm) << "slow touch";
  // The slow touch moved: it started 1 mm above where the fast one stopped.
  EXPECT_GT(o.skip(1).time_s - o.skip(0).time_s, 0.5);
}

// With the check turned off for rapids (Fanuc 1601#5 NCI = 1) the next
// block starts as soon as the command reaches the G00's end, with the axis
// still lagging by millimetres; with it on (the default) the axis is within
// the width first.
TEST(InPosition, Fanuc1601Bit5TurnsTheRapidCheckOff) {
  const char* program = "G21 G90 G54 G0 X50.\nG1 X60. F3000.\nM30\n";
  auto lag_at_next_block = [](const Outcome& o) {
    // The first period of the G01: its command is just past X50.
    for (const auto& s : o.trace) {
      if (s.cmd[0] > 50.0 + 1e-9) return std::fabs(s.act[0] - 50.0);
    }
    return -1.0;
  };
  const double on = lag_at_next_block(Rig().traced().run(program));
  const double off = lag_at_next_block(Rig().param("1601#5=1").traced().run(program));
  EXPECT_GE(on, 0.0);
  EXPECT_LE(on, 0.002) << "in position, then one period of the G01's start";
  EXPECT_GT(off, 0.1) << "started before the axis settled";
}

// A dwell starts once the axes are in position: the axis is at rest (within
// the width) for the whole dwell, and the dwell lasts its time.
TEST(InPosition, ADwellFollowsTheSettlingInsteadOfOverlappingIt) {
  const Outcome o = Rig().traced().run("G21 G90 G54 G0 X50.\nG04 X1.\nG0 X60.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  double settled = -1.0, left = -1.0;
  for (const auto& s : o.trace) {
    if (settled < 0.0 && s.cmd[0] == 50.0 && std::fabs(s.act[0] - 50.0) <= kInPos) settled = s.t;
    if (left < 0.0 && s.cmd[0] > 50.0) left = s.t;
  }
  ASSERT_GT(settled, 0.0);
  ASSERT_GT(left, settled);
  // The dwell begins in the period the check passes and lasts 1 s; the next
  // rapid's first command follows it.
  EXPECT_NEAR(left - settled, 1.0, 0.0025);
}

// G09 (one block) and G61 (modal) end a cutting block only in position: the
// next block's command starts with the axis within the width.
TEST(InPosition, G09AndG61CuttingBlocksEndInPosition) {
  for (const char* mode : {"G64 G09", "G61"}) {
    const Outcome o = Rig().traced().run(std::string("G21 G90 G54 ") + mode +
                                         " G1 X20. F3000.\nG64 G1 X40.\nM30\n");
    ASSERT_TRUE(o.completed()) << o.alarm_code();
    bool checked = false;
    for (std::size_t k = 1; k < o.trace.size(); ++k) {
      if (o.trace[k - 1].cmd[0] == 20.0 && o.trace[k].cmd[0] > 20.0) {
        EXPECT_LE(std::fabs(o.trace[k - 1].act[0] - 20.0), kInPos) << mode;
        checked = true;
        break;
      }
    }
    EXPECT_TRUE(checked) << mode;
  }
  // G64 without G09: the axis is still far behind when X40 begins.
  const Outcome c = Rig().traced().run("G21 G90 G54 G64 G1 X20. F3000.\nX40.\nM30\n");
  for (std::size_t k = 1; k < c.trace.size(); ++k) {
    if (c.trace[k].cmd[0] > 20.0 && c.trace[k - 1].cmd[0] <= 20.0) {
      EXPECT_GT(std::fabs(c.trace[k].act[0] - 20.0), 0.1);
      break;
    }
  }
}

// A move whose end is past a rigid stop never gets in position: after
// in_position_timeout_s (1 s on mill3) at rest the run ends with the alarm,
// and the final position is where the axis is, against the stop (was: the
// run waited until the simulated-time limit and reported the command).
TEST(InPosition, AnAxisHeldByAStopEndsInTheTimeoutAlarm) {
  const Outcome o = Rig().stop('Z', -3.0).run("G21 G90 G54 G1 Z-3.5 F100.\nM30\n");
  EXPECT_EQ(o.alarm_id(), AlarmId::kInPositionTimeout);
  EXPECT_EQ(o.alarm_code(), "SN9072");
  EXPECT_NEAR(o.r.final_machine[2], -3.0, 0.01) << "against the stop";
  // 3.5 mm at F100 (2.1 s), then 1 s at rest: seconds, not hours.
  EXPECT_LT(o.r.time_s, 4.0);
}

// A torque limit skip with no torque limit commanded (6280 = 0, Q omitted)
// into the stop: the command runs to its end and the axis stays at the stop.
TEST(InPosition, ATorqueSkipWithoutATorqueLimitIntoAStopEndsInAnAlarm) {
  const Outcome o =
      Rig().stop('Z', -3.0).param("6280=0").run("G21 G90 G54 G31 P99 Z-10. F300.\nM30\n");
  ASSERT_FALSE(o.completed());
  EXPECT_TRUE(o.alarm_id() == AlarmId::kInPositionTimeout ||
              o.alarm_id() == AlarmId::kServoExcessError)
      << o.alarm_code();
  EXPECT_NEAR(o.r.final_machine[2], -3.0, 0.01);
  EXPECT_LT(o.r.time_s, 5.0);
}

// G54 Z-200 and H1 = 100 mm: the tip at work Z-3 is at machine Z-103,
// where X0.4 turns on.
Rig g54_and_h1(const char* dialect) {
  return Rig(dialect)
      .machine([](config::MachineConfig& m) {
        m.work_offsets[1][2] = -200.0;  // G54 Z
        m.tool_offsets[1].length_geometry = 100.0;
      })
      .trigger("X0.4", 'Z', -103.0);
}

// Fanuc-class: #5001.. is the programmed point (tool offsets out), #5041..
// and #5061.. have the tool length in them: #5043 - #5003 is the active H
// and #5063 - #5083 the tip at the latch. Machine coordinates are where
// the machine is. The report says which point the skip position is.
TEST(PositionVariables, FanucHasTheToolLengthInCurrentAndSkipPositions) {
  const Outcome o = g54_and_h1("fanuc").run(
      "G21 G90 G54 G43 H1 G0 Z10.\n"
      "#100 = #5003\n#101 = #5043\n#102 = #5023\n"
      "G31 Z-10. F100.\n"
      "#103 = #5063\n#104 = #5083\n#105 = #5063 - #5083\n"
      "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), 10.0, kUm) << "#5003: programmed point";
  EXPECT_NEAR(o.var(101), 110.0, kInPos) << "#5043: tool reference point";
  EXPECT_NEAR(o.var(101) - o.var(100), 100.0, kInPos) << "#5043 - #5003 = H1";
  EXPECT_NEAR(o.var(102), -90.0, kInPos) << "#5023: machine";
  EXPECT_NEAR(o.var(103), 97.0, kUm) << "#5063: latch with H1 in it";
  EXPECT_NEAR(o.var(104), 100.0, kUm);
  EXPECT_NEAR(o.var(105), -3.0, kUm) << "the tip at the latch";
  EXPECT_TRUE(o.skip().position_has_tool_offsets);
  EXPECT_NEAR(o.skip().position[2], 97.0, kUm);
}

// NCT and CompassNC store the compensated (programmed) point: the same
// program reads the tip in #5063 and #5043 (rule 23, rule 26).
TEST(PositionVariables, NctAndCompassStoreTheProgrammedPoint) {
  for (const char* d : {"nct", "compass"}) {
    const Outcome o = g54_and_h1(d).run(
        "G21 G90 G54 G43 H1 G0 Z10.\n"
        "#101 = #5043\n"
        "G31 Z-10. F100.\n"
        "#103 = #5063\n"
        "M30\n");
    ASSERT_TRUE(o.completed()) << d << " " << o.alarm_code();
    EXPECT_NEAR(o.var(101), 10.0, kInPos) << d;
    EXPECT_NEAR(o.var(103), -3.0, kUm) << d;
    EXPECT_FALSE(o.skip().position_has_tool_offsets) << d;
  }
}

// A dialect switch changes it (a machine's own dialect file can).
TEST(PositionVariables, TheSwitchIsTheDialects) {
  const Outcome o =
      Rig("mitsubishi")
          .machine([](config::MachineConfig& m) { m.tool_offsets[1].length_geometry = 50.0; })
          .run("G21 G90 G54 G43 H1 G0 Z10.\n#100 = #5003\n#101 = #5043\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), 10.0, kUm);
  EXPECT_NEAR(o.var(101), 60.0, kInPos);
}

}  // namespace
}  // namespace skipnc::rules

namespace skipnc::rules {
namespace {

// G30 is its own return: P2-P4 (P omitted: 2) go to the machine file's
// [reference_points], through the intermediate point, only on the axes named
// (was: the same as G28, machine zero).
TEST(ReferenceReturn, G30GoesToTheSecondToFourthReferencePoint) {
  const auto points = [](config::MachineConfig& m) {
    m.reference_points[0] = AxisVec{};
    m.reference_points[0][0] = 100.0;
    m.reference_points[0][1] = 50.0;
    m.reference_points[0][2] = -10.0;
    m.reference_points[1][2] = -20.0;
  };
  const Outcome o = Rig().machine(points).run(
      "G21 G90 G54 G0 X1. Y2. Z3.\n"
      "G30 P3 Z0\n#100 = #5023\n#101 = #5021\n"
      "G30 X0 Y0\n#102 = #5021\n#103 = #5022\n#104 = #5023\n"
      "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), -20.0, kInPos) << "3rd reference point, Z only";
  EXPECT_NEAR(o.var(101), 1.0, kInPos) << "X not named: stays";
  EXPECT_NEAR(o.var(102), 100.0, kInPos) << "P omitted: the 2nd";
  EXPECT_NEAR(o.var(103), 50.0, kInPos);
  EXPECT_NEAR(o.var(104), -20.0, kInPos) << "Z not named: stays";
  const Outcome bad = Rig().run("G21 G90 G30 P5 Z0\nM30\n");
  EXPECT_EQ(bad.alarm_id(), AlarmId::kBadValue);
}

// Machine lock (and Z-axis cancel for Z): the machine does not move, so its
// machine coordinates stay still while the work position follows the program.
TEST(MachineLock, MachineCoordinatesStayStillAndTheWorkPositionMoves) {
  const Outcome o = Rig().param("90010=1").run(
      "G21 G90 G54 G0 X10. Z-50.\n#100 = #5021\n#101 = #5023\n#102 = #5043\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), 0.0, kUm);
  EXPECT_NEAR(o.var(101), 0.0, kUm);
  EXPECT_NEAR(o.var(102), -50.0, kUm);
  const Outcome z =
      Rig().param("90011=1").run("G21 G90 G54 G0 X10. Z-50.\n#100 = #5021\n#101 = #5023\nM30\n");
  ASSERT_TRUE(z.completed()) << z.alarm_code();
  EXPECT_NEAR(z.var(100), 10.0, kInPos) << "X moves";
  EXPECT_NEAR(z.var(101), 0.0, kUm) << "Z cancelled";
}

}  // namespace
}  // namespace skipnc::rules

namespace skipnc::rules {
namespace {

// A dwell after a move lasts exactly its time in servo periods: G04 X5. is
// 5000 periods of 1 ms (was 4999: the dwell began inside the period in which
// the move ended).
TEST(InPosition, ADwellIsExactToTheServoPeriod) {
  const Outcome o = Rig().param("3401#0=1").traced().run("G0 X1.\nG04 X5.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  int periods = 0;
  for (const auto& s : o.trace) periods += s.line == 2 ? 1 : 0;
  EXPECT_EQ(periods, 5000);
}

}  // namespace
}  // namespace skipnc::rules
