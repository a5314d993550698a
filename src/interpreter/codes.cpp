// The code table. Groups and meanings: Fanuc 0i/30i G code lists (machining
// centre, and G-code system A of a lathe); a lathe numbers plane selection
// group 16 and G96/G97 group 02. Codes that only some dialects have carry
// their availability bit; the dialect files add the codes a control lacks
// or has without skipnc simulating them (absent_g, not_simulated_g).
#include "interpreter/codes.hpp"

#include <array>
#include <iterator>

#include "config/dialect.hpp"

namespace skipnc::interp {
namespace {

template <auto Field, auto Value>
constexpr void (*setter)(ModalState&) noexcept = [](ModalState& m) noexcept { m.*Field = Value; };

constexpr auto kNoSet = static_cast<void (*)(ModalState&) noexcept>(nullptr);

template <int Decimal>
constexpr void (*probe_setter)(ModalState&) noexcept = [](ModalState& m) noexcept {
  m.motion = Motion::kProbe;
  m.probe = GCode(38, Decimal);  // G38.2-G38.5
};

// Rows of the table, by kind.
struct Doc {
  const char* mill = nullptr;
  const char* lathe = nullptr;
};

constexpr CodeDef modal(GCode c, Group g, std::uint8_t avail, ModalSetter set, const char* summary,
                        Doc doc = {}) {
  return {c,
          g,
          avail,
          Handler::kModal,
          set,
          Action::kNone,
          Cycle::kNone,
          FrameCode::kNone,
          summary,
          doc.mill,
          doc.lathe};
}
constexpr CodeDef one_shot(GCode c, std::uint8_t avail, Action a, const char* summary,
                           Doc doc = {}) {
  return {c,       Group::k00, avail,        Handler::kOneShot,
          kNoSet,  a,          Cycle::kNone, FrameCode::kNone,
          summary, doc.mill,   doc.lathe};
}
constexpr CodeDef cycle(GCode c, Cycle cy, const char* summary, const char* doc) {
  return {c,       Group::k09, kMill,  Handler::kCycle, kNoSet, Action::kNone, cy, FrameCode::kNone,
          summary, doc,        nullptr};
}
constexpr CodeDef frame(GCode c, Group g, FrameCode f, const char* summary, const char* doc) {
  return {c, g,       kMill, Handler::kFrame, kNoSet, Action::kNone, Cycle::kNone,
          f, summary, doc,   nullptr};
}
// A mill code of another kind (no effect, not simulated, dialect-dependent).
constexpr CodeDef mill(GCode c, Group g, Handler h, const char* summary, const char* doc,
                       std::uint8_t avail = kMill) {
  return {c,       g,   avail,  h, kNoSet, Action::kNone, Cycle::kNone, FrameCode::kNone,
          summary, doc, nullptr};
}
// A code G-code system A (a lathe) gives another meaning or does not have,
// with what to write instead. The turning cycles are not modelled.
constexpr CodeDef refused(GCode c, const char* why) {
  return {c,      Group::k00,    kLathe,       Handler::kRefused,
          kNoSet, Action::kNone, Cycle::kNone, FrameCode::kNone,
          why,    nullptr,       nullptr};
}

constexpr GCode G(int number, int decimal = 0) {
  return GCode(number, decimal);
}

constexpr const char* kNotSystemA = " is not a code of a lathe";
constexpr const char* kTOffsets = " is not a code of a lathe: the T code offsets the tool";

// The mill's codes beside the core ones (mill_codes.cpp): canned cycles,
// frames, codes without effect, codes not simulated. Sources: Fanuc Series
// 30i/31i/32i-MODEL A operator's manual (machining centre) B-63944EN.
// clang-format off
constexpr CodeDef kG[] = {
    modal(G(0), Group::k01, kBoth, setter<&ModalState::motion, Motion::kRapid>, "positioning (rapid traverse)", {"positioning (rapid)"}),
    modal(G(1), Group::k01, kBoth, setter<&ModalState::motion, Motion::kLinear>, "linear interpolation", {"linear interpolation"}),
    modal(G(2), Group::k01, kBoth, setter<&ModalState::motion, Motion::kCwArc>, "circular interpolation CW", {"circular interpolation CW"}),
    modal(G(3), Group::k01, kBoth, setter<&ModalState::motion, Motion::kCcwArc>, "circular interpolation CCW", {"circular interpolation CCW"}),
    one_shot(G(4), kBoth, Action::kDwell, "dwell", {"dwell"}),
    mill(G(5, 1), Group::k00, Handler::kNoEffect, "AI contour control / high-speed machining mode", "AI contour control / high-speed machining"),
    mill(G(7, 1), Group::k00, Handler::kNotSimulated, "cylindrical interpolation", "cylindrical interpolation"),
    mill(G(8), Group::k00, Handler::kNoEffect, "advanced preview control", "advanced preview control"),
    one_shot(G(9), kBoth, Action::kExactStop, "exact stop (this block)", {"exact stop (one block)"}),
    one_shot(G(10), kBoth, Action::kDataSetting, "programmable data input", {"programmable data input"}),
    mill(G(12), Group::k00, Handler::kNotSimulated, "circle cutting (CW)", "circle cutting CW"),
    mill(G(12, 1), Group::k21, Handler::kNotSimulated, "polar coordinate interpolation", "polar coordinate interpolation"),
    mill(G(13), Group::k00, Handler::kNotSimulated, "circle cutting (CCW)", "circle cutting CCW"),
    mill(G(13, 1), Group::k21, Handler::kNoEffect, "polar coordinate interpolation cancel", "polar coordinate interpolation cancel"),
    frame(G(15), Group::k17, FrameCode::kPolarCancel, "polar coordinate command cancel", "polar coordinate command cancel"),
    frame(G(16), Group::k17, FrameCode::kPolar, "polar coordinate command", "polar coordinate command"),
    modal(G(17), Group::k02, kMill, setter<&ModalState::plane, PlaneSel::kXY>, "XY plane", {"XY plane"}),
    modal(G(17), Group::k16, kLathe, setter<&ModalState::plane, PlaneSel::kXY>, "XY plane"),
    modal(G(18), Group::k02, kMill, setter<&ModalState::plane, PlaneSel::kZX>, "ZX plane", {"ZX plane"}),
    modal(G(18), Group::k16, kLathe, setter<&ModalState::plane, PlaneSel::kZX>, "ZX plane"),
    modal(G(19), Group::k02, kMill, setter<&ModalState::plane, PlaneSel::kYZ>, "YZ plane", {"YZ plane"}),
    modal(G(19), Group::k16, kLathe, setter<&ModalState::plane, PlaneSel::kYZ>, "YZ plane"),
    modal(G(20), Group::k06, kBoth, setter<&ModalState::units, Units::kInch>, "inch input", {"inch input"}),
    modal(G(21), Group::k06, kBoth, setter<&ModalState::units, Units::kMetric>, "metric input", {"metric input"}),
    one_shot(G(28), kBoth, Action::kRefReturn, "reference position return", {"reference position return"}),
    one_shot(G(28, 1), kMill | kG38Dialect, Action::kNgc, "store the G28 position (#5161..)"),
    one_shot(G(30), kBoth, Action::kRefReturn2, "2nd-4th reference position return", {"2nd-4th reference position return"}),
    one_shot(G(30, 1), kMill | kG38Dialect, Action::kNgc, "store the G30 position (#5181..)"),
    one_shot(G(31), kBoth | kSkipDialect, Action::kSkip, "skip function", {"skip function"}),
    // G31.1-G31.3: simulated where the dialect has their parameters.
    mill(G(31, 1), Group::k00, Handler::kSkipStep, "multi-step skip on this control", "multi-step skip 1"),
    mill(G(31, 2), Group::k00, Handler::kSkipStep, "multi-step skip on this control", "multi-step skip 2"),
    mill(G(31, 3), Group::k00, Handler::kSkipStep, "multi-step skip on this control", "multi-step skip 3"),
    // G37: simulated where the dialect has its parameters (fanuc.toml).
    mill(G(37), Group::k00, Handler::kG37, "automatic tool length measurement on this control", "automatic tool length measurement"),
    // G37.1: a code where the dialect has its parameters (Mitsubishi's TLM).
    mill(G(37, 1), Group::k00, Handler::kG37_1, "automatic tool length measurement", nullptr),
    modal(G(38, 2), Group::k01, kMill | kG38Dialect, probe_setter<2>, "straight probe toward the part, error without contact", {"straight probe toward, error without contact"}),
    modal(G(38, 3), Group::k01, kMill | kG38Dialect, probe_setter<3>, "straight probe toward the part", {"straight probe toward"}),
    modal(G(38, 4), Group::k01, kMill | kG38Dialect, probe_setter<4>, "straight probe away from the part, error without loss of contact", {"straight probe away, error without loss of contact"}),
    modal(G(38, 5), Group::k01, kMill | kG38Dialect, probe_setter<5>, "straight probe away from the part", {"straight probe away"}),
    modal(G(40), Group::k07, kBoth, setter<&ModalState::cutter, CutterComp::kOff>, "cutter compensation cancel", {"cutter compensation cancel", "tool nose radius compensation cancel"}),
    mill(G(40, 1), Group::k19, Handler::kNoEffect, "normal direction control cancel", "normal direction control cancel"),
    modal(G(41), Group::k07, kBoth, setter<&ModalState::cutter, CutterComp::kLeft>, "cutter compensation left", {"cutter compensation left", "tool nose radius compensation left"}),
    mill(G(41, 1), Group::k19, Handler::kNotSimulated, "normal direction control left", "normal direction control left"),
    modal(G(42), Group::k07, kBoth, setter<&ModalState::cutter, CutterComp::kRight>, "cutter compensation right", {"cutter compensation right", "tool nose radius compensation right"}),
    mill(G(42, 1), Group::k19, Handler::kNotSimulated, "normal direction control right", "normal direction control right"),
    modal(G(43), Group::k08, kMill, setter<&ModalState::length, LengthComp::kPlus>, "tool length offset +", {"tool length compensation +"}),
    refused(G(43), kTOffsets),
    one_shot(G(43, 1), kMill | kG38Dialect, Action::kNgc, "dynamic tool length offset"),
    mill(G(43, 4), Group::k08, Handler::kNotSimulated, "tool centre point control", "tool centre point control"),
    modal(G(44), Group::k08, kMill, setter<&ModalState::length, LengthComp::kMinus>, "tool length offset -", {"tool length compensation -"}),
    refused(G(44), kTOffsets),
    one_shot(G(45), kMill | kToolPosOffsetDialect, Action::kToolPosOffset, "tool position offset increase", {"tool offset increase"}),
    refused(G(45), kNotSystemA),
    one_shot(G(46), kMill | kToolPosOffsetDialect, Action::kToolPosOffset, "tool position offset decrease", {"tool offset decrease"}),
    refused(G(46), kNotSystemA),
    one_shot(G(47), kMill | kToolPosOffsetDialect, Action::kToolPosOffset, "tool position offset double increase", {"tool offset double increase"}),
    refused(G(47), kNotSystemA),
    one_shot(G(48), kMill | kToolPosOffsetDialect, Action::kToolPosOffset, "tool position offset double decrease", {"tool offset double decrease"}),
    refused(G(48), kNotSystemA),
    modal(G(49), Group::k08, kMill, setter<&ModalState::length, LengthComp::kOff>, "tool length offset cancel", {"tool length compensation cancel"}),
    refused(G(49), kTOffsets),
    frame(G(50), Group::k11, FrameCode::kScalingCancel, "scaling cancel", "scaling cancel"),
    one_shot(G(50), kLathe, Action::kLatheCoordSet, "coordinate system setting, spindle speed limit (lathe)", {nullptr, "coordinate system setting, spindle speed clamp"}),
    frame(G(50, 1), Group::k22, FrameCode::kMirrorCancel, "programmable mirror image cancel", "programmable mirror image cancel"),
    frame(G(51), Group::k11, FrameCode::kScaling, "scaling", "scaling"),
    frame(G(51, 1), Group::k22, FrameCode::kMirror, "programmable mirror image", "programmable mirror image"),
    one_shot(G(52), kBoth, Action::kLocalShift, "local coordinate system", {"local coordinate system"}),
    one_shot(G(53), kBoth, Action::kMachineCoord, "machine coordinate system (this block)", {"machine coordinate system"}),
    modal(G(54), Group::k14, kBoth, setter<&ModalState::work, 1>, "work coordinate system 1", {"work coordinate system 1"}),
    modal(G(54, 1), Group::k14, kBoth, kNoSet, "additional work coordinate system (P1-P300)", {"additional work coordinate systems"}),
    // G54.4: where the dialect has its parameter (fanuc.toml 11200).
    frame(G(54, 4), Group::k14, FrameCode::kSettingError, "workpiece setting error compensation", "workpiece setting error compensation"),
    modal(G(55), Group::k14, kBoth, setter<&ModalState::work, 2>, "work coordinate system 2", {"work coordinate system 2"}),
    modal(G(56), Group::k14, kBoth, setter<&ModalState::work, 3>, "work coordinate system 3", {"work coordinate system 3"}),
    modal(G(57), Group::k14, kBoth, setter<&ModalState::work, 4>, "work coordinate system 4", {"work coordinate system 4"}),
    modal(G(58), Group::k14, kBoth, setter<&ModalState::work, 5>, "work coordinate system 5", {"work coordinate system 5"}),
    modal(G(59), Group::k14, kBoth, setter<&ModalState::work, 6>, "work coordinate system 6", {"work coordinate system 6"}),
    modal(G(59, 1), Group::k14, kMill | kG38Dialect, setter<&ModalState::work, 7>, "work coordinate system 7"),
    modal(G(59, 2), Group::k14, kMill | kG38Dialect, setter<&ModalState::work, 8>, "work coordinate system 8"),
    modal(G(59, 3), Group::k14, kMill | kG38Dialect, setter<&ModalState::work, 9>, "work coordinate system 9"),
    mill(G(60), Group::k00, Handler::kNotSimulated, "single direction positioning", "single direction positioning"),
    modal(G(61), Group::k15, kBoth, setter<&ModalState::path, PathMode::kExactStop>, "exact stop mode", {"exact stop mode"}),
    modal(G(64), Group::k15, kBoth, setter<&ModalState::path, PathMode::kContinuous>, "cutting mode", {"cutting mode"}),
    one_shot(G(65), kBoth, Action::kMacroCall, "macro call", {"macro call"}),
    modal(G(66), Group::k12, kBoth, setter<&ModalState::modal_macro, true>, "modal macro call", {"macro modal call"}),
    modal(G(67), Group::k12, kBoth, setter<&ModalState::modal_macro, false>, "modal macro call cancel", {"macro modal call cancel"}),
    frame(G(68), Group::k16, FrameCode::kRotation, "coordinate system rotation", "coordinate system rotation"),
    mill(G(68, 2), Group::k16, Handler::kNotSimulated, "tilted working plane command", "tilted working plane"),
    frame(G(69), Group::k16, FrameCode::kRotationCancel, "coordinate system rotation cancel", "coordinate system rotation cancel"),
    cycle(G(73), Cycle::kG73, "high-speed peck drilling cycle", "high-speed peck drilling cycle"),
    cycle(G(74), Cycle::kG74, "left-hand tapping cycle", "left-hand tapping cycle"),
    cycle(G(76), Cycle::kG76, "fine boring cycle", "fine boring cycle"),
    modal(G(80), Group::k09, kBoth, setter<&ModalState::cycle, Cycle::kNone>, "canned cycle cancel", {"canned cycle cancel"}),
    cycle(G(81), Cycle::kG81, "drilling cycle, spot drilling", "drilling cycle"),
    cycle(G(82), Cycle::kG82, "drilling cycle, counter boring (dwell)", "drilling cycle with dwell"),
    cycle(G(83), Cycle::kG83, "peck drilling cycle", "peck drilling cycle"),
    cycle(G(84), Cycle::kG84, "tapping cycle", "tapping cycle"),
    cycle(G(85), Cycle::kG85, "boring cycle (feed out)", "boring cycle"),
    cycle(G(86), Cycle::kG86, "boring cycle (spindle stop, rapid out)", "boring cycle, spindle stop"),
    cycle(G(87), Cycle::kG87, "back boring cycle", "back boring cycle"),
    cycle(G(88), Cycle::kG88, "boring cycle (dwell, spindle stop)", "boring cycle, manual retraction"),
    cycle(G(89), Cycle::kG89, "boring cycle (dwell, feed out)", "boring cycle with dwell"),
    modal(G(90), Group::k03, kMill, setter<&ModalState::distance, Distance::kAbsolute>, "absolute programming", {"absolute programming", "outer diameter cutting cycle"}),
    modal(G(90), Group::k01, kLathe, setter<&ModalState::motion, Motion::kTurningCycle>, "outer diameter cutting cycle (lathe)"),
    modal(G(90, 1), Group::k04, kMill | kG38Dialect, setter<&ModalState::arc_ijk_absolute, true>, "arc centre I J K absolute"),
    modal(G(91), Group::k03, kMill, setter<&ModalState::distance, Distance::kIncremental>, "incremental programming", {"incremental programming"}),
    refused(G(91), " is not a code of G-code system A: U and W are the incremental X and Z"),
    modal(G(91, 1), Group::k04, kMill | kG38Dialect, setter<&ModalState::arc_ijk_absolute, false>, "arc centre I J K incremental"),
    one_shot(G(92), kMill, Action::kCoordSet, "coordinate system setting", {"coordinate system setting", "thread cutting cycle"}),
    refused(G(92), " is the thread cutting cycle in G-code system A (not supported); G50 sets the coordinate system"),
    one_shot(G(92, 1), kMill | kG38Dialect, Action::kNgc, "G92 offset cancel, #5211.. cleared"),
    one_shot(G(92, 2), kMill | kG38Dialect, Action::kNgc, "G92 offset cancel, #5211.. kept"),
    one_shot(G(92, 3), kMill | kG38Dialect, Action::kNgc, "G92 offset from #5211.."),
    modal(G(94), Group::k05, kMill, setter<&ModalState::feed_mode, FeedMode::kPerMinute>, "feed per minute", {"feed per minute", "end face cutting cycle"}),
    refused(G(94), " is the end-face cutting cycle in G-code system A (not supported); G98 is feed per minute"),
    modal(G(95), Group::k05, kMill, setter<&ModalState::feed_mode, FeedMode::kPerRev>, "feed per revolution", {"feed per revolution"}),
    refused(G(95), " is not a code of G-code system A: G99 is feed per revolution"),
    modal(G(96), Group::k02, kLathe, setter<&ModalState::spindle_mode, SpindleMode::kSurfaceSpeed>, "constant surface speed (lathe)", {"constant surface speed"}),
    modal(G(97), Group::k02, kLathe, setter<&ModalState::spindle_mode, SpindleMode::kRpm>, "constant surface speed cancel (lathe)", {"constant surface speed cancel"}),
    // Safe-start blocks of mill posts write G97 (Fanuc M series: group 13).
    modal(G(97), Group::k13, kMill, setter<&ModalState::spindle_mode, SpindleMode::kRpm>, "constant surface speed cancel (spindle speed in rpm)"),
    modal(G(98), Group::k10, kMill, setter<&ModalState::ret, ReturnLevel::kInitial>, "canned cycle return to initial level", {"return to initial level", "feed per minute"}),
    modal(G(98), Group::k05, kLathe, setter<&ModalState::feed_mode, FeedMode::kPerMinute>, "feed per minute (lathe)"),
    modal(G(99), Group::k10, kMill, setter<&ModalState::ret, ReturnLevel::kR>, "canned cycle return to R level", {"return to point R level", "feed per revolution"}),
    modal(G(99), Group::k05, kLathe, setter<&ModalState::feed_mode, FeedMode::kPerRev>, "feed per revolution (lathe)"),
    // G103: only where the dialect has it (haas.toml block_lookahead_g103).
    mill(G(103), Group::k00, Handler::kLookahead, "block look-ahead limit", "block look-ahead limit (Haas)", kMill | kLookaheadDialect),
};
constexpr MCodeDef kM[] = {
    {0, MAction::kProgramStop, "program stop"},
    {1, MAction::kOptionalStop, "optional stop"},
    {2, MAction::kProgramEnd, "end of program"},
    {3, MAction::kSpindleCw, "spindle CW"},
    {4, MAction::kSpindleCcw, "spindle CCW"},
    {5, MAction::kSpindleStop, "spindle stop"},
    {30, MAction::kRewindEnd, "end of program, rewind"},
    {97, MAction::kLocalSubCall, "local subprogram call (Haas)"},
    {98, MAction::kSubCall, "subprogram call"},
    {99, MAction::kSubReturn, "subprogram return"},
};
// clang-format on

// The table's index: for each code on each machine, its first entry + 1
// (0: none).
struct Index {
  std::array<std::uint8_t, GCode::kTableSize> mill{}, lathe{};
};

constexpr bool sorted() {
  for (std::size_t i = 1; i < std::size(kG); ++i) {
    if (kG[i].code < kG[i - 1].code) return false;
  }
  return true;
}
static_assert(sorted(), "the code table is in code order");
static_assert(std::size(kG) < 255, "the index holds entry numbers in a byte");

constexpr Index make_index() {
  Index x;
  for (std::size_t i = 0; i < std::size(kG); ++i) {
    const auto slot = static_cast<std::size_t>(kG[i].code.tenths());
    const auto n = static_cast<std::uint8_t>(i + 1);
    if ((kG[i].avail & kMill) != 0 && x.mill[slot] == 0) x.mill[slot] = n;
    if ((kG[i].avail & kLathe) != 0 && x.lathe[slot] == 0) x.lathe[slot] = n;
  }
  return x;
}
constexpr Index kIndex = make_index();

// M codes below 100 by number: their entry + 1 in kM (0: a machine M code).
constexpr std::array<std::uint8_t, 100> make_m_index() {
  std::array<std::uint8_t, 100> x{};
  for (std::size_t i = 0; i < std::size(kM); ++i) {
    x[static_cast<std::size_t>(kM[i].code)] = static_cast<std::uint8_t>(i + 1);
  }
  return x;
}
constexpr std::array<std::uint8_t, 100> kMIndex = make_m_index();

}  // namespace

std::span<const CodeDef> g_codes() noexcept {
  return kG;
}

const CodeDef* find_g(GCode code, bool lathe) noexcept {
  const auto& index = lathe ? kIndex.lathe : kIndex.mill;
  const std::uint8_t n = index[static_cast<std::size_t>(code.tenths())];
  return n == 0 ? nullptr : &kG[n - 1];
}

std::optional<std::string> not_in_this_dialect(const CodeDef& def, const config::Switches& sw) {
  if ((def.avail & kG38Dialect) != 0 && !sw.probe_g38) {
    // Named as itself: G38.x is the straight probe, G92.1 and its kin
    // are the codes of the G38 controls they are (their summary).
    const bool probe = def.code >= GCode(38, 2) && def.code <= GCode(38, 5);
    return code_name(def.code) + " (" + (probe ? std::string("straight probe") : def.summary) +
           ") is not a code of this control" + (probe ? "; it probes with G31" : "");
  }
  if ((def.avail & kSkipDialect) != 0 && !sw.skip_g31) {
    return code_name(def.code) +
           " (skip function) is not a code of this control; it probes with G38.2-G38.5";
  }
  if ((def.avail & kToolPosOffsetDialect) != 0 && !sw.tool_position_offset) {
    return code_name(def.code) + " (tool position offset) is not a code of this control";
  }
  if ((def.avail & kLookaheadDialect) != 0 && !sw.block_lookahead_g103) {
    return code_name(def.code);
  }
  return std::nullopt;
}

bool g_code_without_effect(GCode code) noexcept {
  const CodeDef* d = find_g(code, false);
  return d != nullptr && d->handler == Handler::kNoEffect;
}

std::span<const MCodeDef> m_codes() noexcept {
  return kM;
}

MAction m_action(int code) noexcept {
  if (code < 0 || code >= static_cast<int>(kMIndex.size())) return MAction::kMachine;
  const std::uint8_t n = kMIndex[static_cast<std::size_t>(code)];
  return n == 0 ? MAction::kMachine : kM[n - 1].action;
}

}  // namespace skipnc::interp
