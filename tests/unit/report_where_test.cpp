// Issue 16: every place a block is named carries its file and O number.
// tests/golden/where/macro_files.nc calls O9023 (macros/O9023.nc, line 3:
// G65 P9024), which runs the touch at line 3 of macros/O9024.nc (N20 G31).
// The scene's signal comes on at machine Z-3: the touch latches Z-3.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/run_cli.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using skipnc::test::read_file;
using skipnc::test::run_cli;

namespace {

const fs::path kDir = fs::path(SKIPNC_SOURCE_DIR) / "tests" / "golden" / "where";

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

TEST(Where, SkipInAMacroOfAMacroNamesItsFileProgramNAndCallers) {
  skipnc::test::TempDir tmp;
  const fs::path report = tmp.path / "r.json";
  const fs::path trace = tmp.path / "t.csv";
  const auto r =
      run_cli({"run", (kDir / "macro_files.nc").string(), "-I", (kDir / "macros").string(),
               "--scene", (kDir / "macro_files.scene.toml").string(), "--report", report.string(),
               "--trace", trace.string(), "--var", "101"});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json j = json::parse(read_file(report));
  ASSERT_EQ(j["skips"].size(), 1u);
  const json& s = j["skips"][0];
  EXPECT_EQ(s["file"], "O9024.nc");
  EXPECT_EQ(s["line"], 3);
  EXPECT_EQ(s["program"], "O9024");
  EXPECT_EQ(s["n"], 20);
  EXPECT_EQ(s["ended_by"], "signal");
  EXPECT_DOUBLE_EQ(s["position"]["Z"].get<double>(), -3.0);
  const std::string where = s["where"];
  EXPECT_EQ(
      where.rfind("O9024.nc:3 (O9024 N20) called from O9023.nc:3 (G65 P9024) called from ", 0), 0u)
      << where;
  EXPECT_TRUE(ends_with(where, "macro_files.nc:5 (G65 P9023)")) << where;
  ASSERT_EQ(s["call_stack"].size(), 3u);
  EXPECT_EQ(s["call_stack"][1]["file"], "O9023.nc");
  EXPECT_EQ(s["call_stack"][1]["line"], 3);
  EXPECT_EQ(s["call_stack"][1]["program"], "O9023");
  EXPECT_EQ(s["call_stack"][2]["line"], 5);
  EXPECT_EQ(s["call_stack"][2]["program"], "O1000");
  EXPECT_EQ(j["variables"]["101"], -3.0);
  EXPECT_EQ(j["units"]["program"], "mm");
  // The summary names the file too.
  EXPECT_NE(r.out.find("O9024.nc:3 (O9024 N20)"), std::string::npos) << r.out;

  // The trace: rows of line 3 run in O9024.nc (G31) or O9023.nc (no motion
  // there), never in the main program, whose line 4 is the only rapid to Z5
  // before the call.
  std::istringstream t(read_file(trace));
  std::string row;
  std::getline(t, row);
  ASSERT_EQ(row.rfind("time_s,line,file,", 0), 0u) << row;
  int main_rows = 0, touch_rows = 0;
  while (std::getline(t, row)) {
    std::istringstream cells(row);
    std::string time, line, file;
    std::getline(cells, time, ',');
    std::getline(cells, line, ',');
    std::getline(cells, file, ',');
    if (line == "3") {
      EXPECT_EQ(file, "O9024.nc") << row;
      ++touch_rows;
    }
    if (line == "4" && ends_with(file, "macro_files.nc")) ++main_rows;
  }
  EXPECT_GT(touch_rows, 0);
  EXPECT_GT(main_rows, 0);
}

TEST(Where, CanonPrintsAFileLineWhereTheCommandsChangeFile) {
  const auto r =
      run_cli({"canon", (kDir / "macro_files.nc").string(), "-I", (kDir / "macros").string()});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::istringstream in(r.out);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 7u) << r.out;
  EXPECT_EQ(lines[0], "4 RAPID X0 Y0 Z5");
  EXPECT_EQ(
      lines[1].rfind("FILE O9024.nc O9024 called from O9023.nc:3 (G65 P9024) called from ", 0), 0u)
      << lines[1];
  EXPECT_TRUE(ends_with(lines[1], "macro_files.nc:5 (G65 P9023)")) << lines[1];
  EXPECT_EQ(lines[2], "2 FEED X0 Y0 Z2 F1000");
  EXPECT_EQ(lines[3].rfind("3 SKIP X0 Y0 Z-10 F100", 0), 0u) << lines[3];
  EXPECT_EQ(lines[4], "4 RAPID X0 Y0 Z5");
  EXPECT_TRUE(ends_with(lines[5], "macro_files.nc O1000")) << lines[5];
  EXPECT_EQ(lines[5].rfind("FILE ", 0), 0u);
  EXPECT_EQ(lines[6], "6 STOP M30");
}

// The summary prints each --var as the report has it: a value to 0.1 um,
// or vacant; a named variable with its #<name>.
TEST(Where, SummaryPrintsTheVariablesAskedFor) {
  const std::string nc = std::string(SKIPNC_SOURCE_DIR) + "/tests/golden/macro/goto_search.nc";
  const auto r =
      run_cli({"run", nc, "--var", "100", "--var", "#101", "--var", "102", "--var", "#<abc>"});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("\n  #100 = 3.0000\n  #101 = 2.0000\n  #102 = vacant\n  #<abc> = vacant\n"),
            std::string::npos)
      << r.out;
}

// A value that rounds to zero at 0.1 um is printed without a sign: a centre
// computed as a few 1e-15 below zero (the worked probing example's #136) read
// "-0.0000".
TEST(Where, SummaryPrintsAValueThatRoundsToZeroWithoutASign) {
  skipnc::test::TempDir dir;
  const auto nc =
      dir.write("zero.nc", "#100=[0.1+0.2-0.3]*-1\n#101=-0.00004\n#102=-0.00005\nM30\n");
  const auto r = run_cli({"run", nc.string(), "--var", "100", "--var", "101", "--var", "102"});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("\n  #100 = 0.0000\n  #101 = 0.0000\n  #102 = -0.0001\n"), std::string::npos)
      << r.out;
}

}  // namespace
