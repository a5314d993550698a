// Microbenchmarks (Google Benchmark). Results and how to reproduce them:
// bench/README.md.
#include <benchmark/benchmark.h>

#include <string>

#include "bench_programs.hpp"
#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "gcode/parser.hpp"
#include "interpreter/interpreter.hpp"
#include "kernel/kernel.hpp"
#include "kernel/kernel_config.hpp"
#include "machine/plant.hpp"
#include "sim/simulator.hpp"

namespace {

using namespace skipnc;

struct World {
  config::MachineConfig machine = *config::builtin_machine("mill3");
  config::Dialect dialect = *config::builtin_dialect("fanuc");
  config::Parameters params{&dialect};
};

class NullSink final : public canon::CommandSink {
 public:
  void emit(const canon::Stamped& c) override {
    benchmark::DoNotOptimize(&c);
    ++count;
  }
  long count = 0;
};

void BM_ParseBlock(benchmark::State& state) {
  gcode::Block b;
  const std::string_view text = "N120 G1 X10.123 Y-3.5 Z[#5+2.] F1000.";
  for (auto _ : state) {
    auto r = gcode::parse_block(text, SourceLoc{"bench", 1, 1}, 0, b);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ParseBlock);

// A block like those of the LinuxCNC peer kit's gen_expr.py.
void BM_ParseExprBlock(benchmark::State& state) {
  gcode::Block b;
  const std::string_view text = "#24=[[#7*SIN[#21]-#28/4.000]/[2.000+ABS[SIN[#12]]]]";
  for (auto _ : state) {
    auto r = gcode::parse_block(text, SourceLoc{"bench", 1, 1}, 0, b);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ParseExprBlock);

void interpret(benchmark::State& state, const std::string& program) {
  World w;
  interp::Setup setup;
  setup.machine = &w.machine;
  setup.dialect = &w.dialect;
  setup.params = &w.params;
  setup.program_text = program;
  long blocks = 0;
  for (auto _ : state) {
    auto in = interp::Interpreter::create(setup, AxisVec{});
    NullSink sink;
    for (;;) {
      auto st = (*in)->step(sink);
      if (!st || *st == interp::Step::kEnd) break;
      ++blocks;
    }
  }
  state.SetItemsProcessed(blocks);
}

void BM_InterpretMotion(benchmark::State& state) {
  static const std::string program = bench::motion_program(100000);
  interpret(state, program);
}
BENCHMARK(BM_InterpretMotion)->Unit(benchmark::kMillisecond);

void BM_InterpretExpr(benchmark::State& state) {
  static const std::string program = bench::expr_program(100000);
  interpret(state, program);
}
BENCHMARK(BM_InterpretExpr)->Unit(benchmark::kMillisecond);

// One kernel tick + one plant period while a long feed move runs.
void BM_KernelTick(benchmark::State& state) {
  World w;
  machine::Scene scene;
  machine::Trigger t;
  t.signal = canon::SignalAddr{'X', 0, 4};
  t.axis = 2;
  t.at = -1e5;
  scene.triggers.push_back(t);
  kernel::Kernel k(kernel::kernel_config(w.machine));
  machine::Plant plant(w.machine, scene, k.clock());
  k.set_position(AxisVec{});
  plant.reset(AxisVec{});
  kernel::TickInput in;
  kernel::TickOutput out;
  AxisVec prev{};
  bool forward = true;
  for (auto _ : state) {
    if (k.motion_idle()) {
      AxisVec target;
      target[0] = forward ? 400.0 : -400.0;
      target[1] = forward ? 300.0 : -300.0;
      forward = !forward;
      if (!k.push({canon::Feed{target, 6000.0, false}, 1})) {
        state.SkipWithError("the kernel refused a move at rest");
        break;
      }
    }
    plant.advance(k.now() + 1, prev, out.commanded, in);
    prev = out.commanded;
    k.tick(in, out);
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_KernelTick);

// A whole simulated run: simulated seconds per wall second is
// items_per_second / 1000 (1 ms period).
void BM_Simulate(benchmark::State& state) {
  World w;
  static const std::string program = bench::motion_program(2000);
  machine::Scene scene;
  long ticks = 0;
  for (auto _ : state) {
    sim::Simulator sim(w.machine, w.dialect, w.params, scene);
    interp::Setup setup;
    setup.machine = &w.machine;
    setup.dialect = &w.dialect;
    setup.params = &w.params;
    setup.program_text = program;
    auto r = sim.run(setup, {});
    ticks += r ? r->ticks : 0;
  }
  state.SetItemsProcessed(ticks);
}
BENCHMARK(BM_Simulate)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
