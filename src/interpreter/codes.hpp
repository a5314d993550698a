// The G and M codes the interpreter executes, as data: code, modal group,
// on which machines and dialects it exists, and what it does (a modal state
// setter or a one-shot action). The block executor (ncblock.cpp) reads
// every G word through this table; docs/codes.md can be generated from it.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "core/diag.hpp"
#include "interpreter/modal.hpp"

namespace skipnc::interp {

// Modal groups, numbered as Fanuc numbers them (group 00: one-shot codes).
enum class Group : std::uint8_t {
  k00 = 0,
  k01 = 1,
  k02 = 2,
  k03 = 3,
  k04 = 4,  // RS274NGC: G90.1 / G91.1 (arc centre distance mode)
  k05 = 5,
  k06 = 6,
  k07 = 7,
  k08 = 8,
  k09 = 9,
  k10 = 10,
  k11 = 11,
  k12 = 12,
  k13 = 13,  // machining centre: G96/G97 (Fanuc M series, constant surface speed)
  k14 = 14,
  k15 = 15,
  k16 = 16,
  k17 = 17,
  k22 = 22,
};
inline constexpr int kGroupSlots = 23;  // index = group number

// Where a code exists (bits): on a machining centre, on a lathe (G-code
// system A), and only in dialects with the tool position offset switch.
enum Avail : std::uint8_t {
  kMill = 1,
  kLathe = 2,
  kBoth = kMill | kLathe,
  kToolPosOffsetDialect = 4,
  kG38Dialect = 8,  // dialects with the probe_g38 switch: LinuxCNC and grbl codes
};

// What a one-shot (group 00) code does. G09 and G53 modify the block's
// motion and combine with it; every other action is the block's only one.
enum class Action : std::uint8_t {
  kNone,
  kDwell,          // G04
  kExactStop,      // G09 (modifier)
  kDataSetting,    // G10
  kRefReturn,      // G28
  kRefReturn2,     // G30
  kSkip,           // G31
  kToolPosOffset,  // G45-G48
  kLatheCoordSet,  // G50 (lathe)
  kLocalShift,     // G52
  kMachineCoord,   // G53 (modifier)
  kMacroCall,      // G65
  kCoordSet,       // G92
  kNgc,  // LinuxCNC/grbl one-shot codes: G28.1 G30.1 G43.1 G92.1 G92.2 G92.3 (ngc_codes.cpp)
};

constexpr bool is_modifier(Action a) noexcept {
  return a == Action::kExactStop || a == Action::kMachineCoord;
}

struct CodeDef {
  int code;  // x10: G54.1 -> 541
  Group group;
  std::uint8_t avail;
  void (*set)(ModalState&) noexcept;  // modal codes: the state it selects (else null)
  Action action;                      // group 00 codes
  const char* summary;
};

// Every G code of the interpreter, in code order.
std::span<const CodeDef> g_codes() noexcept;

// The definition of G code `code` (x10) on this machine, or null.
const CodeDef* find_g(int code, bool lathe) noexcept;

// "G54.1" for 541.
const char* g_summary(int code) noexcept;

// M codes with a meaning of their own; any other M code goes to the machine.
enum class MAction : std::uint8_t {
  kMachine,       // passed on (canon::MCode)
  kProgramStop,   // M00
  kOptionalStop,  // M01
  kProgramEnd,    // M02
  kRewindEnd,     // M30
  kSpindleCw,     // M03
  kSpindleCcw,    // M04
  kSpindleStop,   // M05
  kSubCall,       // M98
  kSubReturn,     // M99
  kLocalSubCall,  // M97 (Haas: local_sub_call_m97; elsewhere a machine M code)
};

struct MCodeDef {
  int code;
  MAction action;
  const char* summary;
};

std::span<const MCodeDef> m_codes() noexcept;
MAction m_action(int code) noexcept;

// docs/codes.md: every G and M code per dialect and machine type, with what
// skipnc does with it, found by running each code through the interpreter
// (codes_doc part of codes.cpp); a test compares the page with the file.
enum class CodeStatus : std::uint8_t {
  kSimulated,     // runs and has its effect
  kNoEffect,      // accepted, changes nothing in the simulation
  kNotSimulated,  // alarm not_simulated: a real code skipnc does not model
  kImproper,      // alarm unknown_g_code: not a code of this machine or control
};

// The status of one G code (x10: G54.1 = 541) on a built-in machine
// ("mill3", "lathe2") under a dialect, found by running it.
[[nodiscard]] Result<CodeStatus> g_code_status(int code, const std::string& machine,
                                               const std::string& dialect);

// True for the G codes that are accepted without effect (mill_codes.cpp).
bool g_code_without_effect(int code) noexcept;

// The whole page (Markdown).
[[nodiscard]] Result<std::string> codes_markdown();

}  // namespace skipnc::interp
