// The control of build_forbidden_include: the same target set-up compiles
// with the kernel's own headers and those of the stages it uses.
#include "canon/canon.hpp"
#include "config/machine_config.hpp"
#include "kernel/kernel.hpp"
#include "planner/planner.hpp"

int main() {
  return 0;
}
