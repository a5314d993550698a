#include "config/skip_inputs.hpp"

#include <charconv>

namespace skipnc::config {

canon::SignalAddr skip_input_address(const Dialect& d, const Parameters& p, int index) noexcept {
  canon::SignalAddr a;
  const bool by_params =
      d.param(param::kSkipAddressing) != nullptr;  // Fanuc-style address parameters
  if (by_params && p.bit(param::kSkipByParameters) && index < 4) {
    a.area = p.bit(param::kSkipAreaG) ? 'G' : 'X';
    a.byte = static_cast<std::uint16_t>(p.get(param::kSkipByte));
    a.bit = static_cast<std::uint8_t>(p.get(param::kSkipBitFirst + index));
    return a;
  }
  if (index >= 0 && index < static_cast<int>(d.fixed_skip_inputs.size()) &&
      (!by_params || index < 4)) {
    return d.fixed_skip_inputs[static_cast<std::size_t>(index)];
  }
  if (!by_params) return d.fixed_skip_inputs.front();  // not reached: P is checked first
  a.area = 'X';
  a.byte = static_cast<std::uint16_t>(p.get(param::kSkip5To12Byte));
  a.bit = static_cast<std::uint8_t>((index - 4) & 7);
  return a;
}

Result<void> check_skip_addresses(const Dialect& d, const Parameters& p) {
  if (d.param(param::kSkipAddressing) == nullptr || !p.bit(param::kSkipByParameters)) return {};
  const double byte = p.get(param::kSkipByte);
  const bool g_area = p.bit(param::kSkipAreaG);
  if (byte < 0 || byte > (g_area ? 511 : 127)) {
    return fail(AlarmId::kConfig,
                "parameter 3012 = " + std::to_string(static_cast<long long>(byte)) +
                    " is out of range for area " + (g_area ? "G (0-511)" : "X (0-127)") +
                    " selected by 3008#1");
  }
  for (int n = param::kSkipBitFirst; n <= param::kSkipBitLast; ++n) {
    const double bit = p.get(n);
    if (bit < 0 || bit > 7) {
      return fail(AlarmId::kConfig, "parameter " + std::to_string(n) + " must be a bit number 0-7");
    }
  }
  if (p.get(param::kSkip5To12Byte) < 0 || p.get(param::kSkip5To12Byte) > 127) {
    return fail(AlarmId::kConfig, "parameter 3025 must be an X byte 0-127");
  }
  return {};
}

std::optional<canon::SignalAddr> parse_signal_name(std::string_view name, const Dialect& d,
                                                   const Parameters& p) {
  if (name.starts_with("SKIP")) {
    std::string_view rest = name.substr(4);
    int n = 1;
    if (!rest.empty()) {
      auto r = std::from_chars(rest.data(), rest.data() + rest.size(), n);
      const int count = d.param(param::kSkipAddressing) != nullptr
                            ? canon::SkipSpec::kMaxInputs
                            : static_cast<int>(d.fixed_skip_inputs.size());
      if (r.ec != std::errc{} || r.ptr != rest.data() + rest.size() || n < 1 || n > count) {
        return std::nullopt;
      }
    }
    return skip_input_address(d, p, n - 1);
  }
  if (name.size() < 4 || (name[0] != 'X' && name[0] != 'G')) return std::nullopt;
  const auto dot = name.find('.');
  if (dot == std::string_view::npos) return std::nullopt;
  unsigned byte = 0, bit = 0;
  auto r1 = std::from_chars(name.data() + 1, name.data() + dot, byte);
  auto r2 = std::from_chars(name.data() + dot + 1, name.data() + name.size(), bit);
  if (r1.ec != std::errc{} || r1.ptr != name.data() + dot || r2.ec != std::errc{} ||
      r2.ptr != name.data() + name.size() || bit > 7 || byte > (name[0] == 'X' ? 127U : 511U)) {
    return std::nullopt;
  }
  canon::SignalAddr a;
  a.area = name[0];
  a.byte = static_cast<std::uint16_t>(byte);
  a.bit = static_cast<std::uint8_t>(bit);
  return a;
}

std::string signal_name(const canon::SignalAddr& a) {
  return std::string(1, a.area) + std::to_string(a.byte) + "." + std::to_string(a.bit);
}

}  // namespace skipnc::config
