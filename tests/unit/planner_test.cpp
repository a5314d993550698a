// Planner: segment geometry, closed-form profiles and lookahead.
#include "planner/planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/motion.hpp"

namespace skipnc::planner {
namespace {

using Kind = Move::Kind;

using test::mill_limits;
using test::xyz;

Move line(AxisVec to, double feed, bool exact_stop = false) {
  Move m;
  m.kind = Kind::kLine;
  m.target = to;
  m.feed_mm_s = feed;
  m.exact_stop = exact_stop;
  return m;
}

Move arc(AxisVec to, double c0, double c1, bool ccw, double feed, int extra_turns = 0) {
  Move m;
  m.kind = Kind::kArc;
  m.target = to;
  m.center0 = c0;
  m.center1 = c1;
  m.ccw = ccw;
  m.extra_turns = extra_turns;
  m.feed_mm_s = feed;
  return m;
}

// Closed-form time of a rest-to-rest trapezoid.
double trapezoid_time(double len, double v, double a) {
  if (len * a >= v * v) return len / v + v / a;
  return 2.0 * std::sqrt(len / a);
}

TEST(Planner, SingleLineDurationIsTheTrapezoidTime) {
  SegmentQueue p(mill_limits());
  ASSERT_TRUE(p.push(line(xyz(100, 0, 0), 100.0)));
  ASSERT_EQ(p.size(), 1u);
  const Segment& s = *p.front();
  EXPECT_NEAR(s.duration, trapezoid_time(100.0, 100.0, 2000.0), 1e-12);
  EXPECT_DOUBLE_EQ(s.v_cruise, 100.0);
  EXPECT_EQ(s.v_entry, 0.0);
  EXPECT_EQ(s.v_exit, 0.0);
}

TEST(Planner, ShortLineIsATriangle) {
  SegmentQueue p(mill_limits());
  ASSERT_TRUE(p.push(line(xyz(1, 0, 0), 100.0)));
  const Segment& s = *p.front();
  EXPECT_NEAR(s.duration, trapezoid_time(1.0, 100.0, 2000.0), 1e-12);
  EXPECT_NEAR(s.v_cruise, std::sqrt(2000.0 * 1.0), 1e-9);
  EXPECT_EQ(s.t_cruise, 0.0);
}

TEST(Planner, DiagonalLineClampedByAxisLimits) {
  Limits lim = mill_limits();
  lim.axes[0].max_velocity_mm_s = 50.0;
  lim.axes[0].max_accel_mm_s2 = 500.0;
  SegmentQueue p(lim);
  ASSERT_TRUE(p.push(line(xyz(30, 40, 0), 300.0)));  // u = (0.6, 0.8)
  const Segment& s = *p.front();
  EXPECT_NEAR(s.v_max, 50.0 / 0.6, 1e-9);
  EXPECT_NEAR(s.accel, 500.0 / 0.6, 1e-9);
  EXPECT_NEAR(s.duration, trapezoid_time(50.0, 50.0 / 0.6, 500.0 / 0.6), 1e-12);
}

TEST(Planner, FeedClampedByPathLimit) {
  Limits lim = mill_limits();
  lim.max_feed_mm_s = 100.0;
  SegmentQueue p(lim);
  ASSERT_TRUE(p.push(line(xyz(0, 0, 50), 1000.0)));
  EXPECT_DOUBLE_EQ(p.front()->v_max, 100.0);
}

TEST(Planner, RapidUsesRapidRatesAndEndsAtRest) {
  Limits lim = mill_limits();
  lim.axes[1].rapid_mm_s = 200.0;
  SegmentQueue p(lim);
  Move m;
  m.kind = Kind::kRapid;
  m.target = xyz(100, 100, 0);
  ASSERT_TRUE(p.push(m));
  ASSERT_TRUE(p.push(line(xyz(200, 100, 0), 100.0)));
  const Segment& s = *p.front();
  EXPECT_NEAR(s.v_max, 200.0 * std::numbers::sqrt2, 1e-9);
  EXPECT_EQ(s.v_exit, 0.0);
}

// A move of no length is dropped; a dwell of no time (G04 X0) is kept as a
// segment of no time, so that the machine comes to rest for it and its
// block is counted as run (issue 30: every dwell has a row in block times).
// A negative or NaN dwell is dropped.
TEST(Planner, ZeroLengthMovesAreDroppedAndZeroDwellsKept) {
  SegmentQueue p(mill_limits());
  ASSERT_TRUE(p.push(line(xyz(0, 0, 0), 100.0)));
  EXPECT_TRUE(p.empty());
  Move d;
  d.kind = Kind::kDwell;
  d.dwell_s = -1.0;
  ASSERT_TRUE(p.push(d));
  EXPECT_TRUE(p.empty());
  d.dwell_s = 0.0;
  ASSERT_TRUE(p.push(d));
  ASSERT_FALSE(p.empty());
  EXPECT_EQ(p.front()->duration, 0.0);
}

TEST(Planner, PositionAtDurationIsTheTargetBitExact) {
  SegmentQueue p(mill_limits());
  const AxisVec target = xyz(12.3456789, -0.1, 7.77777777);
  ASSERT_TRUE(p.push(line(target, 123.4)));
  const Segment& s = *p.front();
  EXPECT_EQ(s.position_at(s.duration), target);
  EXPECT_EQ(s.position_at(s.duration + 1.0), target);
  EXPECT_EQ(s.position_at(0.0), AxisVec{});
  EXPECT_EQ(s.distance_at(-1.0), 0.0);
}

TEST(Planner, ProfileIsContinuous) {
  SegmentQueue p(mill_limits());
  ASSERT_TRUE(p.push(line(xyz(10, 0, 0), 150.0)));
  ASSERT_TRUE(p.push(line(xyz(20, 0, 0), 150.0)));
  const Segment& s = *p.front();
  const double eps = 1e-9;
  for (const double t : {s.t_acc, s.t_acc + s.t_cruise}) {
    EXPECT_NEAR(s.distance_at(t - eps), s.distance_at(t + eps), 1e-6);
    EXPECT_NEAR(s.speed_at(t - eps), s.speed_at(t + eps), 1e-5);
  }
  EXPECT_NEAR(s.speed_at(s.duration), s.v_exit, 1e-12);
}

TEST(Planner, CollinearSegmentsBlendAtFullSpeed) {
  SegmentQueue p(mill_limits());
  ASSERT_TRUE(p.push(line(xyz(10, 10, 0), 100.0)));
  ASSERT_TRUE(p.push(line(xyz(20, 20, 0), 100.0)));
  ASSERT_TRUE(p.push(line(xyz(30, 30, 0), 100.0)));
  const Segment& s = *p.front();
  EXPECT_NEAR(s.v_exit, 100.0, 1e-9);
  EXPECT_NEAR(s.v_entry, 0.0, 1e-12);
}

TEST(Planner, LookaheadLimitsExitSoTheQueueCanStop) {
  SegmentQueue p(mill_limits());
  ASSERT_TRUE(p.push(line(xyz(100, 0, 0), 300.0)));
  ASSERT_TRUE(p.push(line(xyz(100.5, 0, 0), 300.0)));  // 0.5 mm: can stop from sqrt(2 a 0.5)
  EXPECT_NEAR(p.front()->v_exit, std::sqrt(2.0 * 2000.0 * 0.5), 1e-9);
}

TEST(Planner, RightAngleCornerIsNearlyAStop) {
  const Limits lim = mill_limits();
  SegmentQueue p(lim);
  ASSERT_TRUE(p.push(line(xyz(10, 0, 0), 100.0)));
  ASSERT_TRUE(p.push(line(xyz(10, 10, 0), 100.0)));
  const double v = p.front()->v_exit;
  EXPECT_GT(v, 0.0);
  EXPECT_LE(v, lim.axes[0].max_accel_mm_s2 * lim.period_s);
}

TEST(Planner, ExactStopEndsAtRest) {
  SegmentQueue p(mill_limits());
  ASSERT_TRUE(p.push(line(xyz(10, 0, 0), 100.0, /*exact_stop=*/true)));
  ASSERT_TRUE(p.push(line(xyz(20, 0, 0), 100.0)));
  EXPECT_EQ(p.front()->v_exit, 0.0);
}

TEST(Planner, DwellForcesRest) {
  SegmentQueue p(mill_limits());
  ASSERT_TRUE(p.push(line(xyz(10, 0, 0), 100.0)));
  Move d;
  d.kind = Kind::kDwell;
  d.dwell_s = 0.25;
  ASSERT_TRUE(p.push(d));
  ASSERT_TRUE(p.push(line(xyz(20, 0, 0), 100.0)));
  EXPECT_EQ(p.front()->v_exit, 0.0);
  EXPECT_EQ(p.size(), 3u);
}

TEST(Planner, StartedSegmentKeepsItsProfile) {
  SegmentQueue p(mill_limits());
  ASSERT_TRUE(p.push(line(xyz(10, 0, 0), 100.0)));
  Segment* s = p.front();
  s->started = true;
  const double duration = s->duration;
  ASSERT_TRUE(p.push(line(xyz(20, 0, 0), 100.0)));
  EXPECT_EQ(s->v_exit, 0.0);
  EXPECT_EQ(s->duration, duration);
}

TEST(Planner, NoAccelMoveStepsToTheFeed) {
  SegmentQueue p(mill_limits());
  Move m = line(xyz(5, 0, 0), 10.0);
  m.no_accel = true;
  ASSERT_TRUE(p.push(m));
  const Segment& s = *p.front();
  EXPECT_EQ(s.speed_at(0.0), 10.0);
  EXPECT_EQ(s.speed_at(s.duration), 10.0);
  EXPECT_NEAR(s.duration, 0.5, 1e-12);
  EXPECT_NEAR(s.distance_at(0.25), 2.5, 1e-12);
}

TEST(Planner, NonLinearRapidShortAxisArrivesFirst) {
  SegmentQueue p(mill_limits());
  Move m;
  m.kind = Kind::kRapidNonLinear;
  m.target = xyz(100, 10, 0);
  ASSERT_TRUE(p.push(m));
  const Segment& s = *p.front();
  EXPECT_EQ(s.basis_axis, 0);
  EXPECT_NEAR(s.duration, trapezoid_time(100.0, 500.0, 2000.0), 1e-12);
  EXPECT_LT(s.axis_t_total[1], s.duration);
  const AxisVec mid = s.position_at(s.axis_t_total[1]);
  EXPECT_EQ(mid[1], 10.0);
  EXPECT_LT(mid[0], 100.0);
  EXPECT_EQ(s.position_at(s.duration), m.target);
}

TEST(Planner, QuarterArcGeometry) {
  SegmentQueue p(mill_limits());
  p.reset(xyz(10, 0, 0));
  ASSERT_TRUE(p.push(arc(xyz(0, 10, 0), 0.0, 0.0, /*ccw=*/true, 50.0)));
  const Segment& s = *p.front();
  EXPECT_NEAR(s.sweep, std::numbers::pi / 2.0, 1e-15);
  EXPECT_NEAR(s.length, 10.0 * std::numbers::pi / 2.0, 1e-12);
  for (int k = 0; k <= 100; ++k) {
    const AxisVec q = s.position_at(s.duration * k / 100.0);
    EXPECT_NEAR(std::hypot(q[0], q[1]), 10.0, 1e-9);
  }
}

TEST(Planner, ClockwiseArcSweepsTheLongWay) {
  SegmentQueue p(mill_limits());
  p.reset(xyz(10, 0, 0));
  ASSERT_TRUE(p.push(arc(xyz(0, 10, 0), 0.0, 0.0, /*ccw=*/false, 50.0)));
  EXPECT_NEAR(p.front()->sweep, -1.5 * std::numbers::pi, 1e-12);
}

TEST(Planner, CoincidentArcEndsMakeAFullTurnPlusExtraTurns) {
  SegmentQueue p(mill_limits());
  p.reset(xyz(10, 0, 0));
  ASSERT_TRUE(p.push(arc(xyz(10, 0, 0), 0.0, 0.0, true, 50.0)));
  EXPECT_NEAR(p.front()->sweep, 2.0 * std::numbers::pi, 1e-15);
  p.pop_front();
  ASSERT_TRUE(p.push(arc(xyz(10, 0, 0), 0.0, 0.0, false, 50.0, /*extra_turns=*/2)));
  EXPECT_NEAR(p.front()->sweep, -6.0 * std::numbers::pi, 1e-12);
}

TEST(Planner, ArcSpeedLimitedByCentripetalAcceleration) {
  const Limits lim = mill_limits();
  SegmentQueue p(lim);
  p.reset(xyz(1, 0, 0));
  ASSERT_TRUE(p.push(arc(xyz(-1, 0, 0), 0.0, 0.0, true, 300.0)));  // r = 1 mm
  const Segment& s = *p.front();
  EXPECT_LE(s.v_max * s.v_max / 1.0, 2000.0 + 1e-9);
  EXPECT_LT(s.v_max, 300.0);
}

TEST(Planner, ArcWithUnequalRadiiEndsOnTarget) {
  SegmentQueue p(mill_limits());
  p.reset(xyz(10, 0, 0));
  const AxisVec target = xyz(0, 10.002, 0);
  ASSERT_TRUE(p.push(arc(target, 0.0, 0.0, true, 50.0)));
  const Segment& s = *p.front();
  EXPECT_EQ(s.position_at(s.duration), target);
  double prev = 10.0;
  for (int k = 1; k < 100; ++k) {
    const AxisVec q = s.position_at(s.duration * k / 100.0);
    const double r = std::hypot(q[0], q[1]);
    EXPECT_GE(r, prev - 1e-12);
    EXPECT_LE(r, 10.002 + 1e-12);
    prev = r;
  }
  const AxisVec near_end = s.position_at(s.duration * (1.0 - 1e-9));
  EXPECT_NEAR(near_end[0], 0.0, 1e-6);
  EXPECT_NEAR(near_end[1], 10.002, 1e-6);
}

TEST(Planner, ArcTangentMatchesMotion) {
  SegmentQueue p(mill_limits());
  p.reset(xyz(10, 0, 0));
  ASSERT_TRUE(p.push(arc(xyz(10, 0, 5), 0.0, 0.0, true, 50.0)));  // one helical turn
  const Segment& s = *p.front();
  const double t = s.duration * 0.4;
  const double h = 1e-6;
  const AxisVec d = (s.position_at(t + h) - s.position_at(t - h)) * (1.0 / (2.0 * h));
  const AxisVec v = s.velocity_at(t);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(d[i], v[i], 1e-4);
  EXPECT_NEAR(norm(s.tangent_at(t), 3), 1.0, 1e-12);
}

TEST(Planner, ResetForgetsTheQueue) {
  SegmentQueue p(mill_limits());
  ASSERT_TRUE(p.push(line(xyz(10, 0, 0), 100.0)));
  p.reset(xyz(1, 2, 3));
  EXPECT_TRUE(p.empty());
  EXPECT_EQ(p.tail_position(), xyz(1, 2, 3));
  ASSERT_TRUE(p.push(line(xyz(2, 2, 3), 100.0)));
  EXPECT_EQ(p.front()->start, xyz(1, 2, 3));
}

TEST(Planner, RingWrapsAround) {
  SegmentQueue p(mill_limits(), 4);
  double x = 0.0;
  for (int k = 0; k < 20; ++k) {
    while (!p.full()) {
      x += 1.0;
      ASSERT_TRUE(p.push(line(xyz(x, 0, 0), 100.0)));
    }
    p.front()->started = true;
    p.pop_front();
  }
  EXPECT_EQ(p.size(), 3u);
  EXPECT_EQ(p.tail_position()[0], x);
}

}  // namespace
}  // namespace skipnc::planner
