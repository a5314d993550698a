// --expect (skipnc run) and a sweep spec's expect = [...]: assertions on the
// outcome of a run, for CI. One parser for both.
//   #140=-0.05+-0.001   variable #140 within 0.001 of -0.05
//   #140=-0.05          within 1e-9 (float noise) of -0.05
//   #<name>=1.5+-0.01   a named variable
//   #140=vacant         the variable is vacant
//   status=completed    completed, alarm or interrupted
//   alarm=9061          the run ended in alarm number 9061 (the dialect's number)
//   alarm=SN9061        ... in the alarm of that code (the dialect's, as printed)
//   alarm=probe_crash   ... in the alarm of that key (the report's alarm.key)
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "config/dialect.hpp"
#include "core/diag.hpp"
#include "report/report.hpp"

namespace skipnc::run {

struct Expectation {
  enum class Kind : std::uint8_t { kVariable, kStatus, kAlarm };
  std::string text;  // as given
  Kind kind = Kind::kVariable;
  std::string var;  // "140" or "<name>" (as --var takes it)
  bool vacant = false;
  double value = 0.0;
  double tolerance = 1e-9;
  std::string status;      // kStatus
  int alarm = 0;           // kAlarm by number (0: by name)
  std::string alarm_name;  // kAlarm by code (SN9061) or key (probe_crash)
};

// kUsage with what the text should look like when it cannot be read.
[[nodiscard]] Result<Expectation> parse_expectation(const std::string& text);

// alarm=NAME names an alarm of the dialect (a code or a key); kUsage when
// none has that name (a typo would otherwise never match).
[[nodiscard]] Result<void> check_alarm_name(const Expectation& e, const config::Dialect& d);

// What the run gave, for the checks.
struct ObservedRun {
  std::string status;      // "completed", "alarm", "interrupted"
  int alarm = 0;           // alarm number, 0 when none
  std::string alarm_code;  // the dialect's code (SN9061, PS0015), empty when none
  std::string alarm_key;   // the alarm's key (probe_crash), empty when none
  std::vector<std::pair<std::string, std::optional<double>>>
      variables;  // keyed as Expectation::var
};

// One expectation's verdict, as the report and the JUnit file give it.
using ExpectResult = report::CheckResult;

ExpectResult evaluate_expectation(const Expectation& e, const ObservedRun& o);

// Empty when the expectation holds; else the line that says why not.
std::string check_expectation(const Expectation& e, const ObservedRun& o);

}  // namespace skipnc::run
