// --junit FILE: the run's checks as a JUnit XML file, the format CI systems
// (GitLab, Jenkins, GitHub test reporters) show test by test: one
// <testsuite> per command, one <testcase> per check, a <failure> with the
// reason for each that failed. Written whole or not at all.
#pragma once

#include <string>
#include <vector>

#include "core/diag.hpp"

namespace skipnc::cli {

struct JunitCase {
  std::string name;
  std::string classname;
  double time_s = 0.0;
  bool failed = false;
  std::string failure_type;     // "expectation", "alarm", ...
  std::string failure_message;  // one line
  std::string output;           // <system-out>, empty: none
};

// The XML text of one suite (text is escaped; bytes that XML 1.0 forbids
// are replaced by a space).
std::string junit_xml(const std::string& suite, double time_s, const std::vector<JunitCase>& cases);

// Writes it atomically (report::write_atomic).
[[nodiscard]] Result<void> write_junit(const std::string& path, const std::string& suite,
                                       double time_s, const std::vector<JunitCase>& cases);

}  // namespace skipnc::cli
