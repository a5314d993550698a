// Property: a skip always stops within the braking distance for its feed.
//
// A random machine (per-axis acceleration, servo gain and feedforward,
// servo period, exact or sampled latch), a random dialect (and, on Fanuc,
// SKF 6200#7 that switches the stop from immediate to decelerating), a G31
// in a random direction at a random feed, and a probe signal that comes
// on when the axis crosses a random plane on the way. The run is the
// simulated machine as `skipnc run` drives it. Measured along the path,
// from the latched position (#5061.., machine coordinates) to where the axes
// came to rest, the travel d must satisfy
//
//   -w <= d <= v*T + B + (1 - ff)*v/kp + w
//
// with v = F/60 the programmed feed in mm/s, T the servo period, w the
// in-position width, and:
// - v*T: the signal is seen at the first servo period after its instant;
//   the command has moved on by up to one period at most;
// - B: the command's braking distance, 0 for an immediate stop and
//   v^2 / (2 a) for a decelerating one, a the path's deceleration limit
//   min_i(A_i / |u_i|) over the moving axes (kernel.cpp, trigger());
// - (1 - ff)*v/kp: the servo's following error at feed v, which the axes
//   make up after the command stops (first-order servo, plant.cpp).
// Sideways the travel is at most (1 - ff)*v/kp + w: the command stays on
// the line, and a latched actual position is off it by no more than the
// axes' following error (the axes may lag by different amounts).
//
// Seed and count: RC_PARAMS="seed=7 max_success=10000".
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <string>

#include "config/skip_inputs.hpp"
#include "machine/scene.hpp"
#include "property/program_gen.hpp"
#include "sim/simulator.hpp"

namespace skipnc::property {
namespace {

RC_GTEST_PROP(SkipStop, StopsWithinTheBrakingDistanceForItsFeed, ()) {
  const std::string dialect =
      *rc::gen::elementOf(std::vector<std::string>{"fanuc", "nct", "mitsubishi", "compass"});
  Machine m(dialect);
  auto& mc = m.machine;
  const int period_us = *rc::gen::element(500, 1000, 2000);
  mc.period_ns = period_us * 1000;
  for (auto& a : mc.axes) {
    a.accel_mm_s2 = gen_real(200, 5000, 480);
    a.kp_per_s = gen_real(10, 100, 90);
    a.feedforward = gen_real(0, 1, 10);
  }
  const bool sampled = *rc::gen::arbitrary<bool>();
  mc.latch = sampled ? canon::SkipLatch::kSampled : canon::SkipLatch::kExact;
  mc.latch_delay_s = sampled ? gen_real(0, 0.002, 20) : 0.0;
  mc.servo_delay_comp = *rc::gen::arbitrary<bool>();
  if (dialect == "fanuc" && *rc::gen::arbitrary<bool>()) {
    auto s = config::Parameters::parse_setting("6200#7=1");
    RC_ASSERT(s.has_value());
    RC_ASSERT(m.params->apply(*s).has_value());
  }
  RC_ASSERT(config::check_skip_addresses(m.dialect, *m.params).has_value());

  // The move: from the origin towards a random target, 4-25 mm long.
  AxisVec target;
  double len = 0.0;
  do {
    for (int i = 0; i < 3; ++i) target[i] = gen_real(-25, 25, 5000);
    len = std::sqrt(target[0] * target[0] + target[1] * target[1] + target[2] * target[2]);
  } while (len < 4.0);
  const double feed = gen_real(60, 6000, 594);  // mm/min
  // The probe plane on the axis that moves most, 10-80 % of the way.
  int axis = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::fabs(target[i]) > std::fabs(target[axis])) axis = i;
  }
  const double at = target[axis] * gen_real(0.1, 0.8, 70);
  const std::string scene_text = std::string("[[trigger]]\nsignal = \"SKIP\"\naxis = \"") +
                                 "XYZ"[axis] + "\"\nat = " + num(at, 6) + "\ndirection = \"" +
                                 (target[axis] < 0 ? "decreasing" : "increasing") + "\"\n";
  auto scene = machine::parse_scene(scene_text, "prop.scene.toml", mc, m.dialect, *m.params);
  RC_ASSERT(scene.has_value());
  const std::string program = "G90 G0 X0 Y0 Z0\nG31 X" + num(target[0], 4) + " Y" +
                              num(target[1], 4) + " Z" + num(target[2], 4) + " F" + num(feed, 1) +
                              "\nM30\n";

  sim::Simulator sim(mc, m.dialect, *m.params, *scene);
  auto run = sim.run(m.setup(program), {});
  RC_ASSERT(run.has_value());
  RC_ASSERT(run->status == sim::RunStatus::kCompleted);
  RC_ASSERT(run->skips.size() == 1u);
  const record::SkipRecord& sk = run->skips.front();
  RC_ASSERT(sk.triggered);

  // Work coordinates are machine coordinates here (no offsets, metric).
  const double v = feed / 60.0;
  const double T = static_cast<double>(mc.period_ns) * 1e-9;
  double a_path = 1e300;
  double lag = 0.0;
  AxisVec u;
  for (int i = 0; i < 3; ++i) {
    u[i] = target[i] / len;
    const auto& ax = mc.axes[static_cast<std::size_t>(i)];
    if (std::fabs(u[i]) > 1e-12) a_path = std::fmin(a_path, ax.accel_mm_s2 / std::fabs(u[i]));
    lag = std::fmax(lag, (1.0 - ax.feedforward) / ax.kp_per_s);
  }
  const bool decelerates =
      dialect == "nct" || dialect == "compass" || (dialect == "fanuc" && m.params->bit(6200, 7));
  const double braking = decelerates ? v * v / (2.0 * a_path) : 0.0;
  const double w = mc.in_position_mm;
  double d = 0.0;
  AxisVec delta;
  for (int i = 0; i < 3; ++i) {
    delta[i] = sk.end_position[i] - sk.machine_position[i];
    d += delta[i] * u[i];
  }
  double side2 = 0.0;
  for (int i = 0; i < 3; ++i) side2 += (delta[i] - d * u[i]) * (delta[i] - d * u[i]);
  const double bound = v * T + braking + lag * v + w;
  RC_TAG(decelerates ? "decelerates" : "stops at once");
  RC_CLASSIFY(d > 0.5 * bound, "more than half the bound");
  if (!(d <= bound + 1e-9 && d >= -w - 1e-9 && std::sqrt(side2) <= lag * v + w + 1e-9)) {
    RC_FAIL("travel after the latch " + std::to_string(d) + " mm, bound " + std::to_string(bound) +
            " (v*T " + std::to_string(v * T) + ", braking " + std::to_string(braking) + ", lag " +
            std::to_string(lag * v) + "), sideways " + std::to_string(std::sqrt(side2)) + "\n" +
            program + scene_text);
  }
}

}  // namespace
}  // namespace skipnc::property
