// Issue 5 acceptance: a 4-point bore-centre cycle with a 2 mm ball finds
// the scene's bore centre to within 1e-6 mm at 50-2000 mm/min with exact
// latching and no scatter; with the sampled latch, each touch is late by at
// most one servo period of travel (plus the delay, which cancels in the
// centre) and the centre is off by at most half a period of travel.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "interpreter/interpreter.hpp"
#include "sim/simulator.hpp"

namespace skipnc {
namespace {

constexpr double kCx = 12.3456789, kCy = -6.54321, kR = 15.0;

struct BoreRun {
  bool ok = false;
  double x_plus = 0, x_minus = 0, y_plus = 0, y_minus = 0;  // latched ball centres
  double cx = 0, cy = 0, diameter = 0;                      // the macro's results
  double start_y = 0;
};

// A program number: at most 15 significant digits.
std::string num(double v) {
  return fmt::format("{:.7f}", v);
}

BoreRun run_bore(double feed, canon::SkipLatch mode, double delay_s, double ball, double pre,
                 double dx = 0.37, double dy = -0.23) {
  auto m = config::builtin_machine("mill3");
  auto d = config::builtin_dialect("fanuc");
  EXPECT_TRUE(m && d);
  m->latch = mode;
  m->latch_delay_s = delay_s;
  config::Parameters p(&*d);
  machine::Scene scene;
  machine::geo::Part plate;
  plate.solids.push_back(machine::geo::make_box({-60, -60, -40}, {60, 60, -10}));
  plate.holes.push_back(machine::geo::make_cylinder(kCx, kCy, kR, -1e6, 1e6));
  scene.probing.parts.push_back(plate);
  machine::ProbeSpec probe;
  probe.signal = canon::SignalAddr{'X', 0, 4};
  probe.ball_radius = ball;
  probe.pre_travel = pre;
  probe.max_overtravel = 5.0;
  scene.probing.probe = probe;
  const double x0 = kCx + dx, y0 = kCy + dy;
  const std::string f = fmt::format("{}", feed);
  const std::string prog = fmt::format(
      "G21 G90 G54\n"
      "G0 X{x0} Y{y0} Z10.\n"
      "G1 Z-20. F3000.\n"
      "G31 X{xp} F{f}\n#101 = #5061\nG0 X{x0}\n"
      "G31 X{xm} F{f}\n#102 = #5061\n#103 = [#101 + #102] / 2\nG0 X#103\n"
      "G31 Y{yp} F{f}\n#104 = #5062\nG0 Y{y0}\n"
      "G31 Y{ym} F{f}\n#105 = #5062\n#106 = [#104 + #105] / 2\n"
      "#107 = #104 - #105 + 2 * {r}\n"
      "G0 Z10.\nM30\n",
      fmt::arg("x0", num(x0)), fmt::arg("y0", num(y0)), fmt::arg("xp", num(x0 + 20)),
      fmt::arg("xm", num(x0 - 20)), fmt::arg("yp", num(y0 + 20)), fmt::arg("ym", num(y0 - 20)),
      fmt::arg("f", f), fmt::arg("r", num(ball - pre)));
  sim::Simulator sim(*m, *d, p, scene);
  interp::Setup setup;
  setup.machine = &*m;
  setup.dialect = &*d;
  setup.params = &p;
  setup.program_text = prog;
  auto r = sim.run(setup, {});
  BoreRun out;
  out.start_y = y0;
  if (!r || r->status != sim::RunStatus::kCompleted || r->skips.size() != 4) {
    ADD_FAILURE() << "the cycle did not complete: "
                  << (r && r->alarm ? r->alarm->detail : std::string("no result"));
    return out;
  }
  for (const auto& s : r->skips) EXPECT_TRUE(s.triggered);
  out.x_plus = r->skips[0].position[0];
  out.x_minus = r->skips[1].position[0];
  out.y_plus = r->skips[2].position[1];
  out.y_minus = r->skips[3].position[1];
  auto var = [&](int n) { return sim.interpreter()->read_variable(n)->v; };
  out.cx = var(103);
  out.cy = var(106);
  out.diameter = var(107);
  out.ok = true;
  return out;
}

class BoreFeed : public ::testing::TestWithParam<double> {};

TEST_P(BoreFeed, ExactLatchFindsTheBoreCentre) {
  const double feed = GetParam();
  const BoreRun b = run_bore(feed, canon::SkipLatch::kExact, 0.0, 1.0, 0.0);
  ASSERT_TRUE(b.ok);
  EXPECT_NEAR(b.cx, kCx, 1e-6) << "F" << feed;
  EXPECT_NEAR(b.cy, kCy, 1e-6) << "F" << feed;
  EXPECT_NEAR(b.diameter, 2 * kR, 1e-6) << "F" << feed;
  // Each touch is the ball centre at R - r from the axis, on its chord.
  const double half = std::sqrt((kR - 1.0) * (kR - 1.0) - (b.start_y - kCy) * (b.start_y - kCy));
  EXPECT_NEAR(b.x_plus, kCx + half, 1e-6);
  EXPECT_NEAR(b.x_minus, kCx - half, 1e-6);
}

TEST_P(BoreFeed, PreTravelAndALargerBallLeaveTheCentreExact) {
  const double feed = GetParam();
  const BoreRun b = run_bore(feed, canon::SkipLatch::kExact, 0.0, 2.0, 0.004, -0.6, 0.45);
  ASSERT_TRUE(b.ok);
  EXPECT_NEAR(b.cx, kCx, 1e-6) << "F" << feed;
  EXPECT_NEAR(b.cy, kCy, 1e-6) << "F" << feed;
  EXPECT_NEAR(b.diameter, 2 * kR, 1e-6) << "F" << feed;  // the program uses r - pre-travel
}

TEST_P(BoreFeed, SampledLatchErrorIsWithinItsBound) {
  const double feed = GetParam();
  const double v = feed / 60.0, period = 0.001;
  for (double delay : {0.0, 0.0015}) {
    double worst_centre = 0.0;
    // Start points that put the touches at different phases of the servo clock.
    for (double dx : {0.37, 0.1234, -0.271, 0.0555, -0.4, 0.3141}) {
      const BoreRun b = run_bore(feed, canon::SkipLatch::kSampled, delay, 1.0, 0.0, dx, -0.23);
      ASSERT_TRUE(b.ok);
      const double half = std::sqrt(14.0 * 14.0 - (b.start_y - kCy) * (b.start_y - kCy));
      // Late along the direction of travel: by at most v T plus v * delay (the
      // axes slow down once the skip has stopped the command).
      const double late_plus = b.x_plus - (kCx + half);
      const double late_minus = (kCx - half) - b.x_minus;
      for (double late : {late_plus, late_minus}) {
        EXPECT_GE(late, -1e-9) << "F" << feed;
        EXPECT_LE(late, v * (period + delay) + 1e-9) << "F" << feed;
      }
      const double centre_error = b.cx - kCx;
      EXPECT_LE(std::fabs(centre_error), v * period / 2 + 1e-9) << "F" << feed;
      EXPECT_NEAR(centre_error, (late_plus - late_minus) / 2, 1e-9);
      worst_centre = std::max(worst_centre, std::fabs(centre_error));
    }
    // The bound is reached in practice: over six phases the worst centre
    // error is at least a quarter of it (0.3-0.75 of it in this sweep).
    EXPECT_GE(worst_centre, 0.25 * v * period / 2) << "F" << feed << " delay " << delay;
  }
}

INSTANTIATE_TEST_SUITE_P(Feeds, BoreFeed,
                         ::testing::Values(50.0, 100.0, 250.0, 500.0, 1000.0, 2000.0),
                         [](const auto& feed_info) {
                           return "F" + std::to_string(static_cast<int>(feed_info.param));
                         });

}  // namespace
}  // namespace skipnc
