#include "core/utf8.hpp"

#include <cstdint>

namespace skipnc::utf8 {
namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

// The well-formed byte sequences (Unicode 15, table 3-7): for a lead byte,
// how many bytes follow and the range of the first of them; the later ones
// are always 80..BF.
struct Lead {
  std::uint8_t follow = 0;  // 0: not a lead byte (or ASCII when below 0x80)
  std::uint8_t lo = 0x80;
  std::uint8_t hi = 0xBF;
};

constexpr Lead lead_of(std::uint8_t b) noexcept {
  if (b >= 0xC2 && b <= 0xDF) return {1, 0x80, 0xBF};
  if (b == 0xE0) return {2, 0xA0, 0xBF};  // no overlong 3-byte forms
  if (b == 0xED) return {2, 0x80, 0x9F};  // no surrogates D800-DFFF
  if (b >= 0xE1 && b <= 0xEF) return {2, 0x80, 0xBF};
  if (b == 0xF0) return {3, 0x90, 0xBF};  // no overlong 4-byte forms
  if (b == 0xF4) return {3, 0x80, 0x8F};  // nothing above U+10FFFF
  if (b >= 0xF1 && b <= 0xF3) return {3, 0x80, 0xBF};
  return {};
}

// Length of the well-formed sequence at s[i], or 0 with `subpart` set to the
// length of the maximal ill-formed subpart there (at least 1).
std::size_t sequence_at(std::string_view s, std::size_t i, std::size_t& subpart) noexcept {
  const auto b = static_cast<std::uint8_t>(s[i]);
  if (b < 0x80) return 1;
  const Lead l = lead_of(b);
  subpart = 1;
  if (l.follow == 0) return 0;
  for (std::size_t k = 1; k <= l.follow; ++k) {
    if (i + k >= s.size()) return 0;
    const auto c = static_cast<std::uint8_t>(s[i + k]);
    const std::uint8_t lo = k == 1 ? l.lo : 0x80;
    const std::uint8_t hi = k == 1 ? l.hi : 0xBF;
    if (c < lo || c > hi) return 0;
    subpart = k + 1;
  }
  return l.follow + 1;
}

}  // namespace

bool is_valid(std::string_view s) noexcept {
  for (std::size_t i = 0; i < s.size();) {
    std::size_t bad = 0;
    const std::size_t n = sequence_at(s, i, bad);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::string make_valid(std::string_view s) {
  if (is_valid(s)) return std::string(s);
  std::string out;
  out.reserve(s.size() + 8);
  for (std::size_t i = 0; i < s.size();) {
    std::size_t bad = 0;
    const std::size_t n = sequence_at(s, i, bad);
    if (n > 0) {
      out.append(s.substr(i, n));
      i += n;
    } else {
      out += kReplacement;
      i += bad;
    }
  }
  return out;
}

}  // namespace skipnc::utf8
