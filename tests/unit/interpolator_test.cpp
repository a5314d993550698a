// Interpolator: sampled motion of planned segments, skip stops.
#include "interpolator/interpolator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "support/motion.hpp"

namespace skipnc::interpolator {
namespace {

using planner::Limits;
using planner::Move;
using planner::SegmentQueue;
using Kind = Move::Kind;

using test::mill_limits;
using test::xyz;

Move line(AxisVec to, double feed, std::uint32_t tag = 0) {
  Move m;
  m.kind = Kind::kLine;
  m.target = to;
  m.feed_mm_s = feed;
  m.tag = tag;
  return m;
}

Move rapid(AxisVec to, bool linear, std::uint32_t tag = 0) {
  Move m;
  m.kind = linear ? Kind::kRapid : Kind::kRapidNonLinear;
  m.target = to;
  m.tag = tag;
  return m;
}

Move arc(AxisVec to, double c0, double c1, bool ccw, double feed, std::uint32_t tag = 0) {
  Move m;
  m.kind = Kind::kArc;
  m.target = to;
  m.center0 = c0;
  m.center1 = c1;
  m.ccw = ccw;
  m.feed_mm_s = feed;
  m.tag = tag;
  return m;
}

// Samples taken at every tick until the interpolator is idle; sample 0 is the
// position before the first tick.
struct Trace {
  std::vector<AxisVec> pos;
  std::vector<double> speed;
  std::vector<std::uint32_t> tag;
};

Trace run_to_idle(Interpolator& ip, long max_ticks = 10'000'000) {
  Trace tr;
  tr.pos.push_back(ip.position());
  tr.speed.push_back(ip.path_speed());
  tr.tag.push_back(ip.tag());
  for (long k = 0; k < max_ticks && !ip.idle(); ++k) {
    tr.pos.push_back(ip.tick());
    tr.speed.push_back(ip.path_speed());
    tr.tag.push_back(ip.tag());
  }
  return tr;
}

// Largest ratio of sampled per-axis velocity and acceleration to the limits.
// `rapid_tag(tag)` says which velocity limit applies. Acceleration samples
// whose window contains a junction (the tags on either side differ) are
// reported separately: there the sampled second difference also carries the
// planner's junction velocity step: at most 1.5 * A_i, usually at most
// 1.125 * A_i (see planner.cpp, kJunctionAccelShare).
constexpr double kJunctionAccBound = 1.5;
constexpr double kJunctionAccUsual = 1.125;

struct Ratios {
  double vel = 0.0;
  double acc = 0.0;
  double acc_junction = 0.0;
};

template <class RapidTag>
Ratios ratios(const Trace& tr, const Limits& lim, RapidTag rapid_tag) {
  Ratios r;
  const double T = lim.period_s;
  for (std::size_t k = 1; k < tr.pos.size(); ++k) {
    const bool fast = rapid_tag(tr.tag[k]) || rapid_tag(tr.tag[k - 1]);
    for (int i = 0; i < lim.axis_count; ++i) {
      const auto& al = lim.axes[static_cast<std::size_t>(i)];
      const double v = std::abs(tr.pos[k][i] - tr.pos[k - 1][i]) / T;
      r.vel = std::max(r.vel, v / (fast ? al.rapid_mm_s : al.max_velocity_mm_s));
      if (k + 1 < tr.pos.size()) {
        const double a =
            std::abs(tr.pos[k + 1][i] - 2.0 * tr.pos[k][i] + tr.pos[k - 1][i]) / (T * T);
        double& slot = tr.tag[k - 1] != tr.tag[k + 1] ? r.acc_junction : r.acc;
        slot = std::max(slot, a / al.max_accel_mm_s2);
      }
    }
  }
  return r;
}

TEST(Interpolator, LineEndsExactlyOnTargetInTheTrapezoidTime) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  const AxisVec target = xyz(100.000123, 0, 0);
  ASSERT_TRUE(q.push(line(target, 100.0)));
  const double duration = q.front()->duration;
  const Trace tr = run_to_idle(ip);
  EXPECT_EQ(tr.pos.back(), target);
  EXPECT_EQ(ip.position(), target);
  const auto ticks = static_cast<double>(tr.pos.size() - 1);
  EXPECT_EQ(ticks, std::ceil(duration / lim.period_s));
  EXPECT_TRUE(ip.idle());
  EXPECT_EQ(ip.path_speed(), 0.0);
}

TEST(Interpolator, SegmentsCarryTheRestOfThePeriod) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  Move d;
  d.kind = Kind::kDwell;
  d.dwell_s = 0.0104;
  ASSERT_TRUE(q.push(line(xyz(1.23, 0, 0), 100.0)));
  ASSERT_TRUE(q.push(d));
  ASSERT_TRUE(q.push(line(xyz(2.5, 0, 0), 100.0)));
  double total = 0.0;
  for (std::size_t k = 0; k < q.size(); ++k) {
    total += q.front()[k].duration;  // contiguous: nothing has wrapped
  }
  const Trace tr = run_to_idle(ip);
  EXPECT_EQ(static_cast<double>(tr.pos.size() - 1), std::ceil(total / lim.period_s));
  EXPECT_EQ(tr.pos.back(), xyz(2.5, 0, 0));
}

