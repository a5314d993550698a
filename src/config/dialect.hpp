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
#include "core/nc_code.hpp"

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
  kModal,         // F in the block, else the modal F (which the block's F updates)
  kBlockOrParam,  // F in the block, else a parameter (none: F required, Haas); the modal F is
                  // not updated (Mitsubishi)
  kParamSwitch,   // a parameter chooses between F/modal F and a fixed parameter feed (NCT)
  kLastCutting,   // F in the block, else the last F of a non-rapid block (CompassNC)
};

// What the P word of a G31 block means.
enum class SkipPMode : std::uint8_t {
  kMultiStep,  // P<first>..: one input each, reported as multi-step skip (seed 000: P1-P12)
  kSelect,     // P<first>..: chooses the one skip input (NCT: P0-P3 = inputs 1-4)
  kBitmask,    // P1-P255: bit n-1 set = input n ends the block (Mitsubishi multi-step skip 2)
  kNone,       // no P in a G31 block (CompassNC)
};

// Whether feed override and dry run act on a G31 block.
enum class SkipOverride : std::uint8_t {
  kSkfParam,  // 6200#7 SKF = 0: no (fixed 100 %, dry run ignored); SKF = 1: yes (seed 000)
  kFixed,     // never; override 0 % still stops the axes (Mitsubishi)
  kNormal,    // as in G01 (the manual says nothing else)
};

// Whether the G31 move accelerates and decelerates automatically.
enum class SkipAccel : std::uint8_t {
  kSkfParam,  // 6200#7 SKF (seed 000)
  kNever,     // Mitsubishi (2): the feed steps to F
  kAlways,    // as a G01 block
};

// Which axis the n-th variable of a work offset (#5201.., #5221..,
// #7001.., #14001..) is: the machine's n-th axis in its order (Fanuc: the
// controlled-axis number), or the axis named by the n-th letter of X Y Z A B
// C (Haas: #5221-#5225 "G54 X, Y, Z, A, B", and #5226 G54's C as Autodesk's
// Haas post writes it; docs/skip-dialects.md#haas).
enum class OffsetVariables : std::uint8_t { kPosition, kLetter };

// How skip-variable results are exposed.
struct SkipVariables {
  int work_base = 5061;       // #5061.. workpiece position at the latch (0: none)
  int machine_base = 0;       // machine position at the latch (0: none)
  std::string named_machine;  // CompassNC: "NC.SysVars.G31.MCS." + axis name
  std::string named_local;    // CompassNC: "NC.SysVars.G31.LCS." + axis name
  std::string named_aux;      // name of the axes after X Y Z in named variables ("Aux" -> Aux1..)
  int success_flag = 0;       // variable set to 1/0 after a skip (0: none)
};

// The names of the skip handshake signals in the trace (CompassNC's PLC data
// structure G31SkipMove); empty: the dialect has no such handshake to show.
struct SkipHandshakeNames {
  std::string active, skip, recorded, done;
  bool empty() const noexcept { return active.empty(); }
};

// The language of the programs (docs/languages.md).
enum class Language : std::uint8_t {
  kMacroB,    // Fanuc Custom Macro B: #1-#33 locals, IF/GOTO/WHILE/DO/END, G65
  kRs274ngc,  // LinuxCNC RS274NGC: O-word subroutines and control flow, named parameters
  kGrbl,      // grbl: G code only, no parameters or expressions
};

