// libFuzzer harness: the machine file loader (a file that loads must also run a short program).
// The checks are in targets.hpp, shared with tests/regression.
#include <cstdio>
#include <cstdlib>

#include "targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::string problem = skipnc::fuzz::check_machine(input);
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_machine: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
