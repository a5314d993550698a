// The G65/G66 block being executed (ncblock.cpp collect_words): whether
// the block calls a macro, so that every address but G, P and L is an
// argument, and the arguments #1-#33 it gives, in block order
// (macro_call.cpp collect_argument). Held by the interpreter as one member.
#pragma once

#include <array>
#include <cstddef>

#include "interpreter/variables.hpp"

namespace skipnc::interp {

struct CallArguments {
  using Args = std::array<Value, kLocalCount + 1>;  // #1-#33 (index 0 unused)
  Args values{};
  bool in_block = false;  // the block is a G65/G66 call

  // A G65/G66 block begins: no argument given yet.
  void begin() noexcept {
    in_block = true;
    values.fill(Value::null());
  }
  void set(int var, double x) noexcept { values[static_cast<std::size_t>(var)] = Value::of(x); }
};

}  // namespace skipnc::interp
