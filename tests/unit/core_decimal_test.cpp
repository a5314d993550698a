// The fast decimal writers behind canon lines and trace rows.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "core/decimal.hpp"

namespace skipnc::decimal {
namespace {

template <int D>
std::string scaled(std::int64_t m) {
  char buf[40];
  return std::string(buf, write_scaled<D>(buf, m));
}

std::string whole(std::int64_t v) {
  char buf[40];
  return std::string(buf, write_int(buf, v));
}

// "%.<D>f" of m / 10^D, written with integers, trailing zeros and point dropped.
template <int D>
std::string reference(std::int64_t m) {
  std::int64_t scale = 1;
  for (int i = 0; i < D; ++i) scale *= 10;
  const std::uint64_t a = m < 0 ? 0 - static_cast<std::uint64_t>(m) : static_cast<std::uint64_t>(m);
  std::string s =
      fmt::format("{}{}.{:0{}}", m < 0 ? "-" : "", a / static_cast<std::uint64_t>(scale),
                  a % static_cast<std::uint64_t>(scale), D);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

TEST(Decimal, WholeNumbers) {
  EXPECT_EQ(whole(0), "0");
  EXPECT_EQ(whole(7), "7");
  EXPECT_EQ(whole(-42), "-42");
  EXPECT_EQ(whole(1000000), "1000000");
  EXPECT_EQ(whole(std::numeric_limits<std::int64_t>::max()), "9223372036854775807");
  EXPECT_EQ(whole(std::numeric_limits<std::int64_t>::min()), "-9223372036854775808");
}

TEST(Decimal, ScaledValuesDropTrailingZeros) {
  EXPECT_EQ(scaled<3>(12345), "12.345");
  EXPECT_EQ(scaled<3>(-1), "-0.001");
  EXPECT_EQ(scaled<3>(5000), "5");
  EXPECT_EQ(scaled<3>(120), "0.12");
  EXPECT_EQ(scaled<3>(0), "0");
  EXPECT_EQ(scaled<6>(15), "0.000015");
  EXPECT_EQ(scaled<6>(-98515), "-0.098515");
  EXPECT_EQ(scaled<6>(3608642000), "3608.642");
}

TEST(Decimal, ScaledValuesMatchFixedPointText) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::int64_t> d(-999999999999999LL, 999999999999999LL);
  for (int i = 0; i < 100000; ++i) {
    std::int64_t m = d(rng);
    if (i % 4 == 1) m /= 1000;  // short values, trailing zeros
    if (i % 4 == 2) m = (m / 1000) * 1000;
    ASSERT_EQ(scaled<3>(m), reference<3>(m)) << m;
    ASSERT_EQ(scaled<6>(m), reference<6>(m)) << m;
  }
}

}  // namespace
}  // namespace skipnc::decimal
