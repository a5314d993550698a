// Issue 30, "Plots": the alarm line stays inside the picture, a run without
// a probe is not headed "probe: ball centre", G38 moves are labelled G38.x,
// collisions have a marker, labels in the side views do not stack. Each
// through the SVG the binary writes, read with python3's ElementTree.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/run_cli.hpp"
#include "support/svg_json.hpp"

namespace skipnc {
namespace {

using nlohmann::json;
using test::read_file;
using test::run_cli;
using test::TempDir;

// Prints the picture's size, every text (class, x, y, size, anchor, text),
// each view's frame with its label boxes (the width a text of that size
// takes, 0.6 em a character as the writer reckons it) and alarm markers.
constexpr const char* kReader = R"(
import json, sys
import xml.etree.ElementTree as ET
NS = '{http://www.w3.org/2000/svg}'
root = ET.parse(sys.argv[1]).getroot()
vb = [float(x) for x in root.get('viewBox').split()]
def text_of(t):
    return ''.join(t.itertext())
out = {'width': vb[2], 'height': vb[3], 'texts': [], 'views': {}, 'markers': 0}
for t in root.iter(NS + 'text'):
    out['texts'].append({'cls': t.get('class', ''), 'x': float(t.get('x')), 'y': float(t.get('y')),
                         'size': float(t.get('font-size', '11')),
                         'bold': t.get('font-weight') == 'bold',
                         'anchor': t.get('text-anchor', 'start'), 'text': text_of(t)})
for g in root.iter(NS + 'g'):
    if g.get('class') == 'alarm-marker':
        out['markers'] += 1
    if g.get('class') != 'view':
        continue
    v = {'frame': [float(x) for x in g.get('data-frame').split()], 'labels': [], 'alarm': [],
         'latch': []}
    for t in g.iter(NS + 'text'):
        if t.get('class') in ('latch-label', 'rest-label', 'shape-label'):
            s = text_of(t)
            v['labels'].append([float(t.get('x')), float(t.get('y')) - 10.5, 0.6 * 11 * len(s), 13, s])
    for m in g.iter(NS + 'g'):
        if m.get('class') == 'alarm-marker':
            c = m.find(NS + 'circle')
            v['alarm'].append([float(c.get('cx')), float(c.get('cy'))])
    v['latch'] = [[float(c.get('cx')), float(c.get('cy'))] for c in g.iter(NS + 'circle')
                  if 'skip-marker' in c.get('class', '').split()]
    out['views'][g.get('id')[5:]] = v
print(json.dumps(out))
)";

json read_truth_svg(const TempDir& dir, const std::string& svg) {
  return test::read_svg_with(dir, kReader, svg);
}

// Every text the header and legend hold, joined.
std::string all_text(const json& s) {
  std::string t;
  for (const auto& x : s["texts"]) t += x["text"].get<std::string>() + "\n";
  return t;
}

std::string plot(const TempDir& dir, const std::string& program, const std::string& scene,
                 std::vector<std::string> extra, int exit_code) {
  const auto prog = dir.write("p.nc", program);
  const auto svg = (dir.path / "p.svg").string();
  std::vector<std::string> args{"run", prog.string(), "--plot", svg, "-q"};
  if (!scene.empty()) args.insert(args.end(), {"-s", dir.write("s.toml", scene).string()});
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = run_cli(args);
  EXPECT_EQ(r.exit_code, exit_code) << program;
  return svg;
}

// A crash whose alarm text is long (the program in a folder with a long
// name): every line of the red ALARM text lies inside the picture, left to
// right and top to bottom, and none is cut (together they hold the text).
TEST(PlotTruth, TheAlarmLineStaysInsideThePicture) {
  TempDir dir;
  const std::string g = std::string(SKIPNC_SOURCE_DIR) + "/tests/golden/probing/crash";
  const std::string deep(150, 'd');
  std::filesystem::create_directories(dir.path / deep);
  const auto prog = dir.path / deep / "a_program_with_a_rather_long_name_for_the_crash.nc";
  std::filesystem::copy_file(g + ".nc", prog);
  const auto svg = (dir.path / "crash.svg").string();
  const auto r = run_cli({"run", prog.string(), "-s", g + ".scene.toml", "-m", g + ".machine.toml",
                          "--plot", svg, "-q"});
  ASSERT_EQ(r.exit_code, 1);
  const json s = read_truth_svg(dir, svg);
  std::string alarm;
  int lines = 0;
  for (const auto& t : s["texts"]) {
    if (t["cls"] != "alarm") continue;
    ++lines;
    const std::string text = t["text"];
    alarm += (alarm.empty() ? "" : " ") + text;
    const double w = (t["bold"].get<bool>() ? 0.66 : 0.6) * t["size"].get<double>() *
                     static_cast<double>(text.size());
    const double x = t["x"].get<double>();
    const double left = t["anchor"] == "end" ? x - w : x;
    EXPECT_GE(left, 0.0) << text;
    EXPECT_LE(left + w, s["width"].get<double>()) << text;
    EXPECT_GT(t["y"].get<double>(), 0.0);
    EXPECT_LT(t["y"].get<double>(), s["height"].get<double>());
  }
  EXPECT_GE(lines, 2) << "the text is longer than one line of the picture";
  // Lines break at spaces, a word longer than a line is cut: without spaces
  // the lines hold the whole text.
  std::erase(alarm, ' ');
  EXPECT_NE(alarm.find("ALARMSN9061(9061)"), std::string::npos) << alarm;
  EXPECT_NE(alarm.find(deep + "/a_program_with_a_rather_long_name_for_the_crash.nc:8"),
            std::string::npos)
      << alarm;
}

// A tool with a length but no probe: the path is the tool tip, and the
// header says so without "probe: ball centre"; with a [probe] it says both.
TEST(PlotTruth, ARunWithoutAProbeIsNotHeadedBallCentre) {
  const std::string prog = "G21 G90 G54\nT3 M06\nG43 H3 G0 X0 Y0 Z0\nG1 Z-5. F300.\nM30\n";
  TempDir dir;
  const json no_probe = read_truth_svg(
      dir, plot(dir, prog, "[[tool]]\nnumber = 3\nlength = 80.0\nradius = 5.0\n", {}, 0));
  const std::string text = all_text(no_probe);
  EXPECT_NE(text.find("path of the tool tip"), std::string::npos) << text;
  EXPECT_EQ(text.find("ball centre"), std::string::npos) << text;
  TempDir dir2;
  const json probe = read_truth_svg(
      dir2, plot(dir2, "G21 G90 G54\nG0 X0 Y0 Z0\nG31 Z-40. F100.\nM30\n",
                 "[[box]]\npart = \"block\"\nmin = [-20.0, -20.0, -200.0]\nmax = [20.0, 20.0, "
                 "-180.0]\n[probe]\nsignal = \"SKIP\"\ntool = 20\nball_radius = 1.0\nlength = "
                 "150.0\nmax_overtravel = 2.0\n",
                 {}, 0));
  EXPECT_NE(all_text(probe).find("path of the tool tip (probe: ball centre)"), std::string::npos);
}

// LinuxCNC probes with G38.2 and G38.3: the legend names those, and the
// picture says G31 nowhere; Fanuc's legend says G31.
TEST(PlotTruth, G38MovesAreLabelledG38) {
  const std::string scene =
      "[[trigger]]\nsignal = \"SKIP\"\naxis = \"Z\"\nat = -3.0\ndirection = \"decreasing\"\n";
  TempDir dir;
  const json lcnc = read_truth_svg(dir, plot(dir,
                                             "G21 G90 G54\nG0 X0 Y0 Z0\nG38.2 Z-10. F100.\nG0 Z0\n"
                                             "G38.3 Z-2. F100.\nM2\n",
                                             scene, {"-d", "linuxcnc"}, 0));
  const std::string text = all_text(lcnc);
  EXPECT_NE(text.find("probe move (G38.2, G38.3)"), std::string::npos) << text;
  EXPECT_EQ(text.find("G31"), std::string::npos) << text;
  TempDir dir2;
  const json fanuc = read_truth_svg(
      dir2, plot(dir2, "G21 G90 G54\nG0 X0 Y0 Z0\nG31 Z-10. F100.\nM30\n", scene, {}, 0));
  EXPECT_NE(all_text(fanuc).find("skip move (G31)"), std::string::npos);
}

// A probe crash: a marker in every view, inside it, and in the front view
// where the report puts the alarm (alarm.machine_position) relative to the
// latch (skips[0].machine_position), both drawn at the tool tip; its legend.
TEST(PlotTruth, CollisionsHaveAMarker) {
  TempDir dir;
  const std::string g = std::string(SKIPNC_SOURCE_DIR) + "/tests/golden/probing/crash";
  const auto svg = (dir.path / "crash.svg").string();
  const auto rep = (dir.path / "crash.json").string();
  const auto r = run_cli({"run", g + ".nc", "-s", g + ".scene.toml", "-m", g + ".machine.toml",
                          "--plot", svg, "--report", rep, "-q"});
  ASSERT_EQ(r.exit_code, 1);
  const json report = json::parse(read_file(rep));
  const json s = read_truth_svg(dir, svg);
  EXPECT_EQ(s["markers"].get<int>(), 5) << "one per view and the legend's";
  EXPECT_NE(all_text(s).find("probe crash: where the alarm came"), std::string::npos);
  for (const auto& [id, v] : s["views"].items()) {
    ASSERT_EQ(v["alarm"].size(), 1u) << id;
    const auto fr = v["frame"].get<std::vector<double>>();
    EXPECT_GE(v["alarm"][0][0].get<double>(), fr[4]) << id;
    EXPECT_LE(v["alarm"][0][0].get<double>(), fr[4] + fr[6]) << id;
    EXPECT_GE(v["alarm"][0][1].get<double>(), fr[5]) << id;
    EXPECT_LE(v["alarm"][0][1].get<double>(), fr[5] + fr[7]) << id;
  }
  const auto& at = report["alarm"]["machine_position"];
  const auto& latch = report["skips"][0]["machine_position"];
  const json& xz = s["views"]["xz"];
  ASSERT_EQ(xz["latch"].size(), 1u);
  const auto f = xz["frame"].get<std::vector<double>>();
  const double mm_per_px = (f[1] - f[0]) / f[6];
  const double dx = (at["X"].get<double>() - latch["X"].get<double>()) / mm_per_px;
  const double dy = -(at["Z"].get<double>() - latch["Z"].get<double>()) / mm_per_px;
  EXPECT_NEAR(xz["alarm"][0][0].get<double>() - xz["latch"][0][0].get<double>(), dx, 0.05);
  EXPECT_NEAR(xz["alarm"][0][1].get<double>() - xz["latch"][0][1].get<double>(), dy, 0.05);
}

// Sixty touches 0.5 mm apart along X on one plane: in the side views their
// labels would all sit on one line. No two label boxes overlap, and each
// lies inside its view.
TEST(PlotTruth, LabelsInTheSideViewsDoNotStack) {
  std::string prog = "G21 G90 G54\nG0 X0 Y0 Z0\n";
  for (int i = 0; i < 60; ++i) {
    prog += "G0 X" + std::to_string(i * 0.5) + " Z0\nG31 Z-10. F200.\n";
  }
  prog += "G0 Z0\nM30\n";
  TempDir dir;
  const json s = read_truth_svg(
      dir, plot(dir, prog,
                "[[trigger]]\nsignal = \"SKIP\"\naxis = \"Z\"\nat = -3.0\ndirection = "
                "\"decreasing\"\n",
                {}, 0));
  for (const auto& [id, v] : s["views"].items()) {
    const auto f = v["frame"].get<std::vector<double>>();
    const auto& labels = v["labels"];
    EXPECT_GT(labels.size(), 3u) << id;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      const auto& a = labels[i];
      EXPECT_GE(a[0].get<double>(), f[4] - 0.5) << id << " " << a[4];
      EXPECT_LE(a[0].get<double>() + a[2].get<double>(), f[4] + f[6] + 0.5) << id << " " << a[4];
      for (std::size_t j = i + 1; j < labels.size(); ++j) {
        const auto& b = labels[j];
        const bool overlap = a[0].get<double>() < b[0].get<double>() + b[2].get<double>() - 0.5 &&
                             b[0].get<double>() < a[0].get<double>() + a[2].get<double>() - 0.5 &&
                             a[1].get<double>() < b[1].get<double>() + b[3].get<double>() - 0.5 &&
                             b[1].get<double>() < a[1].get<double>() + a[3].get<double>() - 0.5;
        EXPECT_FALSE(overlap) << id << ": '" << a[4] << "' and '" << b[4] << "'";
      }
    }
  }
}

