// Issue 9: `skipnc run --plot` / `skipnc plot` write an SVG that is valid XML
// (checked with python3's xml module) with one skip marker per skip of the
// report in every view, placed where the report's latch and rest positions
// project; and an HTML page that fetches nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_cli.hpp"
#include "support/svg_json.hpp"

namespace skipnc {
namespace {

using nlohmann::json;
using test::read_file;
using test::run_cli;
using test::TempDir;

// Probing a bore in X+, Y+, X-, Y-, then the floor; the scene has a trigger
// plane for each touch and a rigid stop under the floor.
constexpr const char* kProgram = R"(%
O0100 (PROBE A BORE)
G21 G90 G17 G54
G0 X0 Y0 Z5.
G1 Z-5. F1000.
G31 X60. F300.
G0 X0
G31 Y60. F300.
G0 Y0
G31 X-60. F300.
G0 X0
G31 Y-60. F300.
G0 Y0
G1 X10. F800.
G3 X10. Y0 I-10. J0
G1 X0
G31 Z-30. F100.
G0 Z5.
M30
%
)";

constexpr const char* kScene = R"(
[[trigger]]
signal = "X0.4"
axis = "X"
at = 40.0
direction = "increasing"
[[trigger]]
signal = "X0.4"
axis = "Y"
at = 30.0
direction = "increasing"
[[trigger]]
signal = "X0.4"
axis = "X"
at = -40.0
direction = "decreasing"
[[trigger]]
signal = "X0.4"
axis = "Y"
at = -30.0
direction = "decreasing"
[[trigger]]
signal = "X0.4"
axis = "Z"
at = -12.0
direction = "decreasing"
[[stop]]
axis = "Z"
at = -12.5
direction = "decreasing"
)";

// Parses the SVG with ElementTree (an XML error fails the script) and prints
// each view's frame and its skip and rest markers as JSON.
constexpr const char* kSvgReader = R"(
import json, sys
import xml.etree.ElementTree as ET
NS = '{http://www.w3.org/2000/svg}'
root = ET.parse(sys.argv[1]).getroot()
out = {'views': {}, 'zooms': 0}
for g in root.iter(NS + 'g'):
    cls = g.get('class', '')
    if cls == 'latch-zoom':
        out['zooms'] += 1
    if cls != 'view':
        continue
    v = {'frame': [float(x) for x in g.get('data-frame').split()], 'skip': [], 'rest': []}
    for c in g.iter(NS + 'circle'):
        if 'skip-marker' in c.get('class', '').split():
            v['skip'].append([int(c.get('data-skip')), float(c.get('cx')), float(c.get('cy'))])
    for r in g.iter(NS + 'rect'):
        if r.get('class') == 'rest-marker':
            v['rest'].append([int(r.get('data-skip')), float(r.get('x')) + 4, float(r.get('y')) + 4])
    out['views'][g.get('id')[5:]] = v
print(json.dumps(out))
)";

struct Proj {
  double u[3];
  double v[3];
};

// The documented projections (docs/plot.md): top, front, side, and the
// isometric view from +X -Y +Z.
Proj projection(const std::string& id) {
  const double a = 1.0 / std::sqrt(2.0), b = 1.0 / std::sqrt(6.0);
  if (id == "xy") return {{1, 0, 0}, {0, 1, 0}};
  if (id == "xz") return {{1, 0, 0}, {0, 0, 1}};
  if (id == "yz") return {{0, 1, 0}, {0, 0, 1}};
  return {{a, a, 0}, {-b, b, 2 * b}};
}

json read_svg(const TempDir& dir, const std::string& svg) {
  return test::read_svg_with(dir, kSvgReader, svg);
}

// The model the HTML page carries (docs/plot.md, "The page"); null when the
// page has none.
json page_data(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"plot-data\">";
  const auto a = page.find(open);
  if (a == std::string::npos) return json();
  return json::parse(page.substr(a + open.size(), page.find("</script>", a) - a - open.size()));
}

