// G66 modal macro call (macro_call.cpp): the program and arguments that the
// blocks which move call until G67. Held by the interpreter as one member;
// a block that may call copies it (Impl::begin_tables / roll_back_tables).
#pragma once

#include <array>
#include <cstdint>

#include "interpreter/variables.hpp"

namespace skipnc::interp {

struct ModalMacro {
  using Args = std::array<Value, kLocalCount + 1>;  // #1-#33 (index 0 unused)
  std::int64_t program = 0;                         // 0: none
  Args args{};

  void set(std::int64_t p, const Args& a) noexcept {
    program = p;
    args = a;
  }
  bool armed() const noexcept { return program != 0; }
};

}  // namespace skipnc::interp
