// The scene's sensors on their own: the touch probe's switch point
// (pre-travel, lobing, seeded scatter), its release, the tool setter and the
// multi-step diameter gauge, each with the exact instant of its edges.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "machine/probe.hpp"

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

}  // namespace
}  // namespace skipnc::machine
