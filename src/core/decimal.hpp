// Fast decimal text of numbers for the bulk outputs (canon lines, trace rows):
// whole numbers, and values held as a whole number of 10^-decimals units.
#pragma once

#include <cstddef>
#include <cstdint>

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

// Writes the shortest text that reads back to v, the same characters as
// std::to_chars(p, p + 32, v) (fixed or scientific, whichever is shorter;
// "1e-05", "13.074000000000002"), from fmt's Dragonbox digits: about two
// thirds of std::to_chars's instructions. At most 24 characters; returns the end.
char* write_shortest(char* p, double v) noexcept;

}  // namespace skipnc::decimal
