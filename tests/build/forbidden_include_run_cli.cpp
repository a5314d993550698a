// Compiled against skipnc::run alone (what the Python module links), this
// must fail: the run library and the Python module may not see the command
// line's headers (src/cli/). tests/CMakeLists.txt builds it in a ctest that
// expects the compile to fail.
#include "cli/commands.hpp"
#include "run/scenario.hpp"

int main() {
  return 0;
}
