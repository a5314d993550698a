// Modal state: one enum per modal group and the values that persist from
// block to block. A block works on a copy and commits it when it succeeds.
#pragma once

#include <cstdint>
#include <optional>

#include "canon/canon.hpp"
#include "core/axes.hpp"
#include "core/nc_code.hpp"

namespace skipnc::interp {

// Group 01; kTurningCycle is G90 of a lathe (outer-diameter cutting cycle),
// kProbe G38.2-G38.5 (ModalState::probe says which).
enum class Motion : std::uint8_t { kRapid, kLinear, kCwArc, kCcwArc, kTurningCycle, kProbe };
enum class PlaneSel : std::uint8_t { kXY, kZX, kYZ };            // group 02: G17 G18 G19
enum class Distance : std::uint8_t { kAbsolute, kIncremental };  // group 03: G90 G91
// Group 05: G94 G95 on a mill, G98 G99 on a lathe (G-code system A).
enum class FeedMode : std::uint8_t { kPerMinute, kPerRev };
// Lathe group 02: G97 S in rpm, G96 S in surface speed (m/min, ft/min).
enum class SpindleMode : std::uint8_t { kRpm, kSurfaceSpeed };
enum class Units : std::uint8_t { kInch, kMetric };            // group 06: G20 G21
enum class CutterComp : std::uint8_t { kOff, kLeft, kRight };  // group 07: G40 G41 G42
enum class LengthComp : std::uint8_t { kOff, kPlus, kMinus };  // group 08: G49 G43 G44
enum class Cycle : std::uint8_t {                              // group 09
  kNone,
  kG73,
  kG74,
  kG76,
  kG81,
  kG82,
  kG83,
  kG84,
  kG85,
  kG86,
  kG87,
  kG88,
  kG89
};
enum class ReturnLevel : std::uint8_t { kInitial, kR };          // group 10: G98 G99
enum class PathMode : std::uint8_t { kExactStop, kContinuous };  // group 15: G61 G64

struct ModalState {
  bool lathe = false;  // G-code system A: the group numbers of a lathe
  Motion motion = Motion::kRapid;
  PlaneSel plane = PlaneSel::kXY;
  Distance distance = Distance::kAbsolute;
  FeedMode feed_mode = FeedMode::kPerMinute;
  Units units = Units::kMetric;
  CutterComp cutter = CutterComp::kOff;
  LengthComp length = LengthComp::kOff;
  Cycle cycle = Cycle::kNone;
  ReturnLevel ret = ReturnLevel::kInitial;
  PathMode path = PathMode::kContinuous;
  int work = 1;              // 1..6 = G54..G59
  bool modal_macro = false;  // G66 active
  double feed = 0.0;         // F, program units per minute (mm/min or inch/min)
  double spindle = 0.0;      // S: rpm (G97) or surface speed (G96)
  double e = 0.0;            // the last E word, #4108 (modal information)
  SpindleMode spindle_mode = SpindleMode::kRpm;
  int spindle_dir = 0;             // 1 = M03, -1 = M04, 0 = stopped (M05)
  double spindle_clamp_rpm = 0.0;  // G50 S: the G96 speed limit (0: none)
  int tool = 0;                    // T
  int h = 0;                       // active H number (length offset)
  int d = 0;                       // active D number (radius offset)
  int last_m = 0;
  GCode probe;                    // G38.2-G38.5 while motion is kProbe
  bool arc_ijk_absolute = false;  // G90.1 (RS274NGC): I J K are the centre, not an offset
  int seq = 0;                    // last N
  bool operator==(const ModalState&) const = default;
};

// Fanuc's modal information codes (#4001-#4022) for the state.
// Nothing for a group the state does not model.
std::optional<GCode> g_code_of_group(const ModalState& m, int group) noexcept;

}  // namespace skipnc::interp
