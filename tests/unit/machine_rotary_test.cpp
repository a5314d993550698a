// Parts on a rotary table (docs/scene.md, "Rotary tables"): a scene
// [[frame]] with `rotary = "C"` turns with the machine's C axis, and every
// part placed in it (or in a frame based on it) turns too. Expected contacts
// are worked out by hand from the geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/geometry.hpp"
#include "machine/scene.hpp"

namespace skipnc::machine {
namespace {

// mill3 with a C table: axes X Y Z C (C is machine axis 3).
const config::MachineConfig& mill4c() {
  static const auto m = config::parse_machine(R"(extends = "mill3"
[[axis]]
name = "C"
min = -9999.0
max = 9999.0
)",
                                              "mill4c.toml");
  return *m;
}

Result<Scene> load_table(const std::string& text) {
  static const auto d = config::builtin_dialect("fanuc");
  static const config::Parameters p(&*d);
  return parse_scene(text, "table.scene.toml", mill4c(), *d, p);
}

constexpr double kPi = 3.14159265358979323846;

// Positions of X Y Z C for set_turns (only C matters to the material).
struct Axes {
  double v[8] = {};
  explicit Axes(double c) { v[3] = c; }
};

const char* kTable = R"([[frame]]
name = "table"
origin = [100, 0, 0]
rotary = "C"
[[frame]]
name = "fixture"
base = "table"
origin = [20, 0, 0]
[[box]]
part = "block"
frame = "fixture"
min = [0, -5, -10]
max = [10, 5, 0]
)";

TEST(RotaryTable, APartTurnsWithTheAxisAboutTheTablesCentre) {
  auto s = load_table(kTable);
  ASSERT_TRUE(s) << s.error().detail;
  ASSERT_EQ(s->probing.parts.size(), 1u);
  EXPECT_EQ(s->probing.parts[0].rotary.axis, 3);
  geo::Material mat(s->probing.parts);
  ASSERT_TRUE(mat.turns());
  // At C0 the block stands X120..130, Y-5..5. A 1 mm ball coming down at
  // X125 Y0 touches its top at centre Z1.
  geo::Contact c;
  const Axes c0(0.0);
  mat.set_turns(c0.v, c0.v);
  ASSERT_TRUE(mat.first_contact({125, 0, 10}, {125, 0, -5}, 1.0, c));
  EXPECT_NEAR(10.0 - 15.0 * c.t, 1.0, 1e-12);
  // At C90 a table axis turns the table clockwise seen from +Z (rotary_sign
  // -1): the block goes to X95..105, Y-30..-20 about the centre (100, 0).
  const Axes c90(90.0);
  mat.set_turns(c90.v, c90.v);
  EXPECT_FALSE(mat.first_contact({125, 0, 10}, {125, 0, -5}, 1.0, c));
  ASSERT_TRUE(mat.first_contact({100, -25, 10}, {100, -25, -5}, 1.0, c));
  EXPECT_NEAR(10.0 - 15.0 * c.t, 1.0, 1e-12);
  // Its face toward -Y (the fixture's +X end) is at Y-30.
  ASSERT_TRUE(mat.first_contact({100, -40, -5}, {100, -20, -5}, 1.0, c));
  EXPECT_NEAR(-40.0 + 20.0 * c.t, -31.0, 1e-12);
  EXPECT_NEAR(c.normal.y, -1.0, 1e-12);
  EXPECT_EQ(mat.distance({100, -25, 0.5}), 0.5);
}

TEST(RotaryTable, TheTableTurningMeetsABallStandingStill) {
  auto s = load_table(kTable);
  ASSERT_TRUE(s) << s.error().detail;
  geo::Material mat(s->probing.parts);
  // A ball of radius 1 standing still at (110, -20), 22.36 mm from the
  // table's axis. The table turns clockwise as C goes positive, so in the
  // table's frame the ball turns counter-clockwise: it is at
  // (10 cos C + 20 sin C, 10 sin C - 20 cos C), and its centre comes 1 mm
  // from the block's face Y-5 (X20..30 there) when 10 sin C - 20 cos C = -6:
  // C = atan2(20, 10) + asin(-6 / sqrt(500)) = 47.87 degrees (X 21.5 then).
  const double deg = (std::atan2(20.0, 10.0) + std::asin(-6.0 / std::sqrt(500.0))) * 180.0 / kPi;
  ASSERT_GT(deg, 47.0);
  ASSERT_LT(deg, 48.0);
  // Step the table by 0.006 degrees a period (1 rpm), as a servo would,
  // until the ball touches: the contact's instant gives the angle. In the
  // table's frame the ball's path over a period is taken as the chord of
  // its arc, 22.4 (1.05e-4 rad)^2 / 8 = 3e-8 mm inside it: about 1e-8
  // degree of error here.
  const geo::Vec3 ball{110, -20, -5};
  double found = -1.0;
  for (int k = 0; k < 10000 && found < 0.0; ++k) {
    const Axes before(0.006 * k), after(0.006 * (k + 1));
    mat.set_turns(before.v, after.v);
    geo::Contact c;
    if (mat.first_contact(ball, ball, 1.0, c)) found = 0.006 * (k + c.t);
  }
  EXPECT_NEAR(found, deg, 1e-7);
}

TEST(RotaryTable, BadRotaryFramesAreRefusedWithTheirPlace) {
  auto missing = load_table("[[frame]]\nname = \"t\"\nrotary = \"A\"\n");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().loc.line, 3u);
  EXPECT_NE(missing.error().detail.find("not an axis of this machine"), std::string::npos);
  auto letter = load_table("[[frame]]\nname = \"t\"\nrotary = \"X\"\n");
  ASSERT_FALSE(letter);
  EXPECT_EQ(letter.error().loc.line, 3u);
  auto sign = load_table("[[frame]]\nname = \"t\"\nrotary = \"C\"\nrotary_sign = 2\n");
  ASSERT_FALSE(sign);
  EXPECT_EQ(sign.error().loc.line, 4u);
  auto lone = load_table("[[frame]]\nname = \"t\"\nrotary_sign = 1\n");
  ASSERT_FALSE(lone);
  EXPECT_EQ(lone.error().loc.line, 3u);
  auto twice = load_table(
      "[[frame]]\nname = \"t\"\nrotary = \"C\"\n[[frame]]\nname = \"u\"\nbase = \"t\"\n"
      "rotary = \"C\"\n");
  ASSERT_FALSE(twice);
  EXPECT_EQ(twice.error().loc.line, 7u);
  auto setter = load_table(
      "[[frame]]\nname = \"t\"\nrotary = \"C\"\n[tool_setter]\nsignal = \"SKIP\"\n"
      "frame = \"t\"\ncenter = [0, 0]\ntop = 0\nradius = 5\n");
  ASSERT_FALSE(setter);
  EXPECT_EQ(setter.error().loc.line, 6u);
}

}  // namespace
}  // namespace skipnc::machine
