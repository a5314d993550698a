#include "config/machine_config.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>

#include "config/machine_ini.hpp"
#include "config/toml_util.hpp"
#include "core/embedded.hpp"
#include "core/file.hpp"

namespace skipnc::config {
namespace {

// An [[axis]] table over `a` (the axis of the same name the file extends, or
// the defaults): only the keys it has change.
Result<AxisConfig> load_axis(const toml::table& t, std::string_view origin, AxisConfig a) {
  auto keys = check_keys(t,
                         {"name", "min", "max", "rapid", "max_feed", "accel", "kp", "feedforward",
                          "torque_per_mm", "torque_max"},
                         origin, "[[axis]]");
  SKIPNC_TRY(keys);
  const auto* name = t.get("name");
  if (!name) return config_error(t, origin, "[[axis]] needs a name (\"X\", \"Y\", ...)");
  auto s = get_string(*name, origin, "name");
  SKIPNC_TRY(s);
  if (s->size() != 1 || std::string_view("XYZABCUVW").find((*s)[0]) == std::string_view::npos) {
    return config_error(*name, origin, "axis name must be one of X Y Z A B C U V W");
  }
  a.name = (*s)[0];
  struct Field {
    std::string_view key;
    double* out;
    double min, max;
  };
  const Field fields[] = {
      {"min", &a.min_mm, -1e6, 1e6},
      {"max", &a.max_mm, -1e6, 1e6},
      {"rapid", &a.rapid_mm_min, 1e-3, 1e7},
      {"max_feed", &a.max_feed_mm_min, 1e-3, 1e7},
      {"accel", &a.accel_mm_s2, 1e-3, 1e7},
      {"kp", &a.kp_per_s, 0.0, 1e5},
      {"feedforward", &a.feedforward, 0.0, 1.0},
      {"torque_per_mm", &a.torque_pct_per_mm, 0, 1e9},
      {"torque_max", &a.torque_max_pct, 1, 1e4},
  };
  for (const auto& f : fields) {
    if (const auto* n = t.get(f.key)) {
      auto v = get_number(*n, origin, f.key, f.min, f.max);
      SKIPNC_TRY(v);
      *f.out = *v;
    }
  }
  if (a.min_mm >= a.max_mm) {
    return config_error(t, origin, std::string("axis ") + a.name + ": min must be below max");
  }
  return a;
}

// Axis values over `v`: the axes the table names change, the others keep
// what the extended file gave them.
Result<AxisVec> load_axis_values(const toml::node& node, const MachineConfig& m,
                                 std::string_view origin, std::string_view what, AxisVec v) {
  const auto* t = node.as_table();
  if (!t) return config_error(node, origin, std::string(what) + " must be a table of axis values");
  for (const auto& [key, n] : *t) {
    const int i = key.str().size() == 1 ? m.axis_index(key.str()[0]) : -1;
    if (i < 0) {
      return config_error(
          n, origin,
          std::string(what) + ": '" + std::string(key.str()) + "' is not an axis of this machine");
    }
    auto d = get_number(n, origin, key.str(), -1e6, 1e6);
    SKIPNC_TRY(d);
    v[i] = *d;
  }
  return v;
}

Result<void> load_offsets(const toml::table& t, MachineConfig& m, std::string_view origin) {
  static constexpr std::string_view kNames[] = {"EXT", "G54", "G55", "G56", "G57", "G58", "G59"};
  for (const auto& [key, node] : t) {
    int idx = -1;
    for (int i = 0; i < 7; ++i) {
      if (key.str() == kNames[i]) idx = i;
    }
    if (idx < 0) {
      return config_error(
          node, origin,
          "unknown work offset '" + std::string(key.str()) + "' (known: EXT, G54 ... G59)");
    }
    auto v =
        load_axis_values(node, m, origin, key.str(), m.work_offsets[static_cast<std::size_t>(idx)]);
    SKIPNC_TRY(v);
    m.work_offsets[static_cast<std::size_t>(idx)] = *v;
  }
  return {};
}

// [limits]: every key with its range. The ranges' upper ends are the sane
// maxima (issue 21): a value beyond them is a mistake (max_macro_levels =
// 1e12), refused with its file:line:column, never cast into an int.
struct LimitKey {
  std::string_view key;
  double min, max;
  bool whole;  // a count: a whole number
  void (*set)(MachineConfig&, double);
};
constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
template <auto Member>
constexpr void set_count(MachineConfig& m, double v) {
  using T = std::remove_reference_t<decltype(m.limits.*Member)>;
  m.limits.*Member = static_cast<T>(v);
}

constexpr LimitKey kLimitKeys[] = {
    // simulated seconds (about 3 years), kept as servo periods
    {"max_time_s", 1e-3, 1e8, false,
     [](MachineConfig& m, double v) {
       m.limits.max_ticks = static_cast<std::int64_t>(v * 1e9 / static_cast<double>(m.period_ns));
     }},
    {"max_macro_statements", 1, 1e12, true, set_count<&Limits::max_macro_statements>},
    {"max_macro_levels", 1, 100, true, set_count<&Limits::max_macro_levels>},  // Fanuc: 4 or 5
    {"max_subprogram_levels", 1, 100, true, set_count<&Limits::max_subprogram_levels>},  // 10, 15
    {"max_cpu_s", 1e-3, 1e6, false, set_count<&Limits::max_cpu_s>},
    {"max_trace_bytes", 1, 1024 * kGiB, true, set_count<&Limits::max_trace_bytes>},
    {"max_message_bytes", 1024, kGiB, true, set_count<&Limits::max_message_bytes>},
    {"max_dprnt_bytes", 1, kGiB, true, set_count<&Limits::max_dprnt_bytes>},
    {"max_named_variables", 1, 1e7, true, set_count<&Limits::max_named_variables>},
    {"max_label_index", 0, 1e8, true, set_count<&Limits::max_label_index>},
};

Result<void> load_limits(const toml::table& t, MachineConfig& m, std::string_view origin) {
  for (const auto& [key, node] : t) {
    const LimitKey* k = nullptr;
    for (const auto& c : kLimitKeys) k = c.key == key.str() ? &c : k;
    if (k == nullptr) {
      std::string list;
      for (const auto& c : kLimitKeys) list += (list.empty() ? "" : ", ") + std::string(c.key);
      return config_error(
          node, origin,
          "unknown key '" + std::string(key.str()) + "' in [limits] (known: " + list + ")");
    }
    auto v = get_number(node, origin, k->key, k->min, k->max);
    SKIPNC_TRY(v);
    if (k->whole && *v != std::trunc(*v)) {
      return config_error(node, origin, std::string(k->key) + " must be a whole number");
    }
    k->set(m, *v);
  }
  return {};
}

Result<void> load_tools(const toml::table& t, MachineConfig& m, std::string_view origin) {
  for (const auto& [key, node] : t) {
    int number = 0;
    const auto k = key.str();
    auto [p, ec] = std::from_chars(k.data(), k.data() + k.size(), number);
    if (ec != std::errc{} || p != k.data() + k.size() || number < 1 ||
        number > m.tool_offset_count) {
      return config_error(node, origin,
                          "tool offset number '" + std::string(k) + "' must be 1.." +
                              std::to_string(m.tool_offset_count));
    }
    const auto* tab = node.as_table();
    if (!tab) return config_error(node, origin, "tool offset must be a table");
    auto keys = check_keys(
        *tab,
        {"length", "length_wear", "radius", "radius_wear", "x", "z", "x_wear", "z_wear", "tip"},
        origin, "a tool offset");
    if (!keys) return keys;
    ToolOffset o = m.tool_offsets.contains(number) ? m.tool_offsets[number] : ToolOffset{};
    for (const auto& [tk, tn] : *tab) {
      const auto name = tk.str();
      if (name == "tip") {
        auto v = get_number(tn, origin, name, 0, 9);
        SKIPNC_TRY(v);
        if (*v != std::trunc(*v)) return config_error(tn, origin, "tip must be a whole number 0-9");
        o.tip = static_cast<int>(*v);
        continue;
      }
      auto v = get_number(tn, origin, name, -1e5, 1e5);
      SKIPNC_TRY(v);
      if (name == "length")
        o.length_geometry = *v;
      else if (name == "length_wear")
        o.length_wear = *v;
      else if (name == "radius")
        o.radius_geometry = *v;
      else if (name == "radius_wear")
        o.radius_wear = *v;
      else if (name == "x")
        o.x_geometry = *v;
      else if (name == "z")
        o.z_geometry = *v;
      else if (name == "x_wear")
        o.x_wear = *v;
      else
        o.z_wear = *v;
    }
    m.tool_offsets[number] = o;
  }
  return {};
}

}  // namespace

int MachineConfig::axis_index(char letter) const noexcept {
  for (std::size_t i = 0; i < axes.size(); ++i) {
    if (axes[i].name == letter) return static_cast<int>(i);
  }
  return -1;
}

namespace {

// How many files an `extends` chain may have: more is taken for a loop.
constexpr int kMaxExtendsDepth = 8;

Result<MachineConfig> parse_machine_at(std::string_view text, std::string_view origin, int depth);

// The machine a file extends: a built-in machine's name, or a machine file
// (relative to the folder of the file that names it). An error in that file
// is reported at the `extends` key, with the other file's place in words.
Result<MachineConfig> extended_machine(const toml::node& n, std::string_view origin, int depth) {
  auto name = get_string(n, origin, "extends");
  SKIPNC_TRY(name);
  if (depth >= kMaxExtendsDepth) {
    return config_error(n, origin,
                        "extends: more than " + std::to_string(kMaxExtendsDepth) +
                            " machine files extend each other (a loop?)");
  }
  const bool path = name->find('/') != std::string::npos || name->ends_with(".toml");
  const EmbeddedFile* builtin = path ? nullptr : embedded_entry("machines/" + *name + ".toml");
  Result<MachineConfig> base = std::unexpected(Error{});
  std::string where;
  if (builtin != nullptr) {
    base = parse_machine_at(builtin->content, builtin->path, depth + 1);
    where = "built-in " + *name;
  } else {
    std::filesystem::path file(*name);
    if (file.is_relative() && !origin.starts_with("machines/")) {
      // The folder of the file that names it, links followed (a golden
      // test's machine file is a link to an example's).
      std::error_code ec;
      auto real = std::filesystem::canonical(std::filesystem::path(origin), ec);
      if (ec) real = std::filesystem::path(origin);
      file = real.parent_path() / file;
    }
    where = file.lexically_normal().string();
    std::error_code exists_ec;
    if (!std::filesystem::exists(where, exists_ec)) {
      std::string known;
      for (const auto& b : builtin_machine_names()) known += (known.empty() ? "" : ", ") + b;
      return config_error(n, origin,
                          "extends: '" + *name + "' is neither a built-in machine (" + known +
                              ") nor a readable file ('" + where + "')");
    }
    auto text = read_input_file(where, kMachineFileInput);
    if (!text) return config_error(n, origin, "extends: " + text.error().detail);
    base = parse_machine_at(*text, where, depth + 1);
  }
  if (!base) {
    const Error& e = base.error();
    std::string at = where;
    if (e.loc.line > 0) at += ":" + std::to_string(e.loc.line) + ":" + std::to_string(e.loc.column);
    return config_error(n, origin, "extends " + *name + ": " + at + ": " + e.detail);
  }
  base->origin = where;
  return base;
}

// name, dialect and type.
Result<void> load_identity(const toml::table& t, std::string_view origin, MachineConfig& m) {
  if (const auto* n = t.get("name")) {
    auto s = get_string(*n, origin, "name");
    SKIPNC_TRY(s);
    m.name = *s;
  }
  if (const auto* n = t.get("dialect")) {
    auto s = get_string(*n, origin, "dialect");
    SKIPNC_TRY(s);
    m.dialect = *s;
  }
  if (const auto* n = t.get("type")) {
    auto s = get_string(*n, origin, "type");
    SKIPNC_TRY(s);
    if (*s == "mill")
      m.type = MachineType::kMill;
    else if (*s == "lathe")
      m.type = MachineType::kLathe;
    else
      return config_error(*n, origin, "type must be \"mill\" or \"lathe\"");
  }
  return {};
}

// The servo period, units, in-position check, spindle and persistent
// variables' file.
Result<void> load_scalars(const toml::table& t, std::string_view origin, MachineConfig& m) {
  if (const auto* n = t.get("spindle_max_rpm")) {
    auto v = get_number(*n, origin, "spindle_max_rpm", 1.0, 1e6);
    SKIPNC_TRY(v);
    m.spindle_max_rpm = *v;
  }
  if (const auto* n = t.get("servo_period_ms")) {
    auto v = get_number(*n, origin, "servo_period_ms", 0.0625, 100.0);
    SKIPNC_TRY(v);
    const std::int64_t before = m.period_ns;
    m.period_ns = static_cast<std::int64_t>(std::llround(*v * 1e6));
    // The time limit the extended machine set stays the same time.
    if (!m.extends.empty()) m.limits.max_ticks = m.limits.max_ticks * before / m.period_ns;
  }
  if (const auto* n = t.get("inch")) {
    auto v = get_bool(*n, origin, "inch");
    SKIPNC_TRY(v);
    m.inch_machine = *v;
  }
  if (const auto* n = t.get("in_position_mm")) {
    auto v = get_number(*n, origin, "in_position_mm", 1e-9, 10.0);
    SKIPNC_TRY(v);
    m.in_position_mm = *v;
  }
  if (const auto* n = t.get("in_position_timeout_s")) {
    auto v = get_number(*n, origin, "in_position_timeout_s", 0.001, 3600.0);
    SKIPNC_TRY(v);
    m.in_position_timeout_s = *v;
  }
  if (const auto* n = t.get("persistent_variables")) {
    auto s = get_string(*n, origin, "persistent_variables");
    SKIPNC_TRY(s);
    // Relative to the machine file's folder, as `extends` and meshes are (not
    // to the folder the command runs in).
    std::filesystem::path pv(*s);
    if (pv.is_relative() && !s->empty() && !origin.starts_with("machines/")) {
      pv = std::filesystem::path(origin).parent_path() / pv;
    }
    m.persistent_vars = pv.lexically_normal().string();
  }
  return {};
}

// [[axis]]: a name the extended machine has changes that axis; a new name
// adds an axis after the others.
Result<void> load_axes(const toml::table& t, std::string_view origin, MachineConfig& m) {
  const auto* axes = t.get("axis");
  if (axes == nullptr && m.axes.empty()) {
    return config_error(t, origin, "a machine needs at least one [[axis]]");
  }
  if (axes != nullptr && (!axes->as_array() || axes->as_array()->empty())) {
    return config_error(*axes, origin, "a machine needs at least one [[axis]]");
  }
  std::vector<bool> seen(m.axes.size(), false);
  static const toml::array kNoAxes;
  for (const auto& e : axes != nullptr ? *axes->as_array() : kNoAxes) {
    const auto* at = e.as_table();
    if (!at) return config_error(e, origin, "[[axis]] must be a table");
    int existing = -1;
    if (const auto* nm = at->get("name");
        nm != nullptr && nm->value<std::string>() && nm->value<std::string>()->size() == 1) {
      existing = m.axis_index((*nm->value<std::string>())[0]);
    }
    if (existing >= 0 && seen[static_cast<std::size_t>(existing)]) {
      return config_error(e, origin,
                          std::string("axis ") + m.axes[static_cast<std::size_t>(existing)].name +
                              " is defined twice");
    }
    auto a = load_axis(*at, origin,
                       existing >= 0 ? m.axes[static_cast<std::size_t>(existing)] : AxisConfig{});
    SKIPNC_TRY(a);
    if (m.lathe() && a->name != 'X' && a->name != 'Z' && a->name != 'C') {
      // G-code system A: U, W and H are the incremental X, Z and C.
      return config_error(e, origin,
                          std::string("axis ") + a->name + ": a lathe has X, Z and optionally C");
    }
    if (existing >= 0) {
      m.axes[static_cast<std::size_t>(existing)] = *a;
      seen[static_cast<std::size_t>(existing)] = true;
      continue;
    }
    if (m.axes.size() == static_cast<std::size_t>(kMaxAxes)) {
      return config_error(e, origin, "at most " + std::to_string(kMaxAxes) + " axes");
    }
    m.axes.push_back(*a);
    seen.push_back(true);
  }
  for (const auto& a : m.axes) {
    if (m.lathe() && a.name != 'X' && a.name != 'Z' && a.name != 'C') {
      return config_error(axes != nullptr ? *axes : static_cast<const toml::node&>(t), origin,
                          std::string("axis ") + a.name + ": a lathe has X, Z and optionally C");
    }
  }
  if (m.lathe() && (m.axis_index('X') < 0 || m.axis_index('Z') < 0)) {
    return config_error(axes != nullptr ? *axes : static_cast<const toml::node&>(t), origin,
                        "a lathe needs an X and a Z axis");
  }
  return {};
}

// [latch]: the latch mode, its delay, servo-delay compensation.
Result<void> load_latch(const toml::node& n, std::string_view origin, MachineConfig& m) {
  const auto* lt = n.as_table();
  if (!lt) return config_error(n, origin, "[latch] must be a table");
  auto k = check_keys(*lt, {"mode", "delay_ms", "servo_delay_compensation"}, origin, "[latch]");
  SKIPNC_TRY(k);
  if (const auto* mode = lt->get("mode")) {
    auto s = get_string(*mode, origin, "mode");
    SKIPNC_TRY(s);
    if (*s == "exact")
      m.latch = canon::SkipLatch::kExact;
    else if (*s == "sampled")
      m.latch = canon::SkipLatch::kSampled;
    else
      return config_error(*mode, origin, "latch mode must be \"exact\" or \"sampled\"");
  }
  if (const auto* d = lt->get("delay_ms")) {
    auto v = get_number(*d, origin, "delay_ms", 0.0, 1000.0);
    SKIPNC_TRY(v);
    m.latch_delay_s = *v * 1e-3;
  }
  if (const auto* c = lt->get("servo_delay_compensation")) {
    auto v = get_bool(*c, origin, "servo_delay_compensation");
    SKIPNC_TRY(v);
    m.servo_delay_comp = *v;
  }
  return {};
}

// [parameters]: kept as text "N" or "N#B" = value; checked against the
// dialect when the run is set up (the dialect may be overridden on the
// command line).
Result<void> load_params(const toml::node& n, std::string_view origin, MachineConfig& m) {
  const auto* pt = n.as_table();
  if (!pt) return config_error(n, origin, "[parameters] must be a table");
  for (const auto& [key, node] : *pt) {
    auto v = get_number(node, origin, key.str(), -1e300, 1e300);
    SKIPNC_TRY(v);
    const auto k = key.str();
    int number = 0, bit = -1;
    const auto hash = k.find('#');
    auto r = std::from_chars(k.data(),
                             k.data() + (hash == std::string_view::npos ? k.size() : hash), number);
    bool ok = r.ec == std::errc{} &&
              r.ptr == k.data() + (hash == std::string_view::npos ? k.size() : hash);
    if (ok && hash != std::string_view::npos) {
      auto r2 = std::from_chars(k.data() + hash + 1, k.data() + k.size(), bit);
      ok = r2.ec == std::errc{} && r2.ptr == k.data() + k.size() && bit >= 0 && bit <= 7 &&
           (*v == 0 || *v == 1);
    }
    if (!ok || number <= 0) {
      return config_error(node, origin,
                          "parameter '" + std::string(k) + "' must be N = value or N#B = 0/1");
    }
    m.params.push_back(ParamSetting{number, bit, *v, loc_of(node, origin)});
  }
  return {};
}

// [reference_points]: G30 P2-P4, the 2nd-4th reference points, machine
// coordinates (Fanuc parameters 1241-1243).
Result<void> load_reference_points(const toml::node& n, std::string_view origin, MachineConfig& m) {
  const auto* rt = n.as_table();
  if (!rt) return config_error(n, origin, "[reference_points] must be a table");
  for (const auto& [key, node] : *rt) {
    const auto k = key.str();
    const int idx = k == "P2" ? 0 : k == "P3" ? 1 : k == "P4" ? 2 : -1;
    if (idx < 0) {
      return config_error(node, origin,
                          "unknown reference point '" + std::string(k) + "' (known: P2, P3, P4)");
    }
    auto v =
        load_axis_values(node, m, origin, k, m.reference_points[static_cast<std::size_t>(idx)]);
    SKIPNC_TRY(v);
    m.reference_points[static_cast<std::size_t>(idx)] = *v;
  }
  return {};
}

Result<MachineConfig> parse_machine_at(std::string_view text, std::string_view origin, int depth) {
  auto parsed = parse_toml(text, origin);
  SKIPNC_TRY(parsed);
  const toml::table& t = *parsed;
  auto keys = check_keys(
      t,
      {"extends", "name", "type", "dialect", "servo_period_ms", "inch", "in_position_mm",
       "in_position_timeout_s", "spindle_max_rpm", "persistent_variables", "latch", "axis",
       "parameters", "work_offsets", "tool_offsets", "limits", "reference_points", "ini", "hal"},
      origin, "a machine file");
  SKIPNC_TRY(keys);
  MachineConfig m;
  if (const auto* n = t.get("extends")) {
    auto base = extended_machine(*n, origin, depth);
    SKIPNC_TRY(base);
    m = std::move(*base);
    m.extends = m.origin;
    if (!m.origin.starts_with("built-in "))
      m.extends_files.insert(m.extends_files.begin(), m.origin);
  }
  m.origin = std::string(origin);
  SKIPNC_TRY(load_identity(t, origin, m));
  SKIPNC_TRY(load_scalars(t, origin, m));
  SKIPNC_TRY(load_axes(t, origin, m));
  if (const auto* n = t.get("latch")) {
    SKIPNC_TRY(load_latch(*n, origin, m));
  }
  SKIPNC_TRY(load_ini_hal(t, m, origin));
  if (const auto* n = t.get("parameters")) {
    SKIPNC_TRY(load_params(*n, origin, m));
  }
  if (const auto* n = t.get("work_offsets")) {
    const auto* wt = n->as_table();
    if (!wt) return config_error(*n, origin, "[work_offsets] must be a table");
    auto r = load_offsets(*wt, m, origin);
    SKIPNC_TRY(r);
  }
  if (const auto* n = t.get("reference_points")) {
    SKIPNC_TRY(load_reference_points(*n, origin, m));
  }
  if (const auto* n = t.get("tool_offsets")) {
    const auto* tt = n->as_table();
    if (!tt) return config_error(*n, origin, "[tool_offsets] must be a table");
    auto r = load_tools(*tt, m, origin);
    SKIPNC_TRY(r);
  }
  if (const auto* n = t.get("limits")) {
    const auto* lt = n->as_table();
    if (!lt) return config_error(*n, origin, "[limits] must be a table");
    auto r = load_limits(*lt, m, origin);
    SKIPNC_TRY(r);
  }
  return m;
}

}  // namespace

Result<MachineConfig> parse_machine(std::string_view text, std::string_view origin) {
  return parse_machine_at(text, origin, 0);
}

Result<MachineConfig> load_machine_file(const std::string& path) {
  auto text = read_input_file(path, kMachineFileInput);
  if (!text) return fail(AlarmId::kConfig, text.error().detail);
  return parse_machine(*text, path);
}

Result<MachineConfig> builtin_machine(std::string_view name) {
  const EmbeddedFile* f = embedded_entry("machines/" + std::string(name) + ".toml");
  if (!f) {
    std::string known;
    for (const auto& n : builtin_machine_names()) known += (known.empty() ? "" : ", ") + n;
    return fail(AlarmId::kUsage, "no machine file or built-in machine '" + std::string(name) +
                                     "' (built-in: " + known + ")");
  }
  auto m = parse_machine(f->content, f->path);
  if (m) m->origin = "built-in " + std::string(name);
  return m;
}

std::vector<std::string> builtin_machine_names() {
  std::vector<std::string> names;
  for (const auto& f : embedded_files()) {
    if (f.path.starts_with("machines/")) {
      std::string n(f.path.substr(9));
      n.resize(n.size() - 5);
      names.push_back(n);
    }
  }
  return names;
}

}  // namespace skipnc::config
