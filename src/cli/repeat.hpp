// skipnc run PROGRAM --repeat N [--seed S]: measurement uncertainty. The runs
// and their statistics are the run library's (run/repeat.hpp); this prints
// the table and writes the skipnc-repeat/1 report.
#pragma once

#include "cli/commands.hpp"

namespace skipnc::cli {

int repeat_command(const RunArgs& a);

}  // namespace skipnc::cli
