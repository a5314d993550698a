// The simulated machine: interpreter, kernel and plant, run servo period by
// servo period until the program ends or raises an alarm.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "kernel/kernel.hpp"
#include "machine/plant.hpp"
#include "machine/scene.hpp"
#include "record/record.hpp"

namespace skipnc::interp {
class Interpreter;
}  // namespace skipnc::interp

namespace skipnc::sim {

// One servo period as the trace shows it.
struct TraceRow {
  Tick tick = 0;
  double time_s = 0.0;
  const AxisVec* commanded = nullptr;
  const AxisVec* actual = nullptr;
  const AxisVec* torque = nullptr;
  double feed_mm_per_min = 0.0;
  std::uint32_t line = 0;
  std::uint32_t source = 0;  // call context of the active block (record::CallContext)
  // The actual position in the running block's work coordinates (program
  // units, as #5041.. reads it); null when not computed.
  const AxisVec* work = nullptr;
  std::string_view file;                  // file of the active block (valid during the call)
  const machine::Plant* plant = nullptr;  // signal levels
  kernel::SkipHandshake handshake;        // the skip block's handshake
  const config::SkipHandshakeNames* handshake_names = nullptr;  // null: not shown
};

class TraceSink {
 public:
  virtual ~TraceSink() = default;
  virtual void row(const TraceRow& r) = 0;
  // The run's last period, once, after the run: a sink that keeps only some
  // periods (--trace-every) writes it if it did not keep it.
  virtual void last(const TraceRow&) {}
  // The sink keeps only the periods whose tick is a multiple of this (the
  // run may pass over the others without making their rows), and last().
  virtual std::int64_t stride() const noexcept { return 1; }
};

enum class RunStatus : std::uint8_t { kCompleted, kAlarm, kInterrupted };

// The machine's time in one block (one place: call context and line), from
// the block the kernel runs in each servo period. A block that runs again (a
// loop, a subprogram called twice) adds to its place.
struct BlockTime {
  std::uint32_t context = 0;
  std::uint32_t line = 0;
  std::int64_t runs = 0;   // times the place became the running block
  Tick first = 0;          // first period in it (the period ending at first + 1)
  Tick last = 0;           // end of the last period in it
  std::int64_t ticks = 0;  // periods in it, in all
};

// The stock at the end of a run (scene [stock]): the volume cutting removed
// and, for the plot's side views, the deepest cut of each column of cells
// along X (the lowest top over Y) and along Y (over X).
struct StockResult {
  double removed_mm3 = 0.0;
  std::vector<double> x_edges;  // cell edges on X (one more than cells)
  std::vector<double> lowest_along_x;
  std::vector<double> y_edges;
  std::vector<double> lowest_along_y;
};

struct RunResult {
  RunStatus status = RunStatus::kCompleted;
  std::optional<Error> alarm;
  std::optional<AxisVec>
      alarm_position;  // machine position of a probe crash, collision, protection alarm
  AxisVec final_machine;
  AxisVec final_work;
  double time_s = 0.0;
  Tick ticks = 0;
  std::vector<record::SkipRecord> skips;  // the last one ended_by_alarm when an alarm cut it short
  // Where the alarm was raised: its call context (index into contexts).
  std::uint32_t alarm_context = 0;
  std::vector<record::CallContext> contexts;
  bool program_inch = false;  // G20 in effect at the end of the run
  std::vector<std::string> messages;
  std::vector<record::Warning> warnings;  // the interpreter's, then the machine's
  std::vector<BlockTime> block_times;     // in the order the places first ran
  double period_s = 0.0;                  // servo period: ticks to seconds
  std::vector<std::pair<std::string, std::optional<double>>> variables;  // filled by the caller
  std::optional<StockResult> stock;  // with a [stock] in the scene
};

struct RunOptions {
  TraceSink* trace = nullptr;
  // Sees every command the interpreter emits, in order (plots: move kinds).
  canon::CommandSink* commands = nullptr;
  const std::atomic<bool>* interrupt = nullptr;
  // Called about every simulated second with (simulated seconds, line).
  std::function<void(double, std::uint32_t)> progress;
};

class Simulator {
 public:
  Simulator(const config::MachineConfig& m, const config::Dialect& d, const config::Parameters& p,
            const machine::Scene& scene);
  ~Simulator();

  // Runs the program. Errors that stop the run are in the result (alarm);
  // the returned error is for a run that could not start.
  [[nodiscard]] Result<RunResult> run(const record::Setup& setup, const RunOptions& opts);
  // The interpreter of the last run (for variables after the run).
  interp::Interpreter* interpreter() noexcept { return interp_.get(); }

 private:
  const config::MachineConfig& m_;
  const config::Dialect& d_;
  const config::Parameters& p_;
  const machine::Scene& scene_;
  std::unique_ptr<interp::Interpreter> interp_;
};

}  // namespace skipnc::sim
