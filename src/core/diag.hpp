// Program errors are values: a stable alarm identity, where it happened, and
// what was involved. The dialect turns the identity into its own number, code
// and text (data/dialects/*.toml); nothing here knows a vendor's numbering.
#pragma once

#include <cstdint>
#include <expected>
#include <string>
#include <string_view>
#include <utility>

namespace skipnc {

struct SourceLoc {
  std::string_view file;  // points at storage owned by the program store
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  friend bool operator==(const SourceLoc&, const SourceLoc&) = default;
};

// Every alarm the product can raise. The name is the stable key used in the
// dialect tables; keep the list and kAlarmNames in step.
enum class AlarmId : std::uint16_t {
#define SKIPNC_ALARM(id, key) id,
#include "core/alarms.def"
#undef SKIPNC_ALARM
  kCount
};

std::string_view alarm_key(AlarmId id) noexcept;
// Returns kCount when the key is unknown.
AlarmId alarm_from_key(std::string_view key) noexcept;

struct Error {
  AlarmId id = AlarmId::kInternal;
  std::string detail;  // the values involved, in words
  SourceLoc loc;
  // Set for user alarms (#3000 = n): the number the program asked for.
  int user_number = -1;
};

template <class T>
using Result = std::expected<T, Error>;

inline std::unexpected<Error> fail(AlarmId id, std::string detail, SourceLoc loc = {}) {
  return std::unexpected<Error>(Error{id, std::move(detail), loc, -1});
}

}  // namespace skipnc

// Passes a failed result's error up to the caller: `SKIPNC_TRY(r);` returns
// r's error from the enclosing function when r holds one, and does nothing
// otherwise. The argument may be a variable or any expression giving a
// std::expected (`SKIPNC_TRY(check_keys(t, keys, origin));`); the enclosing
// function returns a std::expected (or Flow) with the same error type.
#define SKIPNC_TRY(...)                                                 \
  do {                                                                  \
    if (auto&& skipnc_try_result_ = (__VA_ARGS__); !skipnc_try_result_) \
      return std::unexpected(std::move(skipnc_try_result_).error());    \
  } while (false)
