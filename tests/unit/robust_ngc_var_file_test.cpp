// LinuxCNC's parameter file under the linuxcnc dialect (docs/languages.md):
// the machine file's `persistent_variables` holds "NUMBER VALUE" lines; the
// parameters it lists are read at the start and written back at the end,
// #5161-#5390 always among them, in order, whole; a damaged line stops the
// run before anything is written.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <string>

#include "support/report_run.hpp"
#include "support/run_cli.hpp"

namespace skipnc::test {
namespace {

std::filesystem::path lcnc_machine(TempDir& dir, const std::filesystem::path& vars) {
  std::string machine =
      "name = \"lcnc\"\ndialect = \"linuxcnc\"\npersistent_variables = \"" + vars.string() + "\"\n";
  for (const char* a : {"X", "Y", "Z"}) machine += std::string("[[axis]]\nname = \"") + a + "\"\n";
  return dir.write("m.toml", machine);
}

std::map<int, double> read_var_file(const std::filesystem::path& p) {
  std::map<int, double> out;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) {
    int n = 0;
    double v = 0.0;
    if (std::sscanf(line.c_str(), "%d %lf", &n, &v) == 2) out[n] = v;
  }
  return out;
}

TEST(RobustNgcVarFile, ListedParametersAndTheOffsetsAreKeptAcrossRuns) {
  TempDir dir;
  const auto vars = dir.write("sim.var", "31\t5.000000\n5161\t1.500000\n");
  const auto m = lcnc_machine(dir, vars);
  // #31 is listed: kept. #32 is not: lost. G10 L2 writes G54 (#5221..).
  const auto prog =
      dir.write("p.ngc", "#31 = [#31 + 1]\n#32 = 9\nG10 L2 P1 X12.5 Y-3\n(debug, #5161)\nM2\n");
  for (int run = 0; run < 2; ++run) {
    const auto r = run_with_report(dir, prog, {"-m", m.string()});
    ASSERT_TRUE(r.exit.exited);
    ASSERT_EQ(r.exit.code, 0) << r.err;
    EXPECT_EQ(r.report["messages"][0], " 1.500000");
  }
  const auto v = read_var_file(vars);
  EXPECT_EQ(v.size(), 1u + (5390 - 5161 + 1));  // #31 and #5161-#5390
  EXPECT_EQ(v.at(31), 7.0);                     // 5 + 1 + 1
  EXPECT_FALSE(v.contains(32));
  EXPECT_EQ(v.at(5161), 1.5);
  EXPECT_EQ(v.at(5221), 12.5);
  EXPECT_EQ(v.at(5222), -3.0);
  // Sorted, LinuxCNC's format: "NUMBER<tab>VALUE" with 6 decimals.
  const std::string text = read_file(vars);
  EXPECT_EQ(text.substr(0, 12), "31\t7.000000\n");
}

TEST(RobustNgcVarFile, DamagedLineStopsTheRunWithItsLine) {
  TempDir dir;
  const std::string damaged = "31\t5.000000\n5161 x\n";
  const auto vars = dir.write("sim.var", damaged);
  const auto m = lcnc_machine(dir, vars);
  const auto prog = dir.write("p.ngc", "#31 = 1\nM2\n");
  const auto r = run_with_report(dir, prog, {"-m", m.string()});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 2) << r.err;
  EXPECT_NE(r.err.find("sim.var:2"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(vars), damaged);  // nothing written over it
}

}  // namespace
}  // namespace skipnc::test
