// --expect (docs/cli.md): holds, fails with one clear line and exit status
// 3, and stops a run before it starts when it cannot be read. The program
// (tests/golden/where) touches at machine Z-3, so #101 = #5063 = -3.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/run_cli.hpp"

namespace fs = std::filesystem;
using skipnc::test::read_file;
using skipnc::test::run_cli;

namespace {

const fs::path kDir = fs::path(SKIPNC_SOURCE_DIR) / "tests" / "golden" / "where";

skipnc::test::CliResult run_with(const std::vector<std::string>& expects, const fs::path& err) {
  std::vector<std::string> args = {
      "run",     (kDir / "macro_files.nc").string(),         "-I", (kDir / "macros").string(),
      "--scene", (kDir / "macro_files.scene.toml").string(), "-q"};
  for (const auto& e : expects) args.insert(args.end(), {"--expect", e});
  return run_cli(args, err.string());
}

TEST(Expect, HoldsExitsZero) {
  skipnc::test::TempDir tmp;
  const auto r =
      run_with({"#101=-3+-0.001", "status=completed", "#102=vacant", "#100=0"}, tmp.path / "err");
  EXPECT_EQ(r.exit_code, 0) << read_file(tmp.path / "err");
  EXPECT_EQ(read_file(tmp.path / "err"), "");
}

TEST(Expect, FailsWithOneLinePerFailureAndExitThree) {
  skipnc::test::TempDir tmp;
  const auto r = run_with({"#101=-2.9+-0.05", "status=alarm", "#101=-3"}, tmp.path / "err");
  EXPECT_EQ(r.exit_code, 3);
  const std::string err = read_file(tmp.path / "err");
  EXPECT_NE(err.find("skipnc: expectation failed: #101=-2.9+-0.05: #101 = -3"), std::string::npos)
      << err;
  EXPECT_NE(err.find("skipnc: expectation failed: status=alarm: the run ended completed"),
            std::string::npos)
      << err;
  EXPECT_EQ(err.find("#101=-3:"), std::string::npos) << "the third one holds: " << err;
}

TEST(Expect, AnExpectedAlarmPasses) {
  // The probe crash golden case ends in alarm 9061 (exit 1 without --expect).
  const fs::path p = fs::path(SKIPNC_SOURCE_DIR) / "tests" / "golden" / "probing";
  const auto r =
      run_cli({"run", (p / "crash.nc").string(), "-m", (p / "crash.machine.toml").string(),
               "--scene", (p / "crash.scene.toml").string(), "-q", "--expect", "alarm=9061",
               "--expect", "status=alarm"});
  EXPECT_EQ(r.exit_code, 0);
}

TEST(Expect, BadSyntaxStopsBeforeTheRun) {
  skipnc::test::TempDir tmp;
  for (const std::string bad :
       {"#101", "#101=abc", "#101=-3+-x", "status=done", "speed=3", "alarm=x", "#<NAME=1"}) {
    const auto r = run_with({bad}, tmp.path / "err");
    EXPECT_EQ(r.exit_code, 2) << bad;
    const std::string err = read_file(tmp.path / "err");
    EXPECT_NE(err.find("error: --expect '" + bad + "'"), std::string::npos) << err;
  }
}

}  // namespace
