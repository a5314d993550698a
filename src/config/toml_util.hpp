// Small helpers for strict TOML loading: every error names file:line:column.
#pragma once

#include <toml++/toml.h>

#include <cstdio>
#include <initializer_list>
#include <string>
#include <string_view>

#include "core/diag.hpp"

namespace skipnc::config {

inline SourceLoc loc_of(const toml::node& n, std::string_view origin) {
  const auto& s = n.source();
  return SourceLoc{origin, static_cast<std::uint32_t>(s.begin.line),
                   static_cast<std::uint32_t>(s.begin.column)};
}

inline std::unexpected<Error> config_error(const toml::node& n, std::string_view origin,
                                           std::string what) {
  return fail(AlarmId::kConfig, std::move(what), loc_of(n, origin));
}

// Refuses any key of `table` not in `known`.
[[nodiscard]] inline Result<void> check_keys(const toml::table& table,
                                             std::initializer_list<std::string_view> known,
                                             std::string_view origin, std::string_view where) {
  for (const auto& [key, node] : table) {
    bool ok = false;
    for (auto k : known) ok = ok || key.str() == k;
    if (!ok) {
      std::string list;
      for (auto k : known) {
        if (!list.empty()) list += ", ";
        list += k;
      }
      return config_error(node, origin,
                          "unknown key '" + std::string(key.str()) + "' in " + std::string(where) +
                              " (known: " + list + ")");
    }
  }
  return {};
}

[[nodiscard]] inline Result<double> get_number(const toml::node& n, std::string_view origin,
                                               std::string_view what, double min, double max) {
  std::optional<double> v;
  if (auto d = n.value<double>()) v = *d;
  if (!v) {
    return config_error(n, origin, std::string(what) + " must be a number");
  }
  if (!(*v >= min && *v <= max)) {
    // %g: 1e+12 rather than 1000000000000.000000, 0.001 rather than 0.001000.
    auto num = [](double x) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.10g", x);
      return std::string(buf);
    };
    return config_error(n, origin,
                        std::string(what) + " = " + num(*v) + " is out of range [" + num(min) +
                            ", " + num(max) + "]");
  }
  return *v;
}

[[nodiscard]] inline Result<std::string> get_string(const toml::node& n, std::string_view origin,
                                                    std::string_view what) {
  if (auto s = n.value<std::string>()) return *s;
  return config_error(n, origin, std::string(what) + " must be a string");
}

[[nodiscard]] inline Result<bool> get_bool(const toml::node& n, std::string_view origin,
                                           std::string_view what) {
  if (auto b = n.value<bool>()) return *b;
  return config_error(n, origin, std::string(what) + " must be true or false");
}

// Calls f on each table of the array of tables `key` ([[key]]); a missing key
// is no tables, anything else than an array of tables is an error.
template <class F>
[[nodiscard]] Result<void> each_table(const toml::table& root, std::string_view key,
                                      std::string_view origin, F&& f) {
  const auto* n = root.get(key);
  if (n == nullptr) return {};
  const auto* arr = n->as_array();
  if (arr == nullptr) {
    return config_error(*n, origin, "[[" + std::string(key) + "]] must be an array of tables");
  }
  for (const auto& e : *arr) {
    const auto* t = e.as_table();
    if (t == nullptr)
      return config_error(e, origin, "[[" + std::string(key) + "]] must be a table");
    auto r = f(*t);
    if (!r) return r;
  }
  return {};
}

