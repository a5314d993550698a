#include <algorithm>

#include "config/toml_util.hpp"
#include "machine/scene_toml.hpp"

namespace skipnc::machine {

using config::check_keys;
using config::config_error;
using config::get_bool;
using config::get_number;
using config::get_string;

namespace {

Result<double> need_number(const toml::table& t, std::string_view key, std::string_view origin,
                           double lo, double hi) {
  const auto* n = t.get(key);
  if (n == nullptr) return config_error(t, origin, "needs " + std::string(key));
  return get_number(*n, origin, key, lo, hi);
}

}  // namespace

Result<void> parse_scene_actions(const toml::table& root, std::string_view origin,
                                 const config::MachineConfig& m, Scene& s) {
  auto r = config::each_table(root, "load", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"axis", "at_time", "duration", "torque"}, origin, "[[load]]");
    if (!k) return k;
    Load l;
    const auto* an = t.get("axis");
    if (an == nullptr) return config_error(t, origin, "needs axis = \"X\" (a machine axis)");
    auto a = get_string(*an, origin, "axis");
    SKIPNC_TRY(a);
    l.axis = a->size() == 1 ? m.axis_index((*a)[0]) : -1;
    if (l.axis < 0)
      return config_error(*an, origin, "axis '" + *a + "' is not an axis of this machine");
    auto at = need_number(t, "at_time", origin, 0.0, 1e9);
    SKIPNC_TRY(at);
    auto dur = need_number(t, "duration", origin, 0.0, 1e9);
    SKIPNC_TRY(dur);
    auto tq = need_number(t, "torque", origin, -1e4, 1e4);
    SKIPNC_TRY(tq);
    l.at_time_s = *at;
    l.duration_s = *dur;
    l.torque_pct = *tq;
    s.loads.push_back(l);
    return {};
  });
  if (!r) return r;
  r = config::each_table(root, "operator", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"at_time", "feed_hold", "interlock", "override", "dry_run"}, origin,
                        "[[operator]]");
    if (!k) return k;
    OperatorAction op;
    auto at = need_number(t, "at_time", origin, 0.0, 1e9);
    SKIPNC_TRY(at);
    op.at_time_s = *at;
    for (auto [key, out] :
         {std::pair<std::string_view, std::optional<bool>*>{"feed_hold", &op.feed_hold},
          {"interlock", &op.interlock},
          {"dry_run", &op.dry_run}}) {
      if (const auto* n = t.get(key)) {
        auto b = get_bool(*n, origin, key);
        SKIPNC_TRY(b);
        *out = *b;
      }
    }
    if (const auto* n = t.get("override")) {
      auto v = get_number(*n, origin, "override", 0.0, 200.0);
      SKIPNC_TRY(v);
      op.override_pct = *v;
    }
    if (!op.feed_hold && !op.interlock && !op.override_pct && !op.dry_run) {
      return config_error(
          t, origin,
          "[[operator]] changes nothing: give feed_hold, interlock, override or dry_run");
    }
    s.operator_actions.push_back(op);
    return {};
  });
  if (!r) return r;
  std::stable_sort(
      s.operator_actions.begin(), s.operator_actions.end(),
      [](const OperatorAction& a, const OperatorAction& b) { return a.at_time_s < b.at_time_s; });
  return {};
}

}  // namespace skipnc::machine
