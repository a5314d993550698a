// The mill's frame codes' own state in a block (mill_codes.cpp): G16 polar
// coordinates and the last angles that G91 adds to. Part of BlockState
// (block_state.hpp), so a block changes it on its copy like the rest;
// trivially copyable. The program -> work frame itself is
// Impl::program_frame, which the motion and the offsets read too.
#pragma once

namespace skipnc::interp {

struct FrameCodeState {
  bool polar = false;           // G16 (G15 cancels)
  double polar_angle = 0.0;     // last polar angle, degrees
  double rotation_angle = 0.0;  // last G68 R, degrees (5400#0 RIN: G91 adds to it)

  // A polar angle word `a` (none: `a` = 0 in G91, the last angle in G90):
  // the angle of the block, kept for the next one.
  double next_polar_angle(double a, bool incremental) noexcept {
    polar_angle = incremental ? polar_angle + a : a;
    return polar_angle;
  }
};

}  // namespace skipnc::interp
