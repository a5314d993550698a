// The scene loader's parts that read toml++ tables: the signal key, the
// probing tables (scene_parts.cpp), [[load]] (a torque disturbance on an
// axis) and [[operator]] (feed hold, interlock, override, dry run over time;
// scene_actions.cpp). Internal to the scene loader: not installed, so that
// the package's headers need no toml++.
#pragma once

#include <toml++/toml.h>

#include <string>
#include <string_view>

#include "config/machine_config.hpp"
#include "core/diag.hpp"
#include "machine/scene.hpp"

namespace skipnc::machine {

// The `signal` key of a scene table ("X0.4", "SKIP", "SKIP1".."SKIP12"): its
// address, and its text in `name`. Errors name the table or the key.
[[nodiscard]] Result<canon::SignalAddr> scene_signal(const toml::table& t, std::string_view origin,
                                                     const config::Dialect& d,
                                                     const config::Parameters& p,
                                                     std::string& name);

[[nodiscard]] Result<Probing> parse_probing(const toml::table& root, std::string_view origin,
                                            const config::MachineConfig& m,
                                            const config::Dialect& d, const config::Parameters& p);

[[nodiscard]] Result<void> parse_scene_actions(const toml::table& root, std::string_view origin,
                                               const config::MachineConfig& m, Scene& s);

}  // namespace skipnc::machine
