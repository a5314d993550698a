// skipnc run PROGRAM --repeat N [--seed S]: measurement uncertainty. The
// cycle runs once without the probe's scatter (the nominal run) and N times
// with it, each with its own seed (S, S+1, ...); the latch model is the
// machine's. Every latched value, every --var and every offset the program
// wrote is summarised: nominal, mean, standard deviation, minimum, maximum
// and the worst deviation from the nominal run (docs/scene.md).
#pragma once

#include "cli/commands.hpp"

namespace skipnc::cli {

int repeat_command(const RunArgs& a);

}  // namespace skipnc::cli
