// skipnc run --repeat N --seed S, as a user runs it: the bore-centre example
// with a probe that has pre-travel, 3-lobed lobing and 0.5 um of scatter.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_cli.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using skipnc::test::read_file;
using skipnc::test::run_cli;

const fs::path kExamples = fs::path(SKIPNC_SOURCE_DIR) / "examples" / "probing";

json repeat(int runs, int seed, const skipnc::test::TempDir& tmp, int* exit_code = nullptr) {
  const fs::path report = tmp.path / "repeat.json";
  const auto r = run_cli({"run", (kExamples / "bore_centre.nc").string(), "-s",
                          (kExamples / "fixture_real.scene.toml").string(), "-m",
                          (kExamples / "mill3_probe.machine.toml").string(), "--var", "130",
                          "--var", "131", "--var", "132", "--repeat", std::to_string(runs),
                          "--seed", std::to_string(seed), "--report", report.string(), "-q"});
  if (exit_code != nullptr) *exit_code = r.exit_code;
  return json::parse(read_file(report));
}

std::map<std::string, json> by_name(const json& j) {
  std::map<std::string, json> out;
  for (const auto& v : j["values"]) out[v["name"].get<std::string>()] = v;
  return out;
}

// 100 runs of the bore-centre cycle: enough for the statistics below, and
// within the test time limit under the sanitizers (a run is ~15,000 periods).
constexpr int kRuns = 100;

TEST(Repeat, SummarisesEveryLatchedValueAndVariable) {
  skipnc::test::TempDir tmp;
  int rc = -1;
  const json j = repeat(kRuns, 7, tmp, &rc);
  EXPECT_EQ(rc, 0);
  EXPECT_EQ(j["format"], "skipnc-repeat/1");
  EXPECT_EQ(j["runs"], kRuns);
  EXPECT_EQ(j["seed"], 7);
  auto v = by_name(j);
  ASSERT_TRUE(v.count("#130") && v.count("#131") && v.count("#132"));
  ASSERT_TRUE(v.count("skip 1 (line 11) X") && v.count("skip 4 (line 21) Y"));
  for (const auto& [name, s] : v) EXPECT_EQ(s["count"], kRuns) << name;
  // The nominal run (no scatter) shows the lobing: the X- touch switches
  // 2 um later than the X+ touch, so the X centre is 1 um low; Y is not.
  EXPECT_NEAR(v["#130"]["nominal"].get<double>(), -80.123 - 0.001, 1e-6);
  EXPECT_NEAR(v["#131"]["nominal"].get<double>(), 30.456, 1e-6);
  // ... and the pre-travel (4 um + 1 um of lobing on each Y touch) widens
  // the diameter the program computes with a 1 mm radius by 10 um.
  EXPECT_NEAR(v["#132"]["nominal"].get<double>(), 40.01, 1e-6);
  // Each touch scatters by 0.5 um; a centre is half the difference of two
  // touches: 0.5 / sqrt(2) um. 100 runs: within 20 % (about 2.8 standard
  // errors of a standard deviation estimated from 100 samples).
  const double sigma = 0.0005;
  EXPECT_NEAR(v["skip 1 (line 11) X"]["std"].get<double>(), sigma, 0.2 * sigma);
  EXPECT_NEAR(v["#131"]["std"].get<double>(), sigma / std::sqrt(2.0), 0.2 * sigma / std::sqrt(2.0));
  EXPECT_NEAR(v["#132"]["std"].get<double>(), sigma * std::sqrt(2.0), 0.2 * sigma * std::sqrt(2.0));
  EXPECT_NEAR(v["#131"]["mean"].get<double>(), 30.456, 4 * sigma / std::sqrt(2.0 * kRuns));
  // Worst case: the largest deviation from the nominal run, between 2 and
  // 5 sigma for 100 normal samples, and consistent with min and max.
  for (const char* name : {"#130", "#131", "#132"}) {
    const json& s = v[name];
    const double worst = s["worst"].get<double>();
    const double sd = s["std"].get<double>();
    EXPECT_GT(worst, 2 * sd) << name;
    EXPECT_LT(worst, 5 * sd) << name;
    const double nominal = s["nominal"].get<double>();
    EXPECT_NEAR(worst, std::max(s["max"].get<double>() - nominal, nominal - s["min"].get<double>()),
                1e-12)
        << name;
  }
  // Z never scatters: the probe only moves in X and Y while touching.
  EXPECT_EQ(v["skip 1 (line 11) Z"]["worst"].get<double>(), 0.0);
}

TEST(Repeat, TheSameSeedGivesTheSameNumbers) {
  skipnc::test::TempDir tmp;
  const json a = repeat(5, 11, tmp);
  const json b = repeat(5, 11, tmp);
  const json c = repeat(5, 12, tmp);
  EXPECT_EQ(a["values"], b["values"]);
  EXPECT_NE(a["values"], c["values"]);
}

TEST(Repeat, ReportsTheOffsetsTheProgramWrote) {
  skipnc::test::TempDir tmp;
  const fs::path report = tmp.path / "offsets.json";
  const auto r = run_cli({"run", (kExamples / "work_offset.nc").string(), "-s",
                          (kExamples / "fixture_real.scene.toml").string(), "-m",
                          (kExamples / "mill3_probe.machine.toml").string(), "--repeat", "30",
                          "--report", report.string(), "-q"});
  EXPECT_EQ(r.exit_code, 0);
  auto v = by_name(json::parse(read_file(report)));
  ASSERT_TRUE(v.count("#5221 G54 X") && v.count("#5222 G54 Y") && v.count("#5223 G54 Z"));
  EXPECT_EQ(v.count("#5201 EXT X"), 0U) << "an offset the program did not write is not listed";
  EXPECT_EQ(v["#5221 G54 X"]["kind"], "offset");
  EXPECT_EQ(v["#5221 G54 X"]["count"], 30);
  // The top face: Z touches have no lobing, 4 um of pre-travel.
  EXPECT_NEAR(v["#5223 G54 Z"]["nominal"].get<double>(), -229.87 - 0.004, 1e-6);
  EXPECT_GT(v["#5223 G54 Z"]["std"].get<double>(), 0.0);
}

}  // namespace
