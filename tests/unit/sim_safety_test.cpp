// What the simulator does about the probing scene: the braking distance and
// its warning before a skip move, a crash's overshoot, tool changes and the
// collision of a tool, probe protection for the tool setter.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/plant.hpp"
#include "sim/probe_safety.hpp"
#include "sim/simulator.hpp"
#include "support/motion.hpp"

namespace skipnc::machine {
namespace {

using test::xyz;

struct Rig {
  config::MachineConfig m = *config::builtin_machine("mill3_lowgain");
  config::Dialect d = *config::builtin_dialect("fanuc");
  config::Parameters p{&d};
  Scene scene;

  Rig() {
    geo::Part plate;
    plate.name = "plate";
    plate.solids.push_back(geo::make_box({-100, -100, -60}, {100, 100, -40}));
    scene.probing.parts.push_back(plate);
    ProbeSpec probe;
    probe.signal = canon::SignalAddr{'X', 0, 4};
    probe.ball_radius = 1.0;
    probe.max_overtravel = 0.5;
    scene.probing.probe = probe;
  }
  Result<sim::RunResult> run(const std::string& program) {
    sim::Simulator sim(m, d, p, scene);
    record::Setup setup;
    setup.machine = &m;
    setup.dialect = &d;
    setup.params = &p;
    setup.program_text = program;
    return sim.run(setup, {});
  }
};

TEST(ProbeSafety, BrakingDistanceOfBothStops) {
  Rig r;
  Plant plant(r.m, r.scene, ServoClock{});
  sim::ProbeSafety safety(r.m, r.p, plant, nullptr);
  canon::Skip s;
  s.feed_mm_per_min = 600.0;  // 10 mm/s
  s.target = xyz(50, 0, 0);
  s.spec.stop = canon::SkipStop::kImmediate;
  // Following error v / kp plus one 1 ms period of travel.
  EXPECT_NEAR(safety.braking_distance(s, AxisVec{}), 10.0 / 30.0 + 0.01, 1e-12);
  s.spec.stop = canon::SkipStop::kDecelerate;
  EXPECT_NEAR(safety.braking_distance(s, AxisVec{}), 100.0 / (2 * 2000.0) + 10.0 / 30.0, 1e-12);
  // At 45 degrees in XY the path may decelerate at 2000 / cos 45.
  s.target = xyz(50, 50, 0);
  EXPECT_NEAR(safety.braking_distance(s, AxisVec{}),
              100.0 / (2 * 2000.0 * std::sqrt(2.0)) + 10.0 / 30.0, 1e-12);
}

TEST(ProbeSafety, WarnsBeforeASkipMoveThatCannotStopInTheOverTravel) {
  Rig r;
  // F3000: 50/30 + 0.05 mm to stop, more than 0.5. F100: 0.057 mm, less.
  auto res = r.run("G21 G90 G54\nG0 Z-30.\nG31 Z-45. F100.\nG0 Z-30.\nG31 Z-38. F3000.\nM30\n");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, sim::RunStatus::kCompleted);
  ASSERT_EQ(res->warnings.size(), 1U);
  EXPECT_EQ(res->warnings[0].code, "skip_braking");
  EXPECT_EQ(res->warnings[0].line, 5U);
  EXPECT_NE(res->warnings[0].text.find("needs 1.7167 mm to stop"), std::string::npos)
      << res->warnings[0].text;
  EXPECT_TRUE(res->messages.empty());
}

TEST(ProbeSafety, ACrashReportsHowFarPastTheLimitTheStylusWent) {
  Rig r;
  r.m.axes[2].kp_per_s = 0.0;  // an ideal servo: the actual is the command
  Plant plant(r.m, r.scene, ServoClock{});
  plant.reset(xyz(0, 0, -37.0));
  kernel::TickInput in;
  AxisVec from = xyz(0, 0, -37.0);
  for (int k = 1; k <= 600; ++k) {  // down 0.01 mm per period to Z-43
    const AxisVec to = xyz(0, 0, -37.0 - 0.01 * k);
    plant.advance(k, from, to, in);
    from = to;
  }
  const PlantFault& f = plant.probing().fault();
  ASSERT_EQ(f.kind, PlantFault::Kind::kProbeCrash);
  EXPECT_NEAR(f.at[2], -40.0 + 1.0 - 0.5, 1e-9);  // deflection 0.5: the ball centre at Z-39.5
  EXPECT_NEAR(f.limit, 0.5, 1e-12);
  EXPECT_NEAR(f.deflection, 1.0 + 3.0, 1e-9);  // centre 3 mm into the plate at Z-43
  EXPECT_NEAR(f.overshoot, 3.5, 1e-9);
  EXPECT_NEAR(f.latest[2], -43.0, 1e-9);
}

TEST(ProbeSafety, AToolChangedInByM06CollidesWithThePart) {
  Rig r;
  r.scene.probing.tools.push_back(ToolSpec{1, 100.0, 5.0});
  // The probe touching the plate's top in a G01 would be probe protection;
  // with T1 in the spindle the tool's tip meets it: a collision, where the
  // tip (Z - 100) reaches Z-40.
  auto res = r.run("G21 G90 G54\nG0 Z150.\nT1 M06\nG0 X20. Y20.\nG1 Z50. F3000.\nM30\n");
  ASSERT_TRUE(res);
  ASSERT_TRUE(res->alarm);
  EXPECT_EQ(res->alarm->id, AlarmId::kCollision);
  EXPECT_EQ(res->alarm->loc.line, 5U);
  ASSERT_TRUE(res->alarm_position);
  EXPECT_NEAR((*res->alarm_position)[0], 20.0, 1e-9);
  EXPECT_NEAR((*res->alarm_position)[2], 60.0, 1e-8);  // 1 nm of overlap counts
  // The probe (T0 here) back in the spindle: a move onto the top is probe
  // protection where the ball switches.
  auto back = r.run("G21 G90 G54\nG0 Z150.\nT1 M06\nG0 X20. Y20.\nT0 M06\nG1 Z-45. F3000.\nM30\n");
  ASSERT_TRUE(back && back->alarm);
  EXPECT_EQ(back->alarm->id, AlarmId::kProbeProtection);
  EXPECT_NEAR((*back->alarm_position)[2], -39.0, 1e-9);
}

TEST(ProbeSafety, ToolSetterSwitchedByARapidIsProbeProtection) {
  Rig r;
  r.scene.probing.tools.push_back(ToolSpec{1, 100.0, 5.0});
  ToolSetterSpec setter;
  setter.signal = canon::SignalAddr{'X', 0, 4};
  setter.x = 200;
  setter.y = 0;
  setter.top = -150;
  setter.radius = 6;
  setter.max_overtravel = 3;
  r.scene.probing.tool_setter = setter;
  auto res = r.run("G21 G90 G54\nG0 Z150.\nT1 M06\nG0 X200. Y0\nG0 Z-55.\nM30\n");
  ASSERT_TRUE(res && res->alarm);
  EXPECT_EQ(res->alarm->id, AlarmId::kProbeProtection);
  EXPECT_NEAR((*res->alarm_position)[2], -50.0 - 1e-6, 1e-9);  // the tip 1 nm into the disc
  // With protection off the rapid goes on and crushes the setter past 3 mm.
  ASSERT_TRUE(r.p.apply(config::ParamSetting{sim::kProbeProtectionParam, -1, 0.0, {}}));
  auto off = r.run("G21 G90 G54\nG0 Z150.\nT1 M06\nG0 X200. Y0\nG0 Z-55.\nM30\n");
  ASSERT_TRUE(off && off->alarm);
  EXPECT_EQ(off->alarm->id, AlarmId::kProbeCrash);
  EXPECT_NEAR((*off->alarm_position)[2], -53.0 - 1e-6, 1e-9);
}

}  // namespace
}  // namespace skipnc::machine
