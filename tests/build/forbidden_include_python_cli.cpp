// Compiled against skipnc_python_links, what the Python module (python/)
// links, this must fail: the module reaches a run through the run library
// (src/run/) and may not see the command line's headers (src/cli/).
// tests/CMakeLists.txt builds it in a ctest that expects the compile to fail.
#include "cli/outputs.hpp"
#include "run/scenario.hpp"

int main() {
  return 0;
}
