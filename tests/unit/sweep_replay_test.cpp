// Sweep specs kept under tests/regression/sweep/ and the fuzz seeds of
// tests/fuzz/corpus/sweep/, replayed through the check fuzz_sweep runs
// (tests/fuzz/targets_sweep.hpp), in the normal test run.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz/targets_sweep.hpp"
#include "support/run_cli.hpp"

namespace skipnc::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> kept_specs() {
  std::vector<fs::path> out;
  const fs::path root(SKIPNC_SOURCE_DIR);
  for (const auto& dir :
       {root / "tests" / "regression" / "sweep", root / "tests" / "fuzz" / "corpus" / "sweep"}) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
      if (e.is_regular_file()) out.push_back(e.path());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(SweepKeptInput, EverySpecIsHandledWithoutBreakingARule) {
  const auto specs = kept_specs();
  ASSERT_GE(specs.size(), 2u);
  for (const auto& p : specs) EXPECT_EQ(check_sweep(test::read_file(p)), "") << p.filename();
}

}  // namespace
}  // namespace skipnc::fuzz
