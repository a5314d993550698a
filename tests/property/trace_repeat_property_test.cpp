// Property: the same inputs give a bit-identical trace. A random program
// with skips, run on the simulated machine with a probe scene, is run twice
// with another random program in between; every servo period of the two
// traces (time, commanded and actual position, torque, feed, line, signal
// levels, handshake) and the results (skip records, variables, messages,
// final position) must be equal to the bit. Nothing may depend on what ran
// before, on addresses or on the clock of the host.
//
// Seed and count: RC_PARAMS="seed=7 max_success=10000".
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "machine/scene.hpp"
#include "property/program_gen.hpp"
#include "sim/simulator.hpp"

namespace skipnc::property {
namespace {

// Every value of every period, as raw bytes.
class RawTrace final : public sim::TraceSink {
 public:
  void row(const sim::TraceRow& r) override {
    put(r.tick);
    put(r.time_s);
    put(*r.commanded);
    put(*r.actual);
    put(*r.torque);
    put(r.feed_mm_per_min);
    put(r.line);
    put(r.handshake.active);
    put(r.handshake.skip);
    put(r.handshake.recorded);
    put(r.handshake.done);
    if (r.plant != nullptr) {
      for (std::size_t i = 0; i < r.plant->signal_count(); ++i) put(r.plant->signal_level(i));
    }
  }
  std::vector<unsigned char> bytes;

 private:
  template <class T>
  void put(const T& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof v);
  }
};

struct Outcome {
  std::vector<unsigned char> trace;
  std::vector<unsigned char> results;
  bool ran = false;
};

template <class T>
void put(std::vector<unsigned char>& out, const T& v) {
  const auto* p = reinterpret_cast<const unsigned char*>(&v);
  out.insert(out.end(), p, p + sizeof v);
}

Outcome run(const Machine& m, const machine::Scene& scene, const std::string& program) {
  Outcome o;
  sim::Simulator sim(m.machine, m.dialect, *m.params, scene);
  RawTrace trace;
  sim::RunOptions opts;
  opts.trace = &trace;
  auto r = sim.run(m.setup(program), opts);
  if (!r) return o;
  o.ran = true;
  o.trace = std::move(trace.bytes);
  auto& out = o.results;
  put(out, r->status);
  put(out, r->ticks);
  put(out, r->final_machine);
  put(out, r->final_work);
  if (r->alarm) {
    put(out, r->alarm->id);
    put(out, r->alarm->loc.line);
    put(out, r->alarm->loc.column);
    out.insert(out.end(), r->alarm->detail.begin(), r->alarm->detail.end());
  }
  for (const auto& s : r->skips) {
    put(out, s.line);
    put(out, s.triggered);
    put(out, s.time_s);
    put(out, s.position);
    put(out, s.machine_position);
    put(out, s.end_position);
  }
  for (const auto& msg : r->messages) out.insert(out.end(), msg.begin(), msg.end());
  for (int n : {101, 5061, 5062, 5063, 5001, 5002, 5003}) {
    auto v = sim.interpreter()->read_variable(n);
    if (v) {
      put(out, v->vacant);
      put(out, v->v);
    }
  }
  return o;
}

RC_GTEST_PROP(TraceRepeat, SameInputsGiveABitIdenticalTrace, ()) {
  const Machine m(
      *rc::gen::elementOf(std::vector<std::string>{"fanuc", "nct", "mitsubishi", "compass"}));
  GenOptions o;
  o.max_blocks = 6;
  o.feed_min = 1000.0;  // keeps a case to a few seconds of machine time
  o.reach = 30.0;
  o.units = false;
  const std::string program = gen_program(o);
  const std::string other = gen_program(o);
  const double at = gen_real(-20, 0, 200);
  const std::string scene_text =
      "[[trigger]]\nsignal = \"SKIP\"\naxis = \"Z\"\nat = " + num(at, 3) +
      "\ndirection = \"decreasing\"\n";
  auto scene = machine::parse_scene(scene_text, "prop.scene.toml", m.machine, m.dialect, *m.params);
  RC_ASSERT(scene.has_value());

  const Outcome first = run(m, *scene, program);
  (void)run(m, *scene, other);
  const Outcome second = run(m, *scene, program);
  RC_ASSERT(first.ran == second.ran);
  RC_CLASSIFY(first.trace.size() > 100000, "long trace");
  RC_ASSERT(first.trace.size() == second.trace.size());
  RC_ASSERT(std::memcmp(first.trace.data(), second.trace.data(), first.trace.size()) == 0);
  RC_ASSERT(first.results == second.results);
}

}  // namespace
}  // namespace skipnc::property