// Checks that every view has one marker per skip, at the projection of the
// report's machine position (latch) and of the rest position.
// `tip_length`: the views show the tool tip, this far below the gauge point.
// `rests`: false where a length offset is active (the report's skip position
// has it, as #5063 does, and its end position not: the rest cannot be placed
// from the two), so only the latches are checked.
void expect_markers_where_the_report_says(const json& svg, const json& report,
                                          double tip_length = 0.0, bool rests = true) {
  const auto& skips = report["skips"];
  ASSERT_EQ(svg["views"].size(), 4u);
  for (const auto& [id, view] : svg["views"].items()) {
    const auto f = view["frame"].get<std::vector<double>>();
    const double mm_per_px = (f[1] - f[0]) / f[6];
    const Proj p = projection(id);
    auto px = [&](const json& pos) {
      const double w[3] = {pos["X"].get<double>(), pos["Y"].get<double>(),
                           pos["Z"].get<double>() - tip_length};
      const double u = p.u[0] * w[0] + p.u[1] * w[1] + p.u[2] * w[2];
      const double v = p.v[0] * w[0] + p.v[1] * w[1] + p.v[2] * w[2];
      return std::pair{f[4] + (u - f[0]) / mm_per_px, f[5] + (f[3] - v) / mm_per_px};
    };
    ASSERT_EQ(view["skip"].size(), skips.size()) << "view " << id;
    ASSERT_EQ(view["rest"].size(), skips.size()) << "view " << id;
    for (const auto& mk : view["skip"]) {
      const auto& sk = skips[mk[0].get<std::size_t>()];
      const auto [x, y] = px(sk["machine_position"]);
      EXPECT_NEAR(mk[1].get<double>(), x, 0.02) << "view " << id << " skip line " << sk["line"];
      EXPECT_NEAR(mk[2].get<double>(), y, 0.02) << "view " << id << " skip line " << sk["line"];
    }
    for (const auto& mk : view["rest"]) {
      if (!rests) break;
      // Rest in machine coordinates: the work position plus the offsets in
      // force at the latch (machine_position - position).
      const auto& sk = skips[mk[0].get<std::size_t>()];
      json rest;
      for (const char* a : {"X", "Y", "Z"}) {
        rest[a] = sk["end_position"][a].get<double>() + sk["machine_position"][a].get<double>() -
                  sk["position"][a].get<double>();
      }
      const auto [x, y] = px(rest);
      EXPECT_NEAR(mk[1].get<double>(), x, 0.11) << "view " << id << " rest of line " << sk["line"];
      EXPECT_NEAR(mk[2].get<double>(), y, 0.11) << "view " << id << " rest of line " << sk["line"];
    }
  }
}

TEST(PlotSvg, ValidXmlWithOneMarkerPerSkipWhereTheReportSays) {
  TempDir dir;
  const auto prog = dir.write("bore.nc", kProgram);
  const auto scene = dir.write("bore.toml", kScene);
  const auto svg = (dir.path / "bore.svg").string();
  const auto html = (dir.path / "bore.html").string();
  const auto rep = (dir.path / "bore.json").string();
  const auto r = run_cli({"run", prog.string(), "-s", scene.string(), "--report", rep, "--plot",
                          svg, "--plot", html, "-q"});
  ASSERT_EQ(r.exit_code, 0);
  const json report = json::parse(read_file(rep));
  ASSERT_EQ(report["skips"].size(), 5u);
  const json s = read_svg(dir, svg);
  expect_markers_where_the_report_says(s, report);
  EXPECT_EQ(s["zooms"].get<int>(), 5) << "a zoom on every latch: four in the panel, one below";
}

