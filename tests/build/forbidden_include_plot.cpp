// Compiled against skipnc::plot alone, this must fail: the plot reads a run
// through record/ (skip records, warnings, call contexts, work frames) and
// may not see the interpreter. tests/CMakeLists.txt builds it in a ctest
// that expects the compile to fail.
#include "interpreter/interpreter.hpp"
#include "plot/recorder.hpp"

int main() {
  return 0;
}