TEST(Interpolator, MixedProgramStaysWithinLimits) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  // Tags: 100+ rapids, others feed moves.
  ASSERT_TRUE(q.push(rapid(xyz(10, 0, 5), true, 100)));
  ASSERT_TRUE(q.push(line(xyz(10, 0, 0), 50.0, 1)));
  ASSERT_TRUE(q.push(line(xyz(40, 0, 0), 300.0, 2)));
  ASSERT_TRUE(q.push(arc(xyz(50, 10, 0), 40.0, 10.0, true, 300.0, 3)));  // tangent quarter
  ASSERT_TRUE(q.push(line(xyz(50, 30, 0), 300.0, 4)));
  ASSERT_TRUE(q.push(line(xyz(30, 40, 0), 300.0, 5)));                    // corner
  ASSERT_TRUE(q.push(arc(xyz(20, 30, -2), 30.0, 30.0, true, 200.0, 6)));  // helical, not tangent
  ASSERT_TRUE(
      q.push(arc(xyz(22, 30, -2), 21.0, 30.0, false, 300.0, 7)));  // r = 1: centripetal limit
  ASSERT_TRUE(q.push(line(xyz(25, 33, -1), 300.0, 8)));
  ASSERT_TRUE(q.push(rapid(xyz(0, 0, 10), false, 101)));
  ASSERT_TRUE(q.push(rapid(xyz(-5, 20, 10), true, 102)));
  const Trace tr = run_to_idle(ip);
  EXPECT_EQ(tr.pos.back(), xyz(-5, 20, 10));
  const Ratios r = ratios(tr, lim, [](std::uint32_t tag) { return tag >= 100; });
  EXPECT_LE(r.vel, 1.0 + 1e-9);
  EXPECT_LE(r.acc, 1.0 + 1e-6);
  EXPECT_LE(r.acc_junction, kJunctionAccBound);
  // Every junction here decelerates in and accelerates out (or stops).
  EXPECT_LE(r.acc_junction, kJunctionAccUsual * (1.0 + 1e-9));
}

TEST(Interpolator, CollinearShortSegmentsDoNotStop) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  for (std::uint32_t k = 1; k <= 10; ++k) {
    const double x = 2.0 * k;
    ASSERT_TRUE(q.push(line(xyz(x, x, 0), 100.0, k)));
  }
  const Trace tr = run_to_idle(ip);
  std::size_t first_moving = 0;
  while (tr.speed[first_moving] == 0.0) ++first_moving;
  for (std::size_t k = first_moving; k + 1 < tr.speed.size(); ++k) {
    EXPECT_GT(tr.speed[k], 0.0) << "sample " << k;
    if (tr.tag[k - 1] != 0 && tr.tag[k] != tr.tag[k - 1]) {
      EXPECT_NEAR(tr.speed[k], 100.0, 1e-9);
    }
  }
  EXPECT_EQ(tr.pos.back(), xyz(20, 20, 0));
}

TEST(Interpolator, RightAngleCornerIsNearlyAStop) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  ASSERT_TRUE(q.push(line(xyz(20, 0, 0), 200.0, 1)));
  ASSERT_TRUE(q.push(line(xyz(20, 20, 0), 200.0, 2)));
  const Trace tr = run_to_idle(ip);
  double corner_speed = 1e9;
  for (std::size_t k = 1; k < tr.pos.size(); ++k) {
    if (tr.tag[k] == 2 && tr.tag[k - 1] == 1) corner_speed = tr.speed[k];
  }
  EXPECT_LE(corner_speed, 2.0 * 2000.0 * lim.period_s);  // a few mm/s at most
  const Ratios r = ratios(tr, lim, [](std::uint32_t) { return false; });
  EXPECT_LE(r.acc, 1.0 + 1e-6);
  EXPECT_LE(r.acc_junction, kJunctionAccBound);
  // Every junction here decelerates in and accelerates out (or stops).
  EXPECT_LE(r.acc_junction, kJunctionAccUsual * (1.0 + 1e-9));
}