TEST(PlotSvg, PageFetchesNothingAndCarriesEverySkip) {
  TempDir dir;
  const auto prog = dir.write("bore.nc", kProgram);
  const auto scene = dir.write("bore.toml", kScene);
  const auto html = (dir.path / "bore.html").string();
  const auto r = run_cli({"plot", prog.string(), "-s", scene.string(), "-o", html, "-q"});
  ASSERT_EQ(r.exit_code, 0);
  const std::string page = read_file(html);
  for (const char* remote : {"http://", "https://", "<link", "src=", "@import", "//cdn"}) {
    EXPECT_EQ(page.find(remote), std::string::npos) << remote;
  }
  const json data = page_data(page);
  ASSERT_FALSE(data.is_null());
  EXPECT_EQ(data["format"], "skipnc-plot/2");
  ASSERT_EQ(data["skips"].size(), 5u);
  EXPECT_EQ(data["skips"][0]["line"], 6);
  EXPECT_EQ(data["skips"][0]["vars"][0]["name"], "#5061");
  EXPECT_NEAR(data["skips"][0]["vars"][0]["value"].get<double>(), 40.0, 1e-6);
  ASSERT_EQ(data["files"].size(), 1u);                // the main program only: no call
  EXPECT_EQ(data["files"][0]["source"].size(), 20u);  // line by line
  EXPECT_EQ(data["skips"][0]["ctx"], 0);
  EXPECT_EQ(data["contexts"].size(), 1u);
}

