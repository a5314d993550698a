// Contact during a circular move (issue 5: "exact contact ... for linear
// and circular moves"). A G02/G03 arc runs the probe ball into a wall; the
// move is not a skip move, so the probe switching is probe protection
// (alarm 9063) at the instant of contact. The scene takes the actual motion
// as straight inside each servo period, so the contact lies on the chord
// between two servo samples of the actual (servo-lagged) position.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "sim/simulator.hpp"

namespace skipnc::machine {
namespace {

// The wall: a block whose -X face is at X = kWall; the ball's radius is 1,
// so the ball touches it when its centre reaches X = kWall - 1.
constexpr double kWall = 8.0;
constexpr double kBall = 1.0;
constexpr double kArcRadius = 10.0;

struct ActualRows final : sim::TraceSink {
  std::vector<AxisVec> actual;
  void row(const sim::TraceRow& r) override { actual.push_back(*r.actual); }
};

struct ArcRig {
  config::MachineConfig m = *config::builtin_machine("mill3_lowgain");
  config::Dialect d = *config::builtin_dialect("fanuc");
  config::Parameters p{&d};
  Scene scene;
  ActualRows rows;

  ArcRig() {
    geo::Part wall;
    wall.name = "wall";
    wall.solids.push_back(geo::make_box({kWall, -100, -60}, {100, 100, -40}));
    scene.probing.parts.push_back(wall);
    ProbeSpec probe;
    probe.signal = canon::SignalAddr{'X', 0, 4};
    probe.ball_radius = kBall;
    probe.max_overtravel = 2.0;
    scene.probing.probe = probe;  // length 0: the ball centre is the machine position
  }
  Result<sim::RunResult> run(const std::string& program) {
    sim::Simulator sim(m, d, p, scene);
    record::Setup setup;
    setup.machine = &m;
    setup.dialect = &d;
    setup.params = &p;
    setup.program_text = program;
    sim::RunOptions opts;
    opts.trace = &rows;
    return sim.run(setup, opts);
  }
};

// From (0, 10) clockwise about the origin toward (10, 0): the ball centre
// reaches X = 7 on the arc at Y = sqrt(10^2 - 7^2).
const std::string kClockwise =
    "G21 G90 G17 G54\nG0 X0 Y10. Z-50.\nG02 X10. Y0 I0 J-10. F600.\nM30\n";

TEST(ArcContact, AnIdealServoTouchesTheWallWhereTheArcMeetsIt) {
  ArcRig r;
  for (auto& ax : r.m.axes) ax.kp_per_s = 0.0;  // the actual is the command
  auto res = r.run(kClockwise);
  ASSERT_TRUE(res);
  ASSERT_TRUE(res->alarm);
  EXPECT_EQ(res->alarm->id, AlarmId::kProbeProtection);
  EXPECT_EQ(res->alarm->loc.line, 3U);
  ASSERT_TRUE(res->alarm_position);
  const AxisVec& at = *res->alarm_position;
  EXPECT_NEAR(at[0], kWall - kBall, 1e-9);
  // On the arc, within the sag of one period's chord: (v T)^2 / 8R with
  // v T = 0.01 mm at F600 and a 1 ms period is 1.25e-6 mm.
  const double x = kWall - kBall;
  EXPECT_NEAR(at[1], std::sqrt(kArcRadius * kArcRadius - x * x), 2e-6);
  EXPECT_NEAR(at[2], -50.0, 1e-12);
}

TEST(ArcContact, TheContactIsOnTheLaggedActualPathNotOnTheCommandedArc) {
  ArcRig r;  // mill3_lowgain's servo: kp = 30/s, no feedforward
  // Counter-clockwise from (0, -10) about the origin toward (10, 0).
  auto res = r.run("G21 G90 G17 G54\nG0 X0 Y-10. Z-50.\nG03 X10. Y0 I0 J10. F600.\nM30\n");
  ASSERT_TRUE(res);
  ASSERT_TRUE(res->alarm);
  EXPECT_EQ(res->alarm->id, AlarmId::kProbeProtection);
  EXPECT_EQ(res->alarm->loc.line, 3U);
  ASSERT_TRUE(res->alarm_position);
  const AxisVec& at = *res->alarm_position;
  const double x = kWall - kBall;
  EXPECT_NEAR(at[0], x, 1e-9);
  // The two servo samples of the actual position around the contact, and
  // the point of their chord at X = 7.
  const auto& rows = r.rows.actual;
  std::size_t k = 1;
  while (k < rows.size() && !(rows[k - 1][0] < x && rows[k][0] >= x)) ++k;
  ASSERT_LT(k, rows.size()) << "the actual path never reached X" << x;
  const AxisVec& a = rows[k - 1];
  const AxisVec& b = rows[k];
  const double s = (x - a[0]) / (b[0] - a[0]);
  EXPECT_NEAR(at[1], a[1] + s * (b[1] - a[1]), 1e-9);
  // The lagged path cuts inside the commanded arc: on a circle of radius R
  // at angular speed w = v / R a first-order loop keeps the radius
  // R / sqrt(1 + (w / kp)^2), 5.6 um short here. The contact is where the
  // actual path meets the wall, below the commanded arc's point.
  const double w = 10.0 / kArcRadius, kp = 30.0;
  const double lagged = kArcRadius / std::sqrt(1.0 + (w / kp) * (w / kp));
  EXPECT_NEAR(at[1], -std::sqrt(lagged * lagged - x * x), 2e-4);
  EXPECT_GT(at[1] + std::sqrt(kArcRadius * kArcRadius - x * x), 5e-3);
}

}  // namespace
}  // namespace skipnc::machine
