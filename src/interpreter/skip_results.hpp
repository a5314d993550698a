// What the last skip or probe block stored of the machine's answer
// (skip.cpp record_skip): the latch in the program's work coordinates
// (#5061.., the report's position) and in machine coordinates. Held by the
// interpreter as one member.
#pragma once

#include "core/axes.hpp"

namespace skipnc::interp {

struct SkipResults {
  AxisVec work;       // #5061.. (program units)
  AxisVec machine;    // machine coordinates, mm
  bool have = false;  // a skip has run

  // #5061 + i: the latch, 0 before the first skip.
  double work_or_zero(int i) const noexcept { return have ? work[i] : 0.0; }
};

}  // namespace skipnc::interp
