// The scan that refuses, with their place, the malformed TOML texts that
// Debian's toml++ 3.3 asserts on instead of reporting (config/toml_util.hpp
// says which). One pass over the text, in the order toml++ reads it.
#include <cstdint>
#include <string>
#include <string_view>

#include "config/toml_util.hpp"

namespace skipnc::config {
namespace {

bool bare(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-';
}
bool blank(char c) {
  return c == ' ' || c == '\t';
}
bool high(char c) {
  return static_cast<unsigned char>(c) >= 0x80;
}

class Precheck {
 public:
  Precheck(std::string_view text, std::string_view origin) : text_(text), origin_(origin) {}

  Result<void> run() {
    while (i_ < n_) {
      const char c = text_[i_];
      if (c == '\n') {
        newline(i_++);
        if (open_.empty()) key_ = true;  // a new statement starts with its key
        continue;
      }
      if (blank(c) || c == '\r') {
        ++i_;
        continue;
      }
      if (line_begins_ && open_.empty() && c == '[') {
        if (auto r = table_header(); !r) return r;
        continue;
      }
      line_begins_ = false;
      if (high(c)) {
        return refuse(i_,
                      "a character outside ASCII may only stand in a string value or a comment");
      }
      if (c == '#') {
        while (i_ < n_ && text_[i_] != '\n') ++i_;
        continue;
      }
      if ((c == '"' || c == '\'') && token_start()) {
        if (auto r = string(c); !r) return r;
        continue;
      }
      if (!header_) {
        bool moved = false;
        if (auto r = structure(c, moved); !r) return r;
        if (moved) continue;
      }
      ++i_;
    }
    return {};
  }

 private:
  std::unexpected<Error> refuse(std::size_t at, const char* what) const {
    return fail(AlarmId::kConfig, what,
                SourceLoc{origin_, line_, static_cast<std::uint32_t>(at - line_start_ + 1)});
  }

  void newline(std::size_t at) {
    ++line_;
    line_start_ = at + 1;
    line_begins_ = true;
    header_ = false;
  }

  // A quote opens a string only where TOML lets one start (after '=', '[',
  // '{', ',', '.' or first on a line, blanks between). Elsewhere ("1'x'",
  // "1979-05-27 'x'") it is part of a value that toml++ scans on.
  bool token_start() const {
    std::size_t k = i_;
    while (k > 0 && blank(text_[k - 1])) --k;
    const char before = k > 0 ? text_[k - 1] : '\n';
    return before == '\n' || before == '\r' || before == '=' || before == '[' || before == '{' ||
           before == ',' || before == '.';
  }

  // As toml++ reads a header: '[', blanks, a second '[' only right after the
  // first ("[ [" is an error it reports), blanks, then the name.
  Result<void> table_header() {
    std::size_t j = i_ + 1;
    bool gap = false;
    while (j < n_ && blank(text_[j])) {
      ++j;
      gap = true;
    }
    if (j < n_ && text_[j] == '[' && !gap) {
      ++j;
      gap = false;
      while (j < n_ && blank(text_[j])) ++j;
    }
    const bool reported = j >= n_ || text_[j] == ']' || (text_[j] == '[' && gap);
    if (!reported && !bare(text_[j]) && text_[j] != '"' && text_[j] != '\'') {
      return refuse(j, "a table name must start with a letter, a digit, '_', '-' or a quote");
    }
    header_ = true;
    key_ = true;
    line_begins_ = false;
    i_ = j;
    return {};
  }

  // A string opened by quote `c` at i_, up to its end.
  Result<void> string(char c) {
    const bool multi = i_ + 2 < n_ && text_[i_ + 1] == c && text_[i_ + 2] == c;
    i_ += multi ? 3 : 1;
    while (i_ < n_) {
      if (text_[i_] == '\n') {
        if (!multi) break;  // an unclosed string: toml++ reports it
        newline(i_);
        line_begins_ = false;
      }
      if (key_ && high(text_[i_])) return refuse(i_, "a character outside ASCII in a key");
      if (c == '"' && text_[i_] == '\\') {
        if (auto r = backslash(multi); !r) return r;
        continue;
      }
      if (text_[i_] == c && (!multi || (i_ + 2 < n_ && text_[i_ + 1] == c && text_[i_ + 2] == c))) {
        i_ += multi ? 3 : 1;
        // Up to two more quotes after a multi-line string's closing three
        // belong to its text.
        for (int extra = 0; multi && extra < 2 && i_ < n_ && text_[i_] == c; ++extra) ++i_;
        break;
      }
      ++i_;
    }
    return {};
  }

