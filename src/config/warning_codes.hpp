// The codes of the run's warnings (docs/cli.md's table), in one place: what
// `--allow CODE` and a scene's `[strict] allow` may name. A name not here is
// refused, as a typo would otherwise keep --strict stopping at the warning.
#pragma once

#include <string>
#include <string_view>

namespace skipnc::config {

inline constexpr std::string_view kWarningCodes[] = {
    "no_program_end",       "no_effect",     "skip_missed_read",
    "comp_lookahead",       "feed_clamped",  "skip_braking",
    "skip_unreachable",     "probe_off",     "probe_start_deflected",
    "probe_length_differs", "grbl_servo_lag"};

inline bool is_warning_code(std::string_view code) {
  for (auto c : kWarningCodes) {
    if (c == code) return true;
  }
  return false;
}

// "no_program_end, no_effect, ...", for messages.
inline std::string warning_code_list() {
  std::string out;
  for (auto c : kWarningCodes) {
    if (!out.empty()) out += ", ";
    out += c;
  }
  return out;
}

}  // namespace skipnc::config
