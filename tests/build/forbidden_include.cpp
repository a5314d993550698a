// Compiled against skipnc::kernel alone, this must fail: the kernel may not
// see the plant (machine/), which depends on it. tests/CMakeLists.txt builds
// it in a ctest that expects the compile to fail.
#include "kernel/kernel.hpp"
#include "machine/plant.hpp"

int main() {
  return 0;
}
