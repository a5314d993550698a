#include "run/session.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>

#include "config/skip_inputs.hpp"
#include "config/warning_codes.hpp"
#include "report/report.hpp"

namespace skipnc::run {

Result<void> open_session(const SessionOptions& o, Session& s) {
  return open_session(o, SessionTexts{}, s);
}

Result<void> open_session(const SessionOptions& o, const SessionTexts& texts, Session& s) {
  std::error_code ec;
  const bool is_file = o.machine.find('/') != std::string::npos || o.machine.ends_with(".toml") ||
                       std::filesystem::is_regular_file(o.machine, ec);
  s.machine_file = o.machine;
  s.scene_file = o.scene;
  s.texts = texts;
  auto m = !s.texts.machine.empty() ? config::parse_machine(s.texts.machine, s.machine_file)
           : is_file                ? config::load_machine_file(s.machine_file)
                                    : config::builtin_machine(s.machine_file);
  SKIPNC_TRY(m);
  s.machine = std::move(*m);
  const std::string dname = o.dialect.empty() ? s.machine.dialect : o.dialect;
  auto d = config::builtin_dialect(dname);
  SKIPNC_TRY(d);
  s.dialect = std::move(*d);
  s.machine.dialect = dname;
  s.params = std::make_unique<config::Parameters>(&s.dialect);
  for (const auto& p : s.machine.params) {
    auto r = s.params->apply(p);
    if (!r) return r;
  }
  for (const auto& text : o.params) {
    auto setting = config::Parameters::parse_setting(text);
    SKIPNC_TRY(setting);
    auto r = s.params->apply(*setting);
    if (!r) {
      Error e = r.error();
      e.id = AlarmId::kUsage;
      e.detail = "--param " + text + ": " + e.detail;
      return std::unexpected(e);
    }
  }
  auto chk = config::check_skip_addresses(s.dialect, *s.params);
  if (!chk) return chk;
  if (!s.texts.scene.empty()) {
    auto sc = machine::parse_scene(s.texts.scene, s.scene_file, s.machine, s.dialect, *s.params);
    SKIPNC_TRY(sc);
    s.scene = std::move(*sc);
  } else if (!o.scene.empty()) {
    auto sc = machine::load_scene_file(s.scene_file, s.machine, s.dialect, *s.params);
    SKIPNC_TRY(sc);
    s.scene = std::move(*sc);
  }
  return {};
}

std::vector<std::string> allowed_warnings(const Session& s, const std::vector<std::string>& cli) {
  std::vector<std::string> out;
  for (const auto* list : {&cli, &s.scene.strict_allow}) {
    for (const auto& c : *list) {
      if (std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
    }
  }
  return out;
}

Result<void> check_allow(const std::vector<std::string>& cli) {
  for (const auto& c : cli) {
    if (!config::is_warning_code(c)) {
      return fail(AlarmId::kUsage, "--allow " + c + ": no warning has this code (codes: " +
                                       config::warning_code_list() + ")");
    }
  }
  return {};
}

Result<VarRef> parse_var_ref(const std::string& text) {
  VarRef v;
  std::string_view t = text;
  if (!t.empty() && t.front() == '#') t.remove_prefix(1);
  v.key = std::string(t);
  if (t.size() >= 2 && t.front() == '<' && t.back() == '>') {
    v.name = std::string(t.substr(1, t.size() - 2));
    return v;
  }
  auto r = std::from_chars(t.data(), t.data() + t.size(), v.number);
  if (r.ec != std::errc{} || r.ptr != t.data() + t.size() || v.number < 0) {
    return fail(AlarmId::kUsage,
                "--var " + text + ": expected a variable number (5061, #5061) or #<name>");
  }
  return v;
}

std::string describe(const Error& e, const config::Dialect* d) {
  const report::AlarmView v = report::view_alarm(e, d);
  std::string out;
  if (!e.loc.file.empty()) {
    out += std::string(e.loc.file);
    if (e.loc.line > 0) out += ":" + std::to_string(e.loc.line);
    if (e.loc.column > 0) out += ":" + std::to_string(e.loc.column);
    out += ": ";
  }
  if (e.id == AlarmId::kConfig || e.id == AlarmId::kUsage) {
    out += "error: " + e.detail;
  } else {
    out += "alarm " + v.code + " (" + std::to_string(v.number) + "): " + v.message;
  }
  return out;
}

}  // namespace skipnc::run
