// The PMC input image: X bytes 0-127 and G bytes 0-511, one bit per signal.
#pragma once

#include <array>
#include <cstdint>

#include "canon/canon.hpp"

namespace skipnc::kernel {

class SignalImage {
 public:
  bool get(const canon::SignalAddr& a) const noexcept {
    const std::uint8_t* b = byte(a);
    return b != nullptr && ((*b >> a.bit) & 1U) != 0;
  }
  void set(const canon::SignalAddr& a, bool on) noexcept {
    std::uint8_t* b = byte(a);
    if (b == nullptr) return;
    const auto mask = static_cast<std::uint8_t>(1U << a.bit);
    *b = on ? static_cast<std::uint8_t>(*b | mask) : static_cast<std::uint8_t>(*b & ~mask);
  }
  static bool valid(const canon::SignalAddr& a) noexcept {
    return a.bit < 8 && ((a.area == 'X' && a.byte < 128) || (a.area == 'G' && a.byte < 512));
  }

 private:
  const std::uint8_t* byte(const canon::SignalAddr& a) const noexcept {
    if (a.bit > 7) return nullptr;
    if (a.area == 'X' && a.byte < x_.size()) return &x_[a.byte];
    if (a.area == 'G' && a.byte < g_.size()) return &g_[a.byte];
    return nullptr;
  }
  std::uint8_t* byte(const canon::SignalAddr& a) noexcept {
    return const_cast<std::uint8_t*>(static_cast<const SignalImage*>(this)->byte(a));
  }
  std::array<std::uint8_t, 128> x_{};
  std::array<std::uint8_t, 512> g_{};
};

}  // namespace skipnc::kernel
