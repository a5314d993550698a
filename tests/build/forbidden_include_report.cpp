// Compiled against skipnc::report alone, this must fail: the report reads a
// run through record/ and may not see the interpreter. tests/CMakeLists.txt
// builds it in a ctest that expects the compile to fail.
#include "interpreter/interpreter.hpp"
#include "report/report.hpp"

int main() {
  return 0;
}
