// The fast decimal writers behind canon lines and trace rows.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
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

std::string milli(std::int64_t m) {
  char buf[40];
  return std::string(buf, write_milli(buf, m));
}

std::string line_number(std::uint32_t v) {
  char buf[40];
  return std::string(buf, write_uint32(buf, v));
}

TEST(Decimal, MilliKnownTexts) {
  EXPECT_EQ(milli(0), "0");
  EXPECT_EQ(milli(-1), "-0.001");
  EXPECT_EQ(milli(5000), "5");
  EXPECT_EQ(milli(-16241), "-16.241");
  EXPECT_EQ(milli(30140), "30.14");
  EXPECT_EQ(milli(500), "0.5");
  EXPECT_EQ(milli(999999), "999.999");
  EXPECT_EQ(milli(1000000), "1000");
  EXPECT_EQ(milli(-1234567890), "-1234567.89");
  EXPECT_EQ(milli(std::numeric_limits<std::int64_t>::min()), "-9223372036854775.808");
}

// The same characters as write_scaled<3> for every magnitude, around each
// boundary of the tables (999, 1000) and at random.
TEST(Decimal, MilliMatchesScaled) {
  for (std::int64_t m = -2000000; m <= 2000000; m += 7) ASSERT_EQ(milli(m), scaled<3>(m)) << m;
  for (std::int64_t m = -1001; m <= 1001; ++m) ASSERT_EQ(milli(m), scaled<3>(m)) << m;
  std::mt19937_64 rng(33);
  for (int i = 0; i < 200000; ++i) {
    const auto m = static_cast<std::int64_t>(rng()) >> (i % 60);
    ASSERT_EQ(milli(m), scaled<3>(m)) << m;
  }
}

TEST(Decimal, LineNumbersMatchWholeNumbers) {
  for (std::uint32_t v = 0; v < 1200000; v += (v < 2000 ? 1 : 13)) {
    ASSERT_EQ(line_number(v), whole(v)) << v;
  }
  for (const std::uint32_t v : {999u, 1000u, 1001u, 999999u, 1000000u, 4294967295u}) {
    ASSERT_EQ(line_number(v), whole(v)) << v;
  }
}

std::string shortest(double v) {
  char buf[40];
  return std::string(buf, write_shortest(buf, v));
}

std::string standard(double v) {
  char buf[40];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

TEST(Decimal, ShortestKnownTexts) {
  EXPECT_EQ(shortest(13.074000000000002), "13.074000000000002");
  EXPECT_EQ(shortest(-0.17200000000000001), "-0.17200000000000001");
  EXPECT_EQ(shortest(647.0794312013581), "647.0794312013581");
  EXPECT_EQ(shortest(0.0001), "1e-04");     // shorter than 0.0001
  EXPECT_EQ(shortest(0.00012), "0.00012");  // as long as 1.2e-04: fixed
  EXPECT_EQ(shortest(1e6), "1e+06");        // shorter than 1000000
  EXPECT_EQ(shortest(123456.0), "123456");
  EXPECT_EQ(shortest(5e-324), "5e-324");
  EXPECT_EQ(shortest(1e300), "1e+300");
  EXPECT_EQ(shortest(0.0), "0");
  EXPECT_EQ(shortest(-0.0), "-0");
  EXPECT_EQ(shortest(std::numeric_limits<double>::infinity()), "inf");
}

// The same characters as std::to_chars for values of every kind the canon
// text meets: arithmetic near whole micrometres, feeds from expressions,
// whole numbers, very small and very large values, any bit pattern.
TEST(Decimal, ShortestMatchesToChars) {
  std::mt19937_64 rng(32);
  std::uniform_int_distribution<std::int64_t> um(-999999999, 999999999);
  std::uniform_int_distribution<int> ulps(-4, 4);
  std::uniform_int_distribution<int> e10(-330, 310);
  std::uniform_real_distribution<double> unit(1.0, 10.0);
  for (int i = 0; i < 400000; ++i) {
    double v = 0.0;
    switch (i % 5) {
      case 0:  // a micrometre value a few units in the last place off
        v = static_cast<double>(um(rng)) / 1000.0;
        for (int k = ulps(rng); k != 0; k += k < 0 ? 1 : -1) {
          v = std::nextafter(v, k < 0 ? -1e300 : 1e300);
        }
        break;
      case 1:  // a computed value
        v = std::sqrt(static_cast<double>(um(rng))) * 3.7;
        break;
      case 2:  // whole numbers and their tens
        v = static_cast<double>(um(rng)) * std::pow(10.0, ulps(rng) + 4);
        break;
      case 3:  // any magnitude
        v = unit(rng) * std::pow(10.0, e10(rng));
        break;
      default:  // any bit pattern
        v = std::bit_cast<double>(rng());
        break;
    }
    ASSERT_EQ(shortest(v), standard(v)) << std::bit_cast<std::uint64_t>(v);
  }
  for (int e = -325; e <= 310; ++e) {  // the powers of ten and their neighbours
    const double p = std::pow(10.0, e);
    for (const double v : {p, std::nextafter(p, 0.0), std::nextafter(p, 1e308), -p}) {
      ASSERT_EQ(shortest(v), standard(v)) << e;
    }
  }
}

}  // namespace
}  // namespace skipnc::decimal
