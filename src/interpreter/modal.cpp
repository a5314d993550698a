#include "interpreter/modal.hpp"

namespace skipnc::interp {

int g_code_of_group(const ModalState& m, int group) noexcept {
  switch (group) {
    case 1: {
      static constexpr int k[] = {0, 10, 20, 30};
      return k[static_cast<int>(m.motion)];
    }
    case 2: return 170 + 10 * static_cast<int>(m.plane);
    case 3: return m.distance == Distance::kAbsolute ? 900 : 910;
    case 5: return m.feed_mode == FeedMode::kPerMinute ? 940 : 950;
    case 6: return m.units == Units::kInch ? 200 : 210;
    case 7: return 400 + 10 * static_cast<int>(m.cutter);
    case 8: {
      static constexpr int k[] = {490, 430, 440};
      return k[static_cast<int>(m.length)];
    }
    case 9: {
      static constexpr int k[] = {800, 730, 740, 760, 810, 820, 830, 840, 850, 860, 870, 880, 890};
      return k[static_cast<int>(m.cycle)];
    }
    case 10: return m.ret == ReturnLevel::kInitial ? 980 : 990;
    case 12: return m.modal_macro ? 660 : 670;
    case 14: return 530 + 10 * m.work;
    case 15: return m.path == PathMode::kExactStop ? 610 : 640;
    default: return 0;
  }
}

}  // namespace skipnc::interp
