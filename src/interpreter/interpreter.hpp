// The interpreter: reads blocks, keeps the modal state, offsets and macro
// variables, runs the control flow and calls, and emits canonical commands.
// It never sees the planner: at a synchronisation point (a skip block, a
// macro read of a live position) it returns Step::kSync, the caller drains
// the motion and hands back what happened through sync().
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "canon/canon.hpp"
#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "core/axes.hpp"
#include "core/diag.hpp"
#include "interpreter/modal.hpp"
#include "interpreter/variables.hpp"
#include "record/record.hpp"

namespace skipnc::interp {

// The run's vocabulary (record/record.hpp) under the interpreter's names.
using record::add_warning;
using record::CallContext;
using record::kMaxWarnings;
using record::Setup;
using record::SkipRecord;
using record::Warning;
using record::WorkFrame;

// The interpreter emits canonical commands into a canon::CommandSink.
using canon::CommandSink;

// What the motion side reports at a synchronisation point.
struct SyncState {
  AxisVec machine_position;  // where the command rests now (machine coordinates)
  AxisVec actual_position;   // where the axes are (servo feedback)
  double time_s = 0.0;
  // After a skip block:
  bool skip_done = false;
  bool triggered = false;
  bool torque_reached = false;
  bool active_at_start = false;  // the input was already active (SkipSpec::active_at_start_fails)
  AxisVec latch_machine;         // machine coordinates stored by the skip
  int input_index = -1;          // which selected input ended the block (-1: none/torque)
  // No machine answered (canon): the skip "reached its end point" by
  // assumption, so a read of #5061.. is no read of a miss.
  bool no_machine = false;
};

enum class Step : std::uint8_t { kContinue, kSync, kEnd };

class Interpreter {
 public:
  [[nodiscard]] static Result<std::unique_ptr<Interpreter>> create(const Setup& setup,
                                                                   const AxisVec& start_machine);
  ~Interpreter();

  // Executes the next block (or the rest of it after a sync) and emits its
  // commands. kSync: drain the motion, then call sync(). kEnd: M02/M30/%.
  [[nodiscard]] Result<Step> step(CommandSink& out);
  // Completes a synchronisation. Fails with the dialect's alarm when a skip
  // block ended without a signal and K1 (or the miss parameter) asks for it.
  [[nodiscard]] Result<void> sync(const SyncState& state);

  // Reads a variable as a macro would (system variables included); for
  // --var. Does not synchronise: live positions are those of the last sync.
  [[nodiscard]] Result<Value> read_variable(int number) const;
  [[nodiscard]] Result<Value> read_named(std::string_view name) const;

  const ModalState& modal() const noexcept;
  // Machine coordinates -> work coordinates in program units, with the
  // offsets active now.
  AxisVec work_from_machine(const AxisVec& machine) const noexcept;
  // How a machine position reads in work coordinates with the offsets active
  // now, as #5041.. reads it (the dialect's tool offsets in or out).
  WorkFrame work_frame() const noexcept;
  const std::vector<std::string>& messages() const noexcept;
  const std::vector<Warning>& warnings() const noexcept;
  const std::vector<SkipRecord>& skips() const noexcept;
  std::uint32_t line() const noexcept;     // line of the block being executed
  std::uint32_t context() const noexcept;  // its call context
  // Every call context met so far (index = context id).
  const std::vector<CallContext>& contexts() const noexcept;
  // The skip block the machine is running (between step() returning kSync
  // for it and sync()): its record without the result.
  const SkipRecord* pending_skip() const noexcept;
  // Commanded machine position of the tool: where the machine is when it has
  // done everything emitted so far (under cutter compensation the tool
  // centre, off the programmed point by the offset vector).
  AxisVec position() const noexcept;
  // Writes #500-#999 when they changed, and the DPRNT file when --dprnt
  // named one and the program opened it (POPEN); each file atomically.
  // Called once at the end of a run.
  // Writes #500-#999 (when the run changed them) and the DPRNT file, and
  // lets other runs have the persistent-variable file.
  [[nodiscard]] Result<void> save_persistent();
  // Lets other runs have the file without writing it (an interrupted run).
  void release_persistent() noexcept;

  struct Impl;

 private:
  explicit Interpreter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace skipnc::interp
