// The tick is allocation-free: a counting operator new proves that no heap
// allocation happens inside Kernel::tick or Plant::advance while a program of
// lines, arcs, rapids, dwells and a skip runs through them, and while a
// probe touches parts.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "kernel/kernel.hpp"
#include "kernel/kernel_config.hpp"
#include "machine/plant.hpp"
#include "sim/simulator.hpp"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace

// GCC cannot see that this operator new and these operator deletes pair up.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
// The other forms, so that every new and delete of the process pair up
// (std::stable_sort's buffer uses the nothrow new; ASan checks the pairs).
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
  return std::malloc(n == 0 ? 1 : n);
}
void* operator new[](std::size_t n) {
  return operator new(n);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept {
  return operator new(n, t);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}

namespace skipnc {
namespace {

TEST(KernelRealtime, TickAndPlantDoNotAllocate) {
  config::MachineConfig m;
  for (char c : {'X', 'Y', 'Z'}) {
    config::AxisConfig a;
    a.name = c;
    m.axes.push_back(a);
  }
  machine::Scene scene;
  machine::Trigger t;
  t.signal = canon::SignalAddr{'X', 0, 4};
  t.axis = 2;
  t.at = -3.0;
  scene.triggers.push_back(t);
  kernel::Kernel k(kernel::kernel_config(m));
  machine::Plant plant(m, scene, k.clock());
  k.set_position(AxisVec{});
  plant.reset(AxisVec{});

  // Queue outside the tick (allocation allowed there: none expected either,
  // the planner's ring is preallocated).
  auto at = [](double x, double y, double z) {
    AxisVec v;
    v[0] = x;
    v[1] = y;
    v[2] = z;
    return v;
  };
  ASSERT_TRUE(k.push({canon::Rapid{at(10, 10, 0), true}, 1}));
  ASSERT_TRUE(k.push({canon::Feed{at(20, 10, 0), 3000.0, false}, 2}));
  canon::Arc arc;
  arc.target = at(30, 10, 0);
  arc.center0 = 25;
  arc.center1 = 10;
  arc.feed_mm_per_min = 3000.0;
  ASSERT_TRUE(k.push({arc, 3}));
  ASSERT_TRUE(k.push({canon::Dwell{0.05}, 4}));
  canon::Skip sk;
  sk.target = at(30, 10, -10);
  sk.feed_mm_per_min = 100.0;
  sk.spec.input_count = 1;
  sk.spec.inputs[0] = canon::SignalAddr{'X', 0, 4};
  ASSERT_TRUE(k.push({sk, 5}));

  kernel::TickInput in;
  kernel::TickOutput out;
  AxisVec prev{};
  out.commanded = AxisVec{};
  g_allocations = 0;
  g_counting = true;
  int ticks = 0;
  while (!(k.skip().done) && ticks < 200000) {
    plant.advance(k.now() + 1, prev, out.commanded, in);
    prev = out.commanded;
    k.tick(in, out);
    ++ticks;
  }
  g_counting = false;
  EXPECT_TRUE(k.skip().triggered);
  EXPECT_NEAR(k.skip().latch_machine[2], -3.0, 1e-9);
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations inside " << ticks << " ticks";
}

// The probing scene too: a plate with a bore and a pocket, a probe with
// scatter, a tool setter and a gauge, the ball touching the bore's wall,
// released and touching again, and a tool change in between.
TEST(KernelRealtime, ProbingPlantDoesNotAllocate) {
  config::MachineConfig m;
  for (char c : {'X', 'Y', 'Z'}) {
    config::AxisConfig a;
    a.name = c;
    m.axes.push_back(a);
  }
  machine::Scene scene;
  machine::geo::Part plate;
  plate.solids.push_back(machine::geo::make_box({-50, -50, -40}, {50, 50, -10}));
  plate.holes.push_back(machine::geo::make_cylinder(0, 0, 15, -1e6, 1e6));
  plate.holes.push_back(machine::geo::make_box({20, 20, -20}, {40, 40, 0}));
  scene.probing.parts.push_back(plate);
  machine::ProbeSpec probe;
  probe.signal = canon::SignalAddr{'X', 0, 4};
  probe.max_overtravel = 5.0;
  probe.repeatability = 0.001;
  probe.lobing = 0.002;
  scene.probing.probe = probe;
  machine::ToolSetterSpec setter;
  setter.signal = canon::SignalAddr{'X', 0, 5};
  setter.x = 200;
  scene.probing.tool_setter = setter;
  machine::GaugeSpec gauge;
  gauge.center = -200;
  gauge.raw_diameter = 100;
  gauge.steps.push_back(machine::GaugeStep{canon::SignalAddr{'X', 0, 1}, "SKIP2", 90});
  scene.probing.gauges.push_back(gauge);
  scene.probing.tools.push_back(machine::ToolSpec{1, 5.0, 3.0});
  kernel::Kernel k(kernel::kernel_config(m));
  machine::Plant plant(m, scene, k.clock());
  auto at = [](double x, double y, double z) {
    AxisVec v;
    v[0] = x;
    v[1] = y;
    v[2] = z;
    return v;
  };
  k.set_position(at(0, 0, -20));
  plant.reset(at(0, 0, -20));
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(
        k.push({canon::Feed{at(16, 0, -20), 3000.0, true}, 1}));  // into the wall: 2 mm deflection
    ASSERT_TRUE(k.push({canon::Feed{at(0, 0, -20), 3000.0, true}, 2}));
  }
  canon::Arc arc;
  arc.target = at(0, 0, -20);
  arc.center0 = 5;
  arc.center1 = 0;
  arc.feed_mm_per_min = 3000.0;
  ASSERT_TRUE(k.push({arc, 3}));
  kernel::TickInput in;
  kernel::TickOutput out;
  AxisVec prev = at(0, 0, -20);
  out.commanded = prev;
  int edges = 0;
  g_allocations = 0;
  g_counting = true;
  int ticks = 0;
  for (; ticks < 20000 && !(ticks > 10 && k.idle()); ++ticks) {
    if (ticks == 5) plant.probing().set_spindle_tool(1);  // and back: both ways
    if (ticks == 6) plant.probing().set_spindle_tool(0);
    plant.advance(k.now() + 1, prev, out.commanded, in);
    edges += in.edge_count;
    prev = out.commanded;
    k.tick(in, out);
  }
  g_counting = false;
  EXPECT_EQ(edges, 6) << "three touches, each switching on and off";
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations inside " << ticks << " ticks";
}

}  // namespace
}  // namespace skipnc
