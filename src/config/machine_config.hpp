// The machine file: axes and their limits, servo model, dialect, parameter
// overrides, offsets. Strict: an unknown key or a value out of range is an
// error with file, line and column at load time.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "canon/canon.hpp"
#include "config/dialect.hpp"
#include "config/param_numbers.hpp"
#include "core/axes.hpp"
#include "core/diag.hpp"

namespace skipnc::config {

struct AxisConfig {
  char name = 'X';
  double min_mm = -500.0;  // stroke limits, machine coordinates
  double max_mm = 500.0;
  double rapid_mm_min = 30000.0;
  double max_feed_mm_min = 20000.0;
  double accel_mm_s2 = 2000.0;
  // Servo: velocity = feedforward * commanded velocity + kp * following error.
  double kp_per_s = 30.0;
  double feedforward = 0.0;  // 0..1
  // Motor torque, % of rated: torque_per_mm * following error while the axis
  // is held by a stop; the servo's own torque limit is torque_max_pct.
  double torque_pct_per_mm = 100.0;
  double torque_max_pct = 300.0;
};

struct ToolOffset {
  double length_geometry = 0.0;  // H
  double length_wear = 0.0;
  double radius_geometry = 0.0;  // D; on a lathe the tool-nose radius
  double radius_wear = 0.0;
  // Lathe (T code): X and Z offsets, program units of the axis (X in
  // diameter when the X axis is programmed in diameter, 1006#3).
  double x_geometry = 0.0;
  double z_geometry = 0.0;
  double x_wear = 0.0;
  double z_wear = 0.0;
  int tip = 0;  // imaginary tool-nose direction 0-9
};

// What the machine is: a mill (X Y Z ...) or a lathe (X and Z, optionally
// C), which reads programs in G-code system A (docs/lathe.md).
enum class MachineType : std::uint8_t { kMill, kLathe };

// One parameter setting of the machine file or the command line.
struct ParamSetting {
  int number = 0;
  int bit = -1;  // -1: the whole parameter
  double value = 0.0;
  SourceLoc loc;
};

// Bounds on what one run may take ([limits] in the machine file; each key's
// range is in kLimitKeys, machine_config.cpp, and docs/machine.md). Each
// bound that is passed is its own alarm.
struct Limits {
  std::int64_t max_ticks = 3'600'000'000;  // simulated time limit (1000 h at 1 ms)
  std::int64_t max_macro_statements = 100'000'000;
  int max_macro_levels = 4;
  int max_subprogram_levels = 10;
  double max_cpu_s = 3600.0;                 // processor time of one run (cpu_limit)
  std::int64_t max_trace_bytes = 4LL << 30;  // the --trace file (trace_limit)
  // Kept in memory by one run: the report's messages (past the bound they
  // are dropped, and one message says so), the text of the --dprnt file
  // (dprnt_limit) and the #<name> variables (named_variable_limit).
  std::int64_t max_message_bytes = 16LL << 20;
  std::int64_t max_dprnt_bytes = 64LL << 20;
  std::int64_t max_named_variables = 100000;
  // N labels a program's jump index (GOTO, M99 P) keeps: 24 bytes each. A
  // program with more is searched by a scan per number asked for instead,
  // so memory does not grow with the file.
  std::int64_t max_label_index = 1000000;
};

struct MachineConfig {
  std::string name = "mill3";
  std::string origin;   // file it came from, or "built-in mill3"
  std::string extends;  // the machine it extends (`extends`), as its origin; empty: none
  std::vector<std::string>
      extends_files;  // the machine files of the `extends` chain, nearest first
  std::string dialect = "fanuc";
  MachineType type = MachineType::kMill;
  double spindle_max_rpm = 10000.0;  // the spindle's own top speed
  std::int64_t period_ns = 1'000'000;
  std::vector<AxisConfig> axes;
  std::vector<ParamSetting> params;  // overrides of the dialect's defaults, in order
  // Work offsets: [0] external (EXT / G54 common shift), [1..6] G54..G59, mm.
  std::array<AxisVec, 7> work_offsets{};
  // G30 P2, P3, P4: the 2nd-4th reference points, machine mm (Fanuc 1241-1243).
  std::array<AxisVec, 3> reference_points{};
  std::map<int, ToolOffset> tool_offsets;  // by offset number
  int tool_offset_count = 200;
  bool inch_machine = false;
  canon::SkipLatch latch = canon::SkipLatch::kExact;
  double latch_delay_s = 0.0;      // sampled latch: detection delay after the sample
  bool servo_delay_comp = true;    // latch the actual position (else the commanded)
  double in_position_mm = 0.0005;  // in-position width for exact stop
  // An axis at rest (its command still) that stays out of the width this
  // long is an alarm (in_position_timeout): held by a stop, it never arrives.
  double in_position_timeout_s = 1.0;
  std::string persistent_vars;  // file for #500-#999; empty: not kept
  Limits limits;
  // LinuxCNC's INI file and HAL pins as an RS274NGC program reads them
  // (#<_ini[SECTION]NAME>, #<_hal[pin]>): [ini.SECTION] NAME = value and
  // [hal] "pin" = value (machine_ini.cpp). Keys as written.
  std::map<std::string, std::map<std::string, double>> ini;
  std::map<std::string, double> hal;

  int axis_count() const noexcept { return static_cast<int>(axes.size()); }
  bool lathe() const noexcept { return type == MachineType::kLathe; }
  // Index of an axis by letter, -1 when absent.
  int axis_index(char letter) const noexcept;
};

// A machine file's text. `extends = "mill3"` (a built-in) or `extends =
// "base.toml"` (a file, relative to `origin`'s folder) starts from that
// machine; the keys of this file then change only what they name.
[[nodiscard]] Result<MachineConfig> parse_machine(std::string_view toml_text,
                                                  std::string_view origin);
[[nodiscard]] Result<MachineConfig> load_machine_file(const std::string& path);
// "mill3" and the other built-in machines (data/machines/<name>.toml).
[[nodiscard]] Result<MachineConfig> builtin_machine(std::string_view name);
std::vector<std::string> builtin_machine_names();

// Effective parameters: dialect defaults, then the machine file, then the
// command line. Values are checked against the dialect's ranges.
class Parameters {
 public:
  Parameters() = default;
  explicit Parameters(const Dialect* dialect);

  double get(int number) const noexcept;
  bool bit(int number, int b) const noexcept;
  bool bit(param::Bit b) const noexcept { return bit(b.number, b.bit); }
  [[nodiscard]] Result<void> apply(const ParamSetting& s);
  // "6200#7=1" or "1174=200" (command line)
  [[nodiscard]] static Result<ParamSetting> parse_setting(std::string_view text);
  const std::map<int, double>& overrides() const noexcept { return values_; }

 private:
  void set(int number, double value);

  const Dialect* dialect_ = nullptr;
  std::map<int, double> values_;  // the settings applied
  // Every parameter's effective value, by number: get() is a binary search
  // (it is read in every motion block).
  std::vector<std::pair<int, double>> table_;
};

}  // namespace skipnc::config