  // A backslash at i_ in a basic string. In a multi-line string toml++ tests
  // the character after any backslash for whitespace (a line-ending
  // backslash).
  Result<void> backslash(bool multi) {
    if (multi && i_ + 1 < n_ && high(text_[i_ + 1])) {
      return refuse(i_ + 1, "a character outside ASCII right after a backslash");
    }
    std::size_t j = i_ + 1;
    while (multi && j < n_ && (blank(text_[j]) || text_[j] == '\r' || text_[j] == '\n')) {
      if (text_[j] == '\n') {
        newline(j);
        line_begins_ = false;
      }
      ++j;
    }
    // A line-ending backslash: toml++ tests each following character for
    // whitespace, the first one that is not included.
    if (j > i_ + 1) {
      if (j < n_ && high(text_[j])) {
        return refuse(j, "a character outside ASCII right after a line-ending backslash");
      }
      i_ = j;
    } else {
      i_ += 2;  // an escaped character
    }
    return {};
  }

  // '=', brackets, braces and commas outside a header; a bare value after
  // '=' is scanned whole (`moved`: i_ is past it).
  Result<void> structure(char c, bool& moved) {
    if (c == '=') {
      key_ = false;
    } else if (c == '{') {
      open_ += c;
      key_ = true;
    } else if (c == '[') {
      open_ += c;
      key_ = false;
    } else if (c == ']' || c == '}') {
      if (c == '}' && !open_.empty() && open_.back() == '[') {
        return refuse(i_, "'}' inside an array: an array ends with ']'");
      }
      if (!open_.empty()) open_.pop_back();
      key_ = false;
    } else if (c == ',') {
      key_ = !open_.empty() && open_.back() == '{';
    } else if (!key_) {
      moved = true;
      return bare_value();
    }
    return {};
  }

  bool value_ends(std::size_t at) const {
    return at >= n_ || blank(text_[at]) || text_[at] == '\r' || text_[at] == '\n' ||
           text_[at] == ']' || text_[at] == '}' || text_[at] == ',' || text_[at] == '#';
  }

  // A bare value (number, boolean, date): toml++ scans it up to a value
  // terminator, testing each character for whitespace; a quote or a bracket
  // inside it opens nothing.
  Result<void> bare_value() {
    const std::size_t start = i_;
    std::size_t j = i_;
    while (!value_ends(j)) {
      if (high(text_[j])) {
        return refuse(j, "a character outside ASCII may only stand in a string value or a comment");
      }
      ++j;
    }
    // A date ("1979-05-27") then a blank and one digit alone: toml++ reads on
    // for the time of a date-time and asserts at the terminator.
    if (j - start == 10 && text_[start + 4] == '-' && text_[start + 7] == '-' && j + 1 < n_ &&
        text_[j] == ' ' && text_[j + 1] >= '0' && text_[j + 1] <= '9' && j + 2 < n_ &&
        value_ends(j + 2)) {
      return refuse(j + 1, "a time after a date needs hours, minutes and seconds (hh:mm:ss)");
    }
    i_ = j;
    return {};
  }

  std::string_view text_;
  std::string_view origin_;
  std::size_t n_ = text_.size();
  std::size_t i_ = 0;
  std::uint32_t line_ = 1;
  std::size_t line_start_ = 0;
  std::string open_;         // the [ and { of the value being read, innermost last
  bool line_begins_ = true;  // only blanks so far on this line
  bool header_ = false;      // on a table header line: its brackets are not a value's
  bool key_ = true;          // a string here is a key
};

}  // namespace

Result<void> precheck_toml(std::string_view text, std::string_view origin) {
  return Precheck(text, origin).run();
}

}  // namespace skipnc::config
