#include "cli/junit.hpp"

#include <fmt/format.h>

#include "plot/svg_util.hpp"
#include "report/report.hpp"

namespace skipnc::cli {
namespace {

// XML 1.0 text: the plot's escaping (special characters as entities, bytes
// XML 1.0 forbids replaced, ill-formed UTF-8 made valid).
std::string escape(const std::string& s) {
  return plot::esc(s);
}

}  // namespace

void JunitCounts::add(const JunitCase& c) {
  ++tests;
  if (!c.failed) return;
  switch (c.problem) {
    case JunitProblem::kFailure:
      ++failures;
      break;
    case JunitProblem::kError:
      ++errors;
      break;
    case JunitProblem::kSkipped:
      ++skipped;
      break;
  }
}

std::string junit_head(const std::string& suite, double time_s, const JunitCounts& n) {
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += fmt::format("<testsuites name=\"skipnc\" tests=\"{}\" failures=\"{}\" errors=\"{}\">\n",
                   n.tests, n.failures, n.errors);
  x += fmt::format(
      "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"{}\" "
      "time=\"{:.6f}\">\n",
      escape(suite), n.tests, n.failures, n.errors, n.skipped, time_s);
  return x;
}

std::string junit_case(const JunitCase& c) {
  std::string x = fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.6f}\"",
                              escape(c.name), escape(c.classname), c.time_s);
  if (!c.failed && c.output.empty()) return x + "/>\n";
  x += ">\n";
  if (c.failed) {
    const char* tag = c.problem == JunitProblem::kError     ? "error"
                      : c.problem == JunitProblem::kSkipped ? "skipped"
                                                            : "failure";
    x += fmt::format("      <{} type=\"{}\" message=\"{}\">{}</{}>\n", tag, escape(c.failure_type),
                     escape(c.failure_message),
                     escape(c.failure_text.empty() ? c.failure_message : c.failure_text), tag);
  }
  if (!c.output.empty()) x += "      <system-out>" + escape(c.output) + "</system-out>\n";
  return x + "    </testcase>\n";
}

std::string junit_tail() {
  return "  </testsuite>\n</testsuites>\n";
}

std::string junit_xml(const std::string& suite, double time_s,
                      const std::vector<JunitCase>& cases) {
  JunitCounts n;
  for (const auto& c : cases) n.add(c);
  std::string x = junit_head(suite, time_s, n);
  for (const auto& c : cases) x += junit_case(c);
  return x + junit_tail();
}

Result<void> write_junit(const std::string& path, const std::string& suite, double time_s,
                         const std::vector<JunitCase>& cases) {
  return write_junit_text(path, junit_xml(suite, time_s, cases));
}

Result<void> write_junit_text(const std::string& path, const std::string& xml) {
  auto w = report::write_atomic(path, xml);
  if (!w) {
    Error e = w.error();
    e.detail = "junit: " + e.detail;
    return std::unexpected(std::move(e));
  }
  return {};
}

}  // namespace skipnc::cli
