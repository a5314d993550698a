// The shortest text of a double, as std::to_chars writes it, from fmt's
// Dragonbox digits (decimal.hpp write_shortest).
#include "core/decimal.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstring>

namespace skipnc::decimal {
namespace {

// Room std::to_chars may need for a double (24 characters at most).
constexpr std::size_t kShortestRoom = 32;

// sig x 10^exp in fixed notation (sig has n digits): the digits and the
// zeros of a whole number, the point inside the digits, or "0.000ddd".
char* write_fixed(char* p, std::uint64_t sig, int n, int exp) noexcept {
  const int e10 = n - 1 + exp;
  if (exp >= 0) {
    p = write_uint(p, sig);
    std::memset(p, '0', static_cast<std::size_t>(exp));
    return p + exp;
  }
  if (e10 >= 0) {
    // The whole part, the point, the -exp digits of the fraction: all the
    // digits written once aside, then copied on each side of the point in
    // two moves of fixed size (no division by a power chosen at run time).
    const int whole = e10 + 1;
    char digits[40];
    digits_back(digits + n, sig);
    if (whole <= 8) {
      std::memcpy(p, digits, 8);
      p[whole] = '.';
      std::memcpy(p + whole + 1, digits + whole, 16);  // n - whole <= 16 digits
    } else {
      std::memcpy(p, digits, static_cast<std::size_t>(whole));
      p[whole] = '.';
      std::memcpy(p + whole + 1, digits + whole, static_cast<std::size_t>(n - whole));
    }
    return p + n + 1;
  }
  *p++ = '0';
  *p++ = '.';
  std::memset(p, '0', static_cast<std::size_t>(-e10 - 1));
  p += -e10 - 1;
  return write_uint(p, sig);
}

// d.ddde+XX (at least two digits of exponent), as std::to_chars.
char* write_scientific(char* p, std::uint64_t sig, int n, int e10) noexcept {
  char* const end = p + n + 1;
  digits_back(end, sig);  // the digits from p + 1
  p[0] = p[1];
  if (n > 1) {
    p[1] = '.';
    p = end;
  } else {
    p += 1;
  }
  *p++ = 'e';
  *p++ = e10 < 0 ? '-' : '+';
  const auto a = static_cast<std::uint64_t>(e10 < 0 ? -e10 : e10);
  if (a < 10) *p++ = '0';
  return write_uint(p, a);
}

}  // namespace

char* write_shortest(char* p, double v) noexcept {
  // Zero, infinities, NaN and the values whose fixed text would need more
  // digits than the shortest (whole numbers of 10^15 and more) are left to
  // the standard library.
  const double a = std::fabs(v);
  if (!(a > 0.0 && a < 1e15)) return std::to_chars(p, p + kShortestRoom, v).ptr;
  if (v < 0) *p++ = '-';
  const auto dec = fmt::detail::dragonbox::to_decimal(a);
  const std::uint64_t sig = dec.significand;
  const int exp = dec.exponent;
  const int n = fmt::detail::count_digits(sig);
  const int e10 = n - 1 + exp;
  // std::to_chars's plain form: the shorter of fixed and scientific, fixed on a tie.
  const int fixed = exp >= 0 ? n + exp : (e10 >= 0 ? n + 1 : 2 - exp);
  const int abs_e10 = e10 < 0 ? -e10 : e10;
  const int scientific = n + (n > 1 ? 1 : 0) + 2 + (abs_e10 >= 100 ? 3 : 2);
  return fixed <= scientific ? write_fixed(p, sig, n, exp) : write_scientific(p, sig, n, e10);
}

}  // namespace skipnc::decimal
