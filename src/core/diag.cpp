#include "core/diag.hpp"

#include <array>

namespace skipnc {
namespace {

constexpr std::array<std::string_view, static_cast<std::size_t>(AlarmId::kCount)> kAlarmKeys = {
#define SKIPNC_ALARM(id, key) key,
#include "core/alarms.def"
#undef SKIPNC_ALARM
};

}  // namespace

std::string_view alarm_key(AlarmId id) noexcept {
  const auto i = static_cast<std::size_t>(id);
  return i < kAlarmKeys.size() ? kAlarmKeys[i] : std::string_view("internal");
}

AlarmId alarm_from_key(std::string_view key) noexcept {
  for (std::size_t i = 0; i < kAlarmKeys.size(); ++i) {
    if (kAlarmKeys[i] == key) return static_cast<AlarmId>(i);
  }
  return AlarmId::kCount;
}

}  // namespace skipnc
