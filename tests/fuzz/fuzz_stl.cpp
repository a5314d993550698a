// libFuzzer harness: STL files, binary and ASCII. The checks are in
// targets.hpp, shared with tests/regression.
#include <cstdio>
#include <cstdlib>

#include "targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::string problem = skipnc::fuzz::check_stl(input);
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_stl: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
