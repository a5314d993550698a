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

namespace skipnc::interp {

struct Setup {
  const config::MachineConfig* machine = nullptr;
  const config::Dialect* dialect = nullptr;
  const config::Parameters* params = nullptr;
  std::string program_path;               // the main program file
  std::string program_text;               // used instead of the file when program_path is empty
  std::string program_name = "program";   // shown in errors and reports
  std::vector<std::string> include_dirs;  // subprogram lookup; the program's folder when empty
  std::string log_dir;     // RS274NGC (LOGOPEN,..)/(PROBEOPEN ..) files; empty: not written
  std::string dprnt_path;  // DPRNT output file; empty: DPRNT lines go to messages only
  // Macro variables set before the first block (#1-#33 of the main program,
  // #100-#199, #500-#999; a #500-#999 value replaces the persistent file's
  // and is written back only if the program changes a variable). Python
  // module and sweeps.
  std::vector<std::pair<int, double>> variables;
  // --strict: a warning is an alarm (strict_warning) at the block that
  // raised it, instead of a line in the report.
  bool strict = false;
  // --allow CODE: warnings with these codes stay warnings under --strict.
  std::vector<std::string> strict_allow;
};

// Something the run did that a user should know and that is not an alarm:
// a code accepted without effect, a move that may overcut, a skip value read
// after a miss, a program without an end. `code` is stable (docs/cli.md).
struct Warning {
  std::string code;
  std::uint32_t context = 0;  // CallContext of the block
  std::uint32_t line = 0;
  std::string text;
  int count = 1;  // times the same block raised it (a loop): one entry per place
  friend bool operator==(const Warning&, const Warning&) = default;
};

// Adds `w` to `list`, one entry per (code, context, line): raised again by
// the same block it counts up. At most kMaxWarnings places are kept, then one
// `warnings_dropped` says so. Used by the interpreter and the machine side.
inline constexpr std::size_t kMaxWarnings = 1000;
void add_warning(std::vector<Warning>& list, Warning w);

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

// Where a block runs: its file and program, and the call that led there.
// Every distinct call path is one context; canon::Stamped::source, the
// trace and the report name a block by (context, line). Context 0 is the
// main program.
struct CallContext {
  static constexpr std::uint32_t kNone = 0xffffffffu;
  std::string file;              // as shown (the file name as given or as found)
  std::int64_t program = 0;      // O number (0: a main program without one)
  std::uint32_t parent = kNone;  // the calling context
  std::uint32_t call_line = 0;   // line of the calling block in the parent
  std::string call;              // "G65 P9023", "M98 P1000", "G66 P9023"
  std::string path;              // where the file was read from ("" when given as text)
  friend bool operator==(const CallContext&, const CallContext&) = default;
};

// Machine -> work coordinates for one state of the offsets: axis i reads
// (machine_i * scale_i - shift_i) / unit_mm (program units; scale 2 for a
// lathe's X in diameter). The trace's work columns use the frame of the
// block that is running.
struct WorkFrame {
  AxisVec scale;
  AxisVec shift;
  double unit_mm = 1.0;
  AxisVec apply(const AxisVec& machine, int axes) const noexcept {
    AxisVec w;
    for (int i = 0; i < axes; ++i) w[i] = (machine[i] * scale[i] - shift[i]) / unit_mm + 0.0;
    return w;
  }
  friend bool operator==(const WorkFrame&, const WorkFrame&) = default;
};

// One executed skip block, as the report shows it.
struct SkipRecord {
  std::uint32_t line = 0;
  std::uint32_t context = 0;  // CallContext of the block
  std::int32_t n = -1;        // N number of the block, -1 when none
  std::string block;          // the block's text
  canon::SkipKind kind = canon::SkipKind::kSkip;
  int p = -1;
  std::string signal;  // input that ended the block, "" when none
  bool triggered = false;
  double time_s = 0.0;
  AxisVec position;                        // stored (work coordinates, program units)
  bool position_has_tool_offsets = false;  // the tool reference point (dialect skip_tool_offsets)
  AxisVec machine_position;                // the same instant, machine coordinates
  AxisVec end_position;                    // where the axes came to rest, work coordinates
  // The run stopped by an alarm (probe crash, stroke limit, ...) while the
  // block ran: filled by the machine, which knows where.
  bool ended_by_alarm = false;
  std::optional<AxisVec> crash_machine;  // machine position of the alarm, when it has one
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
