// Canned cycles of the mill (group 09: G73 G74 G76 G81-G89, with G98/G99 of
// group 10): the moves one hole makes, as pure functions of the hole's data.
//
// The rules are Fanuc's (Series 30i/31i/32i-MODEL A operator's manual for
// the machining centre, B-63944EN, 5.1 "Canned cycle for drilling"):
//   operation 1  positioning of X and Y (rapid, at the present Z);
//   operation 2  rapid traverse down to point R;
//   operation 3  hole machining;
//   operation 4  operation at the bottom of the hole (dwell, spindle);
//   operation 5  retraction to point R;
//   operation 6  rapid traverse up to the initial level (G98 only).
// In G90, R and Z are positions on the drilling axis; in G91, R is the
// distance from the initial level to point R and Z the distance from point
// R to the bottom. Q (peck depth or shift) is always an incremental,
// positive length. K repeats: in G91 each repeat moves by the X Y increment
// again (a row of holes), in G90 the same hole is drilled again; K0 stores
// the data without drilling.
//
// Everything here is in program units on the "hole frame": the two axes of
// the plane (x, y) and the drilling axis (z, positive away from the work).
#pragma once

#include <array>
#include <vector>

#include "interpreter/modal.hpp"

namespace skipnc::interp::cycles {

enum class MoveKind : std::uint8_t {
  kRapid,    // to `to`
  kFeed,     // to `to` at the cycle's F
  kDwell,    // `seconds`
  kSpindle,  // start or stop the spindle: `spindle_dir` (1 M03, -1 M04, 0 M05)
  kOrient,   // oriented spindle stop (M19)
};

struct Move {
  MoveKind kind = MoveKind::kRapid;
  std::array<double, 3> to{};  // x, y, drilling axis
  double seconds = 0.0;
  int spindle_dir = 0;
  friend bool operator==(const Move&, const Move&) = default;
};

// One hole, all levels resolved to positions on the drilling axis.
struct Hole {
  Cycle kind = Cycle::kG81;
  ReturnLevel ret = ReturnLevel::kInitial;
  std::array<double, 3> from{};               // where the tool is when the hole starts
  std::array<double, 2> at{};                 // the hole's position in the plane
  double initial = 0.0;                       // initial level
  double r = 0.0;                             // point R
  double bottom = 0.0;                        // point Z
  double q = 0.0;                             // peck depth (G73, G83) or shift (G76, G87); > 0
  double dwell_s = 0.0;                       // P at the bottom (G74 G76 G82 G84 G87 G88 G89)
  double peck_clearance = 0.0;                // d: G73 retraction (5114), G83 clearance (5115)
  std::array<double, 2> shift_dir{1.0, 0.0};  // unit vector of the G76/G87 shift
  int spindle_dir = 1;                        // spindle direction to restore after a stop (M03 = 1)
  // LinuxCNC's rules ("Preliminary and In-Between Motion", G84): below the
  // clearance level (R; in G98 the higher of R and the initial level) the
  // tool first rises to it, then moves to the hole; G98 returns there; a tap
  // feeds back out to the return level itself, with no rapid up from R.
  bool linuxcnc_levels = false;
};

// The moves of one hole, in order. Moves of zero length are left out.
std::vector<Move> hole_moves(const Hole& h);

// The cycle's words as last programmed (modal until G80): program units,
// as written (incremental in G91).
struct Data {
  double r = 0.0;
  double z = 0.0;
  bool have_r = false;
  bool have_z = false;
  double q = 0.0;
  double p_ms = 0.0;
  double initial = 0.0;  // the initial level, set when the cycle mode starts
};

// Point R and point Z on the drilling axis from the cycle's words and the
// distance mode (see the header comment).
struct Levels {
  double r = 0.0;
  double bottom = 0.0;
};
Levels resolve_levels(const Data& d, bool incremental) noexcept;

// The G76 / G87 shift direction from parameter 5101 bits 4 (RD1) and 5
// (RD2): 0 +X, 1 -X, 2 +Y, 3 -Y of the plane (value = RD1 + 2 RD2).
std::array<double, 2> shift_direction(int rd) noexcept;

// Which cycles read each word: Q (peck or shift) and P (dwell).
bool uses_q(Cycle c) noexcept;
bool uses_p(Cycle c) noexcept;
bool pecks(Cycle c) noexcept;

}  // namespace skipnc::interp::cycles
