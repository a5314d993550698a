#include "run/expect.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace skipnc::run {
namespace {

constexpr const char* kForms =
    "expected #N=VALUE[+-TOLERANCE], #<name>=VALUE[+-TOLERANCE], #N=vacant, "
    "status=completed|alarm|interrupted or alarm=NUMBER|CODE|KEY";

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
    e.kind = Expectation::Kind::kAlarm;
    if (std::isdigit(static_cast<unsigned char>(rhs.front())) != 0) {
      const auto r = std::from_chars(rhs.data(), rhs.data() + rhs.size(), e.alarm);
      if (r.ec != std::errc{} || r.ptr != rhs.data() + rhs.size() || e.alarm <= 0) {
        return std::unexpected(bad(text, "the alarm is a number, a code or a key"));
      }
      return e;
    }
    // A code (SN9061, PS0015) or a key (probe_crash): letters, digits, '_'.
    for (char c : rhs) {
      if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_') {
        return std::unexpected(bad(text, "the alarm is a number, a code or a key"));
      }
    }
    e.alarm_name = rhs;
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

namespace {

bool same_word(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  }
  return true;
}

std::string alarm_text(const ObservedRun& o) {
  if (o.alarm == 0 && o.alarm_code.empty()) return "no alarm";
  return fmt::format("alarm {} {} ({})", o.alarm, o.alarm_code, o.alarm_key);
}

void evaluate_variable(const Expectation& e, const ObservedRun& o, ExpectResult& r) {
  r.name = "#" + e.var;
  if (e.vacant) {
    r.expected_text = "vacant";
  } else {
    r.expected = e.value;
    r.tolerance = e.tolerance;
  }
  for (const auto& [key, v] : o.variables) {
    if (key != e.var) continue;
    r.value = v;
    if (!v) r.value_text = "vacant";
    if (e.vacant) {
      r.pass = !v;
      if (!r.pass) r.message = fmt::format("expectation failed: {}: #{} = {}", e.text, e.var, *v);
      return;
    }
    if (!v) {
      r.message = fmt::format("expectation failed: {}: #{} is vacant", e.text, e.var);
      return;
    }
    const double off = *v - e.value;
    r.pass = std::fabs(off) <= e.tolerance + 1e-12;
    if (!r.pass) {
      r.message = fmt::format("expectation failed: {}: #{} = {} ({:+} from {}, tolerance {})",
                              e.text, e.var, *v, off, e.value, e.tolerance);
    }
    return;
  }
  r.message = fmt::format("expectation failed: {}: #{} was not read", e.text, e.var);
}

}  // namespace

Result<void> check_alarm_name(const Expectation& e, const config::Dialect& d) {
  if (e.kind != Expectation::Kind::kAlarm || e.alarm_name.empty()) return {};
  for (std::size_t i = 0; i < static_cast<std::size_t>(AlarmId::kCount); ++i) {
    const auto id = static_cast<AlarmId>(i);
    if (same_word(d.alarm(id).code, e.alarm_name) ||
        same_word(std::string(alarm_key(id)), e.alarm_name))
      return {};
  }
  // A user alarm (#3000 = n) is shown with its own code, the dialect's
  // prefix and n in four digits (MC0001: report::view_alarm).
  const std::string& user = d.alarm(AlarmId::kUserAlarm).code;
  const std::string prefix = user.empty() ? std::string("MC") : user;
  const std::string& n = e.alarm_name;
  if (n.size() == prefix.size() + 4 && same_word(n.substr(0, prefix.size()), prefix) &&
      std::all_of(n.begin() + static_cast<std::ptrdiff_t>(prefix.size()), n.end(),
                  [](char c) { return c >= '0' && c <= '9'; }))
    return {};
  return std::unexpected(bad(
      e.text, "no alarm of the " + d.name + " dialect has the code or key '" + e.alarm_name + "'"));
}

ExpectResult evaluate_expectation(const Expectation& e, const ObservedRun& o) {
  ExpectResult r;
  r.text = e.text;
  switch (e.kind) {
    case Expectation::Kind::kStatus:
      r.name = "status";
      r.expected_text = e.status;
      r.value_text = o.status;
      r.pass = o.status == e.status;
      if (!r.pass) {
        r.message = fmt::format("expectation failed: {}: the run ended {}", e.text,
                                o.status == "alarm" ? "in " + alarm_text(o) : o.status);
      }
      return r;
    case Expectation::Kind::kAlarm:
      r.name = "alarm";
      if (e.alarm > 0) {
        r.expected = e.alarm;
        r.pass = o.alarm == e.alarm;
      } else {
        r.expected_text = e.alarm_name;
        r.pass = (!o.alarm_code.empty() && same_word(o.alarm_code, e.alarm_name)) ||
                 (!o.alarm_key.empty() && same_word(o.alarm_key, e.alarm_name));
      }
      // The run's alarm in the form asked for: its number, or its code.
      if (e.alarm > 0 && o.alarm != 0) r.value = o.alarm;
      r.value_text = o.alarm_code.empty() ? std::string("none") : o.alarm_code;
      if (!r.pass) r.message = fmt::format("expectation failed: {}: {}", e.text, alarm_text(o));
      return r;
    case Expectation::Kind::kVariable:
      break;
  }
  evaluate_variable(e, o, r);
  return r;
}

std::string check_expectation(const Expectation& e, const ObservedRun& o) {
  return evaluate_expectation(e, o).message;
}

}  // namespace skipnc::run
