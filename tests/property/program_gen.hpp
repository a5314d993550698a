// Random part programs for the property tests (rapidcheck generators), and
// the small helpers that run them: through the interpreter alone (the
// canonical command stream, as `skipnc canon`) or on the simulated machine.
//
// A generated program is valid by construction: arcs are written with a
// centre and an end point on the same circle (incremental, so the generator
// need not know where the tool is), feeds are set before the first cut, and
// every number has a decimal point and few digits.
#pragma once

#include <rapidcheck.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "interpreter/interpreter.hpp"

namespace skipnc::property {

// "12.345" with `decimals` places (always a decimal point).
inline std::string num(double v, int decimals = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s.find('.') == std::string::npos) s += '.';
  return s == "-0.000" || s == "-0.0000" ? s.substr(1) : s;
}

inline double gen_real(double lo, double hi, int steps = 100000) {
  const int k = *rc::gen::inRange(0, steps + 1);
  return lo + (hi - lo) * static_cast<double>(k) / steps;
}

struct GenOptions {
  bool units = true;    // G20 / G21 switches
  bool offsets = true;  // G10 L2, G54-G59, G52, G43 H
  bool skips = true;    // G31 blocks
  bool dwells = true;
  bool macros = true;   // #-variables in words
  double reach = 40.0;  // absolute targets within +-reach (program units)
  double feed_min = 50.0;
  int max_blocks = 14;
};

// One block of a random program. Inch moves are scaled so that the machine
// travel stays about the same.
inline std::string gen_block(const GenOptions& o, bool& inch) {
  const int kind = *rc::gen::inRange(0, 16);
  const double scale = inch ? 1.0 / 25.4 : 1.0;
  const int dec = inch ? 4 : 3;
  const double reach = o.reach * scale;
  const double feed = gen_real(o.feed_min, 4000.0) * scale;
  auto axes_words = [&](bool all) {
    std::string s;
    for (const char* a : {"X", "Y", "Z"}) {
      if (all || *rc::gen::inRange(0, 3) != 0)
        s += std::string(" ") + a + num(gen_real(-reach, reach), dec);
    }
    if (s.empty()) s = " X" + num(gen_real(-reach, reach), dec);
    return s;
  };
  switch (kind) {
    case 0:
      return "G90 G0" + axes_words(false);
    case 1:
    case 2:
      return "G90 G1" + axes_words(false) + " F" + num(feed, 1);
    case 3:
      // Short incremental moves.
      return "G91 G1 X" + num(gen_real(-5, 5) * scale, dec) + " Y" +
             num(gen_real(-5, 5) * scale, dec) + " F" + num(feed, 1);
    case 4:
    case 5: {
      // An arc in a random plane, incremental: centre c from the start, end
      // point c + rot(theta) * (-c), helical sometimes.
      const int plane = *rc::gen::inRange(0, 3);
      static constexpr const char* kPlane[] = {"G17", "G18", "G19"};
      static constexpr char kA0[] = {'X', 'Z', 'Y'};
      static constexpr char kA1[] = {'Y', 'X', 'Z'};
      static constexpr char kN[] = {'Z', 'Y', 'X'};
      auto centre = [](char axis) { return axis == 'X' ? 'I' : axis == 'Y' ? 'J' : 'K'; };
      const double r = gen_real(1.0, 15.0) * scale;
      const double phi = gen_real(0, 2 * std::numbers::pi);
      const double theta = gen_real(0.1, 6.0) * (*rc::gen::arbitrary<bool>() ? 1 : -1);
      const double ci = r * std::cos(phi), cj = r * std::sin(phi);
      const double ex = ci - (ci * std::cos(theta) - cj * std::sin(theta));
      const double ey = cj - (ci * std::sin(theta) + cj * std::cos(theta));
      std::string s = std::string(kPlane[plane]) + " G91 " + (theta > 0 ? "G3" : "G2");
      s += std::string(" ") + kA0[plane] + num(ex, dec) + " " + kA1[plane] + num(ey, dec);
      if (*rc::gen::inRange(0, 3) == 0)
        s += std::string(" ") + kN[plane] + num(gen_real(-3, 3) * scale, dec);
      s += std::string(" ") + centre(kA0[plane]) + num(ci, dec) + " " + centre(kA1[plane]) +
           num(cj, dec);
      return s + " F" + num(feed, 1);
    }
    case 6:
      if (!o.dwells) return "G90";
      return *rc::gen::arbitrary<bool>() ? "G4 P" + std::to_string(*rc::gen::inRange(0, 800))
                                         : "G4 X" + num(gen_real(0, 0.8), 3);
    case 7:
      if (!o.skips) return "G91";
      return "G90 G31" + axes_words(false) + " F" + num(feed, 1);
    case 8:
      if (!o.offsets) return "G90";
      return "G10 L2 P" + std::to_string(*rc::gen::inRange(1, 7)) + axes_words(true);
    case 9:
      if (!o.offsets) return "G17";
      return "G" + std::to_string(54 + *rc::gen::inRange(0, 6));
    case 10:
      if (!o.units) return "G21";
      inch = *rc::gen::arbitrary<bool>();
      return inch ? "G20" : "G21";
    case 11:
      if (!o.offsets) return "G90";
      return "G52" + axes_words(false);
    case 12:
      return *rc::gen::arbitrary<bool>() ? "G61" : "G64";
    case 13:
      return "G09 G90 G1" + axes_words(false) + " F" + num(feed, 1);
    case 14:
      if (!o.macros) return "G90";
      return "#101=" + num(gen_real(-reach, reach), dec) + "\nG90 G1 X#101 Y[#101/2] F" +
             num(feed, 1);
    default:
      if (!o.offsets) return "G49";
      return *rc::gen::arbitrary<bool>() ? "G43 H" + std::to_string(*rc::gen::inRange(1, 4)) +
                                               " Z" + num(gen_real(0, reach), dec)
                                         : "G49";
  }
}

