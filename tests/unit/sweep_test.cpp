// skipnc sweep (run/sweep.hpp): every row checked against the hand rule of
// the exact latch, determinism whatever the number of workers, the CLI's
// files and exit status, spec errors with file, line and column.
#include "run/sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>

#include "support/run_cli.hpp"

namespace skipnc::run {
namespace {

const std::string kDir = std::string(SKIPNC_SOURCE_DIR) + "/tests/sweep/";

SweepPlan load(const std::string& name, SweepOverrides o = {}) {
  SweepPlan p;
  auto r = load_sweep(kDir + name, o, p);
  EXPECT_TRUE(r.has_value()) << (r ? "" : describe(r.error(), nullptr));
  return p;
}

// Exact latch, servo-delay compensation on (mill3): #5063 is the plane's
// machine Z minus the G54 Z offset, so #140 = -3 + part.Z - G54.Z to the
// rounding of a double, at any feed.
TEST(Sweep, EveryRowStoresThePlaneMovedByThePartAndTheOffset) {
  const SweepPlan plan = load("touch.sweep.toml");
  ASSERT_EQ(plan.vary.size(), 3u);
  const auto rows = run_scenarios(plan, 0, plan.scenarios, 2);
  ASSERT_EQ(rows.size(), 40u);
  for (const auto& r : rows) {
    ASSERT_EQ(r.status, "completed") << r.alarm_text;
    const double part = r.chosen[0], g54 = r.chosen[1], feed = r.chosen[2];
    EXPECT_GE(part, -0.2);
    EXPECT_LE(part, 0.2);
    constexpr std::array<double, 4> kFeeds{50.0, 200.0, 800.0, 3200.0};
    EXPECT_EQ(feed, kFeeds[static_cast<std::size_t>(r.index % 4)]);
    ASSERT_TRUE(r.values[0].has_value());
    EXPECT_NEAR(*r.values[0], -3.0 + part - g54, 1e-9) << "scenario " << r.index;
    // The checks: |#140 - -3| <= 0.2 and the status.
    EXPECT_EQ(r.checks[0], std::fabs(part - g54) <= 0.2 + 1e-12) << r.index;
    EXPECT_TRUE(r.checks[1]);
    EXPECT_EQ(r.pass, r.checks[0]);
  }
  // The draws are spread: some scenarios must fail the 0.2 mm check (sd of
  // G54.Z alone is 0.05; part.Z spans 0.4 mm).
  int fails = 0;
  for (const auto& r : rows) fails += r.pass ? 0 : 1;
  EXPECT_GT(fails, 0);
  EXPECT_LT(fails, 40);
}

TEST(Sweep, OneWorkerAndTwoWorkersWriteTheSameTable) {
  const SweepPlan plan = load("touch.sweep.toml");
  const auto one = run_scenarios(plan, 0, plan.scenarios, 1);
  const auto two = run_scenarios(plan, 0, plan.scenarios, 2);
  EXPECT_EQ(sweep_csv(plan, one), sweep_csv(plan, two));
  EXPECT_EQ(sweep_json(plan, one), sweep_json(plan, two));
  // A range run on its own gives the same rows (Dask chunks).
  const auto tail = run_scenarios(plan, 25, 40, 1);
  ASSERT_EQ(tail.size(), 15u);
  EXPECT_EQ(tail[0].chosen, one[25].chosen);
  EXPECT_EQ(tail[0].values, one[25].values);
  EXPECT_EQ(tail[0].probe_seed, one[25].probe_seed);
}

TEST(Sweep, AnotherSeedDrawsOtherValues) {
  const SweepPlan a = load("touch.sweep.toml");
  SweepOverrides o;
  o.seed = 8;
  const SweepPlan b = load("touch.sweep.toml", o);
  std::vector<double> ca, cb;
  std::uint64_t sa = 0, sb = 0;
  scenario_variation(a, 3, ca, sa);
  scenario_variation(b, 3, cb, sb);
  EXPECT_NE(ca[0], cb[0]);
  EXPECT_NE(sa, sb);
  EXPECT_EQ(ca[2], cb[2]);  // values = [...] are cycled, not drawn
}

TEST(Sweep, StepsSpanTheRangeEvenly) {
  SweepPlan plan = load("touch.sweep.toml");
  plan.vary[2].draw = VaryRule::Draw::kSteps;
  plan.vary[2].values = {100.0, 490.0};
  std::vector<double> c;
  std::uint64_t s = 0;
  scenario_variation(plan, 0, c, s);
  EXPECT_EQ(c[2], 100.0);
  scenario_variation(plan, 39, c, s);
  EXPECT_EQ(c[2], 490.0);
  scenario_variation(plan, 13, c, s);
  EXPECT_DOUBLE_EQ(c[2], 230.0);  // 100 + 390 * 13 / 39
}

TEST(Sweep, TheSummaryNamesTheWorstScenarioAgainstTheExpectedValue) {
  const SweepPlan plan = load("touch.sweep.toml");
  const auto rows = run_scenarios(plan, 0, plan.scenarios, 2);
  const auto j = nlohmann::json::parse(sweep_json(plan, rows));
  EXPECT_EQ(j["format"], "skipnc-sweep/1");
  EXPECT_EQ(j["rows"].size(), 40u);
  double worst = 0.0;
  std::int64_t at = -1;
  for (const auto& r : rows) {
    const double d = std::fabs(*r.values[0] + 3.0);
    if (d > worst) {
      worst = d;
      at = r.index;
    }
  }
  const auto& w = j["summary"]["variables"]["140"]["worst"];
  EXPECT_EQ(w["scenario"].get<std::int64_t>(), at);
  EXPECT_NEAR(w["deviation"].get<double>(), worst, 1e-12);
  EXPECT_EQ(j["summary"]["variables"]["140"]["reference"], "expect");
  EXPECT_EQ(j["summary"]["statuses"]["completed"], 40);
}

TEST(Sweep, ChecksParseAsTheExpectOption) {
  std::vector<VarRef> vars;
  auto c = parse_check("#140=-0.05+-0.001", vars);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->e.kind, Expectation::Kind::kVariable);
  EXPECT_EQ(c->e.value, -0.05);
  EXPECT_EQ(c->e.tolerance, 0.001);
  EXPECT_EQ(c->var, 0u);
  ASSERT_EQ(vars.size(), 1u);
  EXPECT_EQ(vars[0].number, 140);
  auto s = parse_check("status=completed", vars);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->e.kind, Expectation::Kind::kStatus);
  // The forms of run --expect (one parser): vacant.
  auto v = parse_check("#141=vacant", vars);
  ASSERT_TRUE(v);
  EXPECT_TRUE(v->e.vacant);
  EXPECT_EQ(v->var, 1u);
  EXPECT_FALSE(parse_check("status=done", vars));
  EXPECT_FALSE(parse_check("#140=abc", vars));
  EXPECT_FALSE(parse_check("#140=1+-", vars));
}

