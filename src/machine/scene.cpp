#include "machine/scene.hpp"

#include <fstream>
#include <sstream>

#include "config/skip_inputs.hpp"
#include "config/toml_util.hpp"
#include "config/warning_codes.hpp"
#include "core/file.hpp"
#include "machine/scene_toml.hpp"

namespace skipnc::machine {

using config::check_keys;
using config::config_error;
using config::get_number;
using config::get_string;

namespace {

Result<int> axis_of(const toml::table& t, std::string_view origin, const config::MachineConfig& m) {
  const auto* n = t.get("axis");
  if (!n) return config_error(t, origin, "needs axis = \"X\" (a machine axis)");
  auto s = get_string(*n, origin, "axis");
  if (!s) return std::unexpected(s.error());
  const int i = s->size() == 1 ? m.axis_index((*s)[0]) : -1;
  if (i < 0) return config_error(*n, origin, "axis '" + *s + "' is not an axis of this machine");
  return i;
}

Result<bool> direction_of(const toml::table& t, std::string_view origin) {
  const auto* n = t.get("direction");
  if (!n) return config_error(t, origin, "needs direction = \"decreasing\" or \"increasing\"");
  auto s = get_string(*n, origin, "direction");
  if (!s) return std::unexpected(s.error());
  if (*s == "decreasing") return true;
  if (*s == "increasing") return false;
  return config_error(*n, origin, "direction must be \"decreasing\" or \"increasing\"");
}

Result<double> number_of(const toml::table& t, std::string_view key, std::string_view origin,
                         double min, double max) {
  const auto* n = t.get(key);
  if (!n) return config_error(t, origin, "needs " + std::string(key));
  return get_number(*n, origin, key, min, max);
}

// [strict] allow = ["probe_length_differs", ...]: warnings that stay
// warnings under --strict, as `--allow CODE` (docs/scene.md).
Result<std::vector<std::string>> parse_strict(const toml::table& root, std::string_view origin) {
  std::vector<std::string> out;
  const toml::node* n = root.get("strict");
  if (n == nullptr) return out;
  const toml::table* t = n->as_table();
  if (t == nullptr) return config_error(*n, origin, "[strict] must be a table");
  if (auto k = check_keys(*t, {"allow"}, origin, "[strict]"); !k) return std::unexpected(k.error());
  const toml::node* a = t->get("allow");
  if (a == nullptr) return out;
  const toml::array* arr = a->as_array();
  if (arr == nullptr) return config_error(*a, origin, "allow must be an array of warning codes");
  for (const auto& e : *arr) {
    auto code = config::get_string(e, origin, "allow's element");
    if (!code) return std::unexpected(code.error());
    if (!config::is_warning_code(*code)) {
      return config_error(e, origin,
                          "allow: no warning has the code '" + *code +
                              "' (codes: " + config::warning_code_list() + ")");
    }
    out.push_back(*code);
  }
  return out;
}

}  // namespace

Result<Scene> parse_scene(std::string_view text, std::string_view origin,
                          const config::MachineConfig& m, const config::Dialect& d,
                          const config::Parameters& p) {
  auto parsed = config::parse_toml(text, origin);
  if (!parsed) return std::unexpected(parsed.error());
  const toml::table& root = *parsed;
  auto keys = check_keys(
      root, {"trigger", "pulse",        "stop",  "load",   "operator", "box",   "cylinder",
             "sphere",  "plane",        "bore",  "pocket", "probe",    "tool",  "tool_setter",
             "gauge",   "spindle_tool", "frame", "mesh",   "stock",    "strict"},
      origin, "a scene file");
  if (!keys) return std::unexpected(keys.error());
  Scene s;
  s.origin = std::string(origin);
  auto r = config::each_table(root, "trigger", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"signal", "axis", "at", "direction"}, origin, "[[trigger]]");
    if (!k) return k;
    Trigger tr;
    auto sig = scene_signal(t, origin, d, p, tr.signal_name);
    if (!sig) return std::unexpected(sig.error());
    tr.signal = *sig;
    auto ax = axis_of(t, origin, m);
    if (!ax) return std::unexpected(ax.error());
    tr.axis = *ax;
    auto at = number_of(t, "at", origin, -1e6, 1e6);
    if (!at) return std::unexpected(at.error());
    tr.at = *at;
    auto dir = direction_of(t, origin);
    if (!dir) return std::unexpected(dir.error());
    tr.decreasing = *dir;
    s.triggers.push_back(tr);
    return {};
  });
  if (!r) return std::unexpected(r.error());
  r = config::each_table(root, "pulse", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"signal", "at_time", "duration"}, origin, "[[pulse]]");
    if (!k) return k;
    Pulse pu;
    auto sig = scene_signal(t, origin, d, p, pu.signal_name);
    if (!sig) return std::unexpected(sig.error());
    pu.signal = *sig;
    auto at = number_of(t, "at_time", origin, 0.0, 1e9);
    if (!at) return std::unexpected(at.error());
    pu.at_time_s = *at;
    auto dur = number_of(t, "duration", origin, 0.0, 1e9);
    if (!dur) return std::unexpected(dur.error());
    pu.duration_s = *dur;
    s.pulses.push_back(pu);
    return {};
  });
  if (!r) return std::unexpected(r.error());
  r = config::each_table(root, "stop", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"axis", "at", "direction"}, origin, "[[stop]]");
    if (!k) return k;
    Stop st;
    auto ax = axis_of(t, origin, m);
    if (!ax) return std::unexpected(ax.error());
    st.axis = *ax;
    auto at = number_of(t, "at", origin, -1e6, 1e6);
    if (!at) return std::unexpected(at.error());
    st.at = *at;
    auto dir = direction_of(t, origin);
    if (!dir) return std::unexpected(dir.error());
    st.decreasing = *dir;
    s.stops.push_back(st);
    return {};
  });
  if (!r) return std::unexpected(r.error());
  r = parse_scene_actions(root, origin, m, s);
  if (!r) return std::unexpected(r.error());
  auto probing = parse_probing(root, origin, m, d, p);
  if (!probing) return std::unexpected(probing.error());
  s.probing = std::move(*probing);
  auto allow = parse_strict(root, origin);
  if (!allow) return std::unexpected(allow.error());
  s.strict_allow = std::move(*allow);
  return s;
}

Result<Scene> load_scene_file(const std::string& path, const config::MachineConfig& m,
                              const config::Dialect& d, const config::Parameters& p) {
  auto text = read_input_file(path, kSceneFileInput);
  if (!text) return fail(AlarmId::kConfig, text.error().detail);
  return parse_scene(*text, path, m, d, p);
}

}  // namespace skipnc::machine
