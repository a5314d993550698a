// A small rig for the skip-rule tests: a built-in machine and dialect,
// parameter settings as a user types them (--param), a scene as TOML text,
// a program as text; the run goes through the same Simulator the skipnc
// command uses. What a test looks at is what a user sees: the skip records
// of the report, variables, the alarm's number and code, the trace.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/scene.hpp"
#include "sim/simulator.hpp"

namespace skipnc::rules {

// A micrometre: the tolerance of a latched or final position.
inline constexpr double kUm = 1e-6;

// One servo period of the trace.
struct Sample {
  double t = 0.0;
  std::uint32_t line = 0;
  double feed_mm_min = 0.0;
  AxisVec cmd, act, torque;
  kernel::SkipHandshake hs;
  std::vector<bool> signals;
};

class TraceCapture final : public sim::TraceSink {
 public:
  void row(const sim::TraceRow& r) override {
    Sample s;
    s.t = r.time_s;
    s.line = r.line;
    s.feed_mm_min = r.feed_mm_per_min;
    s.cmd = *r.commanded;
    s.act = *r.actual;
    s.torque = *r.torque;
    s.hs = r.handshake;
    if (r.plant != nullptr) {
      for (std::size_t i = 0; i < r.plant->signal_count(); ++i) {
        s.signals.push_back(r.plant->signal_level(i));
      }
    }
    rows.push_back(std::move(s));
  }
  std::vector<Sample> rows;
};

struct Outcome {
  sim::RunResult r;
  std::unique_ptr<config::Dialect> dialect;  // owned here: the simulator keeps references
  std::unique_ptr<config::MachineConfig> machine;
  std::unique_ptr<config::Parameters> params;
  std::unique_ptr<machine::Scene> scene;
  std::unique_ptr<sim::Simulator> sim;
  std::vector<Sample> trace;

  bool completed() const { return r.status == sim::RunStatus::kCompleted; }
  // The alarm as the report shows it: number and code of the dialect.
  int alarm_number() const { return r.alarm ? dialect->alarm(r.alarm->id).number : 0; }
  std::string alarm_code() const { return r.alarm ? dialect->alarm(r.alarm->id).code : ""; }
  AlarmId alarm_id() const { return r.alarm ? r.alarm->id : AlarmId::kCount; }
  std::uint32_t alarm_line() const { return r.alarm ? r.alarm->loc.line : 0; }
  std::size_t skip_count() const { return r.skips.size(); }
  const record::SkipRecord& skip(std::size_t i = 0) const { return r.skips.at(i); }
  // #n as a macro reads it after the run; NaN when vacant or not a variable.
  double var(int n) const;
  double named(const std::string& name) const;
};

class Rig {
 public:
  // mill3_lowgain: mill3 with kp 30/s and no feedforward, where the servo's
  // lag (what the stored, stopped and commanded positions differ by) shows
  // the most; the rules' expected values are worked out for it.
  explicit Rig(std::string dialect = "fanuc", std::string machine = "mill3_lowgain")
      : dialect_(std::move(dialect)), machine_(std::move(machine)) {}
  // "6200#0=1", "1174=200": as --param.
  Rig& param(std::string setting) {
    params_.push_back(std::move(setting));
    return *this;
  }
  Rig& scene(std::string toml) {
    scene_ += toml;
    scene_ += "\n";
    return *this;
  }
  // A level trigger: `signal` on while `axis` is beyond `at` (machine mm).
  Rig& trigger(const std::string& signal, char axis, double at, bool decreasing = true);
  Rig& pulse(const std::string& signal, double at_time, double duration);
  Rig& stop(char axis, double at, bool decreasing = true);
  // Changes to the machine before the run (servo, latch, offsets).
  Rig& machine(std::function<void(config::MachineConfig&)> f) {
    edits_.push_back(std::move(f));
    return *this;
  }
  // Changes to the dialect's switches (what a dialect file inheriting the
  // built-in one would say).
  Rig& switches(std::function<void(config::Switches&)> f) {
    switch_edits_.push_back(std::move(f));
    return *this;
  }
  Rig& traced() {
    trace_ = true;
    return *this;
  }
  Outcome run(const std::string& program) const;

 private:
  std::string dialect_;
  std::string machine_;
  std::vector<std::string> params_;
  std::string scene_;
  std::vector<std::function<void(config::MachineConfig&)>> edits_;
  std::vector<std::function<void(config::Switches&)>> switch_edits_;
  bool trace_ = false;
};

// A machine whose axes follow the command without lag (feedforward 1):
// positions at rest equal the command, so stopping distances are the
// kernel's alone.
inline void ideal_servo(config::MachineConfig& m) {
  for (auto& a : m.axes) a.feedforward = 1.0;
}

}  // namespace skipnc::rules
