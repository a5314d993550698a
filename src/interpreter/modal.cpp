#include "interpreter/modal.hpp"

namespace skipnc::interp {

int g_code_of_group(const ModalState& m, int group) noexcept {
  if (m.lathe) {
    // G-code system A: G96/G97 are group 02, G98/G99 group 05, the plane
    // group 16; there is no G90/G91 and no return-level group.
    switch (group) {
      case 2:
        return m.spindle_mode == SpindleMode::kSurfaceSpeed ? 960 : 970;
      case 3:
      case 8:
      case 10:
        return 0;
      case 5:
        return m.feed_mode == FeedMode::kPerMinute ? 980 : 990;
      case 16:
        return 170 + 10 * static_cast<int>(m.plane);
      default:
        break;
    }
  }
  switch (group) {
    case 1: {
      if (m.motion == Motion::kProbe) return m.probe;
      static constexpr int k[] = {0, 10, 20, 30, 900};
      return k[static_cast<int>(m.motion)];
    }
    case 2:
      return 170 + 10 * static_cast<int>(m.plane);
    case 3:
      return m.distance == Distance::kAbsolute ? 900 : 910;
    case 5:
      return m.feed_mode == FeedMode::kPerMinute ? 940 : 950;
    case 6:
      return m.units == Units::kInch ? 200 : 210;
    case 7:
      return 400 + 10 * static_cast<int>(m.cutter);
    case 8: {
      static constexpr int k[] = {490, 430, 440};
      return k[static_cast<int>(m.length)];
    }
    case 9: {
      static constexpr int k[] = {800, 730, 740, 760, 810, 820, 830, 840, 850, 860, 870, 880, 890};
      return k[static_cast<int>(m.cycle)];
    }
    case 10:
      return m.ret == ReturnLevel::kInitial ? 980 : 990;
    case 12:
      return m.modal_macro ? 660 : 670;
    case 14:
      return m.work > 6 && m.work <= 9 ? 584 + m.work : 530 + 10 * m.work;  // G59.1-G59.3
    case 15:
      return m.path == PathMode::kExactStop ? 610 : 640;
    default:
      return 0;
  }
}

}  // namespace skipnc::interp
