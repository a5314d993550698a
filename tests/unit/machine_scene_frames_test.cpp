// Scenes as the setup sheet has them: parts and the tool setter placed in a
// work frame of the machine file (G54..G59) or in a scene [[frame]] (an
// origin and a turn about Z, or about X, Y and Z), and the probe's length
// kept in one place.
// Expected contacts are worked out by hand from the geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/geometry.hpp"
#include "machine/scene.hpp"

namespace skipnc::machine {
namespace {

// mill3 with EXT Z-1, G54 (100, 50, -200) and the probe's 150 mm in H20.
const config::MachineConfig& frames_shop() {
  static const auto m = config::parse_machine(R"(extends = "mill3"
[work_offsets]
EXT = { Z = -1.0 }
G54 = { X = 100.0, Y = 50.0, Z = -200.0 }
[tool_offsets]
20 = { length = 149.5, length_wear = 0.5 }
)",
                                              "shop.toml");
  return *m;
}

Result<Scene> load_frames(const std::string& text) {
  static const auto d = config::builtin_dialect("fanuc");
  static const config::Parameters p(&*d);
  return parse_scene(text, "frames.scene.toml", frames_shop(), *d, p);
}

constexpr double kPi = 3.14159265358979323846;

TEST(SceneFrames, APartInG54StandsAtExtPlusG54) {
  auto s = load_frames(R"([[box]]
part = "block"
frame = "G54"
min = [-10, -10, -20]
max = [10, 10, 0]
)");
  ASSERT_TRUE(s) << s.error().detail;
  const geo::Material mat(s->probing.parts);
  // The top face is at work Z0: machine Z = EXT -1 + G54 -200 = -201. A 1 mm
  // ball coming down at X100 Y50 from Z-190 to Z-210 touches it when its
  // centre is at Z-200: half-way.
  geo::Contact c;
  ASSERT_TRUE(mat.first_contact({100, 50, -190}, {100, 50, -210}, 1.0, c));
  EXPECT_NEAR(c.t, 0.5, 1e-12);
  EXPECT_NEAR(c.point.z, -201.0, 1e-12);
  EXPECT_NEAR(c.normal.z, 1.0, 1e-12);
  // The side face X+ is at machine X110: a ball moving -X at Z-211 touches at
  // centre X111.
  ASSERT_TRUE(mat.first_contact({130, 50, -211}, {100, 50, -211}, 1.0, c));
  EXPECT_NEAR(130.0 - 30.0 * c.t, 111.0, 1e-9);
}

TEST(SceneFrames, APartInATurnedFrameIsTouchedOnItsTurnedFace) {
  auto s = load_frames(R"([[frame]]
name = "vise"
base = "G54"
origin = [5, 0, 0]
rotation = 30.0
[[box]]
part = "jaw"
frame = "vise"
min = [0, 0, -20]
max = [40, 20, 0]
)");
  ASSERT_TRUE(s) << s.error().detail;
  const geo::Material mat(s->probing.parts);
  // The jaw's front face is the line through the vise origin, machine
  // (105, 50), along (cos 30, sin 30); outward normal n = (sin 30, -cos 30).
  // A 1 mm ball moving +Y at X125 touches when (X - 105) sin 30 - (Y - 50)
  // cos 30 = 1: Y = 50 + (20 * 0.5 - 1) / cos 30.
  const double y = 50.0 + 9.0 / std::cos(30.0 * kPi / 180.0);
  geo::Contact c;
  ASSERT_TRUE(mat.first_contact({125, 40, -211}, {125, 80, -211}, 1.0, c));
  EXPECT_NEAR(40.0 + 40.0 * c.t, y, 1e-9);
  EXPECT_NEAR(c.normal.x, 0.5, 1e-12);  // n = (sin 30, -cos 30)
  EXPECT_NEAR(c.normal.y, -std::cos(30.0 * kPi / 180.0), 1e-12);
  // Distance and depth are taken in the part's frame too: the vise origin
  // corner (105, 50, -201) is on the surface; 1 mm inside along the face
  // normal is 1 mm deep.
  EXPECT_NEAR(mat.distance({105.0 - 0.5 * 2, 50.0 + std::cos(30.0 * kPi / 180.0) * 2, -201.0 - 5}),
              0.0, 1e-12);
  EXPECT_NEAR(mat.depth({105 + 20 * std::cos(30 * kPi / 180) - 0.5 * 1.0,
                         50 + 20 * 0.5 + std::cos(30 * kPi / 180) * 1.0, -211}),
              1.0, 1e-9);
}

TEST(SceneFrames, ATurnedColumnCheckUsesThePartsFrame) {
  auto s = load_frames(R"([[frame]]
name = "turned"
origin = [0, 0, 0]
rotation = 45.0
[[box]]
frame = "turned"
min = [0, -1, -10]
max = [100, 1, 0]
)");
  ASSERT_TRUE(s) << s.error().detail;
  const geo::Material mat(s->probing.parts);
  // A thin bar along the 45-degree diagonal: a 0.5 mm tool at (50, 50) stands
  // on its axis; at (50, 0) it is 35 mm away.
  EXPECT_EQ(mat.column_hits({50.0 * std::sqrt(0.5), 50.0 * std::sqrt(0.5), 0.5, -5, 100}, 1e-9), 0);
  EXPECT_EQ(mat.column_hits({50, 0, 0.5, -5, 100}, 1e-9), -1);
}

TEST(SceneFrames, AFrameTurnedAboutXStandsAPlateOnItsEdge) {
  auto s = load_frames(R"([[frame]]
name = "on_edge"
rotation = [90.0, 0.0, 0.0]
[[box]]
frame = "on_edge"
min = [0, 0, 0]
max = [10, 5, 2]
)");
  ASSERT_TRUE(s) << s.error().detail;
  const geo::Material mat(s->probing.parts);
  // Turned 90 degrees about X, the frame's Y is machine Z and its Z is
  // machine -Y: the plate stands X 0..10, Y -2..0, Z 0..5. A 1 mm ball coming
  // down at (5, -1) touches its top edge face at centre Z6.
  geo::Contact c;
  ASSERT_TRUE(mat.first_contact({5, -1, 20}, {5, -1, 0}, 1.0, c));
  EXPECT_NEAR(20.0 - 20.0 * c.t, 6.0, 1e-12);
  EXPECT_NEAR(c.normal.z, 1.0, 1e-12);
  // Its face toward -Y is at Y-2: a ball moving +Y at Z2.5 touches at Y-3.
  ASSERT_TRUE(mat.first_contact({5, -10, 2.5}, {5, 0, 2.5}, 1.0, c));
  EXPECT_NEAR(-10.0 + 10.0 * c.t, -3.0, 1e-12);
  EXPECT_NEAR(c.normal.y, -1.0, 1e-12);
}

TEST(SceneFrames, AToolAboveAPartTiltedAboutYHitsItWhereItsRimDips) {
  auto s = load_frames(R"([[frame]]
name = "tilted"
rotation = [0.0, 30.0, 0.0]
[[box]]
frame = "tilted"
min = [0, -5, -1]
max = [50, 5, 0]
)");
  ASSERT_TRUE(s) << s.error().detail;
  const geo::Material mat(s->probing.parts);
  // Turned 30 degrees about Y, the top face is the plane Z = -X tan 30. A
  // 2 mm tool at X20 sees it highest under its rim at X18: Z = -10.392. The
  // column leans in the part's frame, so it is checked point by point
  // (0.094 mm deep at Z-10.5, against a 0.05 mm tolerance).
  EXPECT_EQ(mat.column_hits({20, 0, 2, -10.3, 100}, 0.05), -1);
  EXPECT_EQ(mat.column_hits({20, 0, 2, -10.5, 100}, 0.05), 0);
  EXPECT_EQ(mat.column_hits({20, 20, 2, -30, 100}, 0.05), -1);
}

TEST(SceneFrames, TheToolSetterIsPlacedInItsFrame) {
  auto s = load_frames(R"([tool_setter]
signal = "SKIP"
frame = "G54"
center = [-250, -150]
top = -100
radius = 6
)");
  ASSERT_TRUE(s) << s.error().detail;
  ASSERT_TRUE(s->probing.tool_setter);
  EXPECT_DOUBLE_EQ(s->probing.tool_setter->x, -150.0);
  EXPECT_DOUBLE_EQ(s->probing.tool_setter->y, -100.0);
  EXPECT_DOUBLE_EQ(s->probing.tool_setter->top, -301.0);
}

TEST(SceneFrames, BadFramesAreRefusedWithTheirPlace) {
  auto unknown = load_frames("[[box]]\nframe = \"G60\"\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n");
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error().id, AlarmId::kConfig);
  EXPECT_EQ(unknown.error().loc.line, 2u);
  auto twice = load_frames(R"([[box]]
part = "p"
min = [0, 0, 0]
max = [1, 1, 1]
[[bore]]
part = "p"
frame = "G54"
center = [0, 0]
radius = 0.2
)");
  ASSERT_FALSE(twice);
  EXPECT_EQ(twice.error().loc.line, 7u);
  auto builtin = load_frames("[[frame]]\nname = \"G54\"\n");
  ASSERT_FALSE(builtin);
  EXPECT_EQ(builtin.error().loc.line, 2u);
  auto later = load_frames("[[frame]]\nname = \"a\"\nbase = \"b\"\n[[frame]]\nname = \"b\"\n");
  ASSERT_FALSE(later);
  EXPECT_EQ(later.error().loc.line, 3u);
  auto turn = load_frames("[[frame]]\nname = \"a\"\nrotation = 400.0\n");
  ASSERT_FALSE(turn);
  EXPECT_EQ(turn.error().loc.line, 3u);
  auto two = load_frames("[[frame]]\nname = \"a\"\nrotation = [1.0, 2.0]\n");
  ASSERT_FALSE(two);
  EXPECT_EQ(two.error().loc.line, 3u);
  EXPECT_NE(two.error().detail.find("about X, about Y, about Z"), std::string::npos);
  auto wide = load_frames("[[frame]]\nname = \"a\"\nrotation = [0.0, -361.0, 0.0]\n");
  ASSERT_FALSE(wide);
  EXPECT_EQ(wide.error().loc.line, 3u);
}

