// Program frame -> work frame: rotation, mirror, scaling, polar coordinates,
// with the expected points computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "interpreter/transform.hpp"

namespace {

using namespace skipnc::interp::xform;

void expect_point(const Point& got, const Point& want) {
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << "axis " << i;
}

TEST(Rotation, NinetyDegreesAboutACentre) {
  // G68 X10 Y10 R90: X20 Y10 (10 right of the centre) goes to 10 above it.
  Transform t;
  t.rotating = true;
  t.angle_deg = 90;
  t.rotation_center = {10, 10};
  expect_point(to_work(t, {20, 10, -5}), {10, 20, -5});
}

TEST(Rotation, ThirtyDegreesAboutTheOrigin) {
  // cos 30 = 0.8660254, sin 30 = 0.5: X10 Y0 -> X8.660254 Y5.
  Transform t;
  t.rotating = true;
  t.angle_deg = 30;
  const Point w = to_work(t, {10, 0, 0});
  EXPECT_NEAR(w[0], 8.660254037844, 1e-9);
  EXPECT_NEAR(w[1], 5.0, 1e-12);
}

TEST(Rotation, IncrementalMovesTurnWithoutTheCentre) {
  Transform t;
  t.rotating = true;
  t.angle_deg = -90;
  t.rotation_center = {100, 50};
  expect_point(vector_to_work(t, {5, 0, 1}), {0, -5, 1});
}

TEST(Mirror, AboutXFiftyFlipsX) {
  // G51.1 X50: X60 -> X40; Y unchanged.
  Transform t;
  t.mirror[0] = true;
  t.mirror_center = {50, 0, 0};
  expect_point(to_work(t, {60, 7, 0}), {40, 7, 0});
}

TEST(Scaling, HalfAboutACentre) {
  // G51 X10 Y10 P0.5 (per-axis 0.5): X30 Y10 -> X20 Y10; Z scaled about 0.
  Transform t;
  t.scale = {0.5, 0.5, 0.5};
  t.scale_center = {10, 10, 0};
  expect_point(to_work(t, {30, 10, -4}), {20, 10, -2});
}

TEST(Combined, MirrorThenScaleThenRotate) {
  // Mirror X about 0: (10, 0) -> (-10, 0); scale 2 about 0: (-20, 0);
  // rotate 90 about 0: (0, -20).
  Transform t;
  t.mirror[0] = true;
  t.scale = {2, 2, 1};
  t.rotating = true;
  t.angle_deg = 90;
  expect_point(to_work(t, {10, 0, 3}), {0, -20, 3});
}

TEST(Combined, ToProgramIsTheInverse) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u(-100, 100);
  for (int n = 0; n < 1000; ++n) {
    Transform t;
    t.mirror = {u(rng) > 0, u(rng) > 0, false};
    t.mirror_center = {u(rng), u(rng), u(rng)};
    t.scale = {0.5 + std::fabs(u(rng)) / 50, 0.5 + std::fabs(u(rng)) / 50, 1};
    t.scale_center = {u(rng), u(rng), 0};
    t.rotating = true;
    t.angle_deg = u(rng) * 3.6;
    t.rotation_center = {u(rng), u(rng)};
    const Point p{u(rng), u(rng), u(rng)};
    const Point back = to_program(t, to_work(t, p));
    for (std::size_t i = 0; i < 3; ++i) ASSERT_NEAR(back[i], p[i], 1e-9);
  }
}

TEST(Polar, RadiusAndAngleAboutTheCentre) {
  // G16 X50 Y60 about the origin: (25, 43.30127).
  const auto p = polar_to_xy({0, 0}, 50, 60);
  EXPECT_NEAR(p[0], 25.0, 1e-12);
  EXPECT_NEAR(p[1], 43.301270189222, 1e-9);
  const auto q = polar_to_xy({10, 10}, 5, 180);
  EXPECT_EQ(q[0], 5.0);
  EXPECT_EQ(q[1], 10.0);
}

TEST(Polar, QuarterTurnsAreExact) {
  EXPECT_EQ(cos_sin_deg(90), (std::array<double, 2>{0, 1}));
  EXPECT_EQ(cos_sin_deg(-90), (std::array<double, 2>{0, -1}));
  EXPECT_EQ(cos_sin_deg(540), (std::array<double, 2>{-1, 0}));
}

// The 3-D coordinate conversion G68 X Y Z I J K R (B-62764EN): hand values.
Transform turned(const Spatial& s) {
  return with_spatial(Transform{}, s);
}

TEST(Conversion, NinetyAboutXTurnsYToZ) {
  // Right-handed about +X: +Y goes to +Z, +Z to -Y.
  Spatial s;
  s.conversion[0].m = axis_angle({1, 0, 0}, 90);
  s.conversions = 1;
  const Transform t = turned(s);
  expect_point(to_work(t, {10, 20, 5}), {10, -5, 20});
  EXPECT_TRUE(t.tilted());
}

