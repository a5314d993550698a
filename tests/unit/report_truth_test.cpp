// What the report, the summary and --expect say is true (issue 30), as a
// user sees it through the skipnc binary: each test is named after the
// issue's bullet it checks.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/run_cli.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using skipnc::test::read_file;
using skipnc::test::run_cli;

namespace {

const fs::path kGolden = fs::path(SKIPNC_SOURCE_DIR) / "tests" / "golden";

// A G31 under G43 H1 (100 mm) that misses: #5063 is the tool reference
// point (Z90 on fanuc), the tip ended at work Z-10.
constexpr const char* kMissProgram =
    "G21 G90 G54\nG43 H1 G0 Z0\nG31 Z-10. F500.\n#100 = #5063\nM30\n";
constexpr const char* kMachineH100 =
    "extends = \"mill3\"\n[tool_offsets]\n1 = { length = 100.0 }\n";

TEST(Truth, MissedSkipSummaryNamesTheTipEndPointInWorkCoordinates) {
  skipnc::test::TempDir tmp;
  const auto nc = tmp.write("miss.nc", kMissProgram);
  const auto m = tmp.write("h100.machine.toml", kMachineH100);
  const auto r = run_cli({"run", nc.string(), "-m", m.string(), "--var", "5063"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("no signal: ran to its end point X0.0000 Y0.0000 Z-10.0000"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("#5063 = 90.0000"), std::string::npos) << r.out;
}

TEST(Truth, CanonDoesNotWarnOnEverySkipVariableRead) {
  skipnc::test::TempDir tmp;
  const auto nc = tmp.write("miss.nc", kMissProgram);
  const auto m = tmp.write("h100.machine.toml", kMachineH100);
  const auto r = run_cli({"canon", nc.string(), "-m", m.string()}, (tmp.path / "err").string());
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(read_file(tmp.path / "err"), "");
  // The same program on the machine does warn: the skip really missed.
  const auto run = run_cli({"run", nc.string(), "-m", m.string(), "-q", "--strict"});
  EXPECT_EQ(run.exit_code, 1);
}

TEST(Truth, ExpectationResultsInTheJsonReport) {
  skipnc::test::TempDir tmp;
  const fs::path where = kGolden / "where";
  const auto report = tmp.path / "r.json";
  const auto r = run_cli(
      {"run", (where / "macro_files.nc").string(), "-I", (where / "macros").string(), "--scene",
       (where / "macro_files.scene.toml").string(), "-q", "--report", report.string(), "--expect",
       "#101=-2.9+-0.05", "--expect", "status=completed", "--expect", "#102=vacant"});
  EXPECT_EQ(r.exit_code, 3);
  const json j = json::parse(read_file(report));
  ASSERT_EQ(j["expectations"].size(), 3u) << j.dump(2);
  const json& v = j["expectations"][0];
  EXPECT_EQ(v["expect"], "#101=-2.9+-0.05");
  EXPECT_EQ(v["name"], "#101");
  EXPECT_EQ(v["pass"], false);
  EXPECT_NEAR(v["value"].get<double>(), -3.0, 1e-9);
  EXPECT_NEAR(v["expected"].get<double>(), -2.9, 1e-12);
  EXPECT_NEAR(v["tolerance"].get<double>(), 0.05, 1e-12);
  EXPECT_NE(v["message"].get<std::string>().find("#101 = -3"), std::string::npos);
  const json& s = j["expectations"][1];
  EXPECT_EQ(s["pass"], true);
  EXPECT_EQ(s["value"], "completed");
  EXPECT_EQ(s["expected"], "completed");
  EXPECT_TRUE(s["tolerance"].is_null());
  EXPECT_TRUE(s["message"].is_null());
  EXPECT_EQ(j["expectations"][2]["pass"], true);
  EXPECT_EQ(j["expectations"][2]["value"], "vacant");
}

TEST(Truth, AlarmExpectationAcceptsCodesAndKeys) {
  const fs::path p = kGolden / "probing";
  const std::vector<std::string> base = {
      "run",     (p / "crash.nc").string(),         "-m", (p / "crash.machine.toml").string(),
      "--scene", (p / "crash.scene.toml").string(), "-q"};
  for (const std::string e : {"alarm=SN9061", "alarm=probe_crash", "alarm=sn9061", "alarm=9061"}) {
    auto args = base;
    args.insert(args.end(), {"--expect", e});
    EXPECT_EQ(run_cli(args).exit_code, 0) << e;
  }
  auto wrong = base;
  wrong.insert(wrong.end(), {"--expect", "alarm=collision"});
  EXPECT_EQ(run_cli(wrong).exit_code, 3);
  // A name no alarm of the dialect has is a usage error before the run.
  skipnc::test::TempDir tmp;
  auto typo = base;
  typo.insert(typo.end(), {"--expect", "alarm=probe_crsh"});
  EXPECT_EQ(run_cli(typo, (tmp.path / "err").string()).exit_code, 2);
  EXPECT_NE(read_file(tmp.path / "err").find("no alarm of the fanuc dialect"), std::string::npos);
}

// A user alarm (#3000 = 1) is named by the code the report shows, MC0001,
// as well as by its number and key; another user alarm's code fails.
TEST(Truth, AlarmExpectationAcceptsAUserAlarmsCode) {
  skipnc::test::TempDir tmp;
  const auto nc = tmp.write("u.nc", "#3000 = 1 (CLAMP OPEN)\nM30\n");
  for (const std::string e : {"alarm=MC0001", "alarm=mc0001", "alarm=user_alarm", "alarm=3001"}) {
    EXPECT_EQ(run_cli({"run", nc.string(), "-q", "--expect", e}).exit_code, 0) << e;
  }
  EXPECT_EQ(run_cli({"run", nc.string(), "-q", "--expect", "alarm=MC0002"}).exit_code, 3);
}

TEST(Truth, MessagesWholeNumbersPrintWithoutSixDecimals) {
  skipnc::test::TempDir tmp;
  const auto nc = tmp.write("p.nc", "G21 G90\nG31 P5. X1. F100\nM30\n");
  const auto r = run_cli({"run", nc.string(), "-q"}, (tmp.path / "err").string());
  EXPECT_EQ(r.exit_code, 1);
  const std::string err = read_file(tmp.path / "err");
  EXPECT_EQ(err.find("5.000000"), std::string::npos) << err;
  EXPECT_NE(err.find("P5. is written with a decimal point"), std::string::npos) << err;
  const auto h = tmp.write("h.nc", "G21 G90\nG43 H500. Z0\nM30\n");
  run_cli({"run", h.string(), "-q"}, (tmp.path / "err").string());
  EXPECT_NE(read_file(tmp.path / "err").find("H500\n"), std::string::npos)
      << read_file(tmp.path / "err");
}

TEST(Truth, MessagesG92_1IsNamedAsItself) {
  skipnc::test::TempDir tmp;
  const auto nc = tmp.write("g.nc", "G21 G90\nG92.1\nM30\n");
  run_cli({"run", nc.string(), "-q"}, (tmp.path / "err").string());
  const std::string err = read_file(tmp.path / "err");
  EXPECT_NE(err.find("G92.1 (G92 offset cancel"), std::string::npos) << err;
  EXPECT_EQ(err.find("straight probe"), std::string::npos) << err;
}

// CI output: the README's "In CI" section says how to use --expect,
// --strict (with --allow), --junit for run, repeat and sweep, and each exit
// status the command gives.
TEST(Truth, ReadmeSaysHowToUseExpectStrictJunitAndExitCodesInCi) {
  const std::string readme = read_file(fs::path(SKIPNC_SOURCE_DIR) / "README.md");
  const auto at = readme.find("\n## In CI\n");
  ASSERT_NE(at, std::string::npos);
  const auto end = readme.find("\n## ", at + 1);
  const std::string ci = readme.substr(at, end - at);
  for (const char* words : {"--expect", "--strict", "--allow", "--junit", "--repeat",
                            "skipnc sweep", "Exit status", "`0`", "`1`", "`2`", "`3`"}) {
    EXPECT_NE(ci.find(words), std::string::npos) << words;
  }
}

}  // namespace