// A skip inside a macro file (issue 16): the SVG's labels and skip card name
// the macro's file and line, and the page carries the macro's own text with
// the skip's block in the macro's context (was: "L4" and line 4 of the main
// program, "G65 P9200 X60.").
TEST(PlotSvg, ASkipInAMacroIsNamedByTheMacrosFileAndLine) {
  TempDir dir;
  dir.write("main.nc",
            "%\nO0200 (MAIN)\nG21 G90 G17 G54\nG0 X0 Y0 Z5.\nN50 G65 P9200 X60.\n"
            "G0 X0\nM30\n%\n");
  dir.write("O9200.nc",
            "%\nO9200 (TOUCH ALONG X)\n(X: WHERE TO STOP)\nN10 G31 X#24 F300.\n"
            "#100=#5061\nM99\n%\n");
  const auto scene = dir.write("bore.toml", kScene);
  const auto svg = (dir.path / "main.svg").string();
  const auto html = (dir.path / "main.html").string();
  const auto r = run_cli({"run", (dir.path / "main.nc").string(), "-s", scene.string(), "--plot",
                          svg, "--plot", html, "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string picture = read_file(svg);
  EXPECT_NE(picture.find("O9200.nc:4 N10 #5061=40.0000"), std::string::npos)
      << "the latch label names the macro's line and N";
  const auto card = picture.find("1. O9200.nc:4 (O9200) called from ");
  ASSERT_NE(card, std::string::npos) << "the skip card names the macro's line";
  EXPECT_EQ(picture.find(">L4"), std::string::npos) << "no label names line 4 of the main program";
  const json data = page_data(read_file(html));
  ASSERT_FALSE(data.is_null());
  ASSERT_EQ(data["files"].size(), 2u);
  EXPECT_EQ(data["files"][1]["name"], "O9200.nc");
  EXPECT_EQ(data["files"][1]["source"][3], "N10 G31 X#24 F300.");
  ASSERT_EQ(data["skips"].size(), 1u);
  const int ctx = data["skips"][0]["ctx"].get<int>();
  EXPECT_EQ(data["contexts"][ctx]["file"], 1);
  const std::string where = data["contexts"][ctx]["where"];
  EXPECT_EQ(where.rfind("O9200.nc (O9200) called from ", 0), 0u) << where;
  EXPECT_NE(where.find("main.nc:5 (G65 P9200)"), std::string::npos) << where;
  EXPECT_EQ(data["skips"][0]["line"], 4);
}

// A lathe (issue 16) is drawn as its drawings show it: one view with Z
// horizontal and X up, X labelled in diameter when it is programmed in
// diameter (lathe2: 1006#3 = 1); the latch marker is where the machine
// position projects (Z right, X up).
TEST(PlotSvg, ALatheHasZHorizontalAndXUpInDiameter) {
  TempDir dir;
  const auto prog = dir.write("lathe.nc", "G50 X100. Z50.\nG98 G31 U-80. F100.\nM30\n");
  const auto scene =
      dir.write("lathe.toml",
                "[[trigger]]\nsignal = \"SKIP\"\naxis = \"X\"\nat = -20.0\ndirection = "
                "\"decreasing\"\n");
  const auto svg = (dir.path / "lathe.svg").string();
  const auto rep = (dir.path / "lathe.json").string();
  const auto r = run_cli({"run", prog.string(), "-m", "lathe2", "-s", scene.string(), "--report",
                          rep, "--plot", svg, "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json s = read_svg(dir, svg);
  ASSERT_EQ(s["views"].size(), 1u);
  ASSERT_TRUE(s["views"].contains("zx")) << s.dump();
  const json& v = s["views"]["zx"];
  ASSERT_EQ(v["skip"].size(), 1u);
  // data-frame: u0 u1 v0 v1 x y w h; u is machine Z, v machine X (radius).
  const auto& f = v["frame"];
  const double u0 = f[0], u1 = f[1], v0 = f[2], v1 = f[3], x = f[4], y = f[5], w = f[6], h = f[7];
  const double cx = v["skip"][0][1], cy = v["skip"][0][2];
  EXPECT_NEAR(cx, x + (0.0 - u0) / (u1 - u0) * w, 1.0) << "Z = 0";
  EXPECT_NEAR(cy, y + (v1 - (-20.0)) / (v1 - v0) * h, 1.0) << "X = -20 (radius), up";
  const std::string text = read_file(svg);
  EXPECT_NE(text.find("Z \u2192  X \u2191  (mm, machine, X in diameter"), std::string::npos);
  EXPECT_NE(text.find(">-40</text>"), std::string::npos) << "X -20 labelled -40 (diameter)";
}

// A skip cut short by an alarm (a probe crash) is marked as such: its rest
// label and its card say the alarm stopped it, and the page's data says so.
TEST(PlotSvg, ASkipCutShortByAnAlarmIsMarked) {
  TempDir dir;
  const std::string g = std::string(SKIPNC_SOURCE_DIR) + "/tests/golden/probing/crash";
  const auto svg = (dir.path / "crash.svg").string();
  const auto html = (dir.path / "crash.html").string();
  const auto r = run_cli({"run", g + ".nc", "-s", g + ".scene.toml", "-m", g + ".machine.toml",
                          "--plot", svg, "--plot", html, "-q"});
  ASSERT_EQ(r.exit_code, 1) << r.out;
  const std::string picture = read_file(svg);
  EXPECT_NE(picture.find("L8 ALARM at Z-230.5500"), std::string::npos);
  EXPECT_NE(picture.find("cut short by the alarm: stopped at Z-230.5500 (work)"),
            std::string::npos);
  EXPECT_NE(read_file(html).find("\"endedByAlarm\":true"), std::string::npos);
}

// Two minutes of slow feed end in a touch: the drawing holds a few hundred
// samples, and the latch is still exactly where the report says.
TEST(PlotSvg, LongRunIsThinnedWithoutLosingTheLatch) {
  TempDir dir;
  const auto prog = dir.write(
      "long.nc", "G21 G90 G54\nG1 X100. Y50. F50.\nG1 X0 Y0\nG31 X300. F150.\nG0 X0\nM30\n");
  const auto scene = dir.write("long.toml",
                               "[[trigger]]\nsignal = \"X0.4\"\naxis = \"X\"\nat = 250.0\n"
                               "direction = \"increasing\"\n");
  const auto svg = (dir.path / "long.svg").string();
  const auto html = (dir.path / "long.html").string();
  const auto rep = (dir.path / "long.json").string();
  const auto r = run_cli({"run", prog.string(), "-s", scene.string(), "--report", rep, "--plot",
                          svg, "--plot", html, "-q"});
  ASSERT_EQ(r.exit_code, 0);
  const json report = json::parse(read_file(rep));
  ASSERT_EQ(report["skips"].size(), 1u);
  EXPECT_GT(report["final"]["time"].get<double>(), 200.0);
  const json s = read_svg(dir, svg);
  expect_markers_where_the_report_says(s, report);
  EXPECT_LT(read_file(svg).size(), 400'000u);
  EXPECT_LT(read_file(html).size(), 400'000u);
}

// A touch probe 150 mm long comes down on a block: the views show the ball
// centre, 150 mm below the machine position, touching the block's top
// (Z-180) at the ball's radius; the block is drawn.
TEST(PlotSvg, WithAProbeTheViewsShowTheBallCentreAndThePart) {
  TempDir dir;
  const auto prog =
      dir.write("p.nc", "G21 G90 G54\nG0 X0 Y0 Z0\nG0 Z-25.\nG31 Z-40. F100.\nG0 Z0\nM30\n");
  const auto scene =
      dir.write("s.toml",
                "[[box]]\npart = \"block\"\nmin = [-20.0, -20.0, -200.0]\n"
                "max = [20.0, 20.0, -180.0]\n"
                "[probe]\nsignal = \"SKIP\"\ntool = 20\nball_radius = 1.0\nlength = 150.0\n"
                "max_overtravel = 2.0\n");
  const auto svg = (dir.path / "p.svg").string();
  const auto rep = (dir.path / "p.json").string();
  const auto r =
      run_cli({"run", prog.string(), "-s", scene.string(), "--report", rep, "--plot", svg, "-q"});
  ASSERT_EQ(r.exit_code, 0);
  const json report = json::parse(read_file(rep));
  ASSERT_EQ(report["skips"].size(), 1u);
  EXPECT_NEAR(report["skips"][0]["machine_position"]["Z"].get<double>(), -29.0, 1e-6);
  expect_markers_where_the_report_says(read_svg(dir, svg), report, 150.0);
  const std::string text = read_file(svg);
  EXPECT_NE(text.find("class=\"shape part\""), std::string::npos);
  EXPECT_NE(text.find("path of the tool tip"), std::string::npos);
}

// The path is drawn at the tip of the tool the simulation has in the spindle.
// The interpreter reads on past an M06 while the motion before it runs, so the
// second M06 (T20, the probe) is read while T1 still cuts: T1's feed at
// gauge Z-30 is drawn at its tip, Z-130 (was: at the probe's 150 mm, Z-180,
// the second change placed at the first pause of T1's moves), and the probe's
// rapid after its M06 at Z-150 (gauge Z0); within 0.05 mm, the servo's lag as
// T1's feed begins.
TEST(PlotSvg, EachToolIsDrawnAtItsOwnTipWhenTheNextM06IsReadEarly) {
  TempDir dir;
  const auto prog = dir.write("tools.nc",
                              "G21 G90 G17 G54\nG53 G0 Z0.\nT1 M6\nS8000 M3\nG0 X10. Y10.\n"
                              "G1 Z-30. F1000.\nG1 X30.\nM5\nG53 G0 Z0.\nT20 M6\nG0 X0 Y0\nM30\n");
  const auto scene = dir.write("tools.toml",
                               "spindle_tool = 20\n[probe]\nsignal = \"SKIP\"\ntool = 20\n"
                               "ball_radius = 1.0\nlength = 150.0\nmax_overtravel = 2.0\n"
                               "[[tool]]\nnumber = 1\nlength = 100.0\nradius = 5.0\n");
  const auto html = (dir.path / "tools.html").string();
  const auto r = run_cli({"run", prog.string(), "-s", scene.string(), "--plot", html, "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json data = page_data(read_file(html));
  ASSERT_FALSE(data.is_null());
  int on_feed = 0, on_rapid = 0;
  for (std::size_t i = 0; i < data["t"].size(); ++i) {
    const int line = data["line"][i].get<int>();
    const double z = data["pz"][i].get<double>();
    if (line == 7) {
      ++on_feed;
      EXPECT_NEAR(z, -130.0, 0.05) << "T1's feed at t = " << data["t"][i];
    } else if (line == 11) {
      ++on_rapid;
      EXPECT_NEAR(z, -150.0, 0.05) << "the probe's rapid at t = " << data["t"][i];
    }
  }
  EXPECT_GT(on_feed, 0);
  EXPECT_GT(on_rapid, 0);
}

// The worked example (examples/probe_cut_inspect, its README's plot command):
// the picture shows every touch where the report has it, and the pocket T1 cut
// where the probed G54 put it: the stock's staircase 5 mm deep from the block's
// top (-200.153) between G54 X-99.588 +-20 and Y19.713 +-15, and the path's
// lowest point T1's tip on the floor.
TEST(PlotSvg, TheWorkedExampleShowsThePocketWhereTheProbedG54PutIt) {
  TempDir dir;
  const std::string ex = std::string(SKIPNC_SOURCE_DIR) + "/examples/probe_cut_inspect/";
  const auto svg = (dir.path / "probe_cut_inspect.svg").string();
  const auto html = (dir.path / "probe_cut_inspect.html").string();
  const auto rep = (dir.path / "report.json").string();
  const auto r =
      run_cli({"plot", ex + "probe_cut_inspect.nc", "-I",
               std::string(SKIPNC_SOURCE_DIR) + "/macros/probing", "-m", ex + "cell.machine.toml",
               "-s", ex + "block.scene.toml", "--report", rep, "-o", svg, "-o", html, "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json report = json::parse(read_file(rep));
  ASSERT_EQ(report["skips"].size(), 59u);
  expect_markers_where_the_report_says(read_svg(dir, svg), report, 150.0, false);
  const json data = page_data(read_file(html));
  ASSERT_FALSE(data.is_null());
  double lowest = 0.0;
  for (const auto& z : data["pz"]) lowest = std::min(lowest, z.get<double>());
  EXPECT_NEAR(lowest, -205.153, 2e-3) << "T1's tip on the floor (was: 50 mm lower)";
  std::vector<json> cuts;
  for (const auto& s : data["shapes"]) {
    if (s["ink"] == "stock" && s["kind"] == "polyline") cuts.push_back(s);
  }
  ASSERT_EQ(cuts.size(), 2u) << "the deepest cut along X and along Y";
  for (int axis : {0, 1}) {
    double lo = 1e9, hi = -1e9;
    for (const auto& p : cuts[static_cast<std::size_t>(axis)]["pts"]) {
      if (p[2].get<double>() > -200.2) continue;
      EXPECT_NEAR(p[2].get<double>(), -205.153, 1e-6);
      lo = std::min(lo, p[axis].get<double>());
      hi = std::max(hi, p[axis].get<double>());
    }
    const double centre = axis == 0 ? -99.588 : 19.713, half = axis == 0 ? 20.0 : 15.0;
    EXPECT_NEAR(lo, centre - half, 1e-6) << "axis " << axis;
    EXPECT_NEAR(hi, centre + half, 1e-6) << "axis " << axis;
  }
}

TEST(PlotSvg, UnknownPictureFormatIsAUsageError) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1.\nM30\n");
  const auto r = run_cli({"run", prog.string(), "--plot", (dir.path / "p.png").string(), "-q"});
  EXPECT_EQ(r.exit_code, 2);
}

}  // namespace
}  // namespace skipnc
