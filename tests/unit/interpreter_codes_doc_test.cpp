// docs/codes.md is generated from the interpreter (interpreter/codes.hpp):
// this test fails when the page and the code differ. With
// SKIPNC_UPDATE_DOCS=1 in the environment it writes the page instead.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "interpreter/codes.hpp"

namespace {

using skipnc::GCode;
using skipnc::interp::CodeStatus;
using skipnc::interp::g_code_status;

TEST(CodesDoc, MatchesTheInterpreter) {
  const auto md = skipnc::interp::codes_markdown();
  ASSERT_TRUE(md.has_value()) << md.error().detail;
  const std::filesystem::path page = std::filesystem::path(SKIPNC_SOURCE_DIR) / "docs" / "codes.md";
  const char* update = std::getenv("SKIPNC_UPDATE_DOCS");
  if (update != nullptr && std::string(update) == "1") {
    std::ofstream(page, std::ios::binary) << *md;
  }
  std::ifstream in(page, std::ios::binary);
  std::stringstream have;
  have << in.rdbuf();
  EXPECT_EQ(have.str(), *md) << "docs/codes.md is out of date: run this test with "
                                "SKIPNC_UPDATE_DOCS=1 and review the difference";
}

// The classes of the page, on codes whose status the issue names.
TEST(CodesDoc, StatusOfKnownCodes) {
  EXPECT_EQ(*g_code_status(GCode(81), "mill3", "fanuc"), CodeStatus::kSimulated);
  EXPECT_EQ(*g_code_status(GCode(68), "mill3", "fanuc"), CodeStatus::kSimulated);
  EXPECT_EQ(*g_code_status(GCode(5, 1), "mill3", "fanuc"), CodeStatus::kNoEffect);
  EXPECT_EQ(*g_code_status(GCode(13, 1), "mill3", "fanuc"), CodeStatus::kNoEffect);
  EXPECT_EQ(*g_code_status(GCode(40, 1), "mill3", "fanuc"), CodeStatus::kNoEffect);
  EXPECT_EQ(*g_code_status(GCode(12, 1), "mill3", "fanuc"), CodeStatus::kNotSimulated);
  EXPECT_EQ(*g_code_status(GCode(81), "lathe2", "fanuc"), CodeStatus::kImproper);
  EXPECT_EQ(*g_code_status(GCode(77, 7), "mill3", "fanuc"), CodeStatus::kImproper);
}

}  // namespace
