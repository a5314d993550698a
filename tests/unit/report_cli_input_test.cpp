// What the command line takes besides a program file: the program on
// standard input (`skipnc run -`, `skipnc canon -`), and the demo's -q.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run_cli.hpp"

namespace {

using nlohmann::json;
using skipnc::test::read_file;
using skipnc::test::run_cli;
using skipnc::test::TempDir;

constexpr const char* kTouch =
    "G21 G90 G54\nG0 X0 Y0 Z0\nG31 Z-10. F100.\n#100 = #5063\nG91 G1 Z5. F500.\nM30\n";
constexpr const char* kTrigger =
    "[[trigger]]\nsignal = \"X0.4\"\naxis = \"Z\"\nat = -3.0\ndirection = \"decreasing\"\n";

TEST(CliInput, RunDashReadsTheProgramFromStandardInput) {
  TempDir d;
  const auto prog = d.write("touch.nc", kTouch);
  const auto scene = d.write("s.toml", kTrigger);
  const auto r = run_cli({"run", "-", "-s", scene.string(), "--report", "-", "--var", "100", "-q"},
                         "", prog.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json rep = json::parse(r.out);
  EXPECT_EQ(rep["status"], "completed");
  EXPECT_NEAR(rep["variables"]["100"].get<double>(), -3.0, 1e-6);
  EXPECT_EQ(rep["skips"][0]["file"], "<stdin>");
  EXPECT_EQ(rep["skips"][0]["line"], 3);
}

TEST(CliInput, AnErrorInAProgramFromStandardInputNamesStdinWithLineAndColumn) {
  TempDir d;
  const auto prog = d.write("bad.nc", "G21\nG0 X1 Y\nM30\n");
  const auto err = d.path / "err.txt";
  const auto r = run_cli({"run", "-"}, err.string(), prog.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(read_file(err).find("<stdin>:2:"), std::string::npos) << read_file(err);
}

TEST(CliInput, CanonDashPrintsTheCommandsOfStandardInput) {
  TempDir d;
  const auto prog = d.write("m.nc", "G21 G90\nG0 X12.5\nM30\n");
  const auto from_stdin = run_cli({"canon", "-"}, "", prog.string());
  const auto from_file = run_cli({"canon", prog.string()});
  ASSERT_EQ(from_stdin.exit_code, 0);
  EXPECT_NE(from_stdin.out.find("12.5"), std::string::npos) << from_stdin.out;
  EXPECT_EQ(from_stdin.out, from_file.out);
}

TEST(CliInput, DemoQuietPrintsNothingAndStillWritesTheReport) {
  TempDir d;
  const auto report = d.path / "demo.json";
  const auto r = run_cli({"demo", "-q", "--report", report.string()});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "");
  const json rep = json::parse(read_file(report));
  EXPECT_EQ(rep["status"], "completed");
  EXPECT_EQ(rep["skips"].size(), 2u);
}

}  // namespace
