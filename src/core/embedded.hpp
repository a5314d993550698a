// Data files compiled into the binary (data/ in the source tree): dialect
// tables, built-in machines and scenes.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace skipnc {

struct EmbeddedFile {
  std::string_view path;  // relative to data/, e.g. "dialects/fanuc.toml"
  std::string_view content;
};

std::span<const EmbeddedFile> embedded_files() noexcept;

// The entry for `path`, or nullptr. Its `path` view is static: safe to keep
// in error locations.
inline const EmbeddedFile* embedded_entry(std::string_view path) noexcept {
  for (const auto& f : embedded_files()) {
    if (f.path == path) return &f;
  }
  return nullptr;
}

}  // namespace skipnc
