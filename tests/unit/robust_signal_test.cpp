// A long run stopped with SIGTERM or SIGINT still leaves a whole report that
// says it was interrupted, and a whole trace up to the last servo period run
// (issue 7, "data kept whole"). The run is the skipnc binary, as a user runs
// it; the signal comes while it is busy.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

#include "support/endless_programs.hpp"
#include "support/report_run.hpp"

namespace skipnc::test {
namespace {

struct Interrupted {
  ChildExit exit;
  nlohmann::json report;
  bool report_ok = false;
  std::string trace;
};

// Starts `program`, lets it run for `after_s`, sends `sig`, waits.
Interrupted interrupt(const TempDir& dir, const std::string& program, int sig, double after_s) {
  const auto prog = dir.write("long.nc", program);
  const auto report = dir.path / "report.json";
  const auto trace = dir.path / "trace.csv";
  Child c({"run", prog.string(), "--report", report.string(), "--trace", trace.string(), "-q"},
          "/dev/null", (dir.path / "stderr.txt").string());
  std::this_thread::sleep_for(std::chrono::duration<double>(after_s));
  // The report must not exist before the run ends: it is written once, whole.
  EXPECT_FALSE(std::filesystem::exists(report));
  c.signal(sig);
  Interrupted r;
  r.exit = c.wait(10.0);
  r.report = nlohmann::json::parse(read_file(report), nullptr, false);
  r.report_ok = !r.report.is_discarded() && r.report.is_object();
  r.trace = read_file(trace);
  return r;
}

void expect_interrupted(const Interrupted& r) {
  ASSERT_TRUE(r.exit.exited) << "ended by signal " << r.exit.signal;
  EXPECT_FALSE(r.exit.timed_out) << "the signal did not stop the run";
  EXPECT_EQ(r.exit.code, 1);
  ASSERT_TRUE(r.report_ok);
  EXPECT_EQ(r.report.value("format", ""), "skipnc-report/1");
  EXPECT_EQ(r.report.value("status", ""), "interrupted");
  ASSERT_TRUE(r.report["alarm"].is_object());
  EXPECT_EQ(r.report["alarm"].value("code", ""), alarm_code(AlarmId::kInterrupted));
  EXPECT_GT(r.report["final"]["time"].get<double>(), 0.0);
  // The trace holds every period up to the end: one row per millisecond of
  // simulated time plus the header, each row complete.
  ASSERT_FALSE(r.trace.empty());
  EXPECT_EQ(r.trace.back(), '\n');
  std::size_t rows = 0;
  for (char c : r.trace) rows += c == '\n' ? 1 : 0;
  const double t = r.report["final"]["time"].get<double>();
  EXPECT_EQ(rows - 1, static_cast<std::size_t>(std::llround(t * 1000.0)));
}

TEST(RobustSignal, SigtermDuringMotionLeavesAnInterruptedReport) {
  TempDir dir;
  expect_interrupted(interrupt(dir, kEndlessMotion, SIGTERM, 0.5));
}

TEST(RobustSignal, SigintDuringMotionLeavesAnInterruptedReport) {
  TempDir dir;
  expect_interrupted(interrupt(dir, kEndlessMotion, SIGINT, 0.5));
}

TEST(RobustSignal, SigtermDuringAMacroLoopIsHeardAtOnce) {
  // A loop of statements with no motion: the run must still notice the
  // signal within a fraction of a second, not at the statement limit.
  TempDir dir;
  const auto r = interrupt(dir, kEndlessStatements, SIGTERM, 0.5);
  ASSERT_TRUE(r.exit.exited);
  EXPECT_LT(r.exit.wall_s, 2.0);
  ASSERT_TRUE(r.report_ok);
  EXPECT_EQ(r.report.value("status", ""), "interrupted");
}

// --repeat: SIGTERM ends the repetitions (the run in progress stops at once)
// and the report keeps what finished, with "interrupted": true and exit 1
// (was: the signal waited for every run to end).
TEST(RobustSignal, SigtermDuringRepeatLeavesAnInterruptedRepeatReport) {
  TempDir dir;
  const auto prog = dir.write("long.nc", kEndlessMotion);
  const auto report = dir.path / "report.json";
  Child c({"run", prog.string(), "--repeat", "1000", "--report", report.string(), "-q"},
          "/dev/null", (dir.path / "stderr.txt").string());
  std::this_thread::sleep_for(std::chrono::duration<double>(0.5));
  c.signal(SIGTERM);
  const ChildExit e = c.wait(10.0);
  ASSERT_TRUE(e.exited) << "ended by signal " << e.signal;
  EXPECT_FALSE(e.timed_out) << "the signal did not stop the repetitions";
  EXPECT_EQ(e.code, 1);
  const auto j = nlohmann::json::parse(read_file(report), nullptr, false);
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j.value("format", ""), "skipnc-repeat/1");
  EXPECT_EQ(j.value("interrupted", false), true);
  EXPECT_EQ(j.value("runs", -1), 0);  // the nominal run was cut short: no scattered run
}

// --repeat with a program that cannot be opened writes the report with the
// start alarm (SN9057), as a plain run does (was: no report).
TEST(RobustSignal, RepeatThatCannotStartWritesItsReport) {
  TempDir dir;
  const auto report = dir.path / "report.json";
  const auto r = run_cli(
      {"run", (dir.path / "missing.nc").string(), "--repeat", "3", "--report", report.string()});
  EXPECT_EQ(r.exit_code, 2);
  const auto j = nlohmann::json::parse(read_file(report), nullptr, false);
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j.value("status", ""), "alarm");
  EXPECT_EQ(j["alarm"].value("code", ""), "SN9057");
}

}  // namespace
}  // namespace skipnc::test
