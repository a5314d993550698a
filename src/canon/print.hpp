// The text form of canonical commands: one line per command,
// "<line> <NAME> <fields>", numbers in the shortest form that reads back
// exactly. Used by `skipnc canon` and the golden tests.
#pragma once

#include <fmt/format.h>

#include <string>
#include <string_view>

#include "canon/canon.hpp"

namespace skipnc::canon {

struct AxisNames {
  int count = 3;
  char names[kMaxAxes] = {'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V'};
};

void format_to(fmt::memory_buffer& out, const Stamped& cmd, const AxisNames& axes);
std::string to_string(const Stamped& cmd, const AxisNames& axes);

}  // namespace skipnc::canon
