// Scene tables beyond spec/cli.md's three: [[load]] (a torque disturbance
// on an axis) and [[operator]] (feed hold, interlock, override, dry run over
// time). Internal to the scene loader.
#pragma once

#include <toml++/toml.h>

#include <string_view>

#include "config/machine_config.hpp"
#include "core/diag.hpp"
#include "machine/scene.hpp"

namespace skipnc::machine {

[[nodiscard]] Result<void> parse_scene_actions(const toml::table& root, std::string_view origin,
                                               const config::MachineConfig& m, Scene& s);

}  // namespace skipnc::machine
