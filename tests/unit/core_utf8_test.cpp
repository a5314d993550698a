// Text that goes into JSON is made valid UTF-8: each maximal ill-formed
// subpart becomes U+FFFD, well-formed text is kept as it is (core/utf8.hpp).
#include <gtest/gtest.h>

#include <string>

#include "core/utf8.hpp"

namespace skipnc {
namespace {

constexpr const char* kFffd = "\xEF\xBF\xBD";

TEST(Utf8, WellFormedTextIsKept) {
  for (const std::string s : {"", "CAFE", "CAF\xC3\x89", "\xE2\x82\xAC 5", "\xF0\x9F\x94\xA7"}) {
    EXPECT_TRUE(utf8::is_valid(s)) << s;
    EXPECT_EQ(utf8::make_valid(s), s);
  }
}

TEST(Utf8, LatinOneByteBecomesOneReplacementCharacter) {
  EXPECT_FALSE(utf8::is_valid("CAF\xC9"));
  EXPECT_EQ(utf8::make_valid("CAF\xC9"), std::string("CAF") + kFffd);
  EXPECT_EQ(utf8::make_valid("\xE9t\xE9"), std::string(kFffd) + "t" + kFffd);
}

TEST(Utf8, IllFormedSequencesAreReplacedByMaximalSubpart) {
  // A truncated 3-byte sequence is one subpart; an overlong form, a
  // surrogate and a value above U+10FFFF are one replacement per byte.
  EXPECT_EQ(utf8::make_valid("\xE2\x82"
                             "A"),
            std::string(kFffd) + "A");
  EXPECT_EQ(utf8::make_valid("\xC0\xAF"), std::string(kFffd) + kFffd);
  EXPECT_EQ(utf8::make_valid("\xED\xA0\x80"), std::string(kFffd) + kFffd + kFffd);
  EXPECT_EQ(utf8::make_valid("\xF4\x90\x80\x80"), std::string(kFffd) + kFffd + kFffd + kFffd);
  EXPECT_TRUE(utf8::is_valid(utf8::make_valid("\xFF\xFE\x80 \xF0\x9F")));
}

}  // namespace
}  // namespace skipnc
