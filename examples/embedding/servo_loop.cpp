// Driving the skipnc kernel from your own servo loop, without the simulator.
//
// Each servo period your loop reads the drives (actual positions, torque) and
// the probe input (with the instant of any edge), calls Kernel::tick once, and
// writes the commanded positions to the drives. Outside the tick, the
// interpreter is stepped to keep the kernel's queue full; at a skip block it
// waits until the kernel reports the skip done, then continues from where the
// axes stopped.
//
// Here the "drives" are ideal (the axis is where it was commanded one period
// ago) and the "probe" is a surface at Z = -2.5 mm seen by the loop itself.
// Then a rapid beyond the Z stroke end shows the kernel's own fault check:
// the command stops inside the stroke and TickOutput::fault says why.
// Build: part of the project (target skipnc_embedding_example).
#include <cmath>
#include <cstdio>
#include <deque>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "interpreter/interpreter.hpp"
#include "kernel/kernel.hpp"
#include "kernel/kernel_config.hpp"  // kernel_config(): limits from a machine file

namespace {

// Routes the interpreter's motion commands to the kernel. Kernel::push
// refuses a command when the queue is full, and one block may make more
// moves than the queue holds (a canned cycle with many pecks), so what does
// not fit waits here, in order, and feed() hands it over as the ticks make
// room. Read the next block only once everything is handed over (drained()).
class ToKernel final : public skipnc::canon::CommandSink {
 public:
  explicit ToKernel(skipnc::kernel::Kernel& k) : k_(k) {}
  void emit(const skipnc::canon::Stamped& c) override {
    if (skipnc::canon::is_motion(c.cmd)) {
      waiting_.push_back(c);
      feed();
    }
  }
  void feed() {
    while (!waiting_.empty() && k_.push(waiting_.front())) waiting_.pop_front();
  }
  bool drained() const { return waiting_.empty(); }

 private:
  skipnc::kernel::Kernel& k_;
  std::deque<skipnc::canon::Stamped> waiting_;
};

}  // namespace

int main() {
  using namespace skipnc;
  auto machine = config::builtin_machine("mill3");
  auto dialect = config::builtin_dialect("fanuc");
  if (!machine || !dialect) return 2;
  config::Parameters params(&*dialect);

  interp::Setup setup;
  setup.machine = &*machine;
  setup.dialect = &*dialect;
  setup.params = &params;
  setup.program_name = "embedded.nc";
  setup.program_text =
      "G21 G90 G54\n"
      "G0 X5. Y5. Z0\n"
      "G31 Z-10. F120.\n"
      "#100 = #5063\n"
      "G91 G0 Z3.\n"
      "M30\n";
  auto interpreter = interp::Interpreter::create(setup, AxisVec{});
  if (!interpreter) return 2;
  interp::Interpreter& in = **interpreter;

  kernel::Kernel k(kernel::kernel_config(*machine));
  k.set_position(AxisVec{});
  ToKernel sink(k);

  const canon::SignalAddr probe{'X', 0, 4};
  const double surface_z = -2.5;
  kernel::TickInput tick_in;
  kernel::TickOutput tick_out;
  AxisVec drive = AxisVec{};  // what the drives report: last period's command
  bool probe_on = false;
  bool waiting = false, ending = false;

  for (int period = 0; period < 1'000'000; ++period) {
    // Outside the tick: keep the queue full.
    sink.feed();
    while (!waiting && !ending && sink.drained() && k.can_accept()) {
      auto st = in.step(sink);
      if (!st) {
        std::fprintf(stderr, "alarm at line %u: %s\n", st.error().loc.line,
                     st.error().detail.c_str());
        return 1;
      }
      waiting = *st == interp::Step::kSync;
      ending = *st == interp::Step::kEnd;
    }

    // The servo period: read the drives and the probe...
    const double z0 = tick_in.actual[2];
    tick_in.actual = drive;
    tick_in.edge_count = 0;
    const bool on = drive[2] < surface_z;
    if (on != probe_on) {
      // The instant inside the period where Z crossed the surface.
      const double frac = (surface_z - z0) / (drive[2] - z0);
      tick_in.edges[0] = kernel::SignalEdge{probe, on, frac};
      tick_in.edge_count = 1;
      probe_on = on;
    }
    // ...one call into the kernel...
    k.tick(tick_in, tick_out);
    // ...and write the command to the drives (they reach it by the next period).
    drive = tick_out.commanded;
    if (tick_out.fault) {
      std::fprintf(stderr, "kernel fault on axis %d\n", tick_out.fault.axis);
      return 1;
    }

    // Outside the tick again: complete a skip.
    if (waiting && sink.drained() && k.idle() && (!k.skip().active || k.skip().done)) {
      interp::SyncState s;
      s.machine_position = k.skip().active ? k.skip().stop_position : k.command();
      s.actual_position = drive;
      s.skip_done = k.skip().active;
      s.triggered = k.skip().triggered;
      s.latch_machine = k.skip().latch_machine;
      s.input_index = k.skip().input_index;
      s.time_s = k.skip().time_s;
      k.clear_skip();
      waiting = false;
      if (auto r = in.sync(s); !r) return 1;
    }
    if (ending && sink.drained() && k.idle()) break;
  }
  auto z = in.read_variable(100);
  std::printf("probe touched at Z %.6f (#100); final Z %.6f after %lld periods\n", z ? z->v : 0.0,
              in.position()[2], static_cast<long long>(k.now()));
  if (!z || std::abs(z->v - surface_z) >= 1e-9) return 1;

  // The kernel's own protection: a rapid to Z600, beyond mill3's +500 mm
  // stroke end. The kernel stops giving commands at the last one inside the
  // stroke and reports the fault in TickOutput; no simulator is involved.
  AxisVec beyond = drive;
  beyond[2] = 600.0;
  if (!k.push(canon::Stamped{canon::Rapid{beyond}, 0})) return 1;
  for (int period = 0; period < 100'000 && !tick_out.fault; ++period) {
    tick_in.actual = drive;
    tick_in.edge_count = 0;
    k.tick(tick_in, tick_out);
    drive = tick_out.commanded;
  }
  const kernel::Fault& f = tick_out.fault;
  if (f.kind != kernel::Fault::Kind::kStrokeLimit || f.axis != 2) return 1;
  std::printf("stroke limit: Z commanded to %.4f, beyond %.4f; the kernel holds Z at %.4f\n",
              f.value, f.limit, drive[2]);
  return drive[2] <= 500.0 + 1e-9 ? 0 : 1;
}
