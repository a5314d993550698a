// Program text, read block by block. A source streams a file through a
// fixed-size window, so a program of any length is read in bounded memory,
// and it can seek back to any block it has returned (loops, GOTO, M99).
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "core/diag.hpp"

namespace skipnc::gcode {

// The raw text of one block and where it starts.
struct RawBlock {
  std::string_view text;     // without the end-of-block character
  std::uint64_t offset = 0;  // byte offset of text[0]
  std::uint32_t line = 0;    // 1-based
  std::uint32_t column = 1;  // 1-based column of text[0]
};

// A position to come back to: byte offset plus the line and column there.
struct SourcePos {
  std::uint64_t offset = 0;
  std::uint32_t line = 1;
  std::uint32_t column = 1;
  friend bool operator==(const SourcePos&, const SourcePos&) = default;
};

class Source {
 public:
  virtual ~Source() = default;
  // Next block; false at end of text. Blocks end at '\n', "\r\n" or ';'
  // outside parentheses (SourceLimits::semicolon_ends_block). The view is valid until the next
  // call.
  [[nodiscard]] virtual Result<bool> next(RawBlock& out) = 0;
  // Position of the block that next() returns next.
  virtual SourcePos tell() const noexcept = 0;
  [[nodiscard]] virtual Result<void> seek(SourcePos pos) = 0;
  virtual std::string_view name() const noexcept = 0;
};

struct SourceLimits {
  std::size_t max_block_bytes = 64 * 1024;  // a longer block is kBlockTooLong
  std::size_t window_bytes = 1 << 20;       // read buffer of a file source
  // ';' outside parentheses ends a block (Fanuc's end of block, EOB); when
  // false only a line end does and ';' is left to the parser (RS274NGC and
  // grbl read it as a comment to the end of the line).
  bool semicolon_ends_block = true;
};

// A source over text held in memory (tests, generated programs).
std::unique_ptr<Source> make_string_source(std::string name, std::string text,
                                           SourceLimits limits = {});
// A source that streams a file. Fails with kFileAccess if it cannot be opened.
[[nodiscard]] Result<std::unique_ptr<Source>> open_file_source(const std::string& path,
                                                               std::string display_name,
                                                               SourceLimits limits = {});

}  // namespace skipnc::gcode
