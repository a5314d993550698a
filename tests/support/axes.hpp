// A short way to write a position on X alone, for the kernel's tests.
#pragma once

#include "core/axes.hpp"

namespace skipnc::test {

inline AxisVec at_x(double x) {
  AxisVec v;
  v[0] = x;
  return v;
}

}  // namespace skipnc::test
