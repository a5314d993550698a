// The plant's servo model: each axis a first-order position loop integrated
// exactly over the period, its torque, the excess-error flag, locked axes,
// stops and torque limits. Its common case has a loop of its own
// (Plant::advance without stops, loads, locked axes or torque limits); a test
// here holds it to the general loop to the bit.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "config/machine_config.hpp"
#include "core/time.hpp"
#include "machine/plant.hpp"
#include "machine/scene.hpp"
#include "support/motion.hpp"

namespace skipnc::machine {
namespace {

using test::xyz;

config::MachineConfig mill() {
  config::MachineConfig m = *config::builtin_machine("mill3");
  for (auto& a : m.axes) {
    a.kp_per_s = 30.0;
    a.feedforward = 0.0;
    a.torque_pct_per_mm = 100.0;
    a.torque_max_pct = 300.0;
    a.rapid_mm_min = 30000.0;
  }
  return m;
}

ServoClock clock_1ms() {
  ServoClock c;
  c.period_ns = 1'000'000;
  return c;
}

// Drives the plant along `cmd`, one command per period, from rest at 0.
class Drive {
 public:
  explicit Drive(Plant& p) : plant(p) {}
  void to(const AxisVec& c) {
    plant.advance(++k, prev, c, in);
    prev = c;
  }

 private:
  Plant& plant;
  AxisVec prev{};
  Tick k = 0;
  kernel::TickInput in;
};

TEST(Plant, FollowsARampWithTheLagOfAFirstOrderLoop) {
  const auto m = mill();
  Plant plant(m, Scene{}, clock_1ms());
  plant.reset(AxisVec{});
  Drive d(plant);
  const double v = 60.0;  // mm/s on X: a 2 mm lag, 200 % torque (under the 300 % limit)
  for (int i = 1; i <= 1000; ++i) d.to(xyz(v * 0.001 * i, 0, 0));
  // After 1 s (30 time constants) the error is v / kp, and the torque
  // torque_per_mm times it.
  const double fe = 60.0 - plant.actual()[0];
  EXPECT_NEAR(fe, v / 30.0, 1e-9);
  EXPECT_NEAR(plant.torque()[0], 100.0 * fe, 1e-9);
  EXPECT_EQ(plant.actual()[1], 0.0);
}

TEST(Plant, FeedforwardShrinksTheLag) {
  auto m = mill();
  m.axes[0].feedforward = 0.75;
  Plant plant(m, Scene{}, clock_1ms());
  plant.reset(AxisVec{});
  Drive d(plant);
  for (int i = 1; i <= 1000; ++i) d.to(xyz(0.1 * i, 0, 0));
  EXPECT_NEAR(100.0 - plant.actual()[0], 0.25 * 100.0 / 30.0, 1e-9);
}

// The fast loop and the general one give the same numbers: a stop far from
// the path makes the plant take the general loop without changing the motion.
TEST(Plant, TheCommonCaseLoopAgreesWithTheGeneralOneToTheBit) {
  const auto m = mill();
  Scene far;
  far.stops.push_back(Stop{0, -1e6, true});
  Plant fast(m, Scene{}, clock_1ms());
  Plant general(m, far, clock_1ms());
  fast.reset(AxisVec{});
  general.reset(AxisVec{});
  Drive a(fast), b(general);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> step(-0.5, 0.5);
  AxisVec c{};
  for (int i = 0; i < 20000; ++i) {
    for (int ax = 0; ax < 3; ++ax) c[ax] += step(rng);
    a.to(c);
    b.to(c);
    for (int ax = 0; ax < 3; ++ax) {
      ASSERT_EQ(fast.actual()[ax], general.actual()[ax]) << "period " << i << " axis " << ax;
      ASSERT_EQ(fast.torque()[ax], general.torque()[ax]) << "period " << i << " axis " << ax;
    }
  }
}

TEST(Plant, ALockedAxisStaysAndAnIdealServoIsWhereItIsCommanded) {
  auto m = mill();
  m.axes[1].kp_per_s = 0.0;  // Y: ideal
  Plant plant(m, Scene{}, clock_1ms());
  plant.reset(AxisVec{});
  AxisMask z;
  z.set(2);
  plant.set_locked(z);
  Drive d(plant);
  for (int i = 1; i <= 10; ++i) d.to(xyz(0.1 * i, 0.2 * i, 0.3 * i));
  EXPECT_LT(plant.actual()[0], 1.0);  // X lags
  EXPECT_EQ(plant.actual()[1], 2.0);  // Y exact
  EXPECT_EQ(plant.actual()[2], 0.0);  // Z locked
  EXPECT_EQ(plant.torque()[2], 0.0);
}

TEST(Plant, AStopHoldsTheAxisAndTheTorqueSaturatesAtTheLimit) {
  const auto m = mill();
  Scene s;
  s.stops.push_back(Stop{2, -3.0, true});  // Z cannot go below -3
  Plant plant(m, s, clock_1ms());
  plant.reset(AxisVec{});
  Drive d(plant);
  for (int i = 1; i <= 2000; ++i) d.to(xyz(0, 0, -0.005 * i));  // to Z-10 at 5 mm/s
  EXPECT_EQ(plant.actual()[2], -3.0);
  EXPECT_EQ(plant.torque()[2], -300.0);  // 7 mm of error: the servo's own limit
  AxisVec limit{};
  limit[2] = 40.0;
  plant.set_torque_limit(limit);
  EXPECT_TRUE(plant.torque_limited());
  d.to(xyz(0, 0, -10.0));
  EXPECT_EQ(plant.torque()[2], -40.0);
  plant.set_torque_limit(AxisVec{});
  EXPECT_FALSE(plant.torque_limited());
  d.to(xyz(0, 0, -10.0));
  EXPECT_EQ(plant.torque()[2], -300.0);
}

}  // namespace
}  // namespace skipnc::machine