TEST(Conversion, AboutZIsThePlaneRotationAndNotTilted) {
  // I0 J0 K1 R90 about X10 Y5 turns X20 Y5 to X10 Y15 as G68 X10 Y5 R90;
  // K-1 the other way; Z is kept.
  Spatial s;
  s.conversion[0] = {axis_angle({0, 0, 1}, 90), {10, 5, -3}};
  s.conversions = 1;
  expect_point(to_work(turned(s), {20, 5, 7}), {10, 15, 7});
  EXPECT_FALSE(turned(s).tilted());
  s.conversion[0].m = axis_angle({0, 0, -1}, 90);
  expect_point(to_work(turned(s), {20, 5, 7}), {10, -5, 7});
}

TEST(Conversion, OneTwentyAboutTheDiagonalPermutesTheAxes) {
  // 120 degrees about 1 1 1 carries X to Y, Y to Z, Z to X: d = 1 2 3 ->
  // 3 1 2 about the centre 10 20 30.
  Spatial s;
  s.conversion[0] = {axis_angle({1, 1, 1}, 120), {10, 20, 30}};
  s.conversions = 1;
  const Point w = to_work(turned(s), {11, 22, 33});
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(w[i], (Point{13, 21, 32})[i], 1e-12);
}

TEST(Conversion, TheSecondIsInTheFirstsFrame) {
  // G68 ... I0 J0 K1 R90 then G68 I1 J0 K0 R90 (B-62764EN's example form):
  // 10 20 5 -> about X': 10 -5 20 -> about Z: 5 10 20.
  Spatial s;
  s.conversion[0].m = axis_angle({0, 0, 1}, 90);
  s.conversion[1].m = axis_angle({1, 0, 0}, 90);
  s.conversions = 2;
  expect_point(to_work(turned(s), {10, 20, 5}), {5, 10, 20});
  expect_point(to_program(turned(s), {5, 10, 20}), {10, 20, 5});
  // A vector turns without the centres.
  s.conversion[0].center = {100, 200, 300};
  expect_point(vector_to_work(turned(s), {1, 0, 0}), {0, 1, 0});
}

TEST(Conversion, ToProgramUndoesToWork) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-100, 100);
  for (int n = 0; n < 500; ++n) {
    Spatial s;
    s.conversions = 2;
    for (auto& k : s.conversion)
      k = {axis_angle({u(rng), u(rng), u(rng)}, u(rng) * 3.6), {u(rng), u(rng), u(rng)}};
    const Transform t = turned(s);
    const Point p{u(rng), u(rng), u(rng)};
    const Point back = to_program(t, to_work(t, p));
    for (std::size_t i = 0; i < 3; ++i) ASSERT_NEAR(back[i], p[i], 1e-9);
  }
}

TEST(Conversion, ZeroVectorIsTheIdentity) {
  const Matrix m = axis_angle({0, 0, 0}, 30);
  EXPECT_EQ(m[0][0], 1.0);
  EXPECT_EQ(m[1][0], 0.0);
}

TEST(Conversion, NoneLeavesTheFrameSmall) {
  // Without a conversion or a setting error the 3-D part is not held.
  EXPECT_EQ(turned(Spatial{}).spatial, nullptr);
  EXPECT_FALSE(turned(Spatial{}).active());
}

// G54.4 (A-79634E): the setting system's origin at d, turned about X, then
// Y, then Z: work = d + R p.
TEST(SettingError, TurnsAboutXThenZAndShifts) {
  Spatial s;
  s.setting_error = true;
  s.setting_turn = turn_xyz(90, 0, 90);
  s.setting_shift = {1, 0, 0};
  const Transform t = turned(s);
  // 10 20 5 -> about X: 10 -5 20 -> about Z: 5 10 20 -> + d: 6 10 20.
  expect_point(to_work(t, {10, 20, 5}), {6, 10, 20});
  expect_point(to_program(t, {6, 10, 20}), {10, 20, 5});
  expect_point(vector_to_work(t, {0, 0, 1}), {1, 0, 0});  // Z -> -Y -> X
  EXPECT_TRUE(t.tilted());
  s.setting_turn = turn_xyz(0, 0, 30);
  EXPECT_FALSE(turned(s).tilted());
}

TEST(SettingError, IsOutsideTheConversion) {
  // G68 I0 J0 K1 R90 inside G54.4 dc 0 with d = 100 0 0: the conversion
  // turns first, the setting error shifts after: 10 0 0 -> 0 10 0 -> 100 10 0.
  Spatial s;
  s.conversion[0].m = axis_angle({0, 0, 1}, 90);
  s.conversions = 1;
  s.setting_error = true;
  s.setting_shift = {100, 0, 0};
  expect_point(to_work(turned(s), {10, 0, 0}), {100, 10, 0});
  expect_point(to_program(turned(s), {100, 10, 0}), {10, 0, 0});
}

}  // namespace
