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
#pragma once

#include <array>

namespace skipnc::interp::xform {

using Point = std::array<double, 3>;  // X, Y, Z in program units

struct Transform {
  std::array<bool, 3> mirror{};  // G51.1 per axis
  Point mirror_center{};
  std::array<double, 3> scale{1.0, 1.0, 1.0};  // G51 per axis (1: none)
  Point scale_center{};
  bool rotating = false;  // G68 in the XY plane
  double angle_deg = 0.0;
  std::array<double, 2> rotation_center{};

  bool active() const noexcept {
    return rotating || mirror[0] || mirror[1] || mirror[2] || scale[0] != 1.0 || scale[1] != 1.0 ||
           scale[2] != 1.0;
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

// G16: radius and angle (degrees, counterclockwise from +X) about a centre
// -> X and Y.
std::array<double, 2> polar_to_xy(const std::array<double, 2>& center, double radius,
                                  double angle_deg) noexcept;

// cos and sin of an angle in degrees, exact at the multiples of 90.
std::array<double, 2> cos_sin_deg(double deg) noexcept;

}  // namespace skipnc::interp::xform
