// The interpreter alone on the built-in mill3, for the tests that step it
// by hand: a sink that keeps the commands, and the machine, dialect and
// parameters an interpreter is created on.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "interpreter/interpreter.hpp"

namespace skipnc::test {

class Collect final : public interp::CommandSink {
 public:
  void emit(const canon::Stamped& c) override { cmds.push_back(c); }
  std::vector<canon::Stamped> cmds;
};

// mill3 in `dialect`; start() creates an interpreter on a program text.
struct Mill {
  config::MachineConfig machine;
  config::Dialect dialect;
  std::unique_ptr<config::Parameters> params;
  bool strict = false;
  explicit Mill(const std::string& name = "fanuc") {
    machine = *config::builtin_machine("mill3");
    dialect = *config::builtin_dialect(name);
    machine.dialect = name;
    params = std::make_unique<config::Parameters>(&dialect);
  }
  std::unique_ptr<interp::Interpreter> start(const std::string& program) const {
    interp::Setup s;
    s.machine = &machine;
    s.dialect = &dialect;
    s.params = params.get();
    s.program_text = program;
    s.program_name = "test.nc";
    s.strict = strict;
    auto in = interp::Interpreter::create(s, AxisVec{});
    EXPECT_TRUE(in.has_value());
    return in ? std::move(*in) : nullptr;
  }
};

}  // namespace skipnc::test
