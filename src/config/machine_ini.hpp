// The [ini] and [hal] tables of a machine file: the values an RS274NGC
// program reads as #<_ini[SECTION]NAME> and #<_hal[pin]> (LinuxCNC "Named
// Parameters": INI file values and HAL pins, read-only).
#pragma once

#include <string_view>

#include "config/machine_config.hpp"
#include "config/toml_util.hpp"

namespace skipnc::config {

// [ini.SECTION] NAME = number, [hal] "pin" = number (or true/false) into `m`.
[[nodiscard]] Result<void> load_ini_hal(const toml::table& t, MachineConfig& m,
                                        std::string_view origin);

}  // namespace skipnc::config
