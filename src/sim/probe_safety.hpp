// What the simulator does about the probing scene between servo periods:
// tool changes (M06 takes the tool of the last T word, once the motion
// before it has ended), the braking-distance warning before a skip move,
// and the alarms for a probe crash, a collision and probe protection.
//
// It sits in the command stream as a tap (it forwards every command to the
// next sink) and is asked once per period, after the kernel's tick.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/machine_config.hpp"
#include "kernel/kernel.hpp"
#include "machine/plant.hpp"
#include "record/record.hpp"

namespace skipnc::sim {

// Parameter of every dialect (data/dialects/base.toml): probe protection,
// an alarm when a probe or tool-setter input switches on outside a skip
// move (as grblHAL's setting). 1 = on (default), 0 = off.
inline constexpr int kProbeProtectionParam = 90020;

struct SafetyAlarm {
  Error error;
  AxisVec machine_position;  // where it happened
};

class ProbeSafety final : public canon::CommandSink {
 public:
  ProbeSafety(const config::MachineConfig& m, const config::Parameters& p,
              const machine::Plant& plant, canon::CommandSink* next);

  // The command stream (forwarded to `next`).
  void emit(const canon::Stamped& c) override;
  // True while a tool change waits for the motion before it to end: the
  // interpreter must not read further.
  bool holds_reading() const noexcept {
    return tool_change_.has_value() || power_change_.has_value();
  }
  // After each kernel tick. `line` is the line the kernel shows now.
  [[nodiscard]] std::optional<SafetyAlarm> after_period(machine::Plant& plant,
                                                        const kernel::Kernel& k, std::uint32_t line,
                                                        std::string_view file) {
    if (quiet(plant)) {
      period_line_ = line;  // nothing to do (most periods)
      return std::nullopt;
    }
    return check_period(plant, k, line, file);
  }
  // Nothing waits to be checked after a period: no tool change, no probe
  // power change or warm-up, no fault, no switched-on touch under
  // protection.
  bool quiet(const machine::Plant& plant) const noexcept {
    const machine::ProbeScene& ps = plant.probing();
    return !tool_change_ && !power_change_ && power_on_at_s_ < 0.0 &&
           ps.fault().kind == machine::PlantFault::Kind::kNone &&
           !(protection_ && ps.touch_switched_on());
  }
  const std::vector<std::string>& messages() const noexcept { return messages_; }
  // Structured warnings (skip_braking), record::Warning.
  const std::vector<record::Warning>& warnings() const noexcept { return warnings_; }

  // Distance the axes travel after a switch at this feed before they stop:
  // following error plus one period (immediate stop) or v^2/2a plus the
  // following error (deceleration). `from` -> `to` gives the direction.
  double braking_distance(const canon::Skip& s, const AxisVec& from) const noexcept;

 private:
  std::optional<SafetyAlarm> check_period(machine::Plant& plant, const kernel::Kernel& k,
                                          std::uint32_t line, std::string_view file);
  void make_switches(machine::ProbeScene& ps, const kernel::Kernel& k);
  std::optional<SafetyAlarm> fault_alarm(const machine::ProbeScene& ps, const kernel::Kernel& k,
                                         std::uint32_t at_line, std::string_view file) const;
  std::string where(const AxisVec& machine) const;
  void warn_braking(const canon::Skip& s, const canon::Stamped& at);
  void warn_unreachable(const canon::Skip& s, const canon::Stamped& at);
  // The tool the next command will run with: the commands are read ahead
  // of the machine, so a tool change may be on its way still.
  int tool_for_next_command() const noexcept;
  // Can something of the scene switch `input` on somewhere along the ray
  // from `from` in direction `dir` (unit, machine mm)? nullopt: nothing of
  // the scene drives that input.
  std::optional<bool> reachable(const canon::SignalAddr& input, const AxisVec& from,
                                const AxisVec& dir) const;

  const config::MachineConfig& m_;
  const machine::Plant& plant_;
  canon::CommandSink* next_;
  bool protection_ = true;
  AxisVec last_target_;
  int selected_tool_ = -1;
  std::optional<int> tool_change_;
  // A switched probe (ProbeSpec::on_m): the switch read and not yet made
  // (made once the motion before it has ended, as a tool change), the
  // instant its start-up time ends, and its state as the program has set it.
  std::optional<bool> power_change_;
  double power_on_at_s_ = -1.0;
  bool switched_on_ = true;
  std::uint32_t power_source_ = 0, power_line_ = 0;  // the block of the last switch-on
  // A skip that listens to a switched-off probe: warning probe_off; true
  // when said.
  bool warn_probe_off(const canon::Skip& s, const canon::Stamped& at);
  std::uint32_t period_line_ = 0;
  std::vector<std::string> messages_;
  std::vector<record::Warning> warnings_;
};

}  // namespace skipnc::sim
