// A block that queues more moves than the kernel's queue holds (a G83 with a
// small Q: three moves a peck, about 1,500 in one block against a queue of
// 256) runs all of them: what does not fit waits for room (it was lost
// without a word when the queue was full).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "sim/simulator.hpp"

namespace skipnc {
namespace {

class LowestZ final : public sim::TraceSink {
 public:
  void row(const sim::TraceRow& r) override {
    lowest_cmd = std::min(lowest_cmd, (*r.commanded)[2]);
    if (r.work != nullptr) lowest_work = std::min(lowest_work, (*r.work)[2]);
    if (r.line == 4) ++rows_in_cycle;
  }
  double lowest_cmd = 1e300;
  double lowest_work = 1e300;
  long rows_in_cycle = 0;
};

TEST(MachineLongBlock, PeckCycleWithMoreMovesThanTheQueueReachesTheBottom) {
  auto m = config::builtin_machine("mill3");
  auto d = config::builtin_dialect("fanuc");
  ASSERT_TRUE(m && d);
  config::Parameters p(&*d);
  machine::Scene scene;
  record::Setup setup;
  setup.machine = &*m;
  setup.dialect = &*d;
  setup.params = &p;
  setup.program_name = "peck.nc";
  setup.program_text =
      "G21 G90 G54 G17\n"
      "G0 X0. Y0. Z10.\n"
      "M03 S1000\n"
      "G99 G83 X10. Y0. Z-50. R2. Q0.1 F3000.\n"
      "G80\n"
      "G0 Z10.\n"
      "M30\n";
  sim::Simulator sim(*m, *d, p, scene);
  LowestZ trace;
  sim::RunOptions opts;
  opts.trace = &trace;
  auto r = sim.run(setup, opts);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, sim::RunStatus::kCompleted) << (r->alarm ? r->alarm->detail : std::string());
  // Sampled once a period: the turn at the bottom falls inside a period, and
  // within 1 ms of rest the command is within a micrometre of it.
  EXPECT_NEAR(trace.lowest_cmd, -50.0, 1e-3);
  // The actual position lags, and turns back a little short of the bottom.
  EXPECT_NEAR(trace.lowest_work, -50.0, 0.05);
  EXPECT_NEAR(r->final_machine[0], 10.0, 1e-12);
  EXPECT_NEAR(r->final_machine[2], 10.0, 1e-12);
  // 520 pecks, each back to R: 330 s; the moves that fitted in the queue
  // made about 31 s.
  EXPECT_GT(static_cast<double>(trace.rows_in_cycle) * r->period_s, 300.0);
}

}  // namespace
}  // namespace skipnc
