// libFuzzer harness: LinuxCNC's parameter file (load, save, load again). The checks are in
// targets.hpp, shared with tests/regression.
#include <cstdio>
#include <cstdlib>

#include "targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::string problem = skipnc::fuzz::check_ngc_params(input);
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_ngc_params: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
