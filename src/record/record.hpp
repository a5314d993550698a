// The run's vocabulary, below the interpreter: what a program run is given
// (Setup) and what it leaves for those who read it (skip records, warnings,
// call contexts, work frames). The interpreter fills these values; the
// simulator, the report and the plot read them without seeing the
// interpreter (docs/architecture.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "canon/canon.hpp"
#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "core/axes.hpp"

namespace skipnc::record {

// What a program run is given.
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
  std::string code = "G31";   // the move's code: G31, G37, G38.2-G38.5 (modal G38 too)
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

}  // namespace skipnc::record
