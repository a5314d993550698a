// The probing tables of a scene file: what they load into, and the errors a
// user gets (with the line) for what they cannot be.
#include <gtest/gtest.h>

#include <string>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/scene.hpp"

namespace skipnc::machine {
namespace {

Result<Scene> load_scene(const std::string& text) {
  static const auto m = config::builtin_machine("mill3");
  static const auto d = config::builtin_dialect("fanuc");
  static const config::Parameters p(&*d);
  return parse_scene(text, "test.scene.toml", *m, *d, p);
}

TEST(SceneProbing, LoadsPartsProbeToolsSetterAndGauge) {
  auto s = load_scene(R"(spindle_tool = 1
[[box]]
part = "plate"
min = [-10, -20, -30]
max = [10, 20, 0]
[[bore]]
part = "plate"
center = [1, 2]
radius = 5
bottom = -20
[[pocket]]
part = "plate"
min = [-8, 10, -5]
max = [8, 18, 1]
[[cylinder]]
center = [50, 0]
radius = 7.5
bottom = -30
top = -10
[[sphere]]
center = [0, 50, -20]
radius = 12.7
[[plane]]
point = [0, 0, -100]
normal = [0, 0, 2]
[probe]
signal = "SKIP"
tool = 20
ball_radius = 1.5
length = 120
pre_travel = 0.003
max_overtravel = 1.2
lobing = { amplitude = 0.002, lobes = 3, phase = 15 }
repeatability = 0.0004
seed = 99
[[tool]]
number = 1
length = 100
radius = 6
[tool_setter]
signal = "X0.5"
center = [-200, -100]
top = -250
radius = 4
[[gauge]]
axis = "X"
center = -100
raw_diameter = 52
steps = [{ signal = "SKIP2", diameter = 50.2 }, { signal = "SKIP3", diameter = 50 }]
)");
  ASSERT_TRUE(s) << s.error().detail;
  const Probing& pr = s->probing;
  ASSERT_EQ(pr.parts.size(), 2U);  // "plate" and the unnamed part
  EXPECT_EQ(pr.parts[0].name, "plate");
  EXPECT_EQ(pr.parts[0].solids.size(), 1U);
  EXPECT_EQ(pr.parts[0].holes.size(), 2U);
  EXPECT_EQ(pr.parts[1].solids.size(), 3U);
  const geo::Shape& bore = pr.parts[0].holes[1];  // pockets are read before bores
  EXPECT_EQ(bore.kind, geo::ShapeKind::kCylinder);
  EXPECT_EQ(bore.lo.z, -20.0);
  EXPECT_EQ(bore.hi.z, 1e6);  // a bore without top: open upward
  ASSERT_TRUE(pr.probe);
  EXPECT_EQ(pr.probe->signal, (canon::SignalAddr{'X', 0, 4}));
  EXPECT_EQ(pr.probe->tool, 20);
  EXPECT_EQ(pr.probe->ball_radius, 1.5);
  EXPECT_EQ(pr.probe->lobes, 3);
  EXPECT_EQ(pr.probe->lobing_phase_deg, 15.0);
  EXPECT_EQ(pr.probe->seed, 99U);
  ASSERT_TRUE(pr.tool_setter);
  EXPECT_EQ(pr.tool_setter->signal, (canon::SignalAddr{'X', 0, 5}));
  EXPECT_EQ(pr.tool_setter->thickness, 5.0);
  ASSERT_NE(pr.tool(1), nullptr);
  EXPECT_EQ(pr.spindle_tool, 1);
  ASSERT_EQ(pr.gauges.size(), 1U);
  EXPECT_EQ(pr.gauges[0].steps[1].signal, (canon::SignalAddr{'X', 0, 2}));  // SKIP3 on Fanuc
}

TEST(SceneProbing, TheProbeIsInTheSpindleUnlessSaidOtherwise) {
  auto s =
      load_scene("[probe]\nsignal = \"SKIP\"\ntool = 7\nball_radius = 1\nmax_overtravel = 1\n");
  ASSERT_TRUE(s) << s.error().detail;
  EXPECT_EQ(s->probing.spindle_tool, 7);
}

// The error names the place in the file.
void expect_error(const std::string& text, std::uint32_t line) {
  auto s = load_scene(text);
  ASSERT_FALSE(s) << text;
  EXPECT_EQ(s.error().id, AlarmId::kConfig);
  if (line > 0) {
    EXPECT_EQ(s.error().loc.line, line) << s.error().detail;
  }
}

TEST(SceneProbing, RefusesWhatCannotBe) {
  expect_error("[[box]]\nmin = [0, 0, 0]\nmax = [1, 1, 1]\ncolour = \"red\"\n", 4);  // unknown key
  expect_error("[[box]]\nmin = [0, 0]\nmax = [1, 1, 1]\n", 2);                       // 2 numbers
  expect_error("[[box]]\nmin = [0, 0, 5]\nmax = [1, 1, 1]\n", 1);                    // max < min
  expect_error("[[bore]]\ncenter = [0, 0]\nradius = 5\n", 1);                        // no solid
  // A named part's holes need a solid of the same part: the first table that names it.
  expect_error(
      "[[box]]\nmin = [0, 0, 0]\nmax = [9, 9, 9]\n\n[[bore]]\npart = \"plate\"\n"
      "center = [0, 0]\nradius = 5\n",
      5);
  expect_error("[[cylinder]]\ncenter = [0, 0]\nradius = -1\nbottom = 0\ntop = 1\n", 3);
  expect_error("[[plane]]\npoint = [0, 0, 0]\nnormal = [0, 0, 0]\n", 1);
  expect_error("[probe]\nsignal = \"SKIP\"\nball_radius = 1\npre_travel = 1\nmax_overtravel = 1\n",
               4);
  expect_error("[probe]\nsignal = \"Y0.4\"\nball_radius = 1\nmax_overtravel = 1\n", 2);
  expect_error("[probe]\nsignal = \"SKIP\"\nball_radius = 1\n", 1);  // max_overtravel missing
  // A switched probe: off_m and start_time need on_m; on and off differ.
  expect_error("[probe]\nsignal = \"SKIP\"\nball_radius = 1\nmax_overtravel = 1\noff_m = 82\n", 5);
  expect_error("[probe]\nsignal = \"SKIP\"\nball_radius = 1\nmax_overtravel = 1\nstart_time = 1\n",
               5);
  expect_error(
      "[probe]\nsignal = \"SKIP\"\nball_radius = 1\nmax_overtravel = 1\non_m = 81\noff_m = 81\n",
      6);
  expect_error("[probe]\nsignal = \"SKIP\"\nball_radius = 1\nmax_overtravel = 1\nstart_time = 61\n",
               5);
  expect_error("spindle_tool = 3\n[[tool]]\nnumber = 1\nlength = 10\nradius = 1\n", 1);
  expect_error(
      "[[tool]]\nnumber = 1\nlength = 10\nradius = 1\n[[tool]]\nnumber = 1\nlength = 5\nradius = "
      "1\n",
      5);
  expect_error(
      "[[gauge]]\naxis = \"Q\"\ncenter = 0\nraw_diameter = 5\nsteps = [{ signal = \"SKIP1\", "
      "diameter = 4 }]\n",
      2);
  expect_error(
      "[[gauge]]\naxis = \"X\"\ncenter = 0\nraw_diameter = 5\nsteps = [{ signal = \"SKIP1\", "
      "diameter = 6 }]\n",
      5);
}

}  // namespace
}  // namespace skipnc::machine