// alarm= checks by the dialect's code and by the key, as run --expect takes
// them: without a feed (#101 vacant) every scenario ends in PS0011
// skip_no_feed (fanuc) and passes.
TEST(Sweep, AlarmChecksTakeTheCodeAndTheKey) {
  SweepPlan plan = load("touch.sweep.toml");
  plan.vary.clear();
  plan.checks.clear();
  for (const char* text : {"alarm=PS0011", "alarm=skip_no_feed", "alarm=11"}) {
    auto c = parse_check(text, plan.request.vars);
    ASSERT_TRUE(c) << text;
    plan.checks.push_back(*c);
  }
  const ScenarioRow row = run_scenario(plan, 0);
  EXPECT_EQ(row.status, "alarm");
  EXPECT_EQ(row.alarm, 11);
  EXPECT_EQ(row.checks, (std::vector<bool>{true, true, true}));
  EXPECT_TRUE(row.pass);
  auto other = parse_check("alarm=PS0003", plan.request.vars);
  ASSERT_TRUE(other);
  plan.checks = {*other};
  const ScenarioRow miss = run_scenario(plan, 0);
  EXPECT_EQ(miss.checks, std::vector<bool>{false});
  EXPECT_FALSE(miss.pass);
}

TEST(SweepCli, WritesBothTablesAndExitsOneWhenAScenarioFails) {
  test::TempDir tmp;
  const auto csv = (tmp.path / "t.csv").string();
  const auto json = (tmp.path / "t.json").string();
  const auto r =
      test::run_cli({"sweep", kDir + "touch.sweep.toml", "--csv", csv, "--json", json, "-j", "2"});
  EXPECT_EQ(r.exit_code, 1);  // some scenarios are off by more than 0.2 mm
  const std::string text = test::read_file(csv);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "scenario,probe_seed,status,alarm,part.Z,G54.Z,#101,#140,#140=-3+-0.2,"
            "status=completed,pass,time_s");
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 41);
  EXPECT_NE(r.out.find("40 scenarios (seed 7)"), std::string::npos) << r.out;
  // Only the scenarios with |part.Z - G54.Z| <= 0.2: all pass.
  const auto r2 = test::run_cli(
      {"sweep", kDir + "touch.sweep.toml", "--csv", csv, "--json", json, "-n", "1", "-q"});
  const auto j = nlohmann::json::parse(test::read_file(json));
  const double part = j["rows"][0]["chosen"]["part.Z"], g54 = j["rows"][0]["chosen"]["G54.Z"];
  EXPECT_EQ(r2.exit_code, std::fabs(part - g54) <= 0.2 ? 0 : 1);
  EXPECT_EQ(r2.out, "");
}

TEST(SweepCli, ABadSpecNamesFileLineAndColumnAndExitsTwo) {
  test::TempDir tmp;
  const auto err = (tmp.path / "err.txt").string();
  const auto r = test::run_cli(
      {"sweep", kDir + "bad_key.sweep.toml", "--csv", (tmp.path / "t.csv").string()}, err);
  EXPECT_EQ(r.exit_code, 2);
  const std::string msg = test::read_file(err);
  EXPECT_NE(msg.find("bad_key.sweep.toml:5:8: error: [[vary]] what = \"part.Q\""),
            std::string::npos)
      << msg;
  EXPECT_FALSE(std::filesystem::exists(tmp.path / "t.csv"));
}

}  // namespace
}  // namespace skipnc::run
