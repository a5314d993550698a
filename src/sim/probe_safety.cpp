#include "sim/probe_safety.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>
#include <type_traits>

#include "config/skip_inputs.hpp"
#include "machine/geometry.hpp"
#include "machine/scene.hpp"

namespace skipnc::sim {

using machine::GaugeSpec;
using machine::GaugeStep;
using machine::Plant;
using machine::PlantFault;
using machine::ProbeScene;
using machine::Probing;
using machine::Pulse;
using machine::Scene;
using machine::ToolSpec;
using machine::TouchProbe;
using machine::Trigger;
namespace geo = machine::geo;

ProbeSafety::ProbeSafety(const config::MachineConfig& m, const config::Parameters& p,
                         const Plant& plant, canon::CommandSink* next)
    : m_(m), plant_(plant), next_(next), protection_(p.get(kProbeProtectionParam) != 0.0) {
  const auto& probe = plant.probing().spec().probe;
  switched_on_ = !(probe && probe->on_m != 0);
}

std::string ProbeSafety::where(const AxisVec& v) const {
  std::string out;
  for (int i = 0; i < m_.axis_count(); ++i) {
    out += fmt::format("{}{}{:.4f}", out.empty() ? "" : " ",
                       m_.axes[static_cast<std::size_t>(i)].name, v[i] + 0.0);
  }
  return out + " (machine)";
}

void ProbeSafety::emit(const canon::Stamped& c) {
  if (next_ != nullptr) next_->emit(c);
  std::visit(
      [&](const auto& cmd) {
        using T = std::decay_t<decltype(cmd)>;
        if constexpr (std::is_same_v<T, canon::Skip>) {
          warn_braking(cmd, c);
          if (!warn_probe_off(cmd, c)) warn_unreachable(cmd, c);
          last_target_ = cmd.target;
        } else if constexpr (std::is_same_v<T, canon::Rapid> || std::is_same_v<T, canon::Feed> ||
                             std::is_same_v<T, canon::Arc>) {
          last_target_ = cmd.target;
        } else if constexpr (std::is_same_v<T, canon::ToolSelect>) {
          selected_tool_ = cmd.tool;
        } else if constexpr (std::is_same_v<T, canon::MCode>) {
          if (cmd.code == 6 && selected_tool_ >= 0) tool_change_ = selected_tool_;
          const auto& probe = plant_.probing().spec().probe;
          if (probe && probe->on_m != 0 && (cmd.code == probe->on_m || cmd.code == probe->off_m)) {
            switched_on_ = cmd.code == probe->on_m;
            power_change_ = switched_on_;
            if (switched_on_) {
              power_source_ = c.source;
              power_line_ = c.line;
            }
          }
        }
      },
      c.cmd);
}

bool ProbeSafety::warn_probe_off(const canon::Skip& s, const canon::Stamped& at) {
  const auto& probe = plant_.probing().spec().probe;
  if (switched_on_ || !probe || tool_for_next_command() != probe->tool ||
      s.spec.kind == canon::SkipKind::kTorque) {
    return false;
  }
  bool listens = false;
  for (int i = 0; i < s.spec.input_count; ++i)
    listens = listens || s.spec.inputs[i] == probe->signal;
  if (!listens) return false;
  record::add_warning(
      warnings_, record::Warning{"probe_off", at.source, at.line,
                                 fmt::format("the skip listens to the probe's input {}, but the "
                                             "probe is switched off (M{} switches it on)",
                                             config::signal_name(probe->signal), probe->on_m)});
  return true;
}

// How far a skip's direction is followed when looking for a surface: past
// any machine's travel.
constexpr double kRayMm = 100000.0;

std::optional<bool> ProbeSafety::reachable(const canon::SignalAddr& input, const AxisVec& from,
                                           const AxisVec& dir) const {
  const Scene& sc = plant_.scene();
  const ProbeScene& ps = plant_.probing();
  const Probing& spec = ps.spec();
  const int tool_no = tool_for_next_command();
  const bool probe_in = spec.probe && tool_no == spec.probe->tool;
  const ToolSpec* tool = probe_in ? nullptr : spec.tool(tool_no);
  const AxisVec far = from + dir * kRayMm;
  std::optional<bool> out;
  const auto found = [&](bool yes) { out = out.value_or(false) || yes; };
  for (const Trigger& t : sc.triggers) {
    if (!(t.signal == input)) continue;
    const bool on_at_start = t.decreasing ? from[t.axis] < t.at : from[t.axis] > t.at;
    found(on_at_start || (t.decreasing ? dir[t.axis] < 0.0 : dir[t.axis] > 0.0));
  }
  for (const Pulse& p : sc.pulses) {
    if (p.signal == input) found(true);  // in time, not in space: it may come
  }
  for (const GaugeSpec& g : spec.gauges) {
    for (const GaugeStep& st : g.steps) {
      if (st.signal == input) found(true);  // follows the grinding, not a surface
    }
  }
  if (spec.probe && spec.probe->signal == input) {
    if (!probe_in) {
      found(false);  // no probe to switch it
    } else {
      const geo::Vec3 a = ps.ball_at(from);
      const double r = spec.probe->ball_radius;
      const geo::Solids solids = ps.solids();
      geo::Contact c;
      found(solids.distance(a) <= r || solids.first_contact(a, ps.ball_at(far), r, c));
    }
  }
  if (spec.tool_setter && spec.tool_setter->signal == input) {
    const geo::Column setter = spec.tool_setter->disc();
    if (tool == nullptr) {
      found(false);  // the setter senses a tool, not the probe (docs/scene.md)
    } else {
      const geo::Column col = ps.tool_column(*tool, from);
      double t = 0.0;
      found(geo::column_overlap(col, setter) > 0.0 ||
            geo::column_first_overlap(col, ps.point(far) - ps.point(from), setter, 1e-6, t));
    }
  }
  return out;
}

// A skip whose direction leads away from everything of the scene that
// switches its inputs can only run to its end point (a wrong sign, a wrong
// axis, a wrong P word). Said before the move, as the warning skip_unreachable.
// Nothing is said when the scene drives none of the inputs (a scene-less
// run, a pulse) or for a torque limit skip (ended by torque, not an input).
void ProbeSafety::warn_unreachable(const canon::Skip& s, const canon::Stamped& at) {
  if (s.spec.kind == canon::SkipKind::kTorque || s.spec.ignore_inputs) return;
  const int n = m_.axis_count();
  AxisVec dir = s.target - last_target_;
  const double len = norm(dir, n);
  if (len < 1e-9) return;
  dir = dir * (1.0 / len);
  bool any_source = false;
  std::string inputs;
  for (int i = 0; i < s.spec.input_count; ++i) {
    const std::optional<bool> r = reachable(s.spec.inputs[i], last_target_, dir);
    if (!r) continue;
    if (*r) return;
    any_source = true;
    inputs += (inputs.empty() ? "" : ", ") + config::signal_name(s.spec.inputs[i]);
  }
  if (!any_source) return;
  std::string heading;
  for (int i = 0; i < n; ++i) {
    if (std::fabs(dir[i]) < 1e-9) continue;
    heading += fmt::format("{}{}{}", heading.empty() ? "" : " ", dir[i] > 0.0 ? "+" : "-",
                           m_.axes[static_cast<std::size_t>(i)].name);
  }
  record::add_warning(
      warnings_,
      record::Warning{"skip_unreachable", at.source, at.line,
                      fmt::format("the skip move from {} along {} leads away from everything in "
                                  "the scene that switches {}: it can only run to its end point",
                                  where(last_target_), heading, inputs)});
}

double ProbeSafety::braking_distance(const canon::Skip& s, const AxisVec& from) const noexcept {
  const int n = m_.axis_count();
  const AxisVec d = s.target - from;
  const double len = norm(d, n);
  if (len <= 0.0) return 0.0;
  const double v = s.feed_mm_per_min / 60.0;
  double fe2 = 0.0;
  double accel = 0.0;
  for (int i = 0; i < n; ++i) {
    const auto& ax = m_.axes[static_cast<std::size_t>(i)];
    const double u = d[i] / len;
    if (ax.kp_per_s > 0.0) {
      const double fe = (1.0 - ax.feedforward) * v * u / ax.kp_per_s;
      fe2 += fe * fe;
    }
    // The path's deceleration: the smallest a_i / |u_i| over the moving axes.
    if (std::fabs(u) > 1e-12) {
      const double a = ax.accel_mm_s2 / std::fabs(u);
      accel = accel == 0.0 ? a : std::fmin(accel, a);
    }
  }
  const double fe = std::sqrt(fe2);
  if (s.spec.stop == canon::SkipStop::kImmediate || accel <= 0.0) {
    return fe + v * plant_.clock_period_s();
  }
  return v * v / (2.0 * accel) + fe;
}

int ProbeSafety::tool_for_next_command() const noexcept {
  return tool_change_ ? *tool_change_ : plant_.probing().next_spindle_tool();
}

void ProbeSafety::warn_braking(const canon::Skip& s, const canon::Stamped& at) {
  const ProbeScene& ps = plant_.probing();
  const Probing& spec = ps.spec();
  const int tool = tool_for_next_command();
  const bool probe_in = spec.probe && tool == spec.probe->tool;
  double limit = -1.0;
  const char* what = "";
  for (int i = 0; i < s.spec.input_count; ++i) {
    if (probe_in && s.spec.inputs[i] == spec.probe->signal) {
      limit = spec.probe->max_overtravel;
      what = "the probe's stylus";
    } else if (spec.tool_setter && !probe_in && spec.tool(tool) != nullptr &&
               s.spec.inputs[i] == spec.tool_setter->signal) {
      limit = spec.tool_setter->max_overtravel;
      what = "the tool setter";
    }
  }
  if (limit < 0.0) return;
  const double dist = braking_distance(s, last_target_);
  if (dist <= limit) return;
  const bool immediate = s.spec.stop == canon::SkipStop::kImmediate;
  std::string text = fmt::format(
      "the skip move at F{:g} needs {:.4f} mm to stop after the switch ({}), more than the "
      "{:.4f} mm over-travel of {}",
      s.feed_mm_per_min, dist,
      immediate ? "immediate stop: following error + one servo period"
                : "deceleration: v^2/2a + following error",
      limit, what);
  record::add_warning(warnings_,
                      record::Warning{"skip_braking", at.source, at.line, std::move(text)});
}

// The tool change and the probe's switch, made when the motion before them
// has ended; switched on, the probe signals once its start-up time has passed.
void ProbeSafety::make_switches(ProbeScene& ps, const kernel::Kernel& k) {
  if (tool_change_ && k.idle()) {
    ps.set_spindle_tool(*tool_change_);
    tool_change_.reset();
  }
  const double now_s = k.clock().seconds(k.now());
  if (power_change_ && k.idle()) {
    if (*power_change_) {
      power_on_at_s_ = now_s + ps.spec().probe->start_time_s;
    } else {
      ps.set_probe_power(false);
      power_on_at_s_ = -1.0;
    }
    power_change_.reset();
  }
  if (power_on_at_s_ >= 0.0 && now_s >= power_on_at_s_ - 1e-12) {
    ps.set_probe_power(true);
    power_on_at_s_ = -1.0;
    // Coming on with the stylus already deflected, the input rises at once:
    // a skip running then stores where the probe was, past the surface.
    const TouchProbe* probe = ps.probe_in_spindle() ? ps.probe() : nullptr;
    if (probe != nullptr && probe->deflection() > 0.0) {
      record::add_warning(
          warnings_,
          record::Warning{"probe_start_deflected", power_source_, power_line_,
                          fmt::format("the probe switched on here became ready at {:.4f} s with "
                                      "its stylus already deflected {:.4f} mm: its input came on "
                                      "at once, wherever the axes were",
                                      now_s, probe->deflection())});
    }
  }
}

// The plant's fault of this period as an alarm: a collision, or a probe or
// tool setter pushed past its over-travel (not while a skip stops the axes).
std::optional<SafetyAlarm> ProbeSafety::fault_alarm(const ProbeScene& ps, const kernel::Kernel& k,
                                                    std::uint32_t at_line,
                                                    std::string_view file) const {
  const PlantFault& f = ps.fault();
  const SourceLoc loc{file, at_line, 1};
  switch (f.kind) {
    case PlantFault::Kind::kNone:
      break;
    case PlantFault::Kind::kCollision: {
      const auto& parts = ps.spec().parts;
      const std::string part =
          f.stock ? "the stock"
          : f.part >= 0 && !parts[static_cast<std::size_t>(f.part)].name.empty()
              ? "part '" + parts[static_cast<std::size_t>(f.part)].name + "'"
              : "a part";
      const std::string who = f.tool >= 0 ? "tool T" + std::to_string(f.tool) : "the probe body";
      return SafetyAlarm{
          Error{AlarmId::kCollision,
                fmt::format("{} touched {} at {}, line {}", who, part, where(f.at), at_line), loc,
                -1},
          f.at};
    }
    case PlantFault::Kind::kProbeCrash:
    case PlantFault::Kind::kSetterCrash: {
      // A crash while a skip stops the axes: the damage is how far they go.
      if (k.skip().active && k.skip().triggered && !k.idle()) break;
      const bool probe = f.kind == PlantFault::Kind::kProbeCrash;
      const std::string what = probe ? "the probe's stylus" : "the tool setter";
      return SafetyAlarm{
          Error{
              AlarmId::kProbeCrash,
              fmt::format(
                  "{} was pushed {:.4f} mm, {:.4f} mm past its limit of {:.4f} mm (switch point + "
                  "maximum over-travel); limit passed at {}, the axes reached {}, line {}",
                  what, f.deflection, f.overshoot, f.limit, where(f.at), where(f.latest), at_line),
              loc, -1},
          f.at};
    }
  }
  return std::nullopt;
}

std::optional<SafetyAlarm> ProbeSafety::check_period(Plant& plant, const kernel::Kernel& k,
                                                     std::uint32_t line, std::string_view file) {
  // The line that was running during the period is the one the kernel
  // showed after the previous tick.
  const std::uint32_t at_line = period_line_ != 0 ? period_line_ : line;
  period_line_ = line;
  ProbeScene& ps = plant.probing();
  make_switches(ps, k);
  if (auto alarm = fault_alarm(ps, k, at_line, file)) return alarm;
  if (protection_ && ps.touch_switched_on() && !(k.skip().active && k.skip().triggered)) {
    const SourceLoc loc{file, at_line, 1};
    return SafetyAlarm{
        Error{
            AlarmId::kProbeProtection,
            fmt::format("the probe input switched on during a move that is not a skip move, at {}, "
                        "line {} (parameter {} = 0 turns probe protection off)",
                        where(ps.touch_position()), at_line, kProbeProtectionParam),
            loc, -1},
        ps.touch_position()};
  }
  return std::nullopt;
}

}  // namespace skipnc::sim
