// The lathe's own state in a block (lathe.cpp): the T code's wear offset and
// the G90 turning cycle's modal Z. Part of BlockState (block_state.hpp), so
// a block changes it on its copy like the rest; trivially copyable.
#pragma once

#include <optional>

namespace skipnc::interp {

class LatheState {
 public:
  // The lower digits of the T code: the wear offset (and nose radius) in use.
  int wear_offset() const noexcept { return wear_offset_; }
  void set_wear_offset(int n) noexcept { wear_offset_ = n; }
  // G90: the Z end of the last pass (machine mm), none before the first.
  std::optional<double> cycle_z() const noexcept {
    return have_cycle_z_ ? std::optional<double>(cycle_z_) : std::nullopt;
  }
  void set_cycle_z(double z_mm) noexcept {
    cycle_z_ = z_mm;
    have_cycle_z_ = true;
  }

 private:
  int wear_offset_ = 0;
  double cycle_z_ = 0.0;
  bool have_cycle_z_ = false;
};

}  // namespace skipnc::interp
