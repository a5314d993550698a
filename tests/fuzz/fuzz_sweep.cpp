// libFuzzer harness: sweep specs (loaded, up to three scenarios run, tables checked). The checks
// are in targets_sweep.hpp, shared with tests/regression.
#include <cstdio>
#include <cstdlib>

#include "targets_sweep.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::string problem = skipnc::fuzz::check_sweep(input);
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_sweep: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