TEST(Interpolator, NonLinearRapidShortAxisArrivesFirst) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  ASSERT_TRUE(q.push(rapid(xyz(100, 10, -3), false, 7)));
  const Trace tr = run_to_idle(ip);
  std::size_t y_done = 0, z_done = 0;
  for (std::size_t k = tr.pos.size(); k-- > 0;) {
    if (y_done == 0 && tr.pos[k][1] != 10.0) y_done = k + 1;
    if (z_done == 0 && tr.pos[k][2] != -3.0) z_done = k + 1;
  }
  const std::size_t x_done = tr.pos.size() - 1;
  EXPECT_LT(y_done, x_done);
  EXPECT_LT(z_done, y_done);
  EXPECT_EQ(tr.pos.back(), xyz(100, 10, -3));
  // Every axis moves with its own profile: Y accelerates at its full rate to
  // the peak of its triangle, far above its share of a linear rapid.
  double vy = 0.0;
  for (std::size_t k = 1; k < tr.pos.size(); ++k) {
    vy = std::max(vy, (tr.pos[k][1] - tr.pos[k - 1][1]) / lim.period_s);
  }
  EXPECT_GT(vy, 0.95 * std::sqrt(2000.0 * 10.0));  // triangle peak; linear: ~50
  const Ratios r = ratios(tr, lim, [](std::uint32_t) { return true; });
  EXPECT_LE(r.vel, 1.0 + 1e-9);
  EXPECT_LE(r.acc, 1.0 + 1e-6);
}

TEST(Interpolator, ArcSamplesLieOnTheCircle) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  q.reset(xyz(15, 5, 0));
  Interpolator ip(q);
  ASSERT_TRUE(q.push(arc(xyz(5, 15, 0), 5.0, 5.0, true, 150.0)));
  const Trace tr = run_to_idle(ip);
  for (const AxisVec& p : tr.pos) {
    EXPECT_NEAR(std::hypot(p[0] - 5.0, p[1] - 5.0), 10.0, 1e-9);
    EXPECT_EQ(p[2], 0.0);
  }
  EXPECT_EQ(tr.pos.back(), xyz(5, 15, 0));
  const Ratios r = ratios(tr, lim, [](std::uint32_t) { return false; });
  EXPECT_LE(r.vel, 1.0 + 1e-9);
  EXPECT_LE(r.acc, 1.0 + 1e-6);
}

TEST(Interpolator, FullCircle) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  q.reset(xyz(10, 0, 0));
  Interpolator ip(q);
  ASSERT_TRUE(q.push(arc(xyz(10, 0, 0), 0.0, 0.0, false, 100.0)));
  const double duration = q.front()->duration;
  EXPECT_NEAR(duration, 2.0 * std::numbers::pi * 10.0 / 100.0 + 100.0 / q.front()->accel, 1e-9);
  const Trace tr = run_to_idle(ip);
  bool quadrant[4] = {};
  for (const AxisVec& p : tr.pos) {
    EXPECT_NEAR(std::hypot(p[0], p[1]), 10.0, 1e-9);
    quadrant[(p[0] >= 0 ? 0 : 1) + (p[1] >= 0 ? 0 : 2)] = true;
  }
  EXPECT_TRUE(quadrant[0] && quadrant[1] && quadrant[2] && quadrant[3]);
  // Clockwise: just after the start, Y is negative.
  EXPECT_LT(tr.pos[5][1], 0.0);
  EXPECT_EQ(tr.pos.back(), xyz(10, 0, 0));
}

TEST(Interpolator, Helix) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  q.reset(xyz(0, 0, 0));
  Interpolator ip(q);
  Move m = arc(xyz(0, 0, -6), 0.0, 5.0, true, 100.0);  // G17: centre (0, 5), r = 5
  m.extra_turns = 1;                                   // two turns: 4 pi, 3 mm per turn
  ASSERT_TRUE(q.push(m));
  const Trace tr = run_to_idle(ip);
  // z is linear in the unwrapped angle: -6 mm over 4 pi.
  const double start_angle = -std::numbers::pi / 2.0;
  double unwrapped = start_angle;
  for (const AxisVec& p : tr.pos) {
    EXPECT_NEAR(std::hypot(p[0], p[1] - 5.0), 5.0, 1e-9);
    const double a = std::atan2(p[1] - 5.0, p[0]);
    unwrapped += std::remainder(a - unwrapped, 2.0 * std::numbers::pi);
    EXPECT_NEAR(p[2], -6.0 * (unwrapped - start_angle) / (4.0 * std::numbers::pi), 1e-9);
  }
  EXPECT_NEAR(unwrapped - start_angle, 4.0 * std::numbers::pi, 1e-12);
  EXPECT_EQ(tr.pos.back(), xyz(0, 0, -6));
}

