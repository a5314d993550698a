#include "rules/rule_rig.hpp"

#include <cmath>
#include <limits>

#include "config/skip_inputs.hpp"
#include "interpreter/interpreter.hpp"

namespace skipnc::rules {

double Outcome::var(int n) const {
  auto v = sim->interpreter()->read_variable(n);
  if (!v || v->vacant) return std::numeric_limits<double>::quiet_NaN();
  return v->v;
}

double Outcome::named(const std::string& name) const {
  auto v = sim->interpreter()->read_named(name);
  if (!v || v->vacant) return std::numeric_limits<double>::quiet_NaN();
  return v->v;
}

Rig& Rig::trigger(const std::string& signal, char axis, double at, bool decreasing) {
  return scene("[[trigger]]\nsignal = \"" + signal + "\"\naxis = \"" + std::string(1, axis) +
               "\"\nat = " + std::to_string(at) + "\ndirection = \"" +
               (decreasing ? "decreasing" : "increasing") + "\"");
}

Rig& Rig::pulse(const std::string& signal, double at_time, double duration) {
  return scene("[[pulse]]\nsignal = \"" + signal + "\"\nat_time = " + std::to_string(at_time) +
               "\nduration = " + std::to_string(duration));
}

Rig& Rig::stop(char axis, double at, bool decreasing) {
  return scene("[[stop]]\naxis = \"" + std::string(1, axis) + "\"\nat = " + std::to_string(at) +
               "\ndirection = \"" + (decreasing ? "decreasing" : "increasing") + "\"");
}

Outcome Rig::run(const std::string& program) const {
  Outcome o;
  auto m = config::builtin_machine(machine_);
  EXPECT_TRUE(m) << (m ? "" : m.error().detail);
  auto d = config::builtin_dialect(dialect_);
  EXPECT_TRUE(d) << (d ? "" : d.error().detail);
  if (!m || !d) return o;
  o.dialect = std::make_unique<config::Dialect>(std::move(*d));
  o.machine = std::make_unique<config::MachineConfig>(std::move(*m));
  o.machine->dialect = dialect_;
  for (const auto& f : edits_) f(*o.machine);
  for (const auto& f : switch_edits_) f(o.dialect->sw);
  o.params = std::make_unique<config::Parameters>(o.dialect.get());
  for (const auto& p : o.machine->params) {
    auto r = o.params->apply(p);
    EXPECT_TRUE(r) << (r ? "" : r.error().detail);
  }
  for (const auto& text : params_) {
    auto s = config::Parameters::parse_setting(text);
    EXPECT_TRUE(s) << text;
    if (!s) continue;
    auto r = o.params->apply(*s);
    EXPECT_TRUE(r) << text << ": " << (r ? "" : r.error().detail);
  }
  auto chk = config::check_skip_addresses(*o.dialect, *o.params);
  EXPECT_TRUE(chk) << (chk ? "" : chk.error().detail);
  auto sc = machine::parse_scene(scene_, "rig.scene.toml", *o.machine, *o.dialect, *o.params);
  EXPECT_TRUE(sc) << (sc ? "" : sc.error().detail);
  o.scene = std::make_unique<machine::Scene>(sc ? std::move(*sc) : machine::Scene{});
  o.sim = std::make_unique<sim::Simulator>(*o.machine, *o.dialect, *o.params, *o.scene);
  record::Setup setup;
  setup.machine = o.machine.get();
  setup.dialect = o.dialect.get();
  setup.params = o.params.get();
  setup.program_text = program;
  setup.program_name = "rule.nc";
  TraceCapture cap;
  sim::RunOptions opts;
  if (trace_) opts.trace = &cap;
  auto r = o.sim->run(setup, opts);
  EXPECT_TRUE(r) << (r ? "" : r.error().detail);
  if (r) o.r = std::move(*r);
  o.trace = std::move(cap.rows);
  return o;
}

}  // namespace skipnc::rules
