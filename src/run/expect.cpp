#include "run/expect.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

namespace skipnc::run {
namespace {

constexpr const char* kForms =
    "expected #N=VALUE[+-TOLERANCE], #<name>=VALUE[+-TOLERANCE], #N=vacant, "
    "status=completed|alarm|interrupted or alarm=NUMBER";

bool read_number(std::string_view t, double& out) {
  if (t.empty()) return false;
  if (t.front() == '+') t.remove_prefix(1);
  const auto r = std::from_chars(t.data(), t.data() + t.size(), out);
  return r.ec == std::errc{} && r.ptr == t.data() + t.size() && std::isfinite(out);
}

Error bad(const std::string& text, const std::string& why) {
  return Error{AlarmId::kUsage, "--expect '" + text + "': " + why + " (" + kForms + ")", {}, -1};
}

}  // namespace

Result<Expectation> parse_expectation(const std::string& text) {
  Expectation e;
  e.text = text;
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    return std::unexpected(bad(text, "no NAME=VALUE"));
  }
  const std::string lhs = text.substr(0, eq);
  const std::string rhs = text.substr(eq + 1);
  if (lhs == "status") {
    if (rhs != "completed" && rhs != "alarm" && rhs != "interrupted") {
      return std::unexpected(bad(text, "unknown status '" + rhs + "'"));
    }
    e.kind = Expectation::Kind::kStatus;
    e.status = rhs;
    return e;
  }
  if (lhs == "alarm") {
    const auto r = std::from_chars(rhs.data(), rhs.data() + rhs.size(), e.alarm);
    if (r.ec != std::errc{} || r.ptr != rhs.data() + rhs.size() || e.alarm <= 0) {
      return std::unexpected(bad(text, "the alarm is a number"));
    }
    e.kind = Expectation::Kind::kAlarm;
    return e;
  }
  if (lhs.front() != '#' || lhs.size() < 2)
    return std::unexpected(bad(text, "unknown name '" + lhs + "'"));
  e.var = lhs.substr(1);
  if (e.var.front() == '<') {
    if (e.var.back() != '>' || e.var.size() < 3)
      return std::unexpected(bad(text, "unclosed #<name>"));
  } else {
    int n = 0;
    const auto r = std::from_chars(e.var.data(), e.var.data() + e.var.size(), n);
    if (r.ec != std::errc{} || r.ptr != e.var.data() + e.var.size() || n < 0) {
      return std::unexpected(bad(text, "'" + lhs + "' is not a variable"));
    }
  }
  if (rhs == "vacant") {
    e.vacant = true;
    return e;
  }
  const auto pm = rhs.find("+-");
  const std::string value = rhs.substr(0, pm);
  if (!read_number(value, e.value))
    return std::unexpected(bad(text, "'" + value + "' is not a number"));
  if (pm != std::string::npos) {
    const std::string tol = rhs.substr(pm + 2);
    if (!read_number(tol, e.tolerance) || e.tolerance < 0.0) {
      return std::unexpected(bad(text, "the tolerance '" + tol + "' is not a number >= 0"));
    }
  }
  return e;
}

std::string check_expectation(const Expectation& e, const ObservedRun& o) {
  switch (e.kind) {
    case Expectation::Kind::kStatus:
      if (o.status == e.status) return {};
      return fmt::format("expectation failed: {}: the run ended {}", e.text,
                         o.status == "alarm" ? fmt::format("in alarm {}", o.alarm) : o.status);
    case Expectation::Kind::kAlarm:
      if (o.alarm == e.alarm) return {};
      return fmt::format("expectation failed: {}: {}", e.text,
                         o.alarm == 0 ? std::string("no alarm") : fmt::format("alarm {}", o.alarm));
    case Expectation::Kind::kVariable:
      break;
  }
  for (const auto& [key, v] : o.variables) {
    if (key != e.var) continue;
    if (e.vacant) {
      if (!v) return {};
      return fmt::format("expectation failed: {}: #{} = {}", e.text, e.var, *v);
    }
    if (!v) return fmt::format("expectation failed: {}: #{} is vacant", e.text, e.var);
    const double off = *v - e.value;
    if (std::fabs(off) <= e.tolerance + 1e-12) return {};
    return fmt::format("expectation failed: {}: #{} = {} ({:+} from {}, tolerance {})", e.text,
                       e.var, *v, off, e.value, e.tolerance);
  }
  return fmt::format("expectation failed: {}: #{} was not read", e.text, e.var);
}

}  // namespace skipnc::run
