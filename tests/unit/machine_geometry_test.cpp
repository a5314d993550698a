// Exact contact of a moving ball with the scene's parts: every feature kind
// (face, edge, corner, boss wall, bore wall, sphere, rim) against an
// independent closed-form answer, in directions that are not along an axis.
#include <gtest/gtest.h>

#include <cmath>

#include "machine/geometry.hpp"

namespace skipnc::machine::geo {
namespace {

constexpr double kTol = 1e-9;

Material one(Shape solid) {
  Part p;
  p.solids.push_back(solid);
  return Material({p});
}

Material with_hole(Shape solid, Shape hole) {
  Part p;
  p.solids.push_back(solid);
  p.holes.push_back(hole);
  return Material({p});
}

Vec3 unit(Vec3 v) {
  return v * (1.0 / length(v));
}

TEST(GeometryContact, BallOnATiltedPlaneAlongAnyDirection) {
  // Material below the plane through (0, 0, -5) with normal (1, 2, 3).
  const Vec3 n = unit({1, 2, 3});
  const Material m = one(make_half_space({0, 0, -5}, {1, 2, 3}));
  const Vec3 a{3, -4, 20}, b{-2, 1, -30};
  const double r = 1.5;
  Contact c;
  ASSERT_TRUE(m.first_contact(a, b, r, c));
  // Signed distance of the centre is linear along the segment: solve = r.
  const double s0 = dot(a - Vec3{0, 0, -5}, n), s1 = dot(b - Vec3{0, 0, -5}, n);
  EXPECT_NEAR(c.t, (s0 - r) / (s0 - s1), kTol);
  EXPECT_NEAR(dot(c.normal, n), 1.0, kTol);
  EXPECT_NEAR(dot(c.point - Vec3{0, 0, -5}, n), 0.0, kTol);
}

TEST(GeometryContact, BallOnABoxFaceEdgeAndCorner) {
  const Material m = one(make_box({0, 0, 0}, {10, 20, 5}));
  const double r = 2.0;
  Contact c;
  // Face: straight down onto the top.
  ASSERT_TRUE(m.first_contact({4, 7, 12}, {4, 7, 2}, r, c));
  EXPECT_NEAR(c.t, (12.0 - 5.0 - r) / 10.0, kTol);
  EXPECT_NEAR(c.point.z, 5.0, kTol);
  // Edge: the top edge along Y at x = 10, approached diagonally in XZ.
  const Vec3 a{16, 3, 11}, b{6, 9, 1};
  ASSERT_TRUE(m.first_contact(a, b, r, c));
  {
    // Distance from the centre to the line x = 10, z = 5 must be r.
    const Vec3 p = lerp(a, b, c.t);
    EXPECT_NEAR(std::hypot(p.x - 10.0, p.z - 5.0), r, kTol);
    EXPECT_NEAR(c.point.x, 10.0, kTol);
    EXPECT_NEAR(c.point.z, 5.0, kTol);
    EXPECT_NEAR(c.point.y, p.y, kTol);
    // And not earlier: the edge is the first feature met.
    const Vec3 q = lerp(a, b, c.t - 1e-6);
    EXPECT_GT(m.distance(q), r);
  }
  // Corner (10, 20, 5): a path whose closest approach is near the corner.
  const Vec3 a2{14, 24, 9}, b2{8, 18, 3};
  ASSERT_TRUE(m.first_contact(a2, b2, r, c));
  {
    const Vec3 p = lerp(a2, b2, c.t);
    EXPECT_NEAR(length(p - Vec3{10, 20, 5}), r, kTol);
    EXPECT_NEAR(length(c.point - Vec3{10, 20, 5}), 0.0, kTol);
    EXPECT_NEAR(length(c.normal - unit(Vec3{1, 1, 1})), 0.0, 1e-9);
  }
}

TEST(GeometryContact, BallOutsideABossAndInsideABore) {
  const double R = 12.5, r = 1.0;
  // Boss: approach along a chord, off the axis.
  const Material boss = one(make_cylinder(3.0, -4.0, R, -10.0, 0.0));
  Contact c;
  const Vec3 a{40, 2, -5}, b{-20, 2, -5};
  ASSERT_TRUE(boss.first_contact(a, b, r, c));
  const Vec3 p = lerp(a, b, c.t);
  EXPECT_NEAR(std::hypot(p.x - 3.0, p.y + 4.0), R + r, kTol);
  EXPECT_GT(p.x, 3.0);  // the near side
  // Bore in a plate: from inside, in an oblique direction.
  const Material plate =
      with_hole(make_box({-50, -50, -20}, {50, 50, 0}), make_cylinder(3.0, -4.0, R, -1e6, 1e6));
  const Vec3 a2{3.5, -3.0, -8}, b2{30, 20, -9};
  ASSERT_TRUE(plate.first_contact(a2, b2, r, c));
  const Vec3 q = lerp(a2, b2, c.t);
  EXPECT_NEAR(std::hypot(q.x - 3.0, q.y + 4.0), R - r, kTol);
  EXPECT_NEAR(std::hypot(c.point.x - 3.0, c.point.y + 4.0), R, kTol);
  // The normal points from the wall back to the axis.
  EXPECT_LT(c.normal.x * (q.x - 3.0) + c.normal.y * (q.y + 4.0), 0.0);
}

TEST(GeometryContact, TheTopFaceOverABoreIsNotMaterial) {
  const Material plate =
      with_hole(make_box({-50, -50, -20}, {50, 50, 0}), make_cylinder(0.0, 0.0, 10.0, -1e6, 1e6));
  Contact c;
  // Straight down the bore's axis: nothing (a through bore).
  EXPECT_FALSE(plate.first_contact({0, 0, 10}, {0, 0, -40}, 2.0, c));
  // Down beside the bore, on the top face.
  ASSERT_TRUE(plate.first_contact({20, 0, 10}, {20, 0, -10}, 2.0, c));
  EXPECT_NEAR(c.point.z, 0.0, kTol);
  // Down near the edge of the bore: the ball meets the rim (a circle).
  const double x = 9.0;  // centre 1 mm inside the bore radius, ball radius 2
  ASSERT_TRUE(plate.first_contact({x, 0, 10}, {x, 0, -10}, 2.0, c));
  const Vec3 p = lerp(Vec3{x, 0, 10}, Vec3{x, 0, -10}, c.t);
  EXPECT_NEAR(p.z, std::sqrt(4.0 - 1.0), 1e-9);  // |(9,0,z) - (10,0,0)| = 2
  EXPECT_NEAR(c.point.x, 10.0, 1e-9);
  EXPECT_NEAR(c.point.z, 0.0, 1e-9);
}

TEST(GeometryContact, BlindBoreFloorAndPocketWalls) {
  const Material plate =
      with_hole(make_box({-50, -50, -20}, {50, 50, 0}), make_cylinder(0.0, 0.0, 10.0, -8.0, 1e6));
  Contact c;
  ASSERT_TRUE(plate.first_contact({1, 2, 5}, {1, 2, -15}, 1.5, c));
  EXPECT_NEAR(lerp(Vec3{1, 2, 5}, Vec3{1, 2, -15}, c.t).z, -8.0 + 1.5, kTol);
  const Material pocket =
      with_hole(make_box({-50, -50, -20}, {50, 50, 0}), make_box({-15, -5, -10}, {15, 5, 1}));
  // Across the pocket in X at mid height: the far wall, from inside.
  ASSERT_TRUE(pocket.first_contact({0, 0, -5}, {40, 3, -5}, 1.0, c));
  EXPECT_NEAR(lerp(Vec3{0, 0, -5}, Vec3{40, 3, -5}, c.t).x, 14.0, kTol);
  EXPECT_NEAR(c.normal.x, -1.0, kTol);
  // Over the pocket's top edge from outside: the rim segment at x = 15, z = 0.
  ASSERT_TRUE(pocket.first_contact({16, 0, 5}, {16, 0, -5}, 2.0, c));
  const Vec3 p = lerp(Vec3{16, 0, 5}, Vec3{16, 0, -5}, c.t);
  EXPECT_NEAR(p.z, 2.0, kTol);  // on the top face (the face wins: x = 16 is material)
}

TEST(GeometryContact, SphereAndUnionOfParts) {
  Part a;
  a.solids.push_back(make_sphere({5, 5, 5}, 3.0));
  Part b;
  b.name = "block";
  b.solids.push_back(make_box({20, -5, -5}, {30, 5, 5}));
  const Material m({a, b});
  Contact c;
  const Vec3 from{-10, 5.5, 5}, to{40, 5.5, 5};
  ASSERT_TRUE(m.first_contact(from, to, 1.0, c));
  EXPECT_EQ(c.part, 0);
  const Vec3 p = lerp(from, to, c.t);
  EXPECT_NEAR(length(p - Vec3{5, 5, 5}), 4.0, kTol);
  // Starting past the sphere, the block is next.
  ASSERT_TRUE(m.first_contact({12, 0, 0}, {40, 0, 0}, 1.0, c));
  EXPECT_EQ(c.part, 1);
  EXPECT_NEAR(lerp(Vec3{12, 0, 0}, Vec3{40, 0, 0}, c.t).x, 19.0, kTol);
}

TEST(GeometryContact, ABallAlreadyInContactDoesNotTouchAgain) {
  const Material m = one(make_box({0, 0, 0}, {10, 10, 10}));
  Contact c;
  EXPECT_FALSE(m.first_contact({5, 5, 10.5}, {5, 5, 9}, 1.0, c));
  EXPECT_FALSE(m.first_contact({5, 5, 12}, {5, 5, 15}, 1.0, c));  // moving away
}

TEST(GeometryDistance, AgreesWithTheFeatures) {
  const Material plate =
      with_hole(make_box({-50, -50, -20}, {50, 50, 0}), make_cylinder(0.0, 0.0, 10.0, -1e6, 1e6));
  EXPECT_NEAR(plate.distance({0, 0, -10}), 10.0, kTol);  // on the axis, inside
  EXPECT_NEAR(plate.distance({6, 0, -10}), 4.0, kTol);
  EXPECT_NEAR(plate.distance({0, 0, 5}), std::hypot(10.0, 5.0), kTol);  // to the rim
  EXPECT_NEAR(plate.distance({30, 0, 5}), 5.0, kTol);
  EXPECT_EQ(plate.distance({30, 0, -5}), 0.0);  // in the material
  EXPECT_NEAR(plate.depth({30, 0, -5}), 5.0, kTol);
}

TEST(GeometryRoots, QuarticRootsInOrder) {
  // (t - 0.1)(t - 0.35)(t - 0.6)(t - 1.7)
  const double r[4] = {0.1, 0.35, 0.6, 1.7};
  double c[5] = {1, 0, 0, 0, 0};
  for (double x : r) {
    double n[5] = {0, 0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) {
      n[i + 1] += c[i];
      n[i] -= x * c[i];
    }
    for (int i = 0; i < 5; ++i) c[i] = n[i];
  }
  double out[4];
  const int k = polynomial_roots(c, 4, 0.0, 1.0, out);
  ASSERT_EQ(k, 3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(out[i], r[i], 1e-12);
}

TEST(GeometryColumns, ToolTipOntoASetterAndFromTheSide) {
  const Column setter{100, 50, 10, -305, -300};
  Column tool{100.5, 50.2, 5, -290, -190};
  double t = 0.0;
  // Down 20 mm: the tip meets the disc top at 10 mm (t = 0.5), plus 0.01 of switch depth.
  ASSERT_TRUE(column_first_overlap(tool, {0, 0, -20}, setter, 0.01, t));
  EXPECT_NEAR(t, 10.01 / 20.0, 1e-12);
  // From the side at the disc's height: radial overlap reaches 0.01 mm.
  Column side{130, 50, 5, -303, -203};
  ASSERT_TRUE(column_first_overlap(side, {-20, 0, 0}, setter, 0.01, t));
  EXPECT_NEAR(130 - 20 * t, 100 + 15 - 0.01, 1e-9);
  EXPECT_FALSE(column_first_overlap(side, {20, 0, 0}, setter, 0.01, t));
}

TEST(GeometryColumns, ToolInABoreDoesNotHitThePlate) {
  const Material plate =
      with_hole(make_box({-50, -50, -20}, {50, 50, 0}), make_cylinder(0.0, 0.0, 10.0, -1e6, 1e6));
  EXPECT_EQ(plate.column_hits(Column{1, 1, 5, -15, 80}, 1e-9), -1);
  EXPECT_EQ(plate.column_hits(Column{6, 0, 5, -15, 80}, 1e-9), 0);    // touches the wall
  EXPECT_EQ(plate.column_hits(Column{30, 0, 5, 0.5, 80}, 1e-9), -1);  // above the top
  EXPECT_EQ(plate.column_hits(Column{30, 0, 5, -0.5, 80}, 1e-9), 0);
}

}  // namespace
}  // namespace skipnc::machine::geo
