// A dialect: one controller family's numbers and names as data
// (data/dialects/<name>.toml), plus the few behaviours that differ, each a
// named switch. Nothing in the interpreter tests a dialect's name.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "canon/canon.hpp"
#include "core/diag.hpp"

namespace skipnc::config {

struct AlarmText {
  int number = 0;
  std::string code;     // e.g. "PS0035", "P608"
  std::string message;  // the control's text
};

enum class ParamKind : std::uint8_t { kBits, kInt, kReal };

struct ParamDef {
  int number = 0;
  std::string name;
  ParamKind kind = ParamKind::kInt;
  double default_value = 0.0;
  double min = -1e300;
  double max = 1e300;
  std::string text;
};

// Where the skip feed comes from.
enum class SkipFeedRule : std::uint8_t {
  kModal,           // F in the block, else the modal F (which the block's F updates)
  kBlockOrParam,    // F in the block, else a parameter; the modal F is not updated (Mitsubishi)
  kParamSwitch,     // a parameter chooses between F/modal F and a fixed parameter feed (NCT)
};

// How skip-variable results are exposed.
struct SkipVariables {
  int work_base = 5061;      // #5061.. workpiece position at the latch (0: none)
  int machine_base = 0;      // machine position at the latch (0: none)
  std::string named_machine; // CompassNC: "NC.SysVars.G31.MCS." + axis name
  std::string named_local;   // CompassNC: "NC.SysVars.G31.LCS." + axis name
  int success_flag = 0;      // variable set to 1/0 after a skip (0: none)
};

struct Switches {
  int macro_bracket_depth = 5;          // [ ] nesting in a macro expression (Fanuc: 5, PS0118)
  int skip_p_first = 1;                 // P value of the first skip input (Fanuc 1, NCT 0)
  int skip_p_count = 12;                // number of selectable inputs
  bool skip_p_required_range = true;    // P outside range is an alarm
  canon::SkipStop skip_stop = canon::SkipStop::kImmediate;
  bool skip_miss_alarm_default = false; // K omitted
  bool skip_active_at_start_ends = true;   // level input already active ends the block
  bool skip_edge_rising_only = false;   // CompassNC: rising edge of Skip only
  SkipFeedRule skip_feed = SkipFeedRule::kModal;
  int skip_feed_param = 0;              // parameter with the skip feed (Mitsubishi 1174, NCT G31FD)
  int skip_feed_switch_param = 0;       // NCT SKIPF
  bool skip_g53_allowed = false;        // CompassNC: G31 G53 targets machine coordinates
  bool torque_skip = true;              // P98/P99 available
  bool multi_step = true;               // P1.. selects inputs
  bool next_block_from_stop = true;     // next block starts where the axes stopped
  bool tool_position_offset = false;    // G45-G48 exist (NCT)
  bool calculator_decimal_default = false;
};

struct Dialect {
  std::string name;
  std::string title;
  std::array<AlarmText, static_cast<std::size_t>(AlarmId::kCount)> alarms{};
  std::vector<ParamDef> params;
  Switches sw;
  SkipVariables skip_vars;
  // Fixed skip-input addresses, index 0 = first selectable input (P first).
  std::vector<canon::SignalAddr> fixed_skip_inputs;

  const ParamDef* param(int number) const noexcept;
  const AlarmText& alarm(AlarmId id) const noexcept {
    return alarms[static_cast<std::size_t>(id)];
  }
};

// Loads a dialect from TOML text. `origin` names the file in errors.
[[nodiscard]] Result<Dialect> parse_dialect(std::string_view toml_text, std::string_view origin);
// A built-in dialect by name (data/dialects/<name>.toml compiled in).
[[nodiscard]] Result<Dialect> builtin_dialect(std::string_view name);
std::vector<std::string> builtin_dialect_names();

}  // namespace skipnc::config
