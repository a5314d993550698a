// The scene: what the machine touches (spec/cli.md, scene TOML v1).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "canon/canon.hpp"
#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "core/diag.hpp"
#include "machine/scene_parts.hpp"

namespace skipnc::machine {

// A level signal, on while the axis's actual position is beyond a plane.
struct Trigger {
  canon::SignalAddr signal;
  std::string signal_name;  // as written
  int axis = 0;
  double at = 0.0;         // machine coordinate, mm
  bool decreasing = true;  // on while axis < at (else while axis > at)
};

// A timed pulse.
struct Pulse {
  canon::SignalAddr signal;
  std::string signal_name;
  double at_time_s = 0.0;
  double duration_s = 0.0;
};

// A rigid stop: the axis cannot pass it.
struct Stop {
  int axis = 0;
  double at = 0.0;
  bool decreasing = true;  // blocks motion toward smaller coordinates (axis >= at)
};

// An external load on an axis motor for a while (a burr, a chip): its
// torque adds to the servo's. Scene [[load]] (docs/skip-dialects.md).
struct Load {
  int axis = 0;
  double at_time_s = 0.0;
  double duration_s = 0.0;
  double torque_pct = 0.0;
};

// What the operator does at a moment: each field that is set changes that
// switch from then on. Scene [[operator]] (docs/skip-dialects.md).
struct OperatorAction {
  double at_time_s = 0.0;
  std::optional<bool> feed_hold;       // true: feed hold; false: cycle start (released)
  std::optional<bool> interlock;       // all-axis interlock
  std::optional<double> override_pct;  // feed override, 0-200 %
  std::optional<bool> dry_run;
};

struct Scene {
  std::string origin;
  std::vector<Trigger> triggers;
  std::vector<Pulse> pulses;
  std::vector<Stop> stops;
  std::vector<Load> loads;
  std::vector<OperatorAction> operator_actions;  // in time order
  Probing probing;  // parts, probe, tools, tool setter, gauges (scene_parts.hpp)
  // [strict] allow: warning codes that stay warnings under --strict, with
  // those of --allow (config/warning_codes.hpp).
  std::vector<std::string> strict_allow;
};

[[nodiscard]] Result<Scene> parse_scene(std::string_view toml_text, std::string_view origin,
                                        const config::MachineConfig& m, const config::Dialect& d,
                                        const config::Parameters& p);
[[nodiscard]] Result<Scene> load_scene_file(const std::string& path, const config::MachineConfig& m,
                                            const config::Dialect& d, const config::Parameters& p);

}  // namespace skipnc::machine
