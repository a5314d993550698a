// Property: on a lathe, diameter and radius programming (1006#3) describe the
// same motion. A random lathe program (G50, rapids and cuts with X/Z and
// U/W, arcs with R, the G90 cycle, G98/G99 with the spindle, G96/G97 with the
// G50 clamp, dwells, G31) is written twice: with X, U and the G50 X value as
// diameters, and as radii. Interpreted on lathe2 with 1006#3 = 1 and = 0
// respectively, both give the same canonical commands: kinds in the same
// order, targets, arc centres, feeds (feed per revolution and surface speed
// included), dwell times and spindle speeds.
//
// Tolerance: 1e-9 (the two programs differ only by a factor of 2 in exactly
// representable decimal inputs; differences are rounding in the last bit).
//
// Seed and count: RC_PARAMS="seed=7 max_success=10000" (ctest: seed=1).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <string>
#include <variant>

#include "property/program_gen.hpp"

namespace skipnc::property {
namespace {

constexpr double kTol = 1e-9;

struct Twin {
  std::string diameter;
  std::string radius;
  void add(const std::string& d, const std::string& r) {
    diameter += d + "\n";
    radius += r + "\n";
  }
};

// A diameter value with 3 decimals and its radius (exact with 4 decimals).
struct XValue {
  std::string d, r;
};
XValue gen_x(double lo, double hi) {
  // Whole thousandths, so that half of the value is exact with 4 decimals.
  const int k = *rc::gen::inRange(static_cast<int>(lo * 1000), static_cast<int>(hi * 1000) + 1);
  return {num(k / 1000.0, 3), num(k / 2000.0, 4)};
}

Twin gen_lathe_program() {
  Twin t;
  const auto start = gen_x(120.0, 200.0);
  t.add("G50 X" + start.d + " Z100. S2500", "G50 X" + start.r + " Z100. S2500");
  t.add("G97 S800 M03", "G97 S800 M03");
  const int n = *rc::gen::inRange(3, 14);
  for (int i = 0; i < n; ++i) {
    const std::string z = num(gen_real(-60.0, 10.0), 3);
    switch (*rc::gen::inRange(0, 9)) {
      case 0: {
        const auto x = gen_x(0.0, 150.0);
        t.add("G00 X" + x.d + " Z" + z, "G00 X" + x.r + " Z" + z);
        break;
      }
      case 1: {
        const auto x = gen_x(0.0, 150.0);
        const std::string f = num(gen_real(0.05, 0.4), 3);
        t.add("G99 G01 X" + x.d + " Z" + z + " F" + f, "G99 G01 X" + x.r + " Z" + z + " F" + f);
        break;
      }
      case 2: {
        const auto u = gen_x(-20.0, 20.0);
        const std::string w = num(gen_real(-10.0, 10.0), 3);
        const std::string f = num(gen_real(50.0, 500.0), 1);
        t.add("G98 G01 U" + u.d + " W" + w + " F" + f, "G98 G01 U" + u.r + " W" + w + " F" + f);
        break;
      }
      case 3: {
        // An arc to an incremental end point with a radius that reaches it.
        const double dx = gen_real(-5.0, 5.0, 10000);  // radial
        const double dz = gen_real(-5.0, 5.0, 10000);
        if (std::hypot(dx, dz) < 0.01) break;
        const std::string r = num(std::hypot(dx, dz) / 2.0 + gen_real(0.1, 5.0), 3);
        const std::string g = *rc::gen::inRange(0, 2) == 0 ? "G02" : "G03";
        const std::string w = num(dz, 4);
        t.add("G98 " + g + " U" + num(2.0 * dx, 4) + " W" + w + " R" + r + " F200.",
              "G98 " + g + " U" + num(dx, 4) + " W" + w + " R" + r + " F200.");
        break;
      }
      case 4:
        t.add("G04 X0.5", "G04 X0.5");
        break;
      case 5: {
        const auto x = gen_x(10.0, 150.0);
        t.add("G99 G90 X" + x.d + " Z" + z + " F0.2", "G99 G90 X" + x.r + " Z" + z + " F0.2");
        t.add("G00", "G00");
        break;
      }
      case 6: {
        const std::string v = num(gen_real(50.0, 300.0), 1);
        t.add("G96 S" + v, "G96 S" + v);
        break;
      }
      case 7: {
        const std::string v = num(gen_real(100.0, 2000.0), 0);
        t.add("G97 S" + v, "G97 S" + v);
        break;
      }
      case 8: {
        const auto u = gen_x(-10.0, 10.0);
        t.add("G98 G31 U" + u.d + " W-1. F100.", "G98 G31 U" + u.r + " W-1. F100.");
        break;
      }
    }
  }
  t.add("M30", "M30");
  return t;
}

bool same_axes(const AxisVec& a, const AxisVec& b) {
  for (int i = 0; i < 2; ++i) {
    if (!(std::fabs(a[i] - b[i]) <= kTol)) return false;
  }
  return true;
}

bool near(double a, double b) {
  return std::fabs(a - b) <= kTol * std::max(1.0, std::fabs(a));
}

// "" when the two commands are the same, else what differs.
std::string compare(const canon::Command& a, const canon::Command& b) {
  if (a.index() != b.index()) return "different kinds";
  if (const auto* r = std::get_if<canon::Rapid>(&a)) {
    if (!same_axes(r->target, std::get<canon::Rapid>(b).target)) return "rapid";
  } else if (const auto* f = std::get_if<canon::Feed>(&a)) {
    const auto& g = std::get<canon::Feed>(b);
    if (!same_axes(f->target, g.target) || !near(f->feed_mm_per_min, g.feed_mm_per_min)) {
      return "feed";
    }
  } else if (const auto* c = std::get_if<canon::Arc>(&a)) {
    const auto& d = std::get<canon::Arc>(b);
    if (!same_axes(c->target, d.target) || !near(c->center0, d.center0) ||
        !near(c->center1, d.center1) || c->ccw != d.ccw || !(c->plane == d.plane) ||
        !near(c->feed_mm_per_min, d.feed_mm_per_min)) {
      return "arc";
    }
  } else if (const auto* w = std::get_if<canon::Dwell>(&a)) {
    if (!near(w->seconds, std::get<canon::Dwell>(b).seconds)) return "dwell";
  } else if (const auto* s = std::get_if<canon::Skip>(&a)) {
    const auto& k = std::get<canon::Skip>(b);
    if (!same_axes(s->target, k.target) || !near(s->feed_mm_per_min, k.feed_mm_per_min)) {
      return "skip";
    }
  } else if (const auto* p = std::get_if<canon::Spindle>(&a)) {
    const auto& q = std::get<canon::Spindle>(b);
    if (!near(p->rpm, q.rpm) || p->direction != q.direction ||
        !near(p->surface_speed, q.surface_speed) || !near(p->max_rpm, q.max_rpm)) {
      return "spindle";
    }
  }
  return "";
}

// lathe2 with 1006#3 set (the Parameters keep a pointer to m.dialect, so
// the machine is set up in place).
void make_lathe(Machine& m, bool diameter) {
  auto l = config::builtin_machine("lathe2");
  RC_ASSERT(l.has_value());
  m.machine = std::move(*l);
  RC_ASSERT(m.params->apply(config::ParamSetting{1006, 3, diameter ? 1.0 : 0.0, {}}).has_value());
}

RC_GTEST_PROP(LatheDiameter, DiameterAndRadiusProgramsGiveTheSameMotion, ()) {
  const Twin t = gen_lathe_program();
  Machine dia;
  make_lathe(dia, true);
  Machine rad;
  make_lathe(rad, false);
  const CanonRun a = canon_of(dia, t.diameter);
  const CanonRun b = canon_of(rad, t.radius);
  RC_ASSERT(!a.alarm);
  RC_ASSERT(!b.alarm);
  RC_ASSERT(a.cmds.size() == b.cmds.size());
  for (std::size_t i = 0; i < a.cmds.size(); ++i) {
    const std::string why = compare(a.cmds[i].cmd, b.cmds[i].cmd);
    if (!why.empty()) {
      RC_FAIL("command " + std::to_string(i) + " (line " + std::to_string(a.cmds[i].line) +
              "): " + why + "\n--- diameter\n" + t.diameter + "--- radius\n" + t.radius);
    }
  }
}

}  // namespace
}  // namespace skipnc::property