TEST(Interpolator, StopNowFreezes) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  ASSERT_TRUE(q.push(line(xyz(100, 0, 0), 200.0, 1)));
  ASSERT_TRUE(q.push(line(xyz(100, 50, 0), 200.0, 2)));
  for (int k = 0; k < 100; ++k) ip.tick();
  const AxisVec here = ip.position();
  ip.stop_now();
  EXPECT_TRUE(ip.idle());
  EXPECT_TRUE(q.empty());
  EXPECT_EQ(q.tail_position(), here);
  EXPECT_EQ(ip.path_speed(), 0.0);
  for (int k = 0; k < 10; ++k) EXPECT_EQ(ip.tick(), here);
  EXPECT_EQ(ip.velocity(), AxisVec{});
  // The queue continues from where it stopped.
  ASSERT_TRUE(q.push(line(xyz(0, 0, 0), 200.0, 3)));
  const Trace tr = run_to_idle(ip);
  EXPECT_EQ(tr.pos.back(), xyz(0, 0, 0));
}

TEST(Interpolator, DecelerateStopsAfterTheBrakingDistance) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  ASSERT_TRUE(q.push(line(xyz(30, 40, 0), 100.0, 1)));
  for (int k = 0; k < 300; ++k) ip.tick();  // cruising at 100 mm/s
  ASSERT_NEAR(ip.path_speed(), 100.0, 1e-9);
  const AxisVec here = ip.position();
  const double a = 1000.0;
  ip.decelerate(a);
  EXPECT_FALSE(ip.idle());
  const Trace tr = run_to_idle(ip);
  EXPECT_TRUE(ip.idle());
  const AxisVec travel = tr.pos.back() - here;
  const double dist = norm(travel, 3);
  const double expect = 100.0 * 100.0 / (2.0 * a);
  EXPECT_NEAR(dist, expect, 100.0 * lim.period_s);
  EXPECT_NEAR(travel[0] / dist, 0.6, 1e-12);  // along the present direction
  EXPECT_NEAR(travel[1] / dist, 0.8, 1e-12);
  EXPECT_NEAR(static_cast<double>(tr.pos.size() - 1) * lim.period_s, 100.0 / a, lim.period_s);
  EXPECT_TRUE(q.empty());
  EXPECT_EQ(q.tail_position(), tr.pos.back());
  const Ratios r = ratios(tr, lim, [](std::uint32_t) { return false; });
  EXPECT_LE(r.acc, a / 2000.0 + 1e-6);
}

TEST(Interpolator, DecelerateAtRestIsAStop) {
  SegmentQueue q(mill_limits());
  Interpolator ip(q);
  ip.decelerate(500.0);
  EXPECT_TRUE(ip.idle());
}

TEST(Interpolator, DwellLastsItsTime) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  ASSERT_TRUE(q.push(line(xyz(1, 0, 0), 100.0, 1)));
  Move d;
  d.kind = Kind::kDwell;
  d.dwell_s = 0.5;
  d.tag = 2;
  ASSERT_TRUE(q.push(d));
  ASSERT_TRUE(q.push(line(xyz(2, 0, 0), 100.0, 3)));
  const Trace tr = run_to_idle(ip);
  int still = 0;
  for (std::size_t k = 1; k < tr.pos.size(); ++k) {
    if (tr.pos[k] == xyz(1, 0, 0) && tr.pos[k - 1] == xyz(1, 0, 0)) ++still;
  }
  EXPECT_NEAR(still * lim.period_s, 0.5, lim.period_s + 1e-12);
}

