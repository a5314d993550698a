// Issue 9: the plot's trace is thinned for drawing, but never loses a block
// boundary, a signal edge or the servo periods around a latch, and stays
// within its tolerance of the full trace.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "plot/recorder.hpp"
#include "sim/simulator.hpp"

namespace skipnc {
namespace {

config::MachineConfig mill3() {
  auto m = config::builtin_machine("mill3");
  EXPECT_TRUE(m.has_value());
  return *m;
}

// One synthetic servo period (no plant: no signals).
void feed_row(plot::Recorder& rec, std::int64_t k, const AxisVec& cmd, const AxisVec& act,
              double feed, std::uint32_t line) {
  AxisVec torque;
  sim::TraceRow r;
  r.tick = k;
  r.time_s = static_cast<double>(k) * 0.001;
  r.commanded = &cmd;
  r.actual = &act;
  r.torque = &torque;
  r.feed_mm_per_min = feed;
  r.line = line;
  rec.row(r);
}

// Linear value of the kept samples at time t.
double kept_at(const std::vector<plot::Sample>& s, double t, int axis) {
  auto it = std::lower_bound(s.begin(), s.end(), t,
                             [](const plot::Sample& a, double x) { return a.t < x; });
  if (it == s.begin()) return it->act[axis];
  if (it == s.end()) return s.back().act[axis];
  const auto& b = *it;
  const auto& a = *(it - 1);
  return a.act[axis] + (b.act[axis] - a.act[axis]) * (t - a.t) / (b.t - a.t);
}

TEST(PlotRecorder, ConstantFeedIsDrawnFromAFewSamples) {
  const auto m = mill3();
  plot::Recorder rec(m);
  const int n = 100000;  // 100 s at 1 ms
  for (int k = 1; k <= n; ++k) {
    AxisVec cmd, act;
    cmd[0] = 0.01 * k;  // 600 mm/min
    act[0] = cmd[0] - 0.3333;
    feed_row(rec, k, cmd, act, 600.0, 7);
  }
  rec.finish();
  EXPECT_EQ(rec.periods_seen(), static_cast<std::uint64_t>(n));
  EXPECT_LT(rec.samples().size(), 10u);
  EXPECT_DOUBLE_EQ(rec.samples().front().t, 0.001);
  EXPECT_DOUBLE_EQ(rec.samples().back().t, 100.0);
  EXPECT_NEAR(rec.samples().back().act[0], 1000.0 - 0.3333, 1e-9);
}

TEST(PlotRecorder, EveryPeriodStaysWithinTwiceTheTolerance) {
  const auto m = mill3();
  plot::Decimation d;
  plot::Recorder rec(m, d);
  std::vector<double> truth;
  const int n = 20000;
  for (int k = 1; k <= n; ++k) {
    const double t = k * 0.001;
    AxisVec cmd, act;
    cmd[0] = 5.0 * std::sin(2 * std::numbers::pi * t / 0.7) + 0.3 * t * t;
    cmd[1] = std::fmod(t, 1.3) < 0.65 ? 2.0 * t : -1.0;  // a jump every 0.65 s
    act[0] = cmd[0] - 0.01 * std::cos(t);
    act[1] = cmd[1];
    truth.push_back(act[0]);
    feed_row(rec, k, cmd, act, 300.0, 3);
  }
  rec.finish();
  const auto& s = rec.samples();
  EXPECT_LT(s.size(), static_cast<std::size_t>(n / 3));
  double worst = 0.0;
  for (int k = 1; k <= n; ++k) {
    worst = std::max(worst,
                     std::fabs(kept_at(s, k * 0.001, 0) - truth[static_cast<std::size_t>(k - 1)]));
  }
  EXPECT_LE(worst, 2 * d.pos_tol_mm + 1e-12);
}

TEST(PlotRecorder, BlockBoundariesAndKindsAreExact) {
  const auto m = mill3();
  plot::Recorder rec(m);
  canon::Stamped c;
  c.line = 4;
  c.cmd = canon::Rapid{};
  rec.emit(c);
  c.line = 5;
  c.cmd = canon::Feed{};
  rec.emit(c);
  c.line = 6;
  canon::Skip sk;
  sk.target[2] = -40.0;
  c.cmd = sk;
  rec.emit(c);
  for (int k = 1; k <= 3000; ++k) {
    AxisVec cmd, act;
    cmd[2] = -0.01 * k;
    act[2] = cmd[2];
    feed_row(rec, k, cmd, act, 600.0, k <= 1000 ? 4 : k <= 2217 ? 5 : 6);
  }
  rec.finish();
  const auto& b = rec.blocks();
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[0].kind, plot::MoveKind::kRapid);
  EXPECT_EQ(b[1].kind, plot::MoveKind::kFeed);
  EXPECT_EQ(b[2].kind, plot::MoveKind::kSkip);
  EXPECT_DOUBLE_EQ(b[1].t0, 1.001);
  EXPECT_DOUBLE_EQ(b[1].t1, 2.217);
  EXPECT_DOUBLE_EQ(b[1].end_cmd[2], -22.17);
  ASSERT_EQ(rec.skip_moves().size(), 1u);
  EXPECT_DOUBLE_EQ(rec.skip_moves()[0].target[2], -40.0);
  // Both sides of each boundary are drawn.
  for (double t : {1.0, 1.001, 2.217, 2.218}) {
    EXPECT_TRUE(std::any_of(rec.samples().begin(), rec.samples().end(),
                            [&](const plot::Sample& s) { return std::fabs(s.t - t) < 1e-12; }))
        << "t = " << t;
  }
}

TEST(PlotRecorder, OverBudgetTheToleranceGrowsButBoundariesStay) {
  const auto m = mill3();
  plot::Decimation d;
  d.max_samples = 400;
  plot::Recorder rec(m, d);
  const int n = 40000;
  for (int k = 1; k <= n; ++k) {
    const double t = k * 0.001;
    AxisVec cmd;
    cmd[0] = 10.0 * std::sin(2 * std::numbers::pi * t / 0.25);
    feed_row(rec, k, cmd, cmd, 100.0, k <= 20000 ? 1 : 2);
  }
  rec.finish();
  EXPECT_GT(rec.tolerance_scale(), 1.0);
  EXPECT_LE(rec.samples().size(), 2 * d.max_samples);
  ASSERT_EQ(rec.blocks().size(), 2u);
  const bool boundary_kept =
      std::any_of(rec.samples().begin(), rec.samples().end(),
                  [](const plot::Sample& s) { return std::fabs(s.t - 20.001) < 1e-12; });
  EXPECT_EQ(boundary_kept, rec.tolerance_scale() <= 4.0);
}

// Issue 31: memory is bounded by the Decimation, not by the program. A long
// program of short blocks pins two samples per block (its boundaries) and
// makes a block run each; the recorder keeps at most max_kept samples and
// max_blocks runs however many periods and blocks it sees, and still the
// first and last period and the last block.
TEST(PlotRecorder, ALongProgramKeepsAtMostTheBoundedSamplesAndBlocks) {
  const auto m = mill3();
  plot::Decimation d;
  d.max_samples = 1000;
  d.max_kept = 2000;
  d.max_blocks = 500;
  plot::Recorder rec(m, d);
  const int n = 300000;  // 100,000 blocks of 3 periods
  std::size_t most_samples = 0, most_blocks = 0;
  for (int k = 1; k <= n; ++k) {
    AxisVec cmd;
    cmd[0] = (k % 7) * 0.1;  // no straight line: the sleeve keeps every change
    feed_row(rec, k, cmd, cmd, 100.0, static_cast<std::uint32_t>(1 + (k - 1) / 3));
    most_samples = std::max(most_samples, rec.samples().size());
    most_blocks = std::max(most_blocks, rec.blocks().size());
  }
  rec.finish();
  EXPECT_LE(most_samples, d.max_kept);
  EXPECT_LE(most_blocks, d.max_blocks);
  EXPECT_GT(rec.blocks().size(), d.max_blocks / 4);
  EXPECT_DOUBLE_EQ(rec.samples().front().t, 0.001);
  EXPECT_DOUBLE_EQ(rec.samples().back().t, n * 0.001);
  EXPECT_EQ(rec.blocks().back().line, static_cast<std::uint32_t>(n / 3));
  EXPECT_DOUBLE_EQ(rec.blocks().front().t0, 0.001);
  EXPECT_EQ(rec.periods_seen(), static_cast<std::uint64_t>(n));
  // The default bound is the one docs/plot.md states.
  EXPECT_EQ(plot::Decimation{}.max_kept, 80000u);
  EXPECT_EQ(plot::Decimation{}.max_blocks, 20000u);
}

// Issue 31: the skip commands and tool changes a plot keeps are bounded too.
// 100,000 skip blocks, each with a T word and M06, placed at a period where
// the command stands; the tool changes every other period (T2 T2 T1 T1 ...),
// so half the M06 are for the tool already in the spindle and change
// nothing. The recorder keeps the first max_skip_moves skip commands, in
// order, and at most max_tool_changes tool changes, the first and the last
// among them.
TEST(PlotRecorder, SkipMovesAndToolChangesStayWithinTheirBounds) {
  const auto m = mill3();
  plot::Decimation d;
  d.max_skip_moves = 300;
  d.max_tool_changes = 400;
  plot::Recorder rec(m, d);
  const int n = 100000;
  std::size_t most_changes = 0;
  AxisVec at;
  for (int k = 1; k <= n; ++k) {
    canon::Stamped c;
    c.line = static_cast<std::uint32_t>(k);
    AxisVec target;
    target[2] = -static_cast<double>(k);
    c.cmd = canon::Skip{target, 100.0, {}};
    rec.emit(c);
    c.cmd = canon::ToolSelect{1 + (k / 2) % 2};
    rec.emit(c);
    c.cmd = canon::MCode{6};
    rec.emit(c);
    feed_row(rec, k, at, at, 0.0, static_cast<std::uint32_t>(k));
    most_changes = std::max(most_changes, rec.tool_changes().size());
  }
  rec.finish();
  ASSERT_EQ(rec.skip_moves().size(), d.max_skip_moves);
  EXPECT_EQ(rec.skip_moves_dropped(), n - d.max_skip_moves);
  for (std::size_t i = 0; i < rec.skip_moves().size(); ++i) {
    EXPECT_EQ(rec.skip_moves()[i].line, i + 1);
    EXPECT_DOUBLE_EQ(rec.skip_moves()[i].target[2], -static_cast<double>(i + 1));
  }
  EXPECT_LE(most_changes, d.max_tool_changes);
  const auto& tc = rec.tool_changes();
  ASSERT_GE(tc.size(), d.max_tool_changes / 2);
  // The first row places nothing (no period before it); the first change is
  // T2 at the second period, the last T1 at the last (k = n, n / 2 even).
  EXPECT_DOUBLE_EQ(tc.front().t, 0.002);
  EXPECT_EQ(tc.front().tool, 2);
  EXPECT_DOUBLE_EQ(tc.back().t, n * 0.001);
  EXPECT_EQ(tc.back().tool, 1);
  for (std::size_t i = 1; i < tc.size(); ++i) {
    EXPECT_LT(tc[i - 1].t, tc[i].t);
  }
  // One change every other period from the second on: 50,000, all counted.
  EXPECT_EQ(tc.size() + rec.tool_changes_dropped(), static_cast<std::size_t>(n / 2));
  // The default bounds are the ones docs/plot.md states.
  EXPECT_EQ(plot::Decimation{}.max_skip_moves, 20000u);
  EXPECT_EQ(plot::Decimation{}.max_tool_changes, 20000u);
}

// A real run: the probe touches a plane twice; a pulse on another input
// comes and goes. Every edge is drawn to the servo period.
TEST(PlotRecorder, SignalEdgesAndLatchesSurviveThinningOfARealRun) {
  auto m = mill3();
  auto dl = config::builtin_dialect("fanuc");
  ASSERT_TRUE(dl.has_value());
  config::Parameters p(&*dl);
  machine::Scene scene;
  machine::Trigger t;
  t.signal = canon::SignalAddr{'X', 0, 4};
  t.signal_name = "X0.4";
  t.axis = 2;
  t.at = -12.3456;
  scene.triggers.push_back(t);
  machine::Pulse pu;
  pu.signal = canon::SignalAddr{'X', 0, 1};
  pu.signal_name = "X0.1";
  pu.at_time_s = 0.2505;
  pu.duration_s = 0.0302;
  scene.pulses.push_back(pu);
  plot::Decimation d;
  d.max_samples = 300;  // a tight budget forces thinning
  plot::Recorder rec(m, d);
  sim::Simulator sim(m, *dl, p, scene);
  record::Setup setup;
  setup.machine = &m;
  setup.dialect = &*dl;
  setup.params = &p;
  setup.program_text =
      "G21 G90 G54\nG0 X0 Y0 Z0\nG31 Z-40. F600.\nG91 G0 Z2.\nG90 G31 Z-40. F60.\nG0 Z0\n"
      "G1 X100. F3000.\nG1 X0 Y50.\nG1 Y0\nM30\n";
  sim::RunOptions opts;
  opts.trace = &rec;
  opts.commands = &rec;
  auto r = sim.run(setup, opts);
  ASSERT_TRUE(r.has_value());
  rec.finish();
  ASSERT_EQ(r->skips.size(), 2u);
  const auto& s = rec.samples();
  EXPECT_LE(s.size(), 3 * d.max_samples);
  ASSERT_EQ(rec.signal_names().size(), 2u);
  // Each latch lies between two kept samples one period apart, with the
  // trigger's input off before and on after.
  const auto idx = static_cast<std::size_t>(
      std::find(rec.signal_names().begin(), rec.signal_names().end(), "X0.4") -
      rec.signal_names().begin());
  for (const auto& sk : r->skips) {
    ASSERT_TRUE(sk.triggered);
    auto it = std::lower_bound(s.begin(), s.end(), sk.time_s,
                               [](const plot::Sample& a, double x) { return a.t < x; });
    ASSERT_NE(it, s.begin());
    ASSERT_NE(it, s.end());
    EXPECT_NEAR(it->t - (it - 1)->t, 0.001, 1e-9) << "latch at " << sk.time_s;
    EXPECT_EQ(((it - 1)->signals >> idx) & 1U, 0U);
    EXPECT_EQ((it->signals >> idx) & 1U, 1U);
  }
  // The pulse: on at 0.2505 s, off at 0.2807 s, each to the period.
  std::vector<double> edges;
  for (std::size_t i = 1; i < s.size(); ++i) {
    if (s[i].signals != s[i - 1].signals) {
      EXPECT_NEAR(s[i].t - s[i - 1].t, 0.001, 1e-9);
      edges.push_back(s[i].t);
    }
  }
  ASSERT_GE(edges.size(), 2u);
  EXPECT_NEAR(edges[0], 0.251, 1e-9);
  EXPECT_NEAR(edges[1], 0.281, 1e-9);
  // The skip blocks are known as skips.
  int skips = 0;
  for (const auto& b : rec.blocks()) skips += b.kind == plot::MoveKind::kSkip ? 1 : 0;
  EXPECT_EQ(skips, 2);
}

}  // namespace
}  // namespace skipnc
