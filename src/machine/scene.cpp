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
  SKIPNC_TRY(s);
  const int i = s->size() == 1 ? m.axis_index((*s)[0]) : -1;
  if (i < 0) return config_error(*n, origin, "axis '" + *s + "' is not an axis of this machine");
  return i;
}

Result<bool> direction_of(const toml::table& t, std::string_view origin) {
  const auto* n = t.get("direction");
  if (!n) return config_error(t, origin, "needs direction = \"decreasing\" or \"increasing\"");
  auto s = get_string(*n, origin, "direction");
  SKIPNC_TRY(s);
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
  SKIPNC_TRY(check_keys(*t, {"allow"}, origin, "[strict]"));
  const toml::node* a = t->get("allow");
  if (a == nullptr) return out;
  const toml::array* arr = a->as_array();
  if (arr == nullptr) return config_error(*a, origin, "allow must be an array of warning codes");
  for (const auto& e : *arr) {
    auto code = config::get_string(e, origin, "allow's element");
    SKIPNC_TRY(code);
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
  SKIPNC_TRY(parsed);
  const toml::table& root = *parsed;
  auto keys = check_keys(
      root, {"trigger", "pulse",        "stop",  "load",   "operator", "box",   "cylinder",
             "sphere",  "plane",        "bore",  "pocket", "probe",    "tool",  "tool_setter",
             "gauge",   "spindle_tool", "frame", "mesh",   "stock",    "strict"},
      origin, "a scene file");
  SKIPNC_TRY(keys);
  Scene s;
  s.origin = std::string(origin);
  auto r = config::each_table(root, "trigger", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"signal", "axis", "at", "direction"}, origin, "[[trigger]]");
    if (!k) return k;
    Trigger tr;
    auto sig = scene_signal(t, origin, d, p, tr.signal_name);
    SKIPNC_TRY(sig);
    tr.signal = *sig;
    auto ax = axis_of(t, origin, m);
    SKIPNC_TRY(ax);
    tr.axis = *ax;
    auto at = number_of(t, "at", origin, -1e6, 1e6);
    SKIPNC_TRY(at);
    tr.at = *at;
    auto dir = direction_of(t, origin);
    SKIPNC_TRY(dir);
    tr.decreasing = *dir;
    s.triggers.push_back(tr);
    return {};
  });
  SKIPNC_TRY(r);
  r = config::each_table(root, "pulse", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"signal", "at_time", "duration"}, origin, "[[pulse]]");
    if (!k) return k;
    Pulse pu;
    auto sig = scene_signal(t, origin, d, p, pu.signal_name);
    SKIPNC_TRY(sig);
    pu.signal = *sig;
    auto at = number_of(t, "at_time", origin, 0.0, 1e9);
    SKIPNC_TRY(at);
    pu.at_time_s = *at;
    auto dur = number_of(t, "duration", origin, 0.0, 1e9);
    SKIPNC_TRY(dur);
    pu.duration_s = *dur;
    s.pulses.push_back(pu);
    return {};
  });
  SKIPNC_TRY(r);
  r = config::each_table(root, "stop", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"axis", "at", "direction"}, origin, "[[stop]]");
    if (!k) return k;
    Stop st;
    auto ax = axis_of(t, origin, m);
    SKIPNC_TRY(ax);
    st.axis = *ax;
    auto at = number_of(t, "at", origin, -1e6, 1e6);
    SKIPNC_TRY(at);
    st.at = *at;
    auto dir = direction_of(t, origin);
    SKIPNC_TRY(dir);
    st.decreasing = *dir;
    s.stops.push_back(st);
    return {};
  });
  SKIPNC_TRY(r);
  r = parse_scene_actions(root, origin, m, s);
  SKIPNC_TRY(r);
  auto probing = parse_probing(root, origin, m, d, p);
  SKIPNC_TRY(probing);
  s.probing = std::move(*probing);
  auto allow = parse_strict(root, origin);
  SKIPNC_TRY(allow);
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
