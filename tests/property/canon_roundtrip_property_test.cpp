// Property: a program round-tripped through its canonical form gives the
// same motion. A random program (units, offsets, tool length, G52, absolute
// and incremental moves, arcs in the three planes, helices, dwells, skips,
// macro variables) is interpreted to its canonical command stream; the
// stream is written back as G-code (tests/support/canon_writer.hpp: machine
// coordinates, metric, absolute); that program is interpreted again. Both
// streams must hold the same motion commands: same kinds in the same order,
// the same targets, arc centres, planes, directions, feeds, dwell times and
// skip specifications.
//
// Tolerance: the writer prints at most 15 significant digits (the parser's
// limit for a number), so a coordinate of up to 2000 mm comes back within
// 1e-11 mm; 1e-9 mm (a nanometre) is asserted.
//
// Seed and count: RC_PARAMS="seed=7 max_success=10000" (ctest runs seed=1
// and the default count).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <string>
#include <variant>

#include "property/program_gen.hpp"
#include "support/canon_writer.hpp"

namespace skipnc::property {
namespace {

constexpr double kTol = 1e-9;

bool same_axes(const AxisVec& a, const AxisVec& b, int n) {
  for (int i = 0; i < n; ++i) {
    if (!(std::fabs(a[i] - b[i]) <= kTol)) return false;
  }
  return true;
}

bool near(double a, double b) {
  return std::fabs(a - b) <= kTol;
}

bool same_spec(const canon::SkipSpec& a, const canon::SkipSpec& b) {
  if (a.input_count != b.input_count) return false;
  for (int i = 0; i < a.input_count; ++i) {
    if (!(a.inputs[i] == b.inputs[i])) return false;
  }
  return a.kind == b.kind && a.active_low == b.active_low && a.edge == b.edge &&
         a.active_at_start_ends == b.active_at_start_ends && a.stop == b.stop &&
         a.accel == b.accel && a.feed_fixed == b.feed_fixed && a.latch == b.latch &&
         a.alarm_on_miss == b.alarm_on_miss;
}

// "" when the two motion commands are the same, else what differs.
std::string compare(const canon::Command& a, const canon::Command& b, int n) {
  if (a.index() != b.index()) return "different kinds";
  if (const auto* r = std::get_if<canon::Rapid>(&a)) {
    const auto& s = std::get<canon::Rapid>(b);
    if (!same_axes(r->target, s.target, n) || r->linear != s.linear) return "rapid";
  } else if (const auto* f = std::get_if<canon::Feed>(&a)) {
    const auto& g = std::get<canon::Feed>(b);
    if (!same_axes(f->target, g.target, n) || !near(f->feed_mm_per_min, g.feed_mm_per_min) ||
        f->exact_stop != g.exact_stop) {
      return "feed";
    }
  } else if (const auto* c = std::get_if<canon::Arc>(&a)) {
    const auto& d = std::get<canon::Arc>(b);
    if (!same_axes(c->target, d.target, n) || !near(c->center0, d.center0) ||
        !near(c->center1, d.center1) || !(c->plane == d.plane) || c->ccw != d.ccw ||
        c->extra_turns != d.extra_turns || !near(c->feed_mm_per_min, d.feed_mm_per_min) ||
        c->exact_stop != d.exact_stop) {
      return "arc";
    }
  } else if (const auto* w = std::get_if<canon::Dwell>(&a)) {
    if (!near(w->seconds, std::get<canon::Dwell>(b).seconds)) return "dwell";
  } else if (const auto* k = std::get_if<canon::Skip>(&a)) {
    const auto& l = std::get<canon::Skip>(b);
    if (!same_axes(k->target, l.target, n) || !near(k->feed_mm_per_min, l.feed_mm_per_min) ||
        !same_spec(k->spec, l.spec)) {
      return "skip";
    }
  }
  return {};
}

std::vector<canon::Stamped> motion_of(const std::vector<canon::Stamped>& all) {
  std::vector<canon::Stamped> out;
  for (const auto& c : all) {
    if (canon::is_motion(c.cmd)) out.push_back(c);
  }
  return out;
}

TEST(CanonRoundTrip, NumbersKeepTheirValueWithinTheParsersDigits) {
  for (double x : {0.0, 1.0, -1.0, 0.5, 1e-13, -123.456789012345678, 1999.99999999999, 3e-7}) {
    const std::string s = test::gcode_number(x);
    EXPECT_NE(s.find('.'), std::string::npos) << s;
    EXPECT_EQ(s.find('e'), std::string::npos) << s;
    EXPECT_NEAR(std::stod(s), x, 1e-11) << s;
  }
}

RC_GTEST_PROP(CanonRoundTrip, SameMotionAfterARoundTripThroughTheCanonicalForm, ()) {
  const Machine m("fanuc");
  const std::string program = gen_program();
  const CanonRun first = canon_of(m, program);
  const auto a = motion_of(first.cmds);
  RC_TAG(first.alarm ? "ends in an alarm" : "completes");
  RC_CLASSIFY(a.size() >= 8, "8 or more motion commands");

  const std::string written = test::CanonWriter(m.machine).write(a);
  const CanonRun second = canon_of(m, written);
  RC_ASSERT(!second.alarm);
  const auto b = motion_of(second.cmds);
  RC_ASSERT(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string diff = compare(a[i].cmd, b[i].cmd, m.machine.axis_count());
    if (!diff.empty()) {
      RC_FAIL("command " + std::to_string(i) + " (line " + std::to_string(a[i].line) +
              "): " + diff + "\nprogram:\n" + program + "\nwritten:\n" + written);
    }
  }
}

}  // namespace
}  // namespace skipnc::property
