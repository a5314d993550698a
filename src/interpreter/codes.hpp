// The code table: every G and M code the interpreter reads, as data: code,
// modal group, on which machines and dialects it exists, what it does (the
// kind of its handler: a modal state setter, a one-shot action, a canned
// cycle, a frame, ...), its name in words. The block plan (block_plan.cpp
// plan_g_codes) reads every G word through it, in O(1); docs/codes.md is
// generated from it (codes_doc.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "core/diag.hpp"
#include "core/nc_code.hpp"
#include "interpreter/modal.hpp"

namespace skipnc::config {
struct Switches;
}

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
  k19 = 19,  // machining centre: G40.1-G42.1 (normal direction control)
  k21 = 21,  // machining centre: G12.1/G13.1 (polar coordinate interpolation)
  k22 = 22,
};
inline constexpr int kGroupSlots = 23;  // index = group number

// Where a code exists (bits): on a machining centre, on a lathe (G-code
// system A), and only in dialects with a switch (config::Switches).
enum Avail : std::uint8_t {
  kMill = 1,
  kLathe = 2,
  kBoth = kMill | kLathe,
  kToolPosOffsetDialect = 4,  // tool_position_offset: G45-G48
  kG38Dialect = 8,            // probe_g38: the LinuxCNC and grbl codes
  kSkipDialect = 16,          // skip_g31: G31
  kLookaheadDialect = 32,     // block_lookahead_g103: G103 (Haas)
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

// What the interpreter does with a code: the kind of its handler.
enum class Handler : std::uint8_t {
  kModal,         // selects a modal state of its group (CodeDef::set)
  kOneShot,       // a group-00 action (CodeDef::action), block_plan.cpp and block_commit.cpp
  kCycle,         // a canned cycle (CodeDef::cycle), mill_codes.cpp
  kFrame,         // G68 G69 G50 G51 G50.1 G51.1 G15 G16 G54.4 (CodeDef::frame), mill_codes.cpp
  kNoEffect,      // accepted without effect: a warning says what it is
  kNotSimulated,  // a real code skipnc does not model: alarm not_simulated
  kLookahead,     // G103 Pn
  kSkipStep,      // G31.1-G31.3: where the dialect has their parameters, else not simulated
  kG37,           // G37: where the dialect has its parameters, else not simulated
  kG37_1,         // G37.1: a code (not simulated) where the dialect has its parameter
  kRefused,       // not a code of this machine: CodeDef::summary says what to write instead
};

// The frames of mill_codes.cpp (Handler::kFrame).
enum class FrameCode : std::uint8_t {
  kNone,
  kRotation,        // G68
  kRotationCancel,  // G69
  kScaling,         // G51
  kScalingCancel,   // G50 (mill)
  kMirror,          // G51.1
  kMirrorCancel,    // G50.1
  kPolar,           // G16
  kPolarCancel,     // G15
  kSettingError,    // G54.4 (where the dialect has its parameter)
};

using ModalSetter = void (*)(ModalState&) noexcept;

struct CodeDef {
  GCode code;
  Group group;
  std::uint8_t avail;
  Handler handler;
  ModalSetter set = nullptr;      // kModal: the state it selects (G54.1: null, P picks it)
  Action action = Action::kNone;  // kOneShot
  Cycle cycle = Cycle::kNone;     // kCycle
  FrameCode frame = FrameCode::kNone;
  const char* summary = nullptr;  // the function, in words (messages)
  // docs/codes.md: the function on a machining centre and, where G-code
  // system A gives it another one, on a lathe. A code is listed when one
  // of its entries has a doc name (the first such entry names it).
  const char* doc = nullptr;
  const char* doc_lathe = nullptr;
  bool modal_state() const noexcept {
    return handler == Handler::kModal || handler == Handler::kOneShot;
  }
};

// Every G code of the interpreter, of every machine and dialect, in code
// order (a code the mill and the lathe read differently has two entries).
std::span<const CodeDef> g_codes() noexcept;

// The definition of G code `code` on this machine, or null; a refusal
// (Handler::kRefused) is returned too. O(1): a table indexed by code.
const CodeDef* find_g(GCode code, bool lathe) noexcept;

// Why `def`, a code only some dialects have, is not a code under these
// switches (the unknown_g_code message), or nothing when the dialect has it.
std::optional<std::string> not_in_this_dialect(const CodeDef& def, const config::Switches& sw);
inline constexpr std::uint8_t kDialectBits =
    kG38Dialect | kSkipDialect | kToolPosOffsetDialect | kLookaheadDialect;
inline std::optional<std::string> not_in_dialect(const CodeDef& def, const config::Switches& sw) {
  if ((def.avail & kDialectBits) == 0) return std::nullopt;  // the common case
  return not_in_this_dialect(def, sw);
}

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
MAction m_action(int code) noexcept;  // O(1)

// docs/codes.md: every G and M code per dialect and machine type, with what
// skipnc does with it, found by running each code through the interpreter
// (codes_doc part of codes.cpp); a test compares the page with the file.
enum class CodeStatus : std::uint8_t {
  kSimulated,     // runs and has its effect
  kNoEffect,      // accepted, changes nothing in the simulation
  kNotSimulated,  // alarm not_simulated: a real code skipnc does not model
  kImproper,      // alarm unknown_g_code: not a code of this machine or control
};

// The status of one G code on a built-in machine ("mill3", "lathe2") under
// a dialect, found by running it.
[[nodiscard]] Result<CodeStatus> g_code_status(GCode code, const std::string& machine,
                                               const std::string& dialect);

// True for the G codes that are accepted without effect.
bool g_code_without_effect(GCode code) noexcept;

// The whole page (Markdown).
[[nodiscard]] Result<std::string> codes_markdown();

}  // namespace skipnc::interp
