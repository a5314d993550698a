// The codes LinuxCNC and grbl give a meaning of their own (docs/languages.md),
// after LinuxCNC's "G Codes" reference and grbl 1.1's command list, checked
// against LinuxCNC's `rs274` (tests/rs274/):
//   G10 L1 Pn     tool n: Z its length, R its radius
//   G10 L2 Pn     work offset n (0: the active one, 1-9: G54-G59.3), always absolute
//   G10 L20 Pn    work offset n such that the present position reads the words given
//   G28.1 G30.1   the present machine position into #5161.. / #5181..
//   G28 G30       to #5161.. / #5181.. (through the point of the axis words, if any)
//   G43.1 Z       a tool length offset given as a value
//   G92.1 G92.2   G92 off; #5211.. cleared (G92.1) or kept (G92.2)
//   G92.3         G92 from #5211..
// Positions and offsets kept in #5161-#5390 are in the machine's units
// whatever G20/G21 is in force (stored_mm()): LinuxCNC's rs274 (2.9), whose
// machine is in inches, stores G21 G10 L2 P1 X25.4 as #5221 = 1.000000 and
// G21 G28.1 at Z10 as #5163 = 0.393701; grbl keeps them in mm.
#include <cmath>
#include <string>

#include "interpreter/impl.hpp"

