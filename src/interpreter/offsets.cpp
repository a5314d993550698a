// Offsets: the machine <-> work conversion through every active offset
// (work, G52, G92, G45-G48, tool length, lathe tool offset), G43/G44/G49
// tool length, and G10 data setting.
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "interpreter/codes.hpp"
#include "interpreter/impl.hpp"
#include "interpreter/offset_units.hpp"

namespace skipnc::interp {

double Interpreter::Impl::work_of(int axis, double machine_mm) const noexcept {
  return (machine_mm * axis_scale[static_cast<std::size_t>(axis)] - offset_total(axis)) / unit_mm();
}

double Interpreter::Impl::tool_offset_total(int axis) const noexcept {
  double o = shifts.get().tool_pos_offset[axis] + shifts.get().lathe_tool_offset[axis];
  if (axis == length_axis) o += length_offset;
  return o;
}

double Interpreter::Impl::position_var(int axis, double machine_mm,
                                       bool tool_offsets) const noexcept {
  const double w = work_of(axis, machine_mm);
  return tool_offsets ? w + tool_offset_total(axis) / unit_mm() : w;
}

Flow<void> Interpreter::Impl::set_tool_length(const Words& words, LengthComp mode) {
  if (mode == LengthComp::kOff) {
    length_offset = 0.0;
    modal.h = 0;
    return {};
  }
  // LinuxCNC: G43 without H takes the tool in the spindle.
  int h = lang->rules.g43_tool_in_spindle && !words.has('H') ? modal.tool : modal.h;
  if (words.has('H')) {
    const double v = words.at('H').value;
    if (v != std::trunc(v) || v < 0 || v > mc.tool_offset_count) {
      return fail(AlarmId::kIllegalOffsetNumber, fmt::format("H{}", v), loc(words.at('H').column));
    }
    h = static_cast<int>(v);
  }
  modal.h = h;
  const auto& t = tools[static_cast<std::size_t>(h)];
  const double len = h == 0 ? 0.0 : (t.length_geometry + t.length_wear) * offset_unit_mm(*this);
  length_offset = mode == LengthComp::kPlus ? len : -len;
  return {};
}

// G10: programmable data input. L2 Pn: work offset n (0 = EXT, 1-6 = G54-G59);
// L20 Pn: G54.1 Pn (1-300); L10/L11: H geometry/wear; L12/L13: D
// geometry/wear; L1: H wear (memory A). G90 sets, G91 adds.
// Nine digits at the least increment of 0.001 mm (X+-999999.999), the
// largest value a coordinate word takes in increment system IS-B: an offset
// or a stored position is no larger. A value beyond it (#5221 = [10 ** 60])
// is refused where it is assigned, in every dialect, as the dialect's
// illegal_offset_value (Fanuc PS0029), so that no later move, report or
// parameter file holds it.
Flow<void> Interpreter::Impl::check_offset(double mm, const std::string& what, SourceLoc at) {
  if (std::fabs(mm) <= kMaxOffsetMm) return {};
  return fail(AlarmId::kIllegalOffsetValue,
              what + " = " + fmt::format("{:g}", mm) + " mm: an offset is at most " +
                  fmt::format("{}", kMaxOffsetMm) + " mm",
              at);
}

Flow<void> Interpreter::Impl::data_setting(const Words& words, SourceLoc where) {
  return lang->data_setting(*this, words, where);
}

// The Fanuc family's G10.
Flow<void> Interpreter::Impl::data_setting_fanuc(const Words& words, SourceLoc where) {
  if (mc.lathe() && !words.has('L')) return lathe_offset_setting(words, where);
  if (!words.has('L')) return fail(AlarmId::kBadValue, "G10 needs L", where);
  const int l = static_cast<int>(words.at('L').value);
  const bool inc = modal.distance == Distance::kIncremental;
  if (!words.has('P')) return fail(AlarmId::kBadValue, "G10 needs P", where);
  const double pv = words.at('P').value;
  if (l == 2 || l == 20) {
    const double lo = l == 2 ? 0 : 1;
    const double hi = l == 2 ? 6 : kExtraWorkSystems;
    if (pv != std::trunc(pv) || pv < lo || pv > hi) {
      return fail(AlarmId::kIllegalOffsetNumber,
                  "G10 L" + std::to_string(l) + " P" + fmt::format("{}", pv) +
                      (l == 2 ? ": work offsets are P0 (EXT) and P1-P6 (G54-G59)"
                              : ": G54.1 work offsets are P1-P300"),
                  loc(words.at('P').column));
    }
    const int set = static_cast<int>(pv) + (l == 20 ? 6 : 0);
    AxisVec o = work_offsets[static_cast<std::size_t>(set)];
    for (int i = 0; i < axis_count; ++i) {
      const char c = axis_letter[static_cast<std::size_t>(i)];
      if (!words.has(c)) continue;
      const double v = word_length(words.at(c)) * unit_mm() / offset_unit_mm(*this);
      o[i] = inc ? o[i] + v : v;
      auto ok = check_offset(o[i] * offset_unit_mm(*this), std::string("G10 ") + c,
                             loc(words.at(c).column));
      if (!ok) return ok;
    }
    work_offsets.write(static_cast<std::size_t>(set)) = o;
    return {};
  }
  if (l == 1 || (l >= 10 && l <= 13)) {
    if (pv != std::trunc(pv) || pv < 1 || pv > mc.tool_offset_count) {
      return fail(AlarmId::kIllegalOffsetNumber, fmt::format("G10 P{}", pv),
                  loc(words.at('P').column));
    }
    if (!words.has('R'))
      return fail(AlarmId::kBadValue, "G10 L" + std::to_string(l) + " needs R", where);
    auto& t = tools.write(static_cast<std::size_t>(pv));
    double* f = l == 10             ? &t.length_geometry
                : l == 11 || l == 1 ? &t.length_wear
                : l == 12           ? &t.radius_geometry
                                    : &t.radius_wear;
    const double v = word_length(words.at('R')) * unit_mm() / offset_unit_mm(*this);
    auto ok = check_offset((inc ? *f + v : v) * offset_unit_mm(*this), "G10 R",
                           loc(words.at('R').column));
    if (!ok) return ok;
    *f = inc ? *f + v : v;
    return {};
  }
  return fail(AlarmId::kBadValue, "G10 L" + std::to_string(l) + " is not supported", where);
}

}  // namespace skipnc::interp
