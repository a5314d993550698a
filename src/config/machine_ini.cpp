#include "config/machine_ini.hpp"

#include <string>

namespace skipnc::config {
namespace {

// A number, or a bit pin's true/false as 1/0 (LinuxCNC reads bit pins so).
Result<double> ini_value(const toml::node& n, std::string_view origin, const std::string& what) {
  if (const auto* b = n.as_boolean()) return b->get() ? 1.0 : 0.0;
  return get_number(n, origin, what, -1e300, 1e300);
}

}  // namespace

Result<void> load_ini_hal(const toml::table& t, MachineConfig& m, std::string_view origin) {
  if (const auto* n = t.get("ini")) {
    const auto* it = n->as_table();
    if (!it) return config_error(*n, origin, "[ini] must hold tables, one per INI section");
    for (const auto& [section, node] : *it) {
      const auto* st = node.as_table();
      if (!st) {
        return config_error(node, origin,
                            "[ini] " + std::string(section.str()) +
                                ": an INI section is a table ([ini." + std::string(section.str()) +
                                "] NAME = value)");
      }
      auto& keys = m.ini[std::string(section.str())];
      for (const auto& [name, value] : *st) {
        auto v = ini_value(value, origin,
                           "[ini." + std::string(section.str()) + "] " + std::string(name.str()));
        SKIPNC_TRY(v);
        keys[std::string(name.str())] = *v;
      }
    }
  }
  if (const auto* n = t.get("hal")) {
    const auto* ht = n->as_table();
    if (!ht) return config_error(*n, origin, "[hal] must be a table of pin = value");
    for (const auto& [pin, value] : *ht) {
      auto v = ini_value(value, origin, "[hal] " + std::string(pin.str()));
      SKIPNC_TRY(v);
      m.hal[std::string(pin.str())] = *v;
    }
  }
  return {};
}

}  // namespace skipnc::config
