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
// (config/toml_precheck.cpp)
[[nodiscard]] Result<void> precheck_toml(std::string_view text, std::string_view origin);

// Parses TOML text; a syntax error becomes a kConfig error with its position.
[[nodiscard]] inline Result<toml::table> parse_toml(std::string_view text,
                                                    std::string_view origin) {
  SKIPNC_TRY(precheck_toml(text, origin));
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