// Debian's toml++ 3.3 has three faults that a malformed file reaches; each
// is an assertion, or undefined behaviour with NDEBUG, instead of a parse
// error (found by tests/fuzz/fuzz_machine and fuzz_scene; the inputs are
// kept in tests/regression/):
// - a table header whose name starts with another character than a
//   bare-key character or a quote ("[&", "[+[axis]]", "[[[1]]]"):
//   parse_key's precondition (upstream marzer/tomlplusplus#294);
// - its whitespace test is wrong for most code points from U+00A1 to
//   U+0499, U+2CDE to U+30D7 and U+FBC6 to U+FEFE (an unreachable branch of
//   is_non_ascii_horizontal_whitespace); it runs on every character between
//   tokens, on every character of a key (quoted ones too) and after any
//   backslash in a multi-line string;
// - a '}' where an array expects a value ("[}", "[1, }"), and a date, a
//   blank and a single digit ("1979-05-27 0"): parse_value's precondition
//   that it does not start or go on at a value terminator.
// This scan refuses all three before toml++ sees the text, with the place: a
// table name must start as TOML says, and a byte above 0x7F may stand only
// in a comment or in a string value (a quote where a value starts), not in
// a key and not first after a backslash in a multi-line string. No valid machine or scene file is
// refused: keys of these files are ASCII names.
[[nodiscard]] inline Result<void> precheck_toml(std::string_view text, std::string_view origin) {
  auto bare = [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  };
  auto blank = [](char c) { return c == ' ' || c == '\t'; };
  auto high = [](char c) { return static_cast<unsigned char>(c) >= 0x80; };
  const std::size_t n = text.size();
  std::size_t i = 0;
  std::uint32_t line = 1;
  std::size_t line_start = 0;
  std::string open;         // the [ and { of the value being read, innermost last
  bool line_begins = true;  // only blanks so far on this line
  bool header = false;      // on a table header line: its brackets are not a value's
  bool key = true;          // a string here is a key
  auto refuse = [&](std::size_t at, const char* what) {
    return fail(AlarmId::kConfig, what,
                SourceLoc{origin, line, static_cast<std::uint32_t>(at - line_start + 1)});
  };
  auto newline = [&](std::size_t at) {
    ++line;
    line_start = at + 1;
    line_begins = true;
    header = false;
  };
  while (i < n) {
    const char c = text[i];
    if (c == '\n') {
      newline(i++);
      if (open.empty()) key = true;  // a new statement starts with its key
      continue;
    }
    if (blank(c) || c == '\r') {
      ++i;
      continue;
    }
    if (line_begins && open.empty() && c == '[') {
      // As toml++ reads a header: '[', blanks, a second '[' only right after
      // the first ("[ [" is an error it reports), blanks, then the name.
      std::size_t j = i + 1;
      bool gap = false;
      while (j < n && blank(text[j])) {
        ++j;
        gap = true;
      }
      if (j < n && text[j] == '[' && !gap) {
        ++j;
        gap = false;
        while (j < n && blank(text[j])) ++j;
      }
      const bool reported = j >= n || text[j] == ']' || (text[j] == '[' && gap);
      if (!reported && !bare(text[j]) && text[j] != '"' && text[j] != '\'') {
        return refuse(j, "a table name must start with a letter, a digit, '_', '-' or a quote");
      }
      header = true;
      key = true;
      line_begins = false;
      i = j;
      continue;
    }
    line_begins = false;
    if (high(c)) {
      return refuse(i, "a character outside ASCII may only stand in a string value or a comment");
    }
    if (c == '#') {
      while (i < n && text[i] != '\n') ++i;
      continue;
    }
    // A quote opens a string only where TOML lets one start (after '=', '[',
    // '{', ',', '.' or first on a line, blanks between). Elsewhere ("1'x'",
    // "1979-05-27 'x'") it is part of a value that toml++ scans on.
    std::size_t k = i;
    while (k > 0 && blank(text[k - 1])) --k;
    const char before = k > 0 ? text[k - 1] : '\n';
    const bool token_start = before == '\n' || before == '\r' || before == '=' || before == '[' ||
                             before == '{' || before == ',' || before == '.';
    if ((c == '"' || c == '\'') && token_start) {
      const bool multi = i + 2 < n && text[i + 1] == c && text[i + 2] == c;
      i += multi ? 3 : 1;
      while (i < n) {
        if (text[i] == '\n') {
          if (!multi) break;  // an unclosed string: toml++ reports it
          newline(i);
          line_begins = false;
        }
        if (key && high(text[i])) {
          return refuse(i, "a character outside ASCII in a key");
        }
        if (c == '"' && text[i] == '\\') {
          // In a multi-line string toml++ tests the character after any
          // backslash for whitespace (a line-ending backslash).
          if (multi && i + 1 < n && high(text[i + 1])) {
            return refuse(i + 1, "a character outside ASCII right after a backslash");
          }
          std::size_t j = i + 1;
          while (multi && j < n && (blank(text[j]) || text[j] == '\r' || text[j] == '\n')) {
            if (text[j] == '\n') {
              newline(j);
              line_begins = false;
            }
            ++j;
          }
          // A line-ending backslash: toml++ tests each following character for
          // whitespace, the first one that is not included.
          if (j > i + 1) {
            if (j < n && high(text[j])) {
              return refuse(j, "a character outside ASCII right after a line-ending backslash");
            }
            i = j;
          } else {
            i += 2;  // an escaped character
          }
          continue;
        }
        if (text[i] == c && (!multi || (i + 2 < n && text[i + 1] == c && text[i + 2] == c))) {
          i += multi ? 3 : 1;
          // Up to two more quotes after a multi-line string's closing three
          // belong to its text.
          for (int extra = 0; multi && extra < 2 && i < n && text[i] == c; ++extra) ++i;
          break;
        }
        ++i;
      }
      continue;
    }
    if (!header) {
      if (c == '=') {
        key = false;
      } else if (c == '{') {
        open += c;
        key = true;
      } else if (c == '[') {
        open += c;
        key = false;
      } else if (c == ']' || c == '}') {
        if (c == '}' && !open.empty() && open.back() == '[') {
          return refuse(i, "'}' inside an array: an array ends with ']'");
        }
        if (!open.empty()) open.pop_back();
        key = false;
      } else if (c == ',') {
        key = !open.empty() && open.back() == '{';
      } else if (!key) {
        // A bare value (number, boolean, date): toml++ scans it up to a value
        // terminator, testing each character for whitespace; a quote or a
        // bracket inside it opens nothing.
        auto ends = [&](std::size_t at) {
          return at >= n || blank(text[at]) || text[at] == '\r' || text[at] == '\n' ||
                 text[at] == ']' || text[at] == '}' || text[at] == ',' || text[at] == '#';
        };
        std::size_t j = i;
        while (!ends(j)) {
          if (high(text[j])) {
            return refuse(
                j, "a character outside ASCII may only stand in a string value or a comment");
          }
          ++j;
        }
        // A date ("1979-05-27") then a blank and one digit alone: toml++
        // reads on for the time of a date-time and asserts at the terminator.
        if (j - i == 10 && text[i + 4] == '-' && text[i + 7] == '-' && j + 1 < n &&
            text[j] == ' ' && text[j + 1] >= '0' && text[j + 1] <= '9' && j + 2 < n &&
            ends(j + 2)) {
          return refuse(j + 1, "a time after a date needs hours, minutes and seconds (hh:mm:ss)");
        }
        i = j;
        continue;
      }
    }
    ++i;
  }
  return {};
}

// Parses TOML text; a syntax error becomes a kConfig error with its position.
[[nodiscard]] inline Result<toml::table> parse_toml(std::string_view text,
                                                    std::string_view origin) {
  if (auto h = precheck_toml(text, origin); !h) return std::unexpected(h.error());
  toml::parse_result r = toml::parse(text, origin);
  if (!r) {
    const auto& e = r.error();
    return fail(AlarmId::kConfig, std::string(e.description()),
                SourceLoc{origin, static_cast<std::uint32_t>(e.source().begin.line),
                          static_cast<std::uint32_t>(e.source().begin.column)});
  }
  return std::move(r).table();
}

}  // namespace skipnc::config
