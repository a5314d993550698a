#include "interpreter/modal.hpp"

namespace skipnc::interp {

namespace {

// The lathe's groups that differ from the mill's (G-code system A).
std::optional<GCode> lathe_code_of_group(const ModalState& m, int group, bool& differs) noexcept {
  // G-code system A: G96/G97 are group 02, G98/G99 group 05, the plane
  // group 16; there is no G90/G91 and no return-level group.
  differs = true;
  switch (group) {
    case 2:
      return GCode(m.spindle_mode == SpindleMode::kSurfaceSpeed ? 96 : 97);
    case 3:
    case 8:
    case 10:
      return std::nullopt;
    case 5:
      return GCode(m.feed_mode == FeedMode::kPerMinute ? 98 : 99);
    case 16:
      return GCode(17 + static_cast<int>(m.plane));
    default:
      differs = false;
      return std::nullopt;
  }
}

}  // namespace

std::optional<GCode> g_code_of_group(const ModalState& m, int group) noexcept {
  if (m.lathe) {
    bool differs = false;
    auto code = lathe_code_of_group(m, group, differs);
    if (differs) return code;
  }
  switch (group) {
    case 1: {
      if (m.motion == Motion::kProbe) return m.probe;
      static constexpr int k[] = {0, 1, 2, 3, 90};
      return GCode(k[static_cast<int>(m.motion)]);
    }
    case 2:
      return GCode(17 + static_cast<int>(m.plane));
    case 3:
      return GCode(m.distance == Distance::kAbsolute ? 90 : 91);
    case 5:
      return GCode(m.feed_mode == FeedMode::kPerMinute ? 94 : 95);
    case 6:
      return GCode(m.units == Units::kInch ? 20 : 21);
    case 7:
      return GCode(40 + static_cast<int>(m.cutter));
    case 8: {
      static constexpr int k[] = {49, 43, 44};
      return GCode(k[static_cast<int>(m.length)]);
    }
    case 9: {
      static constexpr int k[] = {80, 73, 74, 76, 81, 82, 83, 84, 85, 86, 87, 88, 89};
      return GCode(k[static_cast<int>(m.cycle)]);
    }
    case 10:
      return GCode(m.ret == ReturnLevel::kInitial ? 98 : 99);
    case 12:
      return GCode(m.modal_macro ? 66 : 67);
    case 14:
      // G59.1-G59.3 after G54-G59.
      return m.work > 6 && m.work <= 9 ? GCode(59, m.work - 6) : GCode(53 + m.work);
    case 15:
      return GCode(m.path == PathMode::kExactStop ? 61 : 64);
    default:
      return std::nullopt;
  }
}

}  // namespace skipnc::interp
