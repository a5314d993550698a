#include "config/dialect.hpp"

#include <algorithm>
#include <charconv>

#include "config/toml_util.hpp"
#include "core/embedded.hpp"

namespace skipnc::config {
namespace {

Result<canon::SignalAddr> parse_addr(const toml::node& n, std::string_view origin) {
  auto s = get_string(n, origin, "signal address");
  if (!s) return std::unexpected(s.error());
  const std::string& t = *s;
  canon::SignalAddr a;
  unsigned byte = 0, bit = 0;
  const auto dot = t.find('.');
  if (t.size() < 4 || dot == std::string::npos || (t[0] != 'X' && t[0] != 'G')) {
    return config_error(n, origin, "signal address '" + t + "' is not of the form X<byte>.<bit>");
  }
  auto r1 = std::from_chars(t.data() + 1, t.data() + dot, byte);
  auto r2 = std::from_chars(t.data() + dot + 1, t.data() + t.size(), bit);
  if (r1.ec != std::errc{} || r1.ptr != t.data() + dot || r2.ec != std::errc{} ||
      r2.ptr != t.data() + t.size() || bit > 7 || byte > 65535) {
    return config_error(n, origin, "signal address '" + t + "' is not of the form X<byte>.<bit>");
  }
  a.area = t[0];
  a.byte = static_cast<std::uint16_t>(byte);
  a.bit = static_cast<std::uint8_t>(bit);
  return a;
}

Result<void> load_switches(const toml::table& t, std::string_view origin, Switches& sw) {
  auto keys = check_keys(t,
                         {"skip_p_first", "skip_p_count", "skip_p_required_range", "skip_stop",
                          "skip_miss_alarm_default", "skip_active_at_start_ends",
                          "skip_edge_rising_only", "skip_feed", "skip_feed_param",
                          "skip_feed_switch_param", "skip_g53_allowed", "torque_skip",
                          "multi_step", "next_block_from_stop", "tool_position_offset",
                          "calculator_decimal_default", "macro_bracket_depth"},
                         origin, "[switches]");
  if (!keys) return keys;
  for (const auto& [key, node] : t) {
    const auto k = key.str();
    auto as_bool = [&](bool& out) -> Result<void> {
      auto b = get_bool(node, origin, k);
      if (!b) return std::unexpected(b.error());
      out = *b;
      return {};
    };
    auto as_int = [&](int& out, double lo, double hi) -> Result<void> {
      auto v = get_number(node, origin, k, lo, hi);
      if (!v) return std::unexpected(v.error());
      out = static_cast<int>(*v);
      return {};
    };
    Result<void> r;
    if (k == "skip_p_first") r = as_int(sw.skip_p_first, 0, 1);
    else if (k == "skip_p_count") r = as_int(sw.skip_p_count, 1, canon::SkipSpec::kMaxInputs);
    else if (k == "skip_p_required_range") r = as_bool(sw.skip_p_required_range);
    else if (k == "skip_miss_alarm_default") r = as_bool(sw.skip_miss_alarm_default);
    else if (k == "skip_active_at_start_ends") r = as_bool(sw.skip_active_at_start_ends);
    else if (k == "skip_edge_rising_only") r = as_bool(sw.skip_edge_rising_only);
    else if (k == "skip_feed_param") r = as_int(sw.skip_feed_param, 0, 99999);
    else if (k == "skip_feed_switch_param") r = as_int(sw.skip_feed_switch_param, 0, 99999);
    else if (k == "skip_g53_allowed") r = as_bool(sw.skip_g53_allowed);
    else if (k == "torque_skip") r = as_bool(sw.torque_skip);
    else if (k == "multi_step") r = as_bool(sw.multi_step);
    else if (k == "next_block_from_stop") r = as_bool(sw.next_block_from_stop);
    else if (k == "tool_position_offset") r = as_bool(sw.tool_position_offset);
    else if (k == "calculator_decimal_default") r = as_bool(sw.calculator_decimal_default);
    else if (k == "macro_bracket_depth") r = as_int(sw.macro_bracket_depth, 1, 64);
    else if (k == "skip_stop" || k == "skip_feed") {
      auto s = get_string(node, origin, k);
      if (!s) return std::unexpected(s.error());
      if (k == "skip_stop") {
        if (*s == "immediate") sw.skip_stop = canon::SkipStop::kImmediate;
        else if (*s == "decelerate") sw.skip_stop = canon::SkipStop::kDecelerate;
        else return config_error(node, origin, "skip_stop must be \"immediate\" or \"decelerate\"");
      } else {
        if (*s == "modal") sw.skip_feed = SkipFeedRule::kModal;
        else if (*s == "block_or_param") sw.skip_feed = SkipFeedRule::kBlockOrParam;
        else if (*s == "param_switch") sw.skip_feed = SkipFeedRule::kParamSwitch;
        else
          return config_error(node, origin,
                              "skip_feed must be \"modal\", \"block_or_param\" or \"param_switch\"");
      }
    }
    if (!r) return r;
  }
  return {};
}

Result<void> load_skip_vars(const toml::table& t, std::string_view origin, SkipVariables& v) {
  auto keys = check_keys(t, {"work_base", "machine_base", "named_machine", "named_local",
                             "success_flag"},
                         origin, "[skip_variables]");
  if (!keys) return keys;
  for (const auto& [key, node] : t) {
    const auto k = key.str();
    if (k == "named_machine" || k == "named_local") {
      auto s = get_string(node, origin, k);
      if (!s) return std::unexpected(s.error());
      (k == "named_machine" ? v.named_machine : v.named_local) = *s;
    } else {
      auto n = get_number(node, origin, k, 0, 99999);
      if (!n) return std::unexpected(n.error());
      const int i = static_cast<int>(*n);
      if (k == "work_base") v.work_base = i;
      else if (k == "machine_base") v.machine_base = i;
      else v.success_flag = i;
    }
  }
  return {};
}

Result<void> load_params(const toml::table& t, std::string_view origin,
                         std::vector<ParamDef>& out) {
  for (const auto& [key, node] : t) {
    int number = 0;
    const auto k = key.str();
    auto [p, ec] = std::from_chars(k.data(), k.data() + k.size(), number);
    if (ec != std::errc{} || p != k.data() + k.size()) {
      return config_error(node, origin, "parameter key '" + std::string(k) + "' is not a number");
    }
    const auto* tab = node.as_table();
    if (!tab) return config_error(node, origin, "parameter " + std::string(k) + " must be a table");
    auto keys = check_keys(*tab, {"name", "kind", "default", "min", "max", "text"}, origin,
                           "a parameter");
    if (!keys) return std::unexpected(keys.error());
    ParamDef d;
    d.number = number;
    for (const auto& [pk, pn] : *tab) {
      const auto s = pk.str();
      if (s == "name" || s == "text" || s == "kind") {
        auto v = get_string(pn, origin, s);
        if (!v) return std::unexpected(v.error());
        if (s == "name") d.name = *v;
        else if (s == "text") d.text = *v;
        else if (*v == "bits") d.kind = ParamKind::kBits;
        else if (*v == "int") d.kind = ParamKind::kInt;
        else if (*v == "real") d.kind = ParamKind::kReal;
        else return config_error(pn, origin, "kind must be \"bits\", \"int\" or \"real\"");
      } else {
        auto v = get_number(pn, origin, s, -1e300, 1e300);
        if (!v) return std::unexpected(v.error());
        if (s == "default") d.default_value = *v;
        else if (s == "min") d.min = *v;
        else d.max = *v;
      }
    }
    if (d.kind == ParamKind::kBits) {
      d.min = 0;
      d.max = 255;
    }
    out.erase(std::remove_if(out.begin(), out.end(),
                             [&](const ParamDef& e) { return e.number == d.number; }),
              out.end());
    out.push_back(std::move(d));
  }
  return {};
}

Result<void> load_alarms(const toml::table& t, std::string_view origin, Dialect& d) {
  for (const auto& [key, node] : t) {
    const AlarmId id = alarm_from_key(key.str());
    if (id == AlarmId::kCount) {
      return config_error(node, origin, "unknown alarm key '" + std::string(key.str()) + "'");
    }
    const auto* tab = node.as_table();
    if (!tab) return config_error(node, origin, "alarm entry must be a table");
    auto keys = check_keys(*tab, {"number", "code", "message"}, origin, "an alarm");
    if (!keys) return std::unexpected(keys.error());
    AlarmText& a = d.alarms[static_cast<std::size_t>(id)];
    if (const auto* n = tab->get("number")) {
      auto v = get_number(*n, origin, "number", 0, 1e9);
      if (!v) return std::unexpected(v.error());
      a.number = static_cast<int>(*v);
    }
    if (const auto* n = tab->get("code")) {
      auto v = get_string(*n, origin, "code");
      if (!v) return std::unexpected(v.error());
      a.code = *v;
    }
    if (const auto* n = tab->get("message")) {
      auto v = get_string(*n, origin, "message");
      if (!v) return std::unexpected(v.error());
      a.message = *v;
    }
  }
  return {};
}

Result<void> load_into(std::string_view text, std::string_view origin, Dialect& d, int depth) {
  auto parsed = parse_toml(text, origin);
  if (!parsed) return std::unexpected(parsed.error());
  const toml::table& t = *parsed;
  auto keys = check_keys(t,
                         {"name", "title", "inherits", "fixed_skip_inputs", "switches",
                          "skip_variables", "parameters", "alarms"},
                         origin, "a dialect file");
  if (!keys) return keys;
  if (const auto* inh = t.get("inherits")) {
    auto base = get_string(*inh, origin, "inherits");
    if (!base) return std::unexpected(base.error());
    if (depth > 4) return config_error(*inh, origin, "dialect inheritance is too deep");
    const EmbeddedFile* f = embedded_entry("dialects/" + *base + ".toml");
    if (!f) return config_error(*inh, origin, "unknown base dialect '" + *base + "'");
    auto r = load_into(f->content, f->path, d, depth + 1);
    if (!r) return r;
  }
  for (const auto& [key, node] : t) {
    const auto k = key.str();
    Result<void> r;
    if (k == "name" || k == "title") {
      auto s = get_string(node, origin, k);
      if (!s) return std::unexpected(s.error());
      (k == "name" ? d.name : d.title) = *s;
    } else if (k == "fixed_skip_inputs") {
      const auto* arr = node.as_array();
      if (!arr) return config_error(node, origin, "fixed_skip_inputs must be an array");
      d.fixed_skip_inputs.clear();
      for (const auto& e : *arr) {
        auto a = parse_addr(e, origin);
        if (!a) return std::unexpected(a.error());
        d.fixed_skip_inputs.push_back(*a);
      }
    } else if (k != "inherits") {
      const auto* tab = node.as_table();
      if (!tab) return config_error(node, origin, "[" + std::string(k) + "] must be a table");
      if (k == "switches") r = load_switches(*tab, origin, d.sw);
      else if (k == "skip_variables") r = load_skip_vars(*tab, origin, d.skip_vars);
      else if (k == "parameters") r = load_params(*tab, origin, d.params);
      else r = load_alarms(*tab, origin, d);
    }
    if (!r) return r;
  }
  return {};
}

}  // namespace

const ParamDef* Dialect::param(int number) const noexcept {
  for (const auto& p : params) {
    if (p.number == number) return &p;
  }
  return nullptr;
}

Result<Dialect> parse_dialect(std::string_view toml_text, std::string_view origin) {
  Dialect d;
  auto r = load_into(toml_text, origin, d, 0);
  if (!r) return std::unexpected(r.error());
  return d;
}

Result<Dialect> builtin_dialect(std::string_view name) {
  const EmbeddedFile* f = embedded_entry("dialects/" + std::string(name) + ".toml");
  if (!f || name == "base") {
    std::string known;
    for (const auto& n : builtin_dialect_names()) known += (known.empty() ? "" : ", ") + n;
    return fail(AlarmId::kUsage,
                "unknown dialect '" + std::string(name) + "' (known: " + known + ")");
  }
  return parse_dialect(f->content, f->path);
}

std::vector<std::string> builtin_dialect_names() {
  std::vector<std::string> names;
  for (const auto& f : embedded_files()) {
    if (f.path.starts_with("dialects/") && f.path != "dialects/base.toml") {
      std::string n(f.path.substr(9));
      n.resize(n.size() - 5);
      names.push_back(n);
    }
  }
  return names;
}

}  // namespace skipnc::config
