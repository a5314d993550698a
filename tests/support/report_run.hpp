// Runs a program through the skipnc binary as a user would (`skipnc run
// PROGRAM --report FILE ...`) and reads back what the user sees: the exit
// status, how the process ended, and the JSON report.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "config/dialect.hpp"
#include "support/child_process.hpp"
#include "support/run_cli.hpp"

namespace skipnc::test {

struct ReportRun {
  ChildExit exit;
  bool report_ok = false;  // the report exists and is valid JSON
  nlohmann::json report;
  std::string err;  // standard error

  const nlohmann::json& alarm() const { return report.at("alarm"); }
  std::string status() const { return report_ok ? report.value("status", "") : ""; }
};

// Runs `skipnc run program --report <dir>/report.json args...`.
inline ReportRun run_with_report(const TempDir& dir, const std::filesystem::path& program,
                                 std::vector<std::string> args = {}, double timeout_s = 60.0) {
  const auto report = dir.path / "report.json";
  const auto err = dir.path / "stderr.txt";
  std::filesystem::remove(report);
  std::vector<std::string> all = {"run", program.string(), "--report", report.string(), "-q"};
  all.insert(all.end(), args.begin(), args.end());
  Child c(all, "/dev/null", err.string());
  ReportRun r;
  r.exit = c.wait(timeout_s);
  r.err = read_file(err);
  const std::string text = read_file(report);
  r.report = nlohmann::json::parse(text, nullptr, false);
  r.report_ok = !r.report.is_discarded() && r.report.is_object();
  return r;
}

// Runs `skipnc run args... --report <t>/report.json -q` and returns the report.
inline nlohmann::json run_report(const TempDir& t, std::vector<std::string> args) {
  const auto report = t.path / "report.json";
  std::filesystem::remove(report);
  args.insert(args.begin(), "run");
  args.insert(args.end(), {"--report", report.string(), "-q"});
  run_cli(args);
  return nlohmann::json::parse(read_file(report));
}

// The code a dialect gives an alarm ("PS0112"): tests name alarms by the
// dialect's table, not by message text.
inline std::string alarm_code(AlarmId id, const std::string& dialect = "fanuc") {
  auto d = config::builtin_dialect(dialect);
  return d ? d->alarm(id).code : std::string("?");
}

}  // namespace skipnc::test