namespace skipnc::interp {

Flow<void> Interpreter::Impl::ngc_action(const Words& words, GCode code) {
  auto axis_param = [&](int base, int i) {
    const char c = axis_letter[static_cast<std::size_t>(i)];
    const int j = ngc_axis_index(c);
    return j < 0 ? -1 : base + j;
  };
  if (code == GCode(28, 1) || code == GCode(30, 1)) {
    const int base = code == GCode(28, 1) ? 5161 : 5181;
    for (int i = 0; i < axis_count; ++i) {
      const int n = axis_param(base, i);
      if (n > 0) vars.set_ngc_param(n, pos[i] / stored_mm());
    }
    return {};
  }
  if (code == GCode(43, 1)) {
    if (!words.has('Z') || length_axis < 0) {
      return fail(AlarmId::kBadValue, "G43.1 needs Z, the tool length", loc(cur_col));
    }
    const double z = word_length(words.at('Z'), false) * unit_mm();
    if (auto ok = check_offset(z, "G43.1 Z", loc(words.at('Z').column)); !ok) return ok;
    length_offset = z;
    modal.length = LengthComp::kPlus;
    modal.h = 0;
    return {};
  }
  if (code == GCode(92, 1) || code == GCode(92, 2)) {
    const bool clear = code == GCode(92, 1);
    for (int i = 0; i < axis_count; ++i) {
      shifts.write().g92_shift[i] = 0.0;
      const int n = axis_param(5211, i);
      if (clear && n > 0) vars.set_ngc_param(n, 0.0);
    }
    if (clear) vars.set_ngc_param(5210, 0.0);
    return {};
  }
  if (code == GCode(92, 3)) {
    for (int i = 0; i < axis_count; ++i) {
      const int n = axis_param(5211, i);
      shifts.write().g92_shift[i] = n > 0 ? vars.ngc_param(n) * stored_mm() : 0.0;
    }
    vars.set_ngc_param(5210, 1.0);
    return {};
  }
  return fail(AlarmId::kInternal, "no action for " + code_name(code), loc(cur_col));
}

// G92 in RS274NGC: the offset is also kept in #5211.. and #5210 = 1.
void Interpreter::Impl::ngc_store_g92() {
  for (int i = 0; i < axis_count; ++i) {
    const int j = ngc_axis_index(axis_letter[static_cast<std::size_t>(i)]);
    if (j >= 0) vars.set_ngc_param(5211 + j, shifts.get().g92_shift[i] / stored_mm());
  }
  vars.set_ngc_param(5210, 1.0);
}

// G28 / G30: to the stored position (#5161.. / #5181..), through the point
// of the block's axis words; without axis words every axis goes there.
Flow<void> Interpreter::Impl::ngc_reference_return(const Words& words, int g, CommandSink& out) {
  AxisVec mid;
  AxisMask moved;
  auto t = axis_targets(words, false, mid, moved);
  if (!t) return t;
  const int base = g == 28 ? 5161 : 5181;
  AxisVec ref = pos;
  for (int i = 0; i < axis_count; ++i) {
    if (!moved.empty() && !moved.has(i)) continue;
    const int j = ngc_axis_index(axis_letter[static_cast<std::size_t>(i)]);
    ref[i] = j < 0 ? pos[i] : vars.ngc_param(base + j) * stored_mm();
  }
  if (!moved.empty()) emit(out, canon::Rapid{mid, true});
  emit(out, canon::Rapid{ref, true});
  pos = ref;
  motion_since_sync = true;
  return {};
}

Flow<void> Interpreter::Impl::ngc_data_setting(const Words& words, SourceLoc where) {
  if (!words.has('L')) return fail(AlarmId::kBadValue, "G10 needs L", where);
  // grbl refuses a G10 only without both P and L; P left out is P0, the
  // active system (grbl 1.1 gcode.c, "[G10 Errors]"): sender macros write
  // `G10 L20 Z15.5`. LinuxCNC needs P.
  if (!words.has('P') && !lang->rules.g10_p_optional)
    return fail(AlarmId::kBadValue, "G10 needs P", where);
  const double lv = words.at('L').value;
  const double pv = words.has('P') ? words.at('P').value : 0.0;
  const int l = static_cast<int>(lv);
  const SourceLoc p_at = words.has('P') ? loc(words.at('P').column) : where;
  if (l == 2 || l == 20) {
    if (pv != std::trunc(pv) || pv < 0 || pv > 9) {
      return fail(AlarmId::kIllegalOffsetNumber,
                  "G10 L" + std::to_string(l) + " P" + std::to_string(pv) +
                      ": P0 (the active system) or P1-P9 (G54-G59.3)",
                  p_at);
    }
    if (words.has('R') && words.at('R').value != 0.0) {
      return fail(AlarmId::kNotSimulated,
                  "G10 L" + std::to_string(l) + " R (a rotated coordinate system) is not simulated",
                  loc(words.at('R').column));
    }
    const int set = pv == 0 ? modal.work : static_cast<int>(pv);
    // Every axis is checked before the system or #5221.. change.
    AxisVec o = work_offsets[static_cast<std::size_t>(set)];
    for (int i = 0; i < axis_count; ++i) {
      const char c = axis_letter[static_cast<std::size_t>(i)];
      if (!words.has(c)) continue;
      const double mm = word_length(words.at(c), false) * unit_mm();
      if (l == 2) {
        o[i] = mm;  // absolute in G91 too
      } else {
        // The offset that makes the present position read `mm` in system `set`.
        const double others = offset_total(i) -
                              work_offsets[static_cast<std::size_t>(modal.work)][i] -
                              work_offsets[0][i];
        o[i] = pos[i] * axis_scale[static_cast<std::size_t>(i)] - mm - others;
      }
      auto ok = check_offset(o[i], "G10 L" + std::to_string(l) + " " + c, loc(words.at(c).column));
      if (!ok) return ok;
    }
    work_offsets.write(static_cast<std::size_t>(set)) = o;
    for (int i = 0; i < axis_count; ++i) {
      const char c = axis_letter[static_cast<std::size_t>(i)];
      const int j = ngc_axis_index(c);
      if (words.has(c) && j >= 0) vars.set_ngc_param(5221 + 20 * (set - 1) + j, o[i] / stored_mm());
    }
    return {};
  }
  if (l == 1) {
    if (pv != std::trunc(pv) || pv < 1 || pv > mc.tool_offset_count) {
      return fail(AlarmId::kIllegalOffsetNumber, "G10 L1 P" + std::to_string(pv), p_at);
    }
    auto& t = tools.write(static_cast<std::size_t>(pv));
    for (const char c : {'Z', 'R'}) {
      if (!words.has(c)) continue;
      auto ok = check_offset(word_length(words.at(c), false) * unit_mm(),
                             std::string("G10 L1 ") + c, loc(words.at(c).column));
      if (!ok) return ok;
    }
    if (words.has('Z')) {
      t.length_geometry = word_length(words.at('Z'), false) * unit_mm();
      t.length_wear = 0.0;
    }
    if (words.has('R')) {
      t.radius_geometry = word_length(words.at('R'), false) * unit_mm();
      t.radius_wear = 0.0;
    }
    // The active tool's length follows the table (LinuxCNC reloads it).
    if (modal.length == LengthComp::kPlus && modal.h == static_cast<int>(pv)) {
      length_offset = t.length_geometry;
    }
    return {};
  }
  return fail(AlarmId::kNotSimulated,
              "G10 L" + std::to_string(l) + " is not simulated by skipnc (L1, L2, L20 are)",
              loc(words.at('L').column));
}

}  // namespace skipnc::interp
