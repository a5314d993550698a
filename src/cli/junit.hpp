// --junit FILE: the run's checks as a JUnit XML file, the format CI systems
// (GitLab, Jenkins, GitHub test reporters) show test by test: one
// <testsuite> per command, one <testcase> per check, a <failure> with the
// reason for each that failed. Written whole or not at all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/diag.hpp"

namespace skipnc::cli {

// How a failed case is shown: a check that did not hold (<failure>), a case
// that could not run (<error>), one that was not run at all (<skipped>).
enum class JunitProblem : std::uint8_t { kFailure, kError, kSkipped };

struct JunitCase {
  std::string name;
  std::string classname;
  double time_s = 0.0;
  bool failed = false;
  std::string failure_type;     // "expectation", "alarm", ...
  std::string failure_message;  // one line
  std::string output;           // <system-out>, empty: none
  JunitProblem problem = JunitProblem::kFailure;
  std::string failure_text;  // the element's text, empty: the message
};

// The counts a suite's head announces.
struct JunitCounts {
  std::int64_t tests = 0, failures = 0, errors = 0, skipped = 0;
  void add(const JunitCase& c);
};

// The XML text of one suite (text is escaped; bytes that XML 1.0 forbids
// are replaced by a space).
std::string junit_xml(const std::string& suite, double time_s, const std::vector<JunitCase>& cases);
// The same in three parts, for a suite written as its cases come (a sweep):
// the head (XML declaration, <testsuites>, <testsuite>), each case, the tail.
std::string junit_head(const std::string& suite, double time_s, const JunitCounts& n);
std::string junit_case(const JunitCase& c);
std::string junit_tail();

// Writes `xml` (junit_xml, or its parts) atomically to `path`.
[[nodiscard]] Result<void> write_junit_text(const std::string& path, const std::string& xml);

// Writes it atomically (report::write_atomic).
[[nodiscard]] Result<void> write_junit(const std::string& path, const std::string& suite,
                                       double time_s, const std::vector<JunitCase>& cases);

}  // namespace skipnc::cli
