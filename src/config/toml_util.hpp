// Small helpers for strict TOML loading: every error names file:line:column.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

#include <toml++/toml.h>

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
                          "unknown key '" + std::string(key.str()) + "' in " +
                              std::string(where) + " (known: " + list + ")");
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
    return config_error(n, origin,
                        std::string(what) + " = " + std::to_string(*v) + " is out of range [" +
                            std::to_string(min) + ", " + std::to_string(max) + "]");
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

// Parses TOML text; a syntax error becomes a kConfig error with its position.
[[nodiscard]] inline Result<toml::table> parse_toml(std::string_view text,
                                                    std::string_view origin) {
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
