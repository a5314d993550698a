// The scene's sensors on their own: the touch probe's switch point
// (pre-travel, lobing, seeded scatter), its release, the tool setter and the
// multi-step diameter gauge, each with the exact instant of its edges. Then
// the probing scene's rest (ProbeScene::at_rest): periods in which the probe
// is free and it and its body are clear of every part are passed on a
// distance test; a probe that comes from far away fast must still touch and
// collide at the same micrometre as one checked in every period (positions
// worked out by hand from the geometry).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/probe.hpp"
#include "machine/probe_scene.hpp"
#include "machine/scene.hpp"

namespace skipnc::machine {
namespace {

using geo::Vec3;

geo::Material slab() {
  geo::Part p;
  p.solids.push_back(geo::make_box({-50, -50, -20}, {50, 50, 0}));
  return geo::Material({p});
}

ProbeSpec probe_spec(double pre, double lobing = 0.0, double sigma = 0.0, std::uint64_t seed = 1) {
  ProbeSpec s;
  s.ball_radius = 1.0;
  s.pre_travel = pre;
  s.lobing = lobing;
  s.repeatability = sigma;
  s.seed = seed;
  s.max_overtravel = 0.5;
  return s;
}

TEST(TouchProbe, SwitchesAfterThePreTravelAtTheExactInstant) {
  const geo::Material m = slab();
  TouchProbe p(probe_spec(0.01), m);
  p.reset({0, 0, 5});
  SensorEdge e[2];
  // First period: the ball touches (centre at z = 1) but is pushed only 0.005.
  EXPECT_EQ(p.advance({0, 0, 5}, {0, 0, 0.995}, e), 0);
  EXPECT_TRUE(p.touching());
  EXPECT_FALSE(p.on());
  EXPECT_NEAR(p.deflection(), 0.005, 1e-12);
  // Second period: it switches when the centre is at z = 0.99.
  ASSERT_EQ(p.advance({0, 0, 0.995}, {0, 0, 0.9}, e), 1);
  EXPECT_TRUE(e[0].on);
  EXPECT_NEAR(e[0].frac, (0.995 - 0.99) / (0.995 - 0.9), 1e-12);
  EXPECT_NEAR(p.deflection(), 0.1, 1e-12);
  EXPECT_NEAR(p.overshoot(), 0.1 - 0.01 - 0.5, 1e-12);
  // Backing off: it releases where it switched.
  ASSERT_EQ(p.advance({0, 0, 0.9}, {0, 0, 1.5}, e), 1);
  EXPECT_FALSE(e[0].on);
  EXPECT_NEAR(e[0].frac, (0.99 - 0.9) / 0.6, 1e-12);
  EXPECT_FALSE(p.touching());
}

TEST(TouchProbe, ATouchInsideOnePeriodGivesBothEdgesInOrder) {
  geo::Part part;
  part.solids.push_back(geo::make_sphere({0, 0, 0}, 5.0));
  const geo::Material m({part});
  TouchProbe p(probe_spec(0.0), m);
  p.reset({-10, 5.5, 0});
  SensorEdge e[2];
  // A graze: the path passes 5.5 from the centre, the ball reaches 6.
  ASSERT_EQ(p.advance({-10, 5.5, 0}, {10, 5.5, 0}, e), 2);
  EXPECT_TRUE(e[0].on);
  EXPECT_FALSE(e[1].on);
  const double half = std::sqrt(36.0 - 5.5 * 5.5);
  EXPECT_NEAR(e[0].frac, (10.0 - half) / 20.0, 1e-12);
  EXPECT_NEAR(e[1].frac, (10.0 + half) / 20.0, 1e-12);
}

TEST(TouchProbe, LobingDependsOnTheApproachDirection) {
  const ProbeSpec s = probe_spec(0.002, 0.004);  // 3 lobes, phase 0
  const geo::Material m = slab();
  TouchProbe p(s, m);
  // The normal points from the surface to the ball; the probe moves against it.
  EXPECT_NEAR(p.pre_travel_for({-1, 0, 0}), 0.002, 1e-15);  // approach +X: least
  EXPECT_NEAR(p.pre_travel_for({1, 0, 0}), 0.006, 1e-15);   // approach -X: 3 * 180 deg
  const double a = 20.0 * std::numbers::pi / 180.0;         // approach at 200 deg
  EXPECT_NEAR(
      p.pre_travel_for({-std::cos(a + std::numbers::pi), -std::sin(a + std::numbers::pi), 0}),
      0.002 + 0.004 * 0.5 * (1 - std::cos(3 * (a + std::numbers::pi))), 1e-15);
  EXPECT_NEAR(p.pre_travel_for({0, 0, 1}), 0.002, 1e-15);  // along Z: no lobing
}

// The switch deflection of n successive touches on the slab's top.
std::vector<double> switch_points(std::uint64_t seed, double sigma, int n) {
  const geo::Material m = slab();
  TouchProbe p(probe_spec(0.01, 0.0, sigma, seed), m);
  p.reset({0, 0, 3});
  std::vector<double> out;
  SensorEdge e[2];
  for (int i = 0; i < n; ++i) {
    (void)p.advance({0, 0, 3}, {0, 0, 0.9}, e);
    out.push_back(p.switch_deflection());
    (void)p.advance({0, 0, 0.9}, {0, 0, 3}, e);
  }
  return out;
}

TEST(TouchProbe, ScatterIsSeededAndHasItsStandardDeviation) {
  const auto a = switch_points(42, 0.0005, 4000);
  const auto b = switch_points(42, 0.0005, 4000);
  const auto c = switch_points(43, 0.0005, 4000);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  double mean = 0.0;
  for (double v : a) mean += v;
  mean /= static_cast<double>(a.size());
  double ss = 0.0;
  for (double v : a) ss += (v - mean) * (v - mean);
  const double sd = std::sqrt(ss / static_cast<double>(a.size() - 1));
  // 4000 samples: the mean within 4 standard errors, sigma within 5 %.
  EXPECT_NEAR(mean, 0.01, 4 * 0.0005 / std::sqrt(4000.0));
  EXPECT_NEAR(sd, 0.0005, 0.000025);
  // Without scatter, every touch switches at the pre-travel.
  for (double v : switch_points(42, 0.0, 10)) EXPECT_EQ(v, 0.01);
}

TEST(SetterSensor, SwitchesWhenTheTipHasPressedThePreTravel) {
  ToolSetterSpec s;
  s.x = 10;
  s.y = 20;
  s.top = -300;
  s.radius = 8;
  s.pre_travel = 0.005;
  s.max_overtravel = 2;
  SetterSensor setter(s);
  geo::Column tool{10.3, 19.8, 4, -290, -190};
  setter.reset(&tool);
  SensorEdge e[2];
  ASSERT_EQ(setter.advance(&tool, {0, 0, -12}, e), 1);
  EXPECT_NEAR(e[0].frac, 10.005 / 12.0, 1e-12);
  EXPECT_NEAR(setter.deflection(), 2.0, 1e-9);
  EXPECT_NEAR(setter.overshoot(), 2.0 - 0.005 - 2.0, 1e-9);
  geo::Column low = tool;
  low.bottom -= 12;
  low.top -= 12;
  ASSERT_EQ(setter.advance(&low, {0, 0, 4}, e), 1);
  EXPECT_FALSE(e[0].on);
  EXPECT_NEAR(e[0].frac, (2.0 - 0.005) / 4.0, 1e-9);
}

TEST(GaugeSensor, EachStepSwitchesWhenTheDiameterReachesItsSize) {
  GaugeSpec g;
  g.axis = 0;
  g.center = 100.0;
  g.raw_diameter = 52.0;
  g.steps = {GaugeStep{{}, "SKIP2", 50.4}, GaugeStep{{}, "SKIP3", 50.1},
             GaugeStep{{}, "SKIP4", 50.0}};
  GaugeSensor gauge(g);
  gauge.reset(140.0);  // wheel clear of the work
  EXPECT_EQ(gauge.diameter(), 52.0);
  std::vector<std::pair<std::size_t, double>> seen;
  auto record = [&](std::size_t i, double f) { seen.emplace_back(i, f); };
  gauge.advance(140.0, 125.3, record);  // down to diameter 50.6
  EXPECT_TRUE(seen.empty());
  gauge.advance(125.3, 125.1, record);  // through 50.4 at 125.2
  ASSERT_EQ(seen.size(), 1U);
  EXPECT_EQ(seen[0].first, 0U);
  EXPECT_NEAR(seen[0].second, 0.5, 1e-9);
  gauge.advance(125.1, 125.3, record);  // backing off: the part stays ground
  EXPECT_NEAR(gauge.diameter(), 50.2, 1e-12);
  gauge.advance(125.3, 124.9, record);  // through 50.1 and 50.0
  ASSERT_EQ(seen.size(), 3U);
  EXPECT_NEAR(seen[1].second, (125.3 - 125.05) / 0.4, 1e-9);
  EXPECT_NEAR(seen[2].second, (125.3 - 125.0) / 0.4, 1e-9);
}

// A block X0..50, Y0..40, Z-100..-60; the probe's ball centre is 100 mm
// below the spindle, its body (radius 10) from 30 mm above the ball centre
// to the spindle. No pre-travel: the probe switches at the first touch.
const Scene& rest_block_scene() {
  static const auto m = config::builtin_machine("mill3");
  static const auto d = config::builtin_dialect("fanuc");
  static const config::Parameters p(&*d);
  static const Scene s = *parse_scene(R"(spindle_tool = 20
[[box]]
part = "block"
min = [0, 0, -100]
max = [50, 40, -60]
[probe]
signal = "SKIP"
tool = 20
ball_radius = 1.0
length = 100
stylus_length = 30
body_radius = 10
pre_travel = 0.0
max_overtravel = 2.0
)",
                                      "block.scene.toml", *m, *d, p);
  return s;
}

const config::MachineConfig& rest_mill3() {
  static const auto m = config::builtin_machine("mill3");
  return *m;
}

AxisVec rest_at(double x, double y, double z) {
  AxisVec v;
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

// Moves the spindle along X from x0 in steps of `step` mm a period (Y and Z
// fixed) until the probe switches or something collides, or x1 is passed.
// Returns whether the scene was at rest in some period on the way.
bool rest_sweep_x(ProbeScene& ps, double x0, double x1, double step, double y, double z) {
  ps.reset(rest_at(x0, y, z));
  bool rested = false;
  for (double x = x0; x < x1; x += step) {
    ps.advance(rest_at(x, y, z), rest_at(x + step, y, z));
    rested = rested || ps.at_rest();
    if (ps.touch_switched_on() || ps.fault().kind != PlantFault::Kind::kNone) break;
  }
  return rested;
}

TEST(ProbeRest, AFastApproachFromFarTouchesTheFaceAtTheSameMicrometre) {
  ProbeScene ps(rest_block_scene().probing, rest_mill3());
  // 60 m/min in 1 ms periods toward the -X face, the ball at Z-80 (inside
  // the face), the body above the block. The ball's centre touches at X-1.
  EXPECT_TRUE(rest_sweep_x(ps, -60.25, 10.0, 1.0, 20.0, 20.0));
  ASSERT_TRUE(ps.touch_switched_on());
  EXPECT_NEAR(ps.touch_position()[0], -1.0, 1e-9);
  EXPECT_EQ(ps.fault().kind, PlantFault::Kind::kNone);
}

TEST(ProbeRest, ABallPassingAPartsEdgeTouchesTheEdge) {
  ProbeScene ps(rest_block_scene().probing, rest_mill3());
  // Half a millimetre outside the block's Y0 face: the ball meets the
  // vertical edge at X0 Y0 when its centre is 1 mm from it in XY.
  EXPECT_TRUE(rest_sweep_x(ps, -60.25, 10.0, 1.0, -0.5, 20.0));
  ASSERT_TRUE(ps.touch_switched_on());
  EXPECT_NEAR(ps.touch_position()[0], -std::sqrt(0.75), 1e-9);
  EXPECT_NEAR(ps.touch_position()[1], -0.5, 1e-12);
  // 1.5 mm outside it the ball passes by: no touch along the whole block.
  ProbeScene by(rest_block_scene().probing, rest_mill3());
  EXPECT_TRUE(rest_sweep_x(by, -60.25, 80.0, 1.0, -1.5, 20.0));
  EXPECT_FALSE(by.touch_switched_on());
  EXPECT_EQ(by.fault().kind, PlantFault::Kind::kNone);
}

TEST(ProbeRest, TheBodyComingFastCollidesWhereItsSideMeetsTheFace) {
  ProbeScene ps(rest_block_scene().probing, rest_mill3());
  // The ball at Z-100, the body from Z-70 up: its side (radius 10) meets
  // the -X face at X-10, before the ball could reach it at X-1.
  EXPECT_TRUE(rest_sweep_x(ps, -80.25, 10.0, 1.0, 20.0, 0.0));
  ASSERT_EQ(ps.fault().kind, PlantFault::Kind::kCollision);
  EXPECT_EQ(ps.fault().tool, -1);  // the probe body
  EXPECT_NEAR(ps.fault().at[0], -10.0, 1e-6);
  EXPECT_FALSE(ps.touch_switched_on());
}

}  // namespace
}  // namespace skipnc::machine
