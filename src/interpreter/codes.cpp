// The code table. Groups and meanings: Fanuc 0i/30i G code lists (machining
// centre, and G-code system A of a lathe); a lathe numbers plane selection
// group 16 and G96/G97 group 02. Codes that only one dialect has carry its
// availability bit.
#include "interpreter/codes.hpp"

#include <algorithm>

namespace skipnc::interp {
namespace {

template <auto Field, auto Value>
constexpr void (*setter)(ModalState&) noexcept = [](ModalState& m) noexcept { m.*Field = Value; };

constexpr auto kNoSet = static_cast<void (*)(ModalState&) noexcept>(nullptr);

template <int Code>
constexpr void (*probe_setter)(ModalState&) noexcept = [](ModalState& m) noexcept {
  m.motion = Motion::kProbe;
  m.probe = Code;
};

// clang-format off
constexpr CodeDef kG[] = {
    {0,   Group::k01, kBoth, setter<&ModalState::motion, Motion::kRapid>, Action::kNone, "positioning (rapid traverse)"},
    {10,  Group::k01, kBoth, setter<&ModalState::motion, Motion::kLinear>, Action::kNone, "linear interpolation"},
    {20,  Group::k01, kBoth, setter<&ModalState::motion, Motion::kCwArc>, Action::kNone, "circular interpolation CW"},
    {30,  Group::k01, kBoth, setter<&ModalState::motion, Motion::kCcwArc>, Action::kNone, "circular interpolation CCW"},
    {40,  Group::k00, kBoth, kNoSet, Action::kDwell, "dwell"},
    {90,  Group::k00, kBoth, kNoSet, Action::kExactStop, "exact stop (this block)"},
    {100, Group::k00, kBoth, kNoSet, Action::kDataSetting, "programmable data input"},
    {170, Group::k02, kMill, setter<&ModalState::plane, PlaneSel::kXY>, Action::kNone, "XY plane"},
    {170, Group::k16, kLathe, setter<&ModalState::plane, PlaneSel::kXY>, Action::kNone, "XY plane"},
    {180, Group::k02, kMill, setter<&ModalState::plane, PlaneSel::kZX>, Action::kNone, "ZX plane"},
    {180, Group::k16, kLathe, setter<&ModalState::plane, PlaneSel::kZX>, Action::kNone, "ZX plane"},
    {190, Group::k02, kMill, setter<&ModalState::plane, PlaneSel::kYZ>, Action::kNone, "YZ plane"},
    {190, Group::k16, kLathe, setter<&ModalState::plane, PlaneSel::kYZ>, Action::kNone, "YZ plane"},
    {200, Group::k06, kBoth, setter<&ModalState::units, Units::kInch>, Action::kNone, "inch input"},
    {210, Group::k06, kBoth, setter<&ModalState::units, Units::kMetric>, Action::kNone, "metric input"},
    {280, Group::k00, kBoth, kNoSet, Action::kRefReturn, "reference position return"},
    {281, Group::k00, kMill | kG38Dialect, kNoSet, Action::kNgc, "store the G28 position (#5161..)"},
    {300, Group::k00, kBoth, kNoSet, Action::kRefReturn2, "2nd-4th reference position return"},
    {301, Group::k00, kMill | kG38Dialect, kNoSet, Action::kNgc, "store the G30 position (#5181..)"},
    {310, Group::k00, kBoth, kNoSet, Action::kSkip, "skip function"},
    {382, Group::k01, kMill | kG38Dialect, probe_setter<382>, Action::kNone, "straight probe toward the part, error without contact"},
    {383, Group::k01, kMill | kG38Dialect, probe_setter<383>, Action::kNone, "straight probe toward the part"},
    {384, Group::k01, kMill | kG38Dialect, probe_setter<384>, Action::kNone, "straight probe away from the part, error without loss of contact"},
    {385, Group::k01, kMill | kG38Dialect, probe_setter<385>, Action::kNone, "straight probe away from the part"},
    {400, Group::k07, kBoth, setter<&ModalState::cutter, CutterComp::kOff>, Action::kNone, "cutter compensation cancel"},
    {410, Group::k07, kBoth, setter<&ModalState::cutter, CutterComp::kLeft>, Action::kNone, "cutter compensation left"},
    {420, Group::k07, kBoth, setter<&ModalState::cutter, CutterComp::kRight>, Action::kNone, "cutter compensation right"},
    {430, Group::k08, kMill, setter<&ModalState::length, LengthComp::kPlus>, Action::kNone, "tool length offset +"},
    {431, Group::k00, kMill | kG38Dialect, kNoSet, Action::kNgc, "dynamic tool length offset"},
    {440, Group::k08, kMill, setter<&ModalState::length, LengthComp::kMinus>, Action::kNone, "tool length offset -"},
    {450, Group::k00, kMill | kToolPosOffsetDialect, kNoSet, Action::kToolPosOffset, "tool position offset increase"},
    {460, Group::k00, kMill | kToolPosOffsetDialect, kNoSet, Action::kToolPosOffset, "tool position offset decrease"},
    {470, Group::k00, kMill | kToolPosOffsetDialect, kNoSet, Action::kToolPosOffset, "tool position offset double increase"},
    {480, Group::k00, kMill | kToolPosOffsetDialect, kNoSet, Action::kToolPosOffset, "tool position offset double decrease"},
    {490, Group::k08, kMill, setter<&ModalState::length, LengthComp::kOff>, Action::kNone, "tool length offset cancel"},
    {500, Group::k00, kLathe, kNoSet, Action::kLatheCoordSet, "coordinate system setting, spindle speed limit (lathe)"},
    {520, Group::k00, kBoth, kNoSet, Action::kLocalShift, "local coordinate system"},
    {530, Group::k00, kBoth, kNoSet, Action::kMachineCoord, "machine coordinate system (this block)"},
    {540, Group::k14, kBoth, setter<&ModalState::work, 1>, Action::kNone, "work coordinate system 1"},
    {541, Group::k14, kBoth, kNoSet, Action::kNone, "additional work coordinate system (P1-P300)"},
    {550, Group::k14, kBoth, setter<&ModalState::work, 2>, Action::kNone, "work coordinate system 2"},
    {560, Group::k14, kBoth, setter<&ModalState::work, 3>, Action::kNone, "work coordinate system 3"},
    {570, Group::k14, kBoth, setter<&ModalState::work, 4>, Action::kNone, "work coordinate system 4"},
    {580, Group::k14, kBoth, setter<&ModalState::work, 5>, Action::kNone, "work coordinate system 5"},
    {590, Group::k14, kBoth, setter<&ModalState::work, 6>, Action::kNone, "work coordinate system 6"},
    {591, Group::k14, kMill | kG38Dialect, setter<&ModalState::work, 7>, Action::kNone, "work coordinate system 7"},
    {592, Group::k14, kMill | kG38Dialect, setter<&ModalState::work, 8>, Action::kNone, "work coordinate system 8"},
    {593, Group::k14, kMill | kG38Dialect, setter<&ModalState::work, 9>, Action::kNone, "work coordinate system 9"},
    {610, Group::k15, kBoth, setter<&ModalState::path, PathMode::kExactStop>, Action::kNone, "exact stop mode"},
    {640, Group::k15, kBoth, setter<&ModalState::path, PathMode::kContinuous>, Action::kNone, "cutting mode"},
    {650, Group::k00, kBoth, kNoSet, Action::kMacroCall, "macro call"},
    {660, Group::k12, kBoth, setter<&ModalState::modal_macro, true>, Action::kNone, "modal macro call"},
    {670, Group::k12, kBoth, setter<&ModalState::modal_macro, false>, Action::kNone, "modal macro call cancel"},
    {800, Group::k09, kBoth, setter<&ModalState::cycle, Cycle::kNone>, Action::kNone, "canned cycle cancel"},
    {900, Group::k03, kMill, setter<&ModalState::distance, Distance::kAbsolute>, Action::kNone, "absolute programming"},
    {900, Group::k01, kLathe, setter<&ModalState::motion, Motion::kTurningCycle>, Action::kNone, "outer diameter cutting cycle (lathe)"},
    {901, Group::k04, kMill | kG38Dialect, setter<&ModalState::arc_ijk_absolute, true>, Action::kNone, "arc centre I J K absolute"},
    {910, Group::k03, kMill, setter<&ModalState::distance, Distance::kIncremental>, Action::kNone, "incremental programming"},
    {911, Group::k04, kMill | kG38Dialect, setter<&ModalState::arc_ijk_absolute, false>, Action::kNone, "arc centre I J K incremental"},
    {920, Group::k00, kMill, kNoSet, Action::kCoordSet, "coordinate system setting"},
    {921, Group::k00, kMill | kG38Dialect, kNoSet, Action::kNgc, "G92 offset cancel, #5211.. cleared"},
    {922, Group::k00, kMill | kG38Dialect, kNoSet, Action::kNgc, "G92 offset cancel, #5211.. kept"},
    {923, Group::k00, kMill | kG38Dialect, kNoSet, Action::kNgc, "G92 offset from #5211.."},
    {940, Group::k05, kMill, setter<&ModalState::feed_mode, FeedMode::kPerMinute>, Action::kNone, "feed per minute"},
    {950, Group::k05, kMill, setter<&ModalState::feed_mode, FeedMode::kPerRev>, Action::kNone, "feed per revolution"},
    {960, Group::k02, kLathe, setter<&ModalState::spindle_mode, SpindleMode::kSurfaceSpeed>, Action::kNone, "constant surface speed (lathe)"},
    {970, Group::k02, kLathe, setter<&ModalState::spindle_mode, SpindleMode::kRpm>, Action::kNone, "constant surface speed cancel (lathe)"},
    // Safe-start blocks of mill posts write G97 (Fanuc M series: group 13).
    {970, Group::k13, kMill, setter<&ModalState::spindle_mode, SpindleMode::kRpm>, Action::kNone, "constant surface speed cancel (spindle speed in rpm)"},
    {980, Group::k10, kMill, setter<&ModalState::ret, ReturnLevel::kInitial>, Action::kNone, "canned cycle return to initial level"},
    {980, Group::k05, kLathe, setter<&ModalState::feed_mode, FeedMode::kPerMinute>, Action::kNone, "feed per minute (lathe)"},
    {990, Group::k10, kMill, setter<&ModalState::ret, ReturnLevel::kR>, Action::kNone, "canned cycle return to R level"},
    {990, Group::k05, kLathe, setter<&ModalState::feed_mode, FeedMode::kPerRev>, Action::kNone, "feed per revolution (lathe)"},
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

}  // namespace

std::span<const CodeDef> g_codes() noexcept {
  return kG;
}

const CodeDef* find_g(int code, bool lathe) noexcept {
  const std::uint8_t machine = lathe ? kLathe : kMill;
  for (const CodeDef& d : kG) {
    if (d.code == code && (d.avail & machine) != 0) return &d;
  }
  return nullptr;
}

const char* g_summary(int code) noexcept {
  for (const CodeDef& d : kG) {
    if (d.code == code) return d.summary;
  }
  return nullptr;
}

std::span<const MCodeDef> m_codes() noexcept {
  return kM;
}

MAction m_action(int code) noexcept {
  for (const MCodeDef& d : kM) {
    if (d.code == code) return d.action;
  }
  return MAction::kMachine;
}

}  // namespace skipnc::interp
