// Scene tables for probing (docs/scene.md): parts ([[box]], [[cylinder]],
// [[sphere]], [[plane]], [[bore]], [[pocket]]), the stock ([stock]), a spindle touch probe
// ([probe]), tools ([[tool]], spindle_tool), a tool setter ([tool_setter])
// and in-process gauges ([[gauge]]). All positions are machine coordinates,
// lengths in mm.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "canon/canon.hpp"
#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "core/diag.hpp"
#include "machine/geometry.hpp"

namespace skipnc::machine {

// A spindle touch probe. Its ball centre is the spindle's gauge point (the
// machine position) minus `length` along Z. It switches when the ball has
// been pushed `pre_travel` (plus lobing and scatter) past first contact.
struct ProbeSpec {
  canon::SignalAddr signal;
  std::string signal_name;
  int tool = 0;              // the T number that puts the probe in the spindle
  double ball_radius = 1.0;  // mm
  double length = 0.0;       // gauge line to ball centre, mm
  // The machine file's H of the probe when it differs from `length` (the
  // control believes it; the scene is the stylus), else h_number 0.
  int h_number = 0;
  double h_length = 0.0;
  double stylus_length = 0.0;   // ball centre to the probe body, mm
  double body_radius = 0.0;     // probe body (a column up to the gauge line); 0: none
  double pre_travel = 0.0;      // deflection before the signal switches, mm
  double max_overtravel = 1.0;  // deflection past the switch point before damage, mm
  double lobing = 0.0;          // extra pre-travel at the lobes (XY contacts), mm
  int lobes = 3;
  double lobing_phase_deg = 0.0;  // approach direction of least pre-travel
  double repeatability = 0.0;     // 1-sigma scatter of the switch point, mm
  std::uint64_t seed = 1;
  // Switching (an optical or radio probe): the M code that switches it on,
  // 0 when it is always on; the one that switches it off; the time from the
  // switch-on to a probe that signals, s. Off, the probe still deflects (and
  // crashes) but its input stays off.
  int on_m = 0;
  int off_m = 0;
  double start_time_s = 0.0;
};

// A tool in the magazine: a flat-ended column below the gauge line.
struct ToolSpec {
  int number = 0;
  double length = 0.0;  // gauge line to tip, mm
  double radius = 0.0;
};

// A tool setter on the table: a disc whose top the tool tip presses.
struct ToolSetterSpec {
  canon::SignalAddr signal;
  std::string signal_name;
  double x = 0.0;
  double y = 0.0;
  double top = 0.0;  // machine Z of the disc's top
  double radius = 5.0;
  double thickness = 5.0;
  double pre_travel = 0.0;
  double max_overtravel = 1.0;
  // The disc as a vertical column (machine coordinates).
  geo::Column disc() const noexcept { return geo::Column{x, y, radius, top - thickness, top}; }
};

// An in-process gauge: the diameter ground by a wheel whose face is at
// `center` + diameter / 2 on `axis`; each step switches its signal on when
// the diameter reaches its size, and stays on.
struct GaugeStep {
  canon::SignalAddr signal;
  std::string signal_name;
  double diameter = 0.0;
};
struct GaugeSpec {
  int axis = 0;
  double center = 0.0;        // machine coordinate of the work's axis
  double raw_diameter = 0.0;  // before grinding
  std::vector<GaugeStep> steps;
};

// The stock that cutting moves remove ([stock], machine/stock.hpp): an
// axis-aligned box in machine coordinates and the size of its grid's cells.
struct StockSpec {
  geo::Vec3 lo;
  geo::Vec3 hi;
  double resolution = 0.5;  // mm, on X and Y
};

struct Probing {
  std::vector<geo::Part> parts;
  std::optional<StockSpec> stock;
  std::optional<ProbeSpec> probe;
  std::optional<ToolSetterSpec> tool_setter;
  std::vector<ToolSpec> tools;
  std::vector<GaugeSpec> gauges;
  int spindle_tool = 0;                 // in the spindle at the start (the probe's T by default)
  std::vector<std::string> mesh_files;  // the STL files read, as opened (outputs never these)

  const ToolSpec* tool(int number) const noexcept {
    for (const auto& t : tools) {
      if (t.number == number) return &t;
    }
    return nullptr;
  }
  bool empty() const noexcept {
    return parts.empty() && !stock && !probe && !tool_setter && tools.empty() && gauges.empty();
  }
};

// The top-level keys these tables use, for the scene's key check.
inline constexpr std::string_view kProbingKeys[] = {
    "box",  "cylinder",    "sphere", "plane",        "bore",  "pocket", "probe",
    "tool", "tool_setter", "gauge",  "spindle_tool", "frame", "mesh",   "stock"};

}  // namespace skipnc::machine
