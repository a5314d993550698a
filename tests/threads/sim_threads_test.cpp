// Two simulators in two threads of one process give the results each gives
// alone (issue 19): a Simulator shares nothing mutable with another (its
// kernel, plant, scene state and interpreter are its own; the built-in data
// is read-only). Each runs a probing cycle with a scattered probe (seeded),
// so the two runs differ from each other and any crossing would show.
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/scene.hpp"
#include "sim/simulator.hpp"

namespace skipnc {
namespace {

struct Outcome {
  bool ok = false;
  std::vector<AxisVec> latches;
  AxisVec final_machine;
  double time_s = 0.0;
};

Outcome run_cycle(std::uint64_t seed) {
  Outcome o;
  auto m = config::builtin_machine("mill3");
  auto d = config::builtin_dialect("fanuc");
  if (!m || !d) return o;
  config::Parameters p(&*d);
  const std::string scene_text =
      "[[box]]\nmin = [-100.0, -100.0, -260.0]\nmax = [100.0, 100.0, -229.87]\n"
      "[probe]\nsignal = \"SKIP\"\nball_radius = 1.0\nlength = 150.0\n"
      "max_overtravel = 2.0\nrepeatability = 0.002\nseed = " +
      std::to_string(seed) + "\n";
  auto scene = machine::parse_scene(scene_text, "threads.scene.toml", *m, *d, p);
  if (!scene) return o;
  record::Setup setup;
  setup.machine = &*m;
  setup.dialect = &*d;
  setup.params = &p;
  setup.program_name = "touches.nc";
  setup.program_text =
      "G21 G90 G54\n"
      "#1 = 0\n"
      "WHILE [#1 LT 20] DO1\n"
      "G0 X[#1 * 5.] Y0 Z-75.\n"
      "G31 Z-90. F200.\n"
      "#1 = #1 + 1\n"
      "END1\n"
      "G0 Z0\n"
      "M30\n";
  sim::Simulator sim(*m, *d, p, *scene);
  auto r = sim.run(setup, sim::RunOptions{});
  if (!r || r->status != sim::RunStatus::kCompleted) return o;
  for (const auto& s : r->skips) o.latches.push_back(s.machine_position);
  o.final_machine = r->final_machine;
  o.time_s = r->time_s;
  o.ok = true;
  return o;
}

TEST(SimThreads, TwoSimulatorsInTwoThreadsGiveTheResultsOfEachAlone) {
  const Outcome a_alone = run_cycle(11);
  const Outcome b_alone = run_cycle(12);
  ASSERT_TRUE(a_alone.ok);
  ASSERT_TRUE(b_alone.ok);
  ASSERT_EQ(a_alone.latches.size(), 20u);
  // The seeds scatter the switch points differently: the runs differ.
  EXPECT_NE(a_alone.latches[0][2], b_alone.latches[0][2]);

  Outcome a, b;
  std::thread ta([&] { a = run_cycle(11); });
  std::thread tb([&] { b = run_cycle(12); });
  ta.join();
  tb.join();
  ASSERT_TRUE(a.ok);
  ASSERT_TRUE(b.ok);
  ASSERT_EQ(a.latches.size(), a_alone.latches.size());
  ASSERT_EQ(b.latches.size(), b_alone.latches.size());
  for (std::size_t i = 0; i < a.latches.size(); ++i) {
    for (int ax = 0; ax < 3; ++ax) {
      EXPECT_EQ(a.latches[i][ax], a_alone.latches[i][ax]) << "touch " << i;
      EXPECT_EQ(b.latches[i][ax], b_alone.latches[i][ax]) << "touch " << i;
    }
  }
  EXPECT_EQ(a.time_s, a_alone.time_s);
  EXPECT_EQ(b.time_s, b_alone.time_s);
}

}  // namespace
}  // namespace skipnc
