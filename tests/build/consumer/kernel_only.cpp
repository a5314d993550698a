// Links skipnc::kernel only: a machine's limits into a kernel, one feed move
// of Z to -1 mm, ticked until the kernel is idle; prints where Z ended.
#include <cstdio>

#include "config/machine_config.hpp"
#include "kernel/kernel.hpp"
#include "kernel/kernel_config.hpp"

int main() {
  using namespace skipnc;
  auto machine = config::builtin_machine("mill3");
  if (!machine) return 2;
  kernel::Kernel k(kernel::kernel_config(*machine));
  k.set_position(AxisVec{});
  canon::Stamped move;
  AxisVec target{};
  target[2] = -1.0;
  move.cmd = canon::Feed{target, 600.0, true};
  move.line = 1;
  if (!k.push(move)) return 3;
  kernel::TickInput in;
  kernel::TickOutput out;
  for (int period = 0; period < 100'000 && !(period > 0 && k.idle()); ++period) {
    in.actual = out.commanded;  // ideal drives: where they were commanded
    k.tick(in, out);
  }
  std::printf("Z %.4f\n", k.command()[2]);
  return k.idle() && k.command()[2] == -1.0 ? 0 : 1;
}
