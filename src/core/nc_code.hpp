// G and M codes as values, and the one way their names are written.
//
// A G code is a number with at most one decimal (G01, G54.1, G38.2): GCode
// keeps the two apart, compares, hashes and indexes dense tables (the code
// table of the interpreter, interpreter/codes.cpp). Every message, report
// and page names a code through code_name().
#pragma once

#include <cmath>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace skipnc {

class GCode {
 public:
  constexpr GCode() noexcept = default;
  // G<number>.<decimal>: GCode{54, 1} is G54.1.
  constexpr explicit GCode(int number, int decimal = 0) noexcept
      : tenths_(static_cast<std::uint16_t>(number * 10 + decimal)) {}

  // The code a G word's value names: at most one decimal, G0 to G999.9.
  static std::optional<GCode> of_value(double v) noexcept {
    const double tenths = std::round(v * 10.0);
    if (!(std::fabs(v * 10.0 - tenths) <= 1e-6) || tenths < 0 ||
        tenths >= static_cast<double>(kTableSize)) {
      return std::nullopt;
    }
    GCode g;
    g.tenths_ = static_cast<std::uint16_t>(tenths);
    return g;
  }

  constexpr int number() const noexcept { return tenths_ / 10; }
  constexpr int decimal() const noexcept { return tenths_ % 10; }
  // The value as a G word writes it (54.1), as #4001.. report it.
  constexpr double value() const noexcept { return tenths_ / 10.0; }
  // Ten times the value (G38.2: 382): LinuxCNC's own encoding of a code in
  // its parameters (#<_motion_mode>), and a dense index below kTableSize.
  constexpr int tenths() const noexcept { return tenths_; }
  static constexpr std::size_t kTableSize = 10000;

  friend constexpr auto operator<=>(GCode, GCode) noexcept = default;

 private:
  std::uint16_t tenths_ = 0;
};

// How a code's name is written: kShort "G5.1", "G0", "G38.2" (messages);
// kManual "G05.1", "G00", "G38.2" (as the manuals write them: two digits).
enum class CodeStyle : std::uint8_t { kShort, kManual };

std::string code_name(GCode g, CodeStyle style = CodeStyle::kShort);
// "M98", "M3".
std::string m_code_name(int m);

}  // namespace skipnc

template <>
struct std::hash<skipnc::GCode> {
  std::size_t operator()(skipnc::GCode g) const noexcept {
    return static_cast<std::size_t>(g.tenths());
  }
};
