#include "config/dialect.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

#include "config/toml_util.hpp"
#include "core/embedded.hpp"

namespace skipnc::config {
namespace {

Result<canon::SignalAddr> parse_addr(const toml::node& n, std::string_view origin) {
  auto s = get_string(n, origin, "signal address");
  SKIPNC_TRY(s);
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

// A named choice of a string switch.
template <class E>
struct Choice {
  std::string_view text;
  E value;
};

template <class E, std::size_t N>
Result<void> choose(const toml::node& n, std::string_view origin, std::string_view key,
                    const Choice<E> (&choices)[N], E& out) {
  auto s = get_string(n, origin, key);
  SKIPNC_TRY(s);
  std::string known;
  for (const auto& c : choices) {
    if (c.text == *s) {
      out = c.value;
      return {};
    }
    known += (known.empty() ? "\"" : ", \"") + std::string(c.text) + "\"";
  }
  return config_error(n, origin, std::string(key) + " must be one of " + known);
}

struct IntKey {
  std::string_view key;
  int* out;
  double lo, hi;
};
struct BoolKey {
  std::string_view key;
  bool* out;
};

// The [switches] keys that are whole numbers, with their ranges.
std::vector<IntKey> int_keys(Switches& sw) {
  return {
      {"skip_p_first", &sw.skip_p_first, 0, 1},
      {"skip_p_count", &sw.skip_p_count, 1, canon::SkipSpec::kMaxInputs},
      {"skip_miss_param", &sw.skip_miss_param, 0, 99999},
      {"skip_signal_param", &sw.skip_signal_param, 0, 99999},
      {"skip_feed_param", &sw.skip_feed_param, 0, 99999},
      {"skip_feed_switch_param", &sw.skip_feed_switch_param, 0, 99999},
      {"torque_q_param", &sw.torque_q_param, 0, 99999},
      {"torque_delay_param", &sw.torque_delay_param, 0, 99999},
      {"sync_axes_param", &sw.sync_axes_param, 0, 99999},
      {"machine_lock_param", &sw.machine_lock_param, 0, 99999},
      {"z_cancel_param", &sw.z_cancel_param, 0, 99999},
      {"dry_run_feed_param", &sw.dry_run_feed_param, 0, 99999},
      {"block_delete_param", &sw.block_delete_param, 0, 99999},
      {"macro_bracket_depth", &sw.macro_bracket_depth, 1, 64},
      {"rapid_no_in_position_param", &sw.rapid_no_in_position_param, 0, 99999},
      {"skip_signal_param_inputs", &sw.skip_signal_param_inputs, 0, canon::SkipSpec::kMaxInputs},
      {"rapid_no_in_position_bit", &sw.rapid_no_in_position_bit, 0, 7},
      {"probe_invert_param", &sw.probe_invert_param, 0, 99999},
      {"call_levels", &sw.call_levels, 0, 1000},
  };
}

// The [switches] keys that are true or false.
std::vector<BoolKey> bool_keys(Switches& sw) {
  return {
      {"skip_k_word", &sw.skip_k_word},
      {"skip_active_at_start_ends", &sw.skip_active_at_start_ends},
      {"skip_edge_rising_only", &sw.skip_edge_rising_only},
      {"skip_requires_axis", &sw.skip_requires_axis},
      {"skip_g53_allowed", &sw.skip_g53_allowed},
      {"skip_ignored_when_locked", &sw.skip_ignored_when_locked},
      {"skip_locked_stores_command", &sw.skip_locked_stores_command},
      {"torque_skip", &sw.torque_skip},
      {"tool_position_offset", &sw.tool_position_offset},
      {"g_same_group_last_wins", &sw.g_same_group_last_wins},
      {"calculator_decimal_default", &sw.calculator_decimal_default},
      {"block_end_tool_offsets", &sw.block_end_tool_offsets},
      {"current_tool_offsets", &sw.current_tool_offsets},
      {"skip_tool_offsets", &sw.skip_tool_offsets},
      {"skip_position_increment", &sw.skip_position_increment},
      {"slash_comments", &sw.slash_comments},
      {"skip_g31", &sw.skip_g31},
      {"probe_g38", &sw.probe_g38},
      {"probe_report_line", &sw.probe_report_line},
      {"probe_latch_sampled", &sw.probe_latch_sampled},
      {"probe_latch_actual", &sw.probe_latch_actual},
      {"probe_same_point_all", &sw.probe_same_point_all},
      {"local_sub_call_m97", &sw.local_sub_call_m97},
      {"block_lookahead_g103", &sw.block_lookahead_g103},
      {"m99_p_jumps_in_subprogram", &sw.m99_p_jumps_in_subprogram},
      {"conditional_m99", &sw.conditional_m99},
      {"haas_tool_offset_vars", &sw.haas_tool_offset_vars},
  };
}

// The [switches] keys that name one of a few choices; `known` is set when `k`
// is one of them.
Result<void> choose_switch(const toml::node& node, std::string_view origin, std::string_view k,
                           Switches& sw, bool& known) {
  static constexpr Choice<Language> kLanguages[] = {
      {"macro_b", Language::kMacroB}, {"rs274ngc", Language::kRs274ngc}, {"grbl", Language::kGrbl}};
  static constexpr Choice<SkipPMode> kPModes[] = {{"multi_step", SkipPMode::kMultiStep},
                                                  {"select", SkipPMode::kSelect},
                                                  {"bitmask", SkipPMode::kBitmask},
                                                  {"none", SkipPMode::kNone}};
  static constexpr Choice<canon::SkipStop> kStops[] = {
      {"immediate", canon::SkipStop::kImmediate}, {"decelerate", canon::SkipStop::kDecelerate}};
  static constexpr Choice<SkipFeedRule> kFeeds[] = {{"modal", SkipFeedRule::kModal},
                                                    {"block_or_param", SkipFeedRule::kBlockOrParam},
                                                    {"param_switch", SkipFeedRule::kParamSwitch},
                                                    {"last_cutting", SkipFeedRule::kLastCutting}};
  static constexpr Choice<SkipOverride> kOverrides[] = {{"skf_param", SkipOverride::kSkfParam},
                                                        {"fixed", SkipOverride::kFixed},
                                                        {"normal", SkipOverride::kNormal}};
  static constexpr Choice<SkipAccel> kAccels[] = {{"skf_param", SkipAccel::kSkfParam},
                                                  {"never", SkipAccel::kNever},
                                                  {"always", SkipAccel::kAlways}};
  static constexpr Choice<OffsetVariables> kOffsetVars[] = {
      {"position", OffsetVariables::kPosition}, {"letter", OffsetVariables::kLetter}};
  known = true;
  if (k == "offset_variables_by")
    return choose(node, origin, k, kOffsetVars, sw.offset_variables_by);
  if (k == "skip_p_mode") return choose(node, origin, k, kPModes, sw.skip_p_mode);
  if (k == "skip_stop") return choose(node, origin, k, kStops, sw.skip_stop);
  if (k == "skip_feed") return choose(node, origin, k, kFeeds, sw.skip_feed);
  if (k == "skip_override") return choose(node, origin, k, kOverrides, sw.skip_override);
  if (k == "skip_accel") return choose(node, origin, k, kAccels, sw.skip_accel);
  if (k == "language") return choose(node, origin, k, kLanguages, sw.language);
  known = false;
  return {};
}

Result<void> load_switches(const toml::table& t, std::string_view origin, Switches& sw) {
  const std::vector<IntKey> ints = int_keys(sw);
  const std::vector<BoolKey> bools = bool_keys(sw);
  for (const auto& [key, node] : t) {
    const auto k = key.str();
    bool known = false;
    for (const auto& e : ints) {
      if (e.key != k) continue;
      known = true;
      auto v = get_number(node, origin, k, e.lo, e.hi);
      SKIPNC_TRY(v);
      if (*v != static_cast<double>(static_cast<int>(*v))) {
        return config_error(node, origin, std::string(k) + " must be a whole number");
      }
      *e.out = static_cast<int>(*v);
    }
    for (const auto& e : bools) {
      if (e.key != k) continue;
      known = true;
      auto b = get_bool(node, origin, k);
      SKIPNC_TRY(b);
      *e.out = *b;
    }
    if (known) continue;
    if (auto r = choose_switch(node, origin, k, sw, known); !r) return r;
    if (!known) {
      std::string list =
          "skip_p_mode, skip_stop, skip_feed, skip_override, skip_accel, language, "
          "offset_variables_by";
      for (const auto& e : ints) list += ", " + std::string(e.key);
      for (const auto& e : bools) list += ", " + std::string(e.key);
      return config_error(
          node, origin, "unknown key '" + std::string(k) + "' in [switches] (known: " + list + ")");
    }
  }
  return {};
}

Result<void> load_skip_vars(const toml::table& t, std::string_view origin, SkipVariables& v) {
  auto keys = check_keys(
      t, {"work_base", "machine_base", "named_machine", "named_local", "named_aux", "success_flag"},
      origin, "[skip_variables]");
  if (!keys) return keys;
  for (const auto& [key, node] : t) {
    const auto k = key.str();
    if (k == "named_machine" || k == "named_local" || k == "named_aux") {
      auto s = get_string(node, origin, k);
      SKIPNC_TRY(s);
      (k == "named_machine" ? v.named_machine
       : k == "named_local" ? v.named_local
                            : v.named_aux) = *s;
    } else {
      auto n = get_number(node, origin, k, 0, 99999);
      SKIPNC_TRY(n);
      const int i = static_cast<int>(*n);
      if (k == "work_base")
        v.work_base = i;
      else if (k == "machine_base")
        v.machine_base = i;
      else
        v.success_flag = i;
    }
  }
  return {};
}

Result<void> load_handshake(const toml::table& t, std::string_view origin, SkipHandshakeNames& h) {
  auto keys = check_keys(t, {"active", "skip", "recorded", "done"}, origin, "[skip_handshake]");
  if (!keys) return keys;
  for (const auto& [key, node] : t) {
    auto s = get_string(node, origin, key.str());
    SKIPNC_TRY(s);
    const auto k = key.str();
    (k == "active" ? h.active : k == "skip" ? h.skip : k == "recorded" ? h.recorded : h.done) = *s;
  }
  if (h.active.empty() || h.skip.empty() || h.recorded.empty() || h.done.empty()) {
    return config_error(t, origin, "[skip_handshake] needs active, skip, recorded and done");
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
    auto keys =
        check_keys(*tab, {"name", "kind", "default", "min", "max", "text"}, origin, "a parameter");
    SKIPNC_TRY(keys);
    ParamDef d;
    d.number = number;
    for (const auto& [pk, pn] : *tab) {
      const auto s = pk.str();
      if (s == "name" || s == "text" || s == "kind") {
        auto v = get_string(pn, origin, s);
        SKIPNC_TRY(v);
        if (s == "name")
          d.name = *v;
        else if (s == "text")
          d.text = *v;
        else if (*v == "bits")
          d.kind = ParamKind::kBits;
        else if (*v == "int")
          d.kind = ParamKind::kInt;
        else if (*v == "real")
          d.kind = ParamKind::kReal;
        else
          return config_error(pn, origin, "kind must be \"bits\", \"int\" or \"real\"");
      } else {
        auto v = get_number(pn, origin, s, -1e300, 1e300);
        SKIPNC_TRY(v);
        if (s == "default")
          d.default_value = *v;
        else if (s == "min")
          d.min = *v;
        else
          d.max = *v;
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
    SKIPNC_TRY(keys);
    AlarmText& a = d.alarms[static_cast<std::size_t>(id)];
    if (const auto* n = tab->get("number")) {
      auto v = get_number(*n, origin, "number", 0, 1e9);
      SKIPNC_TRY(v);
      a.number = static_cast<int>(*v);
    }
    if (const auto* n = tab->get("code")) {
      auto v = get_string(*n, origin, "code");
      SKIPNC_TRY(v);
      a.code = *v;
    }
    if (const auto* n = tab->get("message")) {
      auto v = get_string(*n, origin, "message");
      SKIPNC_TRY(v);
      a.message = *v;
    }
  }
  return {};
}

// [codes]: G and M codes the control does not have (absent_g, absent_m), and
// those it has that skipnc does not simulate (not_simulated_g, not_simulated_m).
Result<void> load_codes(const toml::table& t, std::string_view origin, Dialect& d) {
  auto keys = check_keys(t, {"absent_g", "not_simulated_g", "not_simulated_m", "absent_m"}, origin,
                         "[codes]");
  if (!keys) return keys;
  for (const auto& [key, node] : t) {
    const auto* arr = node.as_array();
    if (!arr) return config_error(node, origin, std::string(key.str()) + " must be an array");
    const bool m_codes = key.str() == "not_simulated_m" || key.str() == "absent_m";
    if (!m_codes) {
      std::vector<GCode>& out = key.str() == "absent_g" ? d.absent_g : d.not_simulated_g;
      out.clear();
      for (const auto& e : *arr) {
        const auto v = e.value<double>();
        const auto g = v && *v <= 999 ? GCode::of_value(*v) : std::nullopt;
        if (!g || std::round(*v * 10) != *v * 10) {
          return config_error(e, origin, "a G code such as 54 or 54.1");
        }
        out.push_back(*g);
      }
      continue;
    }
    std::vector<int>& out = key.str() == "absent_m" ? d.absent_m : d.not_simulated_m;
    out.clear();
    for (const auto& e : *arr) {
      const auto v = e.value<std::int64_t>();
      if (!v || *v < 0 || *v > 999) return config_error(e, origin, "an M code such as 66");
      out.push_back(static_cast<int>(*v));
    }
  }
  return {};
}

Result<void> load_into(std::string_view text, std::string_view origin, Dialect& d, int depth) {
  auto parsed = parse_toml(text, origin);
  SKIPNC_TRY(parsed);
  const toml::table& t = *parsed;
  auto keys = check_keys(t,
                         {"name", "title", "inherits", "fixed_skip_inputs", "switches",
                          "skip_variables", "skip_handshake", "parameters", "alarms", "codes"},
                         origin, "a dialect file");
  if (!keys) return keys;
  if (const auto* inh = t.get("inherits")) {
    auto base = get_string(*inh, origin, "inherits");
    SKIPNC_TRY(base);
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
      SKIPNC_TRY(s);
      (k == "name" ? d.name : d.title) = *s;
    } else if (k == "fixed_skip_inputs") {
      const auto* arr = node.as_array();
      if (!arr) return config_error(node, origin, "fixed_skip_inputs must be an array");
      d.fixed_skip_inputs.clear();
      for (const auto& e : *arr) {
        auto a = parse_addr(e, origin);
        SKIPNC_TRY(a);
        d.fixed_skip_inputs.push_back(*a);
      }
    } else if (k != "inherits") {
      const auto* tab = node.as_table();
      if (!tab) return config_error(node, origin, "[" + std::string(k) + "] must be a table");
      if (k == "switches")
        r = load_switches(*tab, origin, d.sw);
      else if (k == "skip_variables")
        r = load_skip_vars(*tab, origin, d.skip_vars);
      else if (k == "skip_handshake")
        r = load_handshake(*tab, origin, d.handshake);
      else if (k == "parameters")
        r = load_params(*tab, origin, d.params);
      else if (k == "codes")
        r = load_codes(*tab, origin, d);
      else
        r = load_alarms(*tab, origin, d);
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
  SKIPNC_TRY(r);
  // Every parameter a switch names must be a parameter of the dialect.
  const Switches& sw = d.sw;
  const std::pair<std::string_view, int> refs[] = {
      {"skip_miss_param", sw.skip_miss_param},
      {"skip_signal_param", sw.skip_signal_param},
      {"skip_feed_param", sw.skip_feed_param},
      {"skip_feed_switch_param", sw.skip_feed_switch_param},
      {"torque_q_param", sw.torque_q_param},
      {"torque_delay_param", sw.torque_delay_param},
      {"sync_axes_param", sw.sync_axes_param},
      {"machine_lock_param", sw.machine_lock_param},
      {"z_cancel_param", sw.z_cancel_param},
      {"dry_run_feed_param", sw.dry_run_feed_param},
      {"block_delete_param", sw.block_delete_param},
  };
  for (const auto& [key, number] : refs) {
    if (number != 0 && d.param(number) == nullptr) {
      return fail(AlarmId::kConfig, std::string(origin) + ": [switches] " + std::string(key) +
                                        " = " + std::to_string(number) + " is not in [parameters]");
    }
  }
  // block_or_param without a parameter: the block must have its F (Haas).
  if (sw.skip_feed == SkipFeedRule::kParamSwitch &&
      (sw.skip_feed_param == 0 || sw.skip_feed_switch_param == 0)) {
    return fail(AlarmId::kConfig,
                std::string(origin) +
                    ": skip_feed = param_switch needs skip_feed_param and skip_feed_switch_param");
  }
  if (sw.skip_p_mode != SkipPMode::kMultiStep && sw.skip_p_mode != SkipPMode::kNone &&
      d.fixed_skip_inputs.size() < static_cast<std::size_t>(sw.skip_p_count)) {
    return fail(AlarmId::kConfig, std::string(origin) + ": fixed_skip_inputs must list " +
                                      std::to_string(sw.skip_p_count) + " addresses");
  }
  if (d.fixed_skip_inputs.empty()) {
    return fail(AlarmId::kConfig, std::string(origin) + ": fixed_skip_inputs is empty");
  }
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
