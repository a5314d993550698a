// The text form of canonical commands: one line per command,
// "<line> <NAME> <fields>", numbers in the shortest form that reads back
// exactly. Used by `skipnc canon` and the golden tests.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "canon/canon.hpp"

namespace skipnc::canon {

struct AxisNames {
  int count = 3;
  char names[kMaxAxes] = {'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V'};
};

// Writes canon lines one after another, remembering the text of the last
// value of each field (an axis, a centre, the feed): a value written again
// in its field, as Z and F on most lines of a program, is copied, not
// converted again. The same text as format_to.
class TextWriter {
 public:
  explicit TextWriter(const AxisNames& axes) noexcept : axes_(axes) {}
  // Appends the line of `cmd` to `out`.
  void append(fmt::memory_buffer& out, const Stamped& cmd);

  // One field's last value and its text (0 and "0" at first).
  struct Field {
    std::uint64_t bits = 0;
    std::uint32_t size = 1;
    char text[28] = {'0'};
  };
  // The fields: the axes, the two centre words, the feed.
  static constexpr int kCentre0 = kMaxAxes;
  static constexpr int kCentre1 = kMaxAxes + 1;
  static constexpr int kFeed = kMaxAxes + 2;

 private:
  AxisNames axes_;
  Field fields_[kMaxAxes + 3];
};

void format_to(fmt::memory_buffer& out, const Stamped& cmd, const AxisNames& axes);
std::string to_string(const Stamped& cmd, const AxisNames& axes);

}  // namespace skipnc::canon
