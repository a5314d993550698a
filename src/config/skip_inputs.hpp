// Skip-input addresses: which PMC bit the n-th selectable skip input is.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "canon/canon.hpp"
#include "config/dialect.hpp"
#include "config/machine_config.hpp"

namespace skipnc::config {

// Address of skip input `index` (0 = SKIP / SKIP1 / P<first>). Fanuc
// parameters: 3008#2 = 0 fixed addresses (dialect table); 3008#2 = 1: byte
// 3012 of area X (3008#1 = 0) or G (3008#1 = 1), bit 3020+index for SKIP1-4;
// SKIP5-SKIP12 on the X byte of 3025, bits 0-7.
canon::SignalAddr skip_input_address(const Dialect& d, const Parameters& p, int index) noexcept;

// Checks the address parameters together (ranges that depend on each other).
[[nodiscard]] Result<void> check_skip_addresses(const Dialect& d, const Parameters& p);

// "X0.4", "G12.3", "SKIP", "SKIP1".."SKIP12" -> address. nullopt if malformed.
std::optional<canon::SignalAddr> parse_signal_name(std::string_view name, const Dialect& d,
                                                   const Parameters& p);
std::string signal_name(const canon::SignalAddr& a);

}  // namespace skipnc::config
