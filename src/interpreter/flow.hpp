// The block executor's outcome type (Flow), shared by the interpreter's
// parts and its language objects (language.hpp).
#pragma once

#include <expected>
#include <type_traits>
#include <utility>
#include <variant>

#include "core/diag.hpp"

namespace skipnc::interp {

// The block executor's outcome: a value, an alarm, or NeedSync. NeedSync is
// not an alarm: the block read a live value (#5021.., #5041.., a skip
// result) while motion it had queued was still to run. Nothing of the block
// is committed; step() answers Step::kSync, and after sync() the same block
// runs again with the machine's values.
struct NeedSync {};
using Halt = std::variant<Error, NeedSync>;
template <class T>
using Flow = std::expected<T, Halt>;

inline std::unexpected<Halt> need_sync() {
  return std::unexpected<Halt>(NeedSync{});
}

// The interpreter's public face returns alarms only: a NeedSync reaching it
// means a live value was read outside a block, a bug, said as one.
template <class T>
Result<T> settled(Flow<T> f) {
  if (f) {
    if constexpr (std::is_void_v<T>) {
      return {};
    } else {
      return std::move(*f);
    }
  }
  if (auto* e = std::get_if<Error>(&f.error())) return std::unexpected(std::move(*e));
  return fail(AlarmId::kInternal, "a live value was read outside a block");
}

}  // namespace skipnc::interp
