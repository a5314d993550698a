// libFuzzer harness: the whole interpreter, alone and on the simulated machine, with a statement
// and a tick budget. The checks are in targets.hpp, shared with tests/regression.
#include <cstdio>
#include <cstdlib>

#include "targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::string problem = skipnc::fuzz::check_interp(input);
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_interp: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