inline std::string gen_program(const GenOptions& o = {}) {
  bool inch = false;
  std::string p = "G21 G90 G17 G54 G64\nG0 X0 Y0 Z0\n";
  const int n = *rc::gen::inRange(1, o.max_blocks + 1);
  for (int i = 0; i < n; ++i) p += gen_block(o, inch) + "\n";
  return p + "M30\n";
}

// The built-in mill3 and a dialect, with tool offsets 1-3 for G43.
struct Machine {
  config::MachineConfig machine;
  config::Dialect dialect;
  std::unique_ptr<config::Parameters> params;

  explicit Machine(const std::string& dialect_name = "fanuc") {
    auto m = config::builtin_machine("mill3");
    auto d = config::builtin_dialect(dialect_name);
    RC_ASSERT(m.has_value());
    RC_ASSERT(d.has_value());
    machine = std::move(*m);
    dialect = std::move(*d);
    machine.dialect = dialect_name;
    for (int t = 1; t <= 3; ++t) machine.tool_offsets[t].length_geometry = 10.0 * t;
    params = std::make_unique<config::Parameters>(&dialect);
  }
  interp::Setup setup(const std::string& program) const {
    interp::Setup s;
    s.machine = &machine;
    s.dialect = &dialect;
    s.params = params.get();
    s.program_text = program;
    s.program_name = "gen.nc";
    return s;
  }
};

class Collect final : public canon::CommandSink {
 public:
  void emit(const canon::Stamped& c) override { cmds.push_back(c); }
  std::vector<canon::Stamped> cmds;
};

// The canonical commands of a program (skip blocks reach their end point),
// up to its end or its first alarm.
struct CanonRun {
  std::vector<canon::Stamped> cmds;
  bool alarm = false;
  Error error;
};

inline CanonRun canon_of(const Machine& m, const std::string& program) {
  CanonRun out;
  auto in = interp::Interpreter::create(m.setup(program), AxisVec{});
  if (!in) {
    out.alarm = true;
    out.error = in.error();
    return out;
  }
  Collect sink;
  for (int guard = 0; guard < 100000; ++guard) {
    auto st = (*in)->step(sink);
    if (!st) {
      out.alarm = true;
      out.error = st.error();
      break;
    }
    if (*st == interp::Step::kEnd) break;
    if (*st == interp::Step::kSync) {
      interp::SyncState s;
      s.machine_position = (*in)->position();
      s.actual_position = s.machine_position;
      s.skip_done = true;
      s.latch_machine = s.machine_position;
      auto r = (*in)->sync(s);
      if (!r && r.error().id != AlarmId::kSkipMiss) {
        out.alarm = true;
        out.error = r.error();
        break;
      }
    }
  }
  out.error.loc.file = {};  // points into the interpreter, gone after this
  out.cmds = std::move(sink.cmds);
  return out;
}

}  // namespace skipnc::property
