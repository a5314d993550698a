// The kernel's settings from a machine file: servo period, per-axis
// velocity and acceleration limits, in-position width.
#pragma once

#include "config/machine_config.hpp"
#include "kernel/kernel.hpp"

namespace skipnc::kernel {

KernelConfig kernel_config(const config::MachineConfig& m);

}  // namespace skipnc::kernel
