// Fast decimal text of numbers for the bulk outputs (canon lines, trace rows):
// whole numbers, and values held as a whole number of 10^-decimals units.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace skipnc::decimal {

// "00" to "99": the digits are written two at a time.
inline constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// Writes the 8 digits of a (< 10^8, leading zeros kept) backwards to end at e.
inline void eight_digits_back(char* e, std::uint32_t a) noexcept {
  for (int k = 0; k < 4; ++k) {
    const auto i = static_cast<std::size_t>(a % 100) * 2;
    a /= 100;
    *--e = kPairs[i + 1];
    *--e = kPairs[i];
  }
}

// Writes a (< 10^20) backwards so that it ends at e; returns its first
// character. Eight digits at a time in 32-bit arithmetic while a is longer.
inline char* digits_back(char* e, std::uint64_t a) noexcept {
  while (a >= 100000000) {
    eight_digits_back(e, static_cast<std::uint32_t>(a % 100000000));
    a /= 100000000;
    e -= 8;
  }
  auto b = static_cast<std::uint32_t>(a);
  while (b >= 100) {
    const auto i = static_cast<std::size_t>(b % 100) * 2;
    b /= 100;
    *--e = kPairs[i + 1];
    *--e = kPairs[i];
  }
  if (b >= 10) {
    const auto i = static_cast<std::size_t>(b) * 2;
    *--e = kPairs[i + 1];
    *--e = kPairs[i];
  } else {
    *--e = static_cast<char>('0' + b);
  }
  return e;
}

// Number of decimal digits of a (1 for 0).
inline int digit_count(std::uint64_t a) noexcept {
  int n = 1;
  for (; a >= 10000; a /= 10000) n += 4;
  return n + (a >= 10) + (a >= 100) + (a >= 1000);
}

// Writes a at p; returns the end.
inline char* write_uint(char* p, std::uint64_t a) noexcept {
  char* const e = p + digit_count(a);
  digits_back(e, a);
  return e;
}

// Writes the whole number v at p; returns the end (at most 20 characters).
inline char* write_int(char* p, std::int64_t v) noexcept {
  const std::uint64_t a = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
  if (v < 0) *p++ = '-';
  return write_uint(p, a);
}

// Writes m / 10^Decimals (Decimals 1..9) with the trailing zeros of the
// fraction dropped, and no point when the fraction is zero ("12.5", "-0.001",
// "3"); returns the end (at most 31 characters).
template <int Decimals>
inline char* write_scaled(char* p, std::int64_t m) noexcept {
  static_assert(Decimals >= 1 && Decimals <= 9);
  constexpr std::uint64_t kScale = [] {
    std::uint64_t s = 1;
    for (int i = 0; i < Decimals; ++i) s *= 10;
    return s;
  }();
  const std::uint64_t a = m < 0 ? 0 - static_cast<std::uint64_t>(m) : static_cast<std::uint64_t>(m);
  if (m < 0) *p++ = '-';
  p = write_uint(p, a / kScale);
  const std::uint64_t frac = a % kScale;
  if (frac == 0) return p;
  *p = '.';
  // All the fraction's digits (leading zeros kept), then the trailing zeros off.
  char* e = p + 1 + Decimals;
  digits_back(e, frac + kScale);  // the leading '1' lands on the point,
  *p = '.';                       // which is written again
  while (e[-1] == '0') --e;
  return e;
}

// The text of a number below 1000: up to four characters and their count.
struct ShortText {
  char text[4];
  std::uint8_t size;
};

// "0" to "999" (index: the number), and ".001" to ".999" with the trailing
// zeros dropped ("" for 0, ".5" for 500): a table for each, so that a value
// in thousandths is written by two copies.
inline constexpr auto kWholeBelow1000 = [] {
  struct Table {
    ShortText at[1000];
  } t{};
  for (int i = 0; i < 1000; ++i) {
    ShortText& s = t.at[i];
    const int n = i >= 100 ? 3 : (i >= 10 ? 2 : 1);
    for (int k = n - 1, v = i; k >= 0; --k, v /= 10) s.text[k] = static_cast<char>('0' + v % 10);
    s.size = static_cast<std::uint8_t>(n);
  }
  return t;
}();
inline constexpr auto kThousandths = [] {
  struct Table {
    ShortText at[1000];
  } t{};
  for (int i = 0; i < 1000; ++i) {  // 0: ".000", of size 0
    ShortText& s = t.at[i];
    s.text[0] = '.';
    s.text[1] = static_cast<char>('0' + i / 100);
    s.text[2] = static_cast<char>('0' + i / 10 % 10);
    s.text[3] = static_cast<char>('0' + i % 10);
    s.size = static_cast<std::uint8_t>(i == 0 ? 0 : i % 10 != 0 ? 4 : (i % 100 != 0 ? 3 : 2));
  }
  return t;
}();

// Writes s (all four characters; the room after p must allow it), returns
// the end of its text.
inline char* put_short(char* p, const ShortText& s) noexcept {
  for (int k = 0; k < 4; ++k) p[k] = s.text[k];
  return p + s.size;
}

// write_uint(p, v), the same characters: below 10^6 copied from the tables
// (a line number). Needs 4 characters of room past the end it returns.
inline char* write_uint32(char* p, std::uint32_t v) noexcept {
  if (v < 1000) return put_short(p, kWholeBelow1000.at[v]);
  if (v >= 1000000) return write_uint(p, v);
  const std::uint32_t high = v / 1000;
  p = put_short(p, kWholeBelow1000.at[high]);
  const ShortText& low = kThousandths.at[v - high * 1000];  // ".ddd", all three digits
  p[0] = low.text[1];
  p[1] = low.text[2];
  p[2] = low.text[3];
  return p + 3;
}

// write_scaled<3>(p, m), the same characters: the whole part below 1000 and
// the fraction each copied from a table. Needs 4 characters of room past the
// end it returns (at most 25 characters in all).
inline char* write_milli(char* p, std::int64_t m) noexcept {
  const std::uint64_t a = m < 0 ? 0 - static_cast<std::uint64_t>(m) : static_cast<std::uint64_t>(m);
  if (m < 0) *p++ = '-';
  const std::uint64_t whole = a / 1000;
  const auto frac = static_cast<std::size_t>(a - whole * 1000);
  if (whole < 1000) {
    p = put_short(p, kWholeBelow1000.at[whole]);
  } else {
    p = write_uint(p, whole);
  }
  return put_short(p, kThousandths.at[frac]);
}

// Writes the shortest text that reads back to v, the same characters as
// std::to_chars(p, p + 32, v) (fixed or scientific, whichever is shorter;
// "1e-05", "13.074000000000002"), from fmt's Dragonbox digits: about two
// thirds of std::to_chars's instructions. At most 24 characters, but it may
// write anywhere in the 32 characters from p; returns the end.
char* write_shortest(char* p, double v) noexcept;

}  // namespace skipnc::decimal
