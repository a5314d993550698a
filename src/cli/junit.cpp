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

std::string junit_xml(const std::string& suite, double time_s,
                      const std::vector<JunitCase>& cases) {
  int failures = 0;
  for (const auto& c : cases) failures += c.failed ? 1 : 0;
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += fmt::format("<testsuites name=\"skipnc\" tests=\"{}\" failures=\"{}\" errors=\"0\">\n",
                   cases.size(), failures);
  x += fmt::format(
      "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"0\" "
      "time=\"{:.6f}\">\n",
      escape(suite), cases.size(), failures, time_s);
  for (const auto& c : cases) {
    x += fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.6f}\"", escape(c.name),
                     escape(c.classname), c.time_s);
    if (!c.failed && c.output.empty()) {
      x += "/>\n";
      continue;
    }
    x += ">\n";
    if (c.failed) {
      x +=
          fmt::format("      <failure type=\"{}\" message=\"{}\">{}</failure>\n",
                      escape(c.failure_type), escape(c.failure_message), escape(c.failure_message));
    }
    if (!c.output.empty()) x += "      <system-out>" + escape(c.output) + "</system-out>\n";
    x += "    </testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  return x;
}

Result<void> write_junit(const std::string& path, const std::string& suite, double time_s,
                         const std::vector<JunitCase>& cases) {
  auto w = report::write_atomic(path, junit_xml(suite, time_s, cases));
  if (!w) {
    Error e = w.error();
    e.detail = "junit: " + e.detail;
    return std::unexpected(std::move(e));
  }
  return {};
}

}  // namespace skipnc::cli