// The HTML page of the same crash: the page's data carries the alarm's point
// (the SVG's, in the plot's coordinates) and its legend, and its script draws
// the marker in every view and in the legend.
TEST(PlotTruth, CollisionsHaveAMarkerInTheHtmlPage) {
  TempDir dir;
  const std::string g = std::string(SKIPNC_SOURCE_DIR) + "/tests/golden/probing/crash";
  const auto html = (dir.path / "crash.html").string();
  const auto rep = (dir.path / "crash.json").string();
  const auto r = run_cli({"run", g + ".nc", "-s", g + ".scene.toml", "-m", g + ".machine.toml",
                          "--plot", html, "--report", rep, "-q"});
  ASSERT_EQ(r.exit_code, 1);
  const std::string page = read_file(html);
  EXPECT_NE(page.find("\"alarmLegend\":\"probe crash: where the alarm came\""), std::string::npos);
  const auto at = page.find("\"alarmAt\":[");
  ASSERT_NE(at, std::string::npos);
  // The point is the alarm's machine position (the plot is in machine
  // coordinates here: G54 is zero), X first.
  const json report = json::parse(read_file(rep));
  const double x = std::stod(page.substr(at + 11, 40));
  EXPECT_NEAR(x, report["alarm"]["machine_position"]["X"].get<double>(), 1e-6);
  EXPECT_NE(page.find("K.drawAlarm(ctx, q.x, q.y)"), std::string::npos) << "each view draws it";
  EXPECT_NE(page.find("K.drawAlarm(actx, 17, 8)"), std::string::npos) << "the legend draws it";
}

}  // namespace
}  // namespace skipnc