struct Switches {
  Language language = Language::kMacroB;
  int macro_bracket_depth = 5;  // [ ] nesting in a macro expression (Fanuc: 5, PS0118)
  // Subroutine calls an O-word call may nest (0: the machine's
  // limits.max_macro_levels); LinuxCNC: 9 (INTERP_SUB_ROUTINE_LEVELS 10 with the main).
  int call_levels = 0;
  // G31 and its family exist (false: LinuxCNC, grbl probe with G38 only).
  bool skip_g31 = true;
  // G38.2-G38.5 straight probe, in motion group 01 (LinuxCNC, grbl).
  bool probe_g38 = false;
  // After a G38 probe the control prints "[PRB:x,y,z:1]" (grbl: machine
  // coordinates, 1 = contact).
  bool probe_report_line = false;
  // Parameter whose bit 0 inverts the probe input (grbl $6); 0: none.
  int probe_invert_param = 0;
  // How a G38 probe latches: at the first servo sample that sees the input
  // (LinuxCNC's motion controller, once per servo period) or at the edge's
  // instant; the actual (feedback) position or the command (grbl's step
  // count: a stepper control has no feedback).
  bool probe_latch_sampled = false;
  bool probe_latch_actual = true;
  // A G38 move whose end point is its start point is refused for every
  // G38 (grbl: error 33) or only for G38.2 and G38.4 (LinuxCNC: "Start
  // point too close to probe point"; G38.3/G38.5 run and end at once).
  bool probe_same_point_all = false;
  SkipPMode skip_p_mode = SkipPMode::kMultiStep;
  int skip_p_first = 1;   // P value of the first skip input (Fanuc 1, NCT 0)
  int skip_p_count = 12;  // number of selectable inputs
  canon::SkipStop skip_stop = canon::SkipStop::kImmediate;
  bool skip_k_word = true;                // K0/K1 chooses an alarm on a miss (seed 000)
  int skip_miss_param = 0;                // parameter with the K default (0: no alarm)
  bool skip_active_at_start_ends = true;  // level input already active ends the block
  bool skip_edge_rising_only = false;     // CompassNC: rising edge of Skip only
  int skip_signal_param = 0;              // Fanuc 6200: #0 TSG edge, #1 SK0 low, #7 SKF
  SkipFeedRule skip_feed = SkipFeedRule::kModal;
  int skip_feed_param = 0;         // parameter with the skip feed (Mitsubishi 1174, NCT G31FD)
  int skip_feed_switch_param = 0;  // NCT SKIPF
  SkipOverride skip_override = SkipOverride::kSkfParam;
  SkipAccel skip_accel = SkipAccel::kSkfParam;
  bool skip_requires_axis = false;        // G31 without an axis word is a format error (NCT)
  bool skip_g53_allowed = false;          // CompassNC: G31 G53 targets machine coordinates
  bool skip_ignored_when_locked = false;  // Mitsubishi: machine lock / Z-axis cancel
  // An axis held by machine lock / Z-axis cancel stores its command position
  // at the signal (true) or the machine's, which does not move (false).
  bool skip_locked_stores_command = true;
  bool torque_skip = true;            // P98/P99 available
  int torque_q_param = 0;             // 6280: Q when omitted
  int torque_delay_param = 0;         // 6281: detection delay, ms
  int sync_axes_param = 0;            // axes under synchronous control (bit per axis)
  int machine_lock_param = 0;         // skipnc: machine lock switch
  int z_cancel_param = 0;             // skipnc: Z-axis cancel switch
  int dry_run_feed_param = 0;         // dry-run feed, mm/min
  int block_delete_param = 0;         // skipnc: block delete switches /1../9 (bit n-1)
  bool tool_position_offset = false;  // G45-G48 exist (NCT)
  // The bit that turns the in-position check at the end of a rapid off
  // (Fanuc 1601#5 NCI); 0: always on.
  // How many skip inputs (SKIP, SKIP2, ...) skip_signal_param's TSG and SK0
  // bits apply to; 0: all.
  int skip_signal_param_inputs = 0;
  int rapid_no_in_position_param = 0;
  int rapid_no_in_position_bit = 0;
  // Two G codes of one modal group in a block: the last one is used (true)
  // or the block is refused with g_code_conflict (false).
  bool g_same_group_last_wins = false;
  bool calculator_decimal_default = false;
  // Position variables with the tool offsets (length, G45-G48, lathe tool
  // offset) in them, i.e. the tool reference point rather than the programmed
  // tip (docs/position-variables.md): #5001.. block end point, #5041..
  // current work position, #5061.. skip position. #5021.. (machine) always
  // has them: it is where the machine is.
  bool block_end_tool_offsets = false;
  bool current_tool_offsets = true;
  bool skip_tool_offsets = true;
  // #5061.. (and the report's skips[].position, the same number) hold the
  // skip position rounded to the least input increment (0.001 mm, 0.0001
  // inch: the control counts positions in whole increments), or the latched
  // value as it is (a control computing in floating point).
  bool skip_position_increment = false;
  // `//` starts a comment to the end of the block (CompassNC).
  bool slash_comments = false;
  // M97 Pn Ll: a local subprogram call, to sequence number n of the running
  // program, l times, back with M99 (Haas; docs/skip-dialects.md#haas).
  bool local_sub_call_m97 = false;
  // G103 Pn: block look-ahead limit, P 0-15 (Haas): the planner's window
  // (canon::LookAhead). skipnc's interpreter already waits for the motion
  // wherever a value it reads depends on it, which is what G103 P1 gives a
  // probing macro.
  bool block_lookahead_g103 = false;
  // `N50 [#100 LT 10] M99 P10`: an expression at the head of an M99 block
  // makes it conditional (Haas: "The M99 conditional construct is unique to
  // the Haas control"); false: a value without an address (Fanuc).
  bool conditional_m99 = false;
  // M99 Pn in a subprogram: jumps to Nn of the same subprogram and stays in
  // it (Haas), or returns to Nn of the caller (false: Fanuc).
  bool m99_p_jumps_in_subprogram = false;
  // #2001-#2800 are the tool offsets as Haas numbers them: #2001-#2200
  // length (geometry), #2201-#2400 length wear, #2401-#2600 diameter/radius,
  // #2601-#2800 its wear (false: Fanuc's short forms, #2001.. wear,
  // #2201.. geometry, and #2500-#2806 the old work offsets).
  bool haas_tool_offset_vars = false;
  // Work-offset variables numbered by the axis's position in the machine
  // or by its letter (OffsetVariables).
  OffsetVariables offset_variables_by = OffsetVariables::kPosition;
};

struct Dialect {
  std::string name;
  std::string title;
  std::array<AlarmText, static_cast<std::size_t>(AlarmId::kCount)> alarms{};
  std::vector<ParamDef> params;
  Switches sw;
  SkipVariables skip_vars;
  SkipHandshakeNames handshake;
  // Fixed skip-input addresses, index 0 = first selectable input (P first).
  std::vector<canon::SignalAddr> fixed_skip_inputs;
  // [codes]: codes this control does not have (unknown_g_code), and codes
  // it has that skipnc does not simulate, among them those of skipnc's table
  // that mean something else there (not_simulated).
  std::vector<GCode> absent_g;
  std::vector<GCode> not_simulated_g;
  std::vector<int> not_simulated_m;  // M codes with an effect skipnc does not model
  std::vector<int> absent_m;         // M codes the control refuses (unknown_m_code)

  const ParamDef* param(int number) const noexcept;
  const AlarmText& alarm(AlarmId id) const noexcept { return alarms[static_cast<std::size_t>(id)]; }
};

// Loads a dialect from TOML text. `origin` names the file in errors.
[[nodiscard]] Result<Dialect> parse_dialect(std::string_view toml_text, std::string_view origin);
// A built-in dialect by name (data/dialects/<name>.toml compiled in).
[[nodiscard]] Result<Dialect> builtin_dialect(std::string_view name);
std::vector<std::string> builtin_dialect_names();

}  // namespace skipnc::config
