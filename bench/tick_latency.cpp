// The distribution of the kernel's per-tick cost (planner sampling + skip
// monitor + signal image; the plant's period is not counted): median, p99,
// p99.9 and worst over N ticks of a program that keeps the queue busy with
// short lines and arcs. Usage: skipnc_tick_latency [ticks]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "config/machine_config.hpp"
#include "kernel/kernel.hpp"
#include "kernel/kernel_config.hpp"
#include "machine/plant.hpp"

int main(int argc, char** argv) {
  using namespace skipnc;
  const long n = argc > 1 ? std::atol(argv[1]) : 2'000'000;
  auto m = config::builtin_machine("mill3");
  if (!m) return 2;
  machine::Scene scene;
  kernel::Kernel k(kernel::kernel_config(*m));
  machine::Plant plant(*m, scene, k.clock());
  k.set_position(AxisVec{});
  plant.reset(AxisVec{});
  kernel::TickInput in;
  kernel::TickOutput out;
  AxisVec prev{};
  std::vector<double> ns(static_cast<std::size_t>(n));
  long step = 0;
  for (long i = 0; i < n; ++i) {
    while (k.can_accept()) {
      AxisVec t;
      t[0] = 50.0 * static_cast<double>((step % 7) - 3);
      t[1] = 40.0 * static_cast<double>((step % 5) - 2);
      if (step % 3 == 0) {
        canon::Arc a;
        a.target = t;
        a.center0 = (k.command()[0] + t[0]) / 2.0;
        a.center1 = (k.command()[1] + t[1]) / 2.0;
        a.feed_mm_per_min = 5000.0;
        if (!k.push({a, 1})) return 2;  // not reached: can_accept() leaves room
      } else {
        if (!k.push({canon::Feed{t, 8000.0, false}, 1})) return 2;
      }
      ++step;
    }
    plant.advance(k.now() + 1, prev, out.commanded, in);
    prev = out.commanded;
    const auto t0 = std::chrono::steady_clock::now();
    k.tick(in, out);
    const auto t1 = std::chrono::steady_clock::now();
    ns[static_cast<std::size_t>(i)] = std::chrono::duration<double, std::nano>(t1 - t0).count();
  }
  std::sort(ns.begin(), ns.end());
  auto q = [&](double p) { return ns[static_cast<std::size_t>(p * static_cast<double>(n - 1))]; };
  std::printf("ticks %ld  median %.0f ns  p99 %.0f ns  p99.9 %.0f ns  worst %.0f ns\n", n, q(0.5),
              q(0.99), q(0.999), ns.back());
  return 0;
}