TEST(ProbeLength, ComesFromTheMachineFilesToolOffsetWhenTheSceneLeavesItOut) {
  auto s =
      load_frames("[probe]\nsignal = \"SKIP\"\ntool = 20\nball_radius = 1\nmax_overtravel = 1\n");
  ASSERT_TRUE(s) << s.error().detail;
  EXPECT_DOUBLE_EQ(s->probing.probe->length, 150.0);  // H20: 149.5 + wear 0.5
  auto other = load_frames(
      "[probe]\nsignal = \"SKIP\"\ntool = 7\noffset = 20\nball_radius = 1\n"
      "max_overtravel = 1\n");
  ASSERT_TRUE(other) << other.error().detail;
  EXPECT_DOUBLE_EQ(other->probing.probe->length, 150.0);
  auto none =
      load_frames("[probe]\nsignal = \"SKIP\"\ntool = 7\nball_radius = 1\nmax_overtravel = 1\n");
  ASSERT_TRUE(none);
  EXPECT_DOUBLE_EQ(none->probing.probe->length, 0.0);
  auto here = load_frames(
      "[probe]\nsignal = \"SKIP\"\ntool = 7\nlength = 120\nball_radius = 1\n"
      "max_overtravel = 1\n");
  ASSERT_TRUE(here);
  EXPECT_DOUBLE_EQ(here->probing.probe->length, 120.0);
}

// Issue 29: the scene is the stylus, H what the control believes; the two
// may differ (an uncalibrated H): kept both, never refused.
TEST(ProbeLength, ALengthDifferentFromHIsKeptBesideIt) {
  auto s = load_frames(
      "[probe]\nsignal = \"SKIP\"\ntool = 20\nball_radius = 1\nlength = 151\n"
      "max_overtravel = 1\n");
  ASSERT_TRUE(s) << s.error().detail;
  EXPECT_DOUBLE_EQ(s->probing.probe->length, 151.0);
  EXPECT_EQ(s->probing.probe->h_number, 20);
  EXPECT_DOUBLE_EQ(s->probing.probe->h_length, 150.0);
  auto same = load_frames(
      "[probe]\nsignal = \"SKIP\"\ntool = 20\nball_radius = 1\nlength = 150\n"
      "max_overtravel = 1\n");
  ASSERT_TRUE(same);
  EXPECT_EQ(same->probing.probe->h_number, 0);
  auto missing = load_frames(
      "[probe]\nsignal = \"SKIP\"\ntool = 20\noffset = 21\nball_radius = 1\n"
      "max_overtravel = 1\n");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().loc.line, 4u);
}

}  // namespace
}  // namespace skipnc::machine
