// Issue 17: a switched probe (optical or radio: [probe] on_m, off_m,
// start_time). Switched off, the stylus still deflects and the machine
// still crashes it, but its input never comes; switched on, it signals once
// its start-up time has passed. What the program forgot is said: a skip on
// a switched-off probe (probe_off), a probe that came on already deflected
// (probe_start_deflected), and the stored value is the one the control
// would store.
#include <gtest/gtest.h>

#include <string>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

// A plate with its top at machine Z-200; the ball (1 mm) 50 mm below the
// gauge line, so a touch stores Z-149.
constexpr const char* kScene = R"(
spindle_tool = 20
[[box]]
min = [-100.0, -100.0, -220.0]
max = [100.0, 100.0, -200.0]
[probe]
signal = "SKIP"
tool = 20
ball_radius = 1.0
length = 50.0
max_overtravel = 2.0
on_m = 81
off_m = 82
start_time = 1.0
)";

int count(const Outcome& o, const std::string& code) {
  int n = 0;
  for (const auto& w : o.r.warnings) n += w.code == code ? 1 : 0;
  return n;
}

TEST(ProbePower, SwitchedOnAndGivenItsStartUpTimeItTouches) {
  const Outcome o = Rig().scene(kScene).run(
      "G21 G90 G54 G0 X0 Y0 Z-145.\nM81\nG04 X1.2\nG31 Z-160. F300.\n#100=#5063\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.var(100), -149.0, kUm);
  EXPECT_TRUE(o.r.warnings.empty());
}

// Without the dwell the probe touches at 0.8 s of the G31 and is ready only
// 1 s after the M81: its input comes on where the axes are then, 0.83 mm
// past the surface, and that is what #5063 stores. Said at the M81.
TEST(ProbePower, ReadyTooLateItStoresWhereItCameOnAndSaysSo) {
  const Outcome o = Rig().scene(kScene).run(
      "G21 G90 G54 G0 X0 Y0 Z-145.\nM81\nG31 Z-160. F300.\n#100=#5063\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_LT(o.var(100), -149.5) << "past the surface";
  ASSERT_EQ(count(o, "probe_start_deflected"), 1);
  EXPECT_EQ(o.r.warnings[0].line, 2U) << "the M81";
}

// Never switched on, or switched off again: the skip waits for an input
// that cannot come and the stylus is driven past its over-travel.
TEST(ProbePower, SwitchedOffTheSkipCrashesTheProbeAndIsSaidBefore) {
  for (const char* program : {"G21 G90 G54 G0 X0 Y0 Z-145.\nG31 Z-160. F300.\nM30\n",
                              "G21 G90 G54 G0 X0 Y0 Z-145.\nM81\nG04 X1.2\nM82\nG31 Z-160. "
                              "F300.\nM30\n"}) {
    const Outcome o = Rig().scene(kScene).run(program);
    EXPECT_EQ(o.alarm_id(), AlarmId::kProbeCrash) << program;
    EXPECT_EQ(count(o, "probe_off"), 1) << program;
  }
}

// A probe without on_m is always on (every other scene here).
TEST(ProbePower, WithoutOnMTheProbeIsAlwaysOn) {
  std::string scene = kScene;
  scene = scene.substr(0, scene.find("on_m"));
  const Outcome o = Rig().scene(scene).run("G21 G90 G54 G0 X0 Y0 Z-145.\nG31 Z-160. F300.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_TRUE(o.skip().triggered);
}

}  // namespace
}  // namespace skipnc::rules
