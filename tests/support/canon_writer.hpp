// Canonical form -> G-code: writes a canonical command stream back as a
// program that, run on the same machine and dialect with zero work offsets,
// gives the same commands again. Positions are written in machine
// coordinates, absolute, metric, one command per block:
//   Rapid  G0 X.. Y.. Z..
//   Feed   G1 X.. Y.. Z.. F..        (G09 when it stops exactly)
//   Arc    G17/G18/G19 G2/G3 X.. Y.. Z.. I/J/K.. F..  (centre incremental)
//   Dwell  G4 X<seconds>
//   Skip   G31 X.. Y.. Z.. F..
// Numbers carry at most 15 significant digits (the parser's limit) and
// always a decimal point. Other commands (spindle, tools, M codes,
// messages) are left out: the round trip is about motion.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "canon/canon.hpp"
#include "config/machine_config.hpp"

namespace skipnc::test {

// `x` with a decimal point and at most 15 significant digits, never in
// exponent form ("12.5", "-0.000125", "3.").
inline std::string gcode_number(double x) {
  if (x == 0.0) return "0.";
  const double ax = std::fabs(x);
  const int int_digits = ax >= 1.0 ? static_cast<int>(std::floor(std::log10(ax))) + 1 : 0;
  // Leading zeros after the point are not significant.
  const int lead_zeros = ax < 1.0 ? -static_cast<int>(std::floor(std::log10(ax))) - 1 : 0;
  const int frac = std::max(0, std::min(22, 15 - int_digits + lead_zeros));
  std::array<char, 64> buf{};
  auto r = std::to_chars(buf.data(), buf.data() + buf.size(), x, std::chars_format::fixed, frac);
  std::string s(buf.data(), r.ptr);
  if (s.find('.') == std::string::npos) {
    s += '.';
  } else {
    while (s.back() == '0') s.pop_back();
  }
  if (s == "-0." || s == "0.") return "0.";
  return s;
}

class CanonWriter {
 public:
  explicit CanonWriter(const config::MachineConfig& m) : m_(m) {}

  std::string write(const std::vector<canon::Stamped>& cmds) {
    std::string out = "G21 G90 G54 G17 G94\n";
    AxisVec pos{};  // the interpreter starts at the machine origin
    for (const auto& c : cmds) {
      std::visit([&](const auto& cmd) { block(out, cmd, pos); }, c.cmd);
    }
    out += "M30\n";
    return out;
  }

 private:
  void axes(std::string& out, const AxisVec& target) const {
    for (int i = 0; i < m_.axis_count(); ++i) {
      out += ' ';
      out += m_.axes[static_cast<std::size_t>(i)].name;
      out += gcode_number(target[i]);
    }
  }
  void block(std::string& out, const canon::Rapid& c, AxisVec& pos) const {
    out += "G0";
    axes(out, c.target);
    out += '\n';
    pos = c.target;
  }
  void block(std::string& out, const canon::Feed& c, AxisVec& pos) const {
    out += c.exact_stop ? "G09 G1" : "G1";
    axes(out, c.target);
    out += " F" + gcode_number(c.feed_mm_per_min) + "\n";
    pos = c.target;
  }
  void block(std::string& out, const canon::Arc& c, AxisVec& pos) const {
    const char a0 = m_.axes[static_cast<std::size_t>(c.plane.a0)].name;
    const char a1 = m_.axes[static_cast<std::size_t>(c.plane.a1)].name;
    // The plane by its first axis; the centre word of each plane axis.
    const char* g = a0 == 'X' ? "G17" : a0 == 'Z' ? "G18" : "G19";
    auto centre_word = [](char axis) { return axis == 'X' ? 'I' : axis == 'Y' ? 'J' : 'K'; };
    out += g;
    out += c.exact_stop ? " G09" : "";
    out += c.ccw ? " G3" : " G2";
    axes(out, c.target);
    out += ' ';
    out += centre_word(a0);
    out += gcode_number(c.center0 - pos[c.plane.a0]);
    out += ' ';
    out += centre_word(a1);
    out += gcode_number(c.center1 - pos[c.plane.a1]);
    out += " F" + gcode_number(c.feed_mm_per_min) + "\n";
    pos = c.target;
  }
  void block(std::string& out, const canon::Dwell& c, AxisVec&) const {
    out += "G4 X" + gcode_number(c.seconds) + "\n";
  }
  void block(std::string& out, const canon::Skip& c, AxisVec& pos) const {
    out += "G31";
    axes(out, c.target);
    out += " F" + gcode_number(c.feed_mm_per_min) + "\n";
    pos = c.target;
  }
  template <class T>
  void block(std::string&, const T&, AxisVec&) const {}

  const config::MachineConfig& m_;
};

}  // namespace skipnc::test
