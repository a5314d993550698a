// G37 automatic tool length measurement (mill_codes.cpp): the measurement
// under way, from the G37 block to the machine's answer. Held by the
// interpreter as one member; Impl::g37_block arms it, Impl::finish_g37
// takes it back.
#pragma once

#include <string>

#include "core/diag.hpp"
#include "interpreter/flow.hpp"

namespace skipnc::interp {

class ToolMeasurement {
 public:
  // G37: a dialect has it when it defines epsilon (B-63944EN, 6254).
  static constexpr int kEpsilonParam = 6254;
  // G37.1: a dialect has it (not simulated) when it defines this (Mitsubishi).
  static constexpr int kG37_1SpeedParam = 8004;

  // The G37 block's skip move is queued: `axis` measured towards
  // `target_mm` (machine), the signal allowed within `epsilon_mm` of it.
  void arm(int axis, double target_mm, double epsilon_mm, SourceLoc at) {
    axis_ = axis;
    target_mm_ = target_mm;
    epsilon_mm_ = epsilon_mm;
    at_ = at;
  }
  bool active() const noexcept { return axis_ >= 0; }
  int axis() const noexcept { return axis_; }
  // Where the signal came (`latch_mm`, machine; none: no signal) against the
  // measuring position: the difference in mm, or alarm kG37Signal when it
  // did not come within epsilon.
  Flow<double> deviation(bool triggered, double latch_mm) const;

 private:
  int axis_ = -1;  // -1: no G37 under way
  double target_mm_ = 0.0;
  double epsilon_mm_ = 0.0;
  SourceLoc at_;
};

}  // namespace skipnc::interp