// Time inside a segment is a count of periods, not a sum: over hours at
// 1 ms a sum of 0.001 s runs ahead by about 1.7 us (a 0.0017 fraction of a
// period), which ended this dwell one period early.
TEST(Interpolator, ThreeHourDwellEndsAtTheTickItsDurationSays) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  Move d;
  d.kind = Kind::kDwell;
  d.dwell_s = 3 * 3600.0 + 1e-6;  // a thousandth of a period past a boundary
  ASSERT_TRUE(q.push(d));
  const auto expected = static_cast<std::int64_t>(std::ceil(d.dwell_s / lim.period_s - 1e-6));
  ASSERT_EQ(expected, 10'800'001);
  std::int64_t ticks = 0;
  while (!ip.idle() && ticks < expected + 10) {
    ip.tick();
    ++ticks;
  }
  EXPECT_EQ(ticks, expected);
}

// A line of three hours: each sample is the closed-form position at k
// periods, and the end point comes at the tick the duration says.
TEST(Interpolator, LongLineSamplesTheClosedFormAtWholePeriods) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  ASSERT_TRUE(q.push(line(xyz(1080.0, 0, 0), 0.1)));  // 10,800 s at 0.1 mm/s
  const planner::Segment seg = *q.front();
  const auto expected = static_cast<std::int64_t>(std::ceil(seg.duration / lim.period_s - 1e-6));
  ASSERT_GT(expected, 10'800'000);
  for (std::int64_t k = 1; k < expected; ++k) {
    ip.tick();
    if (k % 1'000'000 == 0) {
      // Drift of the summed time here was about 1.6e-7 mm at 0.1 mm/s.
      const double x = seg.position_at(static_cast<double>(k) * lim.period_s)[0];
      ASSERT_NEAR(ip.position()[0], x, 1e-10) << "tick " << k;
    }
  }
  EXPECT_LT(ip.position()[0], 1080.0);
  EXPECT_FALSE(ip.idle());
  ip.tick();
  EXPECT_EQ(ip.position(), xyz(1080.0, 0, 0));
  EXPECT_TRUE(ip.idle());
}

TEST(Interpolator, TimeScaleZeroHolds) {
  SegmentQueue q(mill_limits());
  Interpolator ip(q);
  ASSERT_TRUE(q.push(line(xyz(10, 0, 0), 100.0)));
  for (int k = 0; k < 50; ++k) ip.tick();
  const AxisVec here = ip.position();
  ip.set_time_scale(0.0);
  for (int k = 0; k < 50; ++k) EXPECT_EQ(ip.tick(), here);
  EXPECT_EQ(ip.path_speed(), 0.0);
  ip.set_time_scale(1.0);
  const Trace tr = run_to_idle(ip);
  EXPECT_EQ(tr.pos.back(), xyz(10, 0, 0));
}

TEST(Interpolator, VelocityIsReported) {
  SegmentQueue q(mill_limits());
  Interpolator ip(q);
  ASSERT_TRUE(q.push(line(xyz(30, 40, 0), 100.0, 9)));
  for (int k = 0; k < 300; ++k) ip.tick();
  EXPECT_NEAR(ip.velocity()[0], 60.0, 1e-9);
  EXPECT_NEAR(ip.velocity()[1], 80.0, 1e-9);
  EXPECT_EQ(ip.tag(), 9u);
}

TEST(Interpolator, SetPositionResetsEverything) {
  SegmentQueue q(mill_limits());
  Interpolator ip(q);
  ASSERT_TRUE(q.push(line(xyz(30, 40, 0), 100.0)));
  for (int k = 0; k < 10; ++k) ip.tick();
  ip.set_position(xyz(1, 1, 1));
  EXPECT_TRUE(ip.idle());
  EXPECT_EQ(ip.position(), xyz(1, 1, 1));
  EXPECT_EQ(q.tail_position(), xyz(1, 1, 1));
  EXPECT_EQ(ip.tick(), xyz(1, 1, 1));
}

TEST(Interpolator, NoAccelSkipMoveRunsAtTheFeedFromTheFirstTick) {
  const Limits lim = mill_limits();
  SegmentQueue q(lim);
  Interpolator ip(q);
  Move m = line(xyz(5, 0, 0), 20.0);
  m.no_accel = true;
  ASSERT_TRUE(q.push(m));
  ip.tick();
  EXPECT_NEAR(ip.position()[0], 20.0 * lim.period_s, 1e-15);
  EXPECT_EQ(ip.path_speed(), 20.0);
  const Trace tr = run_to_idle(ip);
  EXPECT_EQ(tr.pos.back(), xyz(5, 0, 0));
  EXPECT_EQ(tr.pos.size(), 250u);  // 249 more ticks: 0.25 s in all
}

}  // namespace
}  // namespace skipnc::interpolator
