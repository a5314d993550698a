// Program frame -> work frame on the mill: programmable mirror image
// (G50.1/G51.1), scaling (G50/G51), coordinate rotation (G68/G69) and polar
// coordinates (G15/G16), as pure functions of program units.
//
// Order (Fanuc B-63944EN, 5.5 "Coordinate system rotation" and 5.4
// "Scaling"; 5.6 "Programmable mirror image"): a programmed point is first
// mirrored, then scaled, then rotated; each about its own centre, given in
// the work coordinate system when the mode was commanded. The workpiece
// coordinate system itself is not changed: the position variables (#5001,
// #5041, #5061 ...) and the work position on the screen stay in it, so a
// skip position under G68 reads back unrotated (the control's workpiece
// coordinates), not in the rotated program frame.
//
// The 3-D coordinate conversion `G68 X Y Z I J K R` (Fanuc B-62764EN
// "Three-dimensional coordinate conversion"): R degrees about the vector
// I J K through X Y Z, right-handed (K1 turns as the plane rotation does).
// It is applied after the plane rotation; a second G68 in the mode nests,
// its centre and vector given in the frame the first one made (the
// manual's X'Y'Z'), at most two. The workpiece coordinates stay unconverted
// as above: #5041.. and the skip positions read in them.
//
// The workpiece setting error compensation G54.4 Pn (Fanuc A-79634E,
// "Workpiece Setting Error Compensation"): the setting system's origin at
// dx dy dz of the workpiece coordinate system, its axes turned da about X,
// then db about Y, then dc about Z (right-handed); outermost, after the
// conversions: work = d + R p.
#pragma once

#include <array>
#include <memory>

namespace skipnc::interp::xform {

using Point = std::array<double, 3>;  // X, Y, Z in program units
using Matrix = std::array<Point, 3>;  // rows

// One 3-D conversion: a point p of its frame is c + m (p - c) in the frame
// it was commanded in.
struct Conversion {
  Matrix m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  Point center{};
};

// The most conversions in effect at once (B-62764EN: "the coordinate
// system is rotated twice" at most).
inline constexpr int kMaxConversions = 2;

// The 3-D part of the frame: the conversions (G68 I J K, first to last) and
// the G54.4 setting error. Held by pointer in Transform, null when neither
// is on, so that the frame a block saves and restores stays small.
struct Spatial {
  std::array<Conversion, kMaxConversions> conversion{};
  int conversions = 0;
  bool setting_error = false;  // G54.4 Pn, n > 0
  Matrix setting_turn{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  Point setting_shift{};
};

struct Transform {
  std::array<bool, 3> mirror{};  // G51.1 per axis
  Point mirror_center{};
  std::array<double, 3> scale{1.0, 1.0, 1.0};  // G51 per axis (1: none)
  Point scale_center{};
  bool rotating = false;  // G68 in the XY plane
  double angle_deg = 0.0;
  std::array<double, 2> rotation_center{};
  std::shared_ptr<const Spatial> spatial;  // null: no G68 I J K, no G54.4

  int conversions() const noexcept { return spatial ? spatial->conversions : 0; }
  bool setting_error() const noexcept { return spatial && spatial->setting_error; }

  // A conversion that moves Z (its vector not along Z): a program X or Y
  // move moves all three axes, and the program's XY plane is tilted.
  bool tilted() const noexcept;

  bool active() const noexcept {
    return rotating || spatial != nullptr || mirror[0] || mirror[1] || mirror[2] ||
           scale[0] != 1.0 || scale[1] != 1.0 || scale[2] != 1.0;
  }
};

// A programmed point -> the work coordinate system.
Point to_work(const Transform& t, const Point& program) noexcept;
// The inverse: where a work point lies in the program frame. A scale of 0
// has no inverse; the caller refuses it when G51 is read.
Point to_program(const Transform& t, const Point& work) noexcept;

// An incremental move (G91) is a vector: mirrored, scaled and rotated, not
// moved by the centres.
Point vector_to_work(const Transform& t, const Point& v) noexcept;

// The rotation by `angle_deg` about the vector `axis` (right-handed, the
// vector need not be a unit vector; a zero vector gives the identity).
Matrix axis_angle(const Point& axis, double angle_deg) noexcept;

// The frame with `s` as its 3-D part (null when s has no conversion and no
// setting error).
Transform with_spatial(Transform t, const Spatial& s);

// Whether a turn keeps the Z axis (a turn about Z only).
bool keeps_z(const Matrix& m) noexcept;

// The G54.4 turn: da about X, then db about Y, then dc about Z (fixed axes).
Matrix turn_xyz(double da_deg, double db_deg, double dc_deg) noexcept;

// G16: radius and angle (degrees, counterclockwise from +X) about a centre
// -> X and Y.
std::array<double, 2> polar_to_xy(const std::array<double, 2>& center, double radius,
                                  double angle_deg) noexcept;

// cos and sin of an angle in degrees, exact at the multiples of 90.
std::array<double, 2> cos_sin_deg(double deg) noexcept;

}  // namespace skipnc::interp::xform
