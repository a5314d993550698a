// The simulated plant: one servo axis per machine axis, and the scene's
// signal sources and stops. It produces exactly what a real machine gives
// the kernel each period: actual positions, motor torque and input edges
// with their instants.
//
// Servo model (per axis): the command ramps linearly over the period; the
// axis velocity is feedforward * command velocity + kp * following error,
// integrated exactly over the period. Between samples the actual position is
// taken as linear, and signal edges are placed on that line. A stop clamps
// the axis; torque is torque_per_mm * following error plus the scene's loads,
// up to torque_max or the torque limit the kernel applies. A locked axis
// (machine lock) does not move.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "config/machine_config.hpp"
#include "core/axes.hpp"
#include "core/time.hpp"
#include "kernel/kernel.hpp"
#include "machine/probe_scene.hpp"
#include "machine/scene.hpp"

namespace skipnc::machine {

class Plant {
 public:
  Plant(const config::MachineConfig& m, const Scene& scene, ServoClock clock);

  void reset(const AxisVec& position);
  // Levels of the scene's signals at the present state (for the kernel's image).
  template <class F>
  void for_each_signal(F&& f) const {
    for (const auto& s : signals_) f(s.addr, s.level);
  }
  // Advances from t_{k-1} to t_k while the command ramps from `from` to `to`,
  // and fills `in` for the kernel's tick k.
  void advance(Tick k, const AxisVec& from, const AxisVec& to, kernel::TickInput& in) noexcept;

  const AxisVec& actual() const noexcept { return actual_; }
  const AxisVec& torque() const noexcept { return torque_; }
  // Periods from tick `now` on whose advance would repeat the last one bit
  // for bit, given the same command: the last two advances had the command
  // standing, moved no axis and changed no signal, and no pulse or load of
  // the scene begins or ends before then (two periods spare). 0: none.
  std::int64_t quiet_ticks(Tick now) const noexcept;
  // The last two advances changed nothing (the first test of quiet_ticks,
  // inline: it is asked every period).
  bool still() const noexcept { return still_ >= 2; }
  double clock_period_s() const noexcept { return clock_.period_s(); }
  // Whether periods of a command moving at a constant velocity may be passed
  // at once (pass_cruise): nothing of the scene senses, stops or loads the
  // axes (no trigger, pulse, load, stop, probe, setter, gauge, part, stock),
  // no axis is locked or torque-limited and every servo is a first-order
  // lag (kp > 0).
  bool can_cruise() const noexcept {
    return plain_servo_ && locked_.empty() && !limited_ && sources_.empty() && probing_.inert();
  }
  // The following error the servo of `axis` settles at under a command
  // moving `step` per period: (1 - feedforward) x velocity / kp.
  double steady_error(int axis, double step) const noexcept {
    return step * lag_gain_[static_cast<std::size_t>(axis)];
  }
  // Passes n periods of a command moving `step` per period, from `from`
  // (the command at the start) to `to` (the command after n periods):
  // the servo's own recurrence (e' = ess + (e - ess) d per period, d =
  // exp(-kp T)) applied n times in closed form, e = ess + (e0 - ess) d^n.
  // Exact in real arithmetic; in floating point within a few units in the
  // last place of the positions of the period-by-period run.
  void pass_cruise(std::int64_t n, const AxisVec& from, const AxisVec& to, const AxisVec& step,
                   kernel::TickInput& in) noexcept;
  // Torque limit of each axis's servo from now on, % (0: torque_max only):
  // the motor torque saturates there (torque limit skip, kernel output).
  void set_torque_limit(const AxisVec& pct) noexcept {
    torque_limit_ = pct;
    limited_ = false;
    for (int i = 0; i < n_; ++i) limited_ = limited_ || torque_limit_[i] > 0.0;
  }
  bool torque_limited() const noexcept { return limited_; }
  // Axes that do not move (machine lock, Z-axis cancel).
  // (The excess following error is the kernel's check: kernel::Fault.)
  void set_locked(AxisMask axes) noexcept { locked_ = axes; }
  // Is the signal at `index` (scene order of distinct signals) on?
  std::size_t signal_count() const noexcept { return signals_.size(); }
  const canon::SignalAddr& signal_addr(std::size_t i) const noexcept { return signals_[i].addr; }
  bool signal_level(std::size_t i) const noexcept { return signals_[i].level; }
  // Parts, probe, tools, setter and gauges: tool changes, faults, touches.
  ProbeScene& probing() noexcept { return probing_; }
  const Scene& scene() const noexcept { return scene_; }
  const ProbeScene& probing() const noexcept { return probing_; }

 private:
  enum class SourceKind : std::uint8_t { kTrigger, kPulse, kProbing };
  struct Source {
    SourceKind kind = SourceKind::kTrigger;
    std::size_t index = 0;  // into scene triggers / pulses / probing sources
    bool on = false;
  };
  struct Signal {
    canon::SignalAddr addr;
    bool level = false;
    std::vector<std::size_t> sources;  // indices into sources_
  };
  // The servo update with stops, loads, locked axes and torque limits.
  void advance_servo(Tick k, const AxisVec& before, const AxisVec& from,
                     const AxisVec& to) noexcept;
  // The scene's signal sources: their edges inside the period into `in`.
  void source_edges(Tick k, const AxisVec& before, kernel::TickInput& in) noexcept;
  bool trigger_on(const Trigger& t, double pos) const noexcept {
    return t.decreasing ? pos < t.at : pos > t.at;
  }

  const config::MachineConfig& m_;
  Scene scene_;
  ServoClock clock_;
  int n_ = 0;
  AxisVec actual_;
  AxisVec torque_;
  AxisVec torque_limit_;
  AxisMask locked_;
  bool limited_ = false;  // a torque limit is applied on some axis
  int still_ = 0;         // advances in a row that changed nothing (up to 2)
  int moving_axis_ = 0;   // the last axis found moving (advance's still test), < n_
  // Servo constants per axis.
  std::array<double, kMaxAxes> decay_{};          // exp(-kp * T)
  std::array<double, kMaxAxes> lag_gain_{};       // (1 - feedforward) / (kp * T)
  std::array<double, kMaxAxes> torque_per_mm_{};  // torque_pct_per_mm
  std::array<double, kMaxAxes> torque_max_{};     // torque_max_pct
  // No stops and no loads in the scene and no ideal servo (kp = 0): the
  // servo update is the same arithmetic on every axis (advance's fast loop).
  bool plain_servo_ = false;
  std::vector<Source> sources_;
  // The scene's triggers and pulses, first in sources_ (the probing
  // sources follow): source_edges times only these.
  std::size_t timed_sources_ = 0;
  std::vector<Signal> signals_;
  struct Event {
    double frac;
    std::size_t source;
    bool on;
  };
  std::vector<Event> events_;  // reserved once; reused each period
  ProbeScene probing_;
  std::vector<std::size_t> probing_source_;  // probing source -> index into sources_
};

}  // namespace skipnc::machine
