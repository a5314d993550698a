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

namespace {

using Impl = Interpreter::Impl;

// G10 L2 / L20 Pn: work offset n, always absolute (L2) or such that the
// present position reads the words given (L20).
Flow<void> work_offset_setting(Impl& im, const Words& words, int l, double pv, SourceLoc p_at) {
  if (pv != std::trunc(pv) || pv < 0 || pv > 9) {
    return fail(AlarmId::kIllegalOffsetNumber,
                "G10 L" + std::to_string(l) + " P" + std::to_string(pv) +
                    ": P0 (the active system) or P1-P9 (G54-G59.3)",
                p_at);
  }
  if (words.has('R') && words.at('R').value != 0.0) {
    return fail(AlarmId::kNotSimulated,
                "G10 L" + std::to_string(l) + " R (a rotated coordinate system) is not simulated",
                im.loc(words.at('R').column));
  }
  const int set = pv == 0 ? im.modal.work : static_cast<int>(pv);
  // Every axis is checked before the system or #5221.. change.
  AxisVec o = im.work_offsets[static_cast<std::size_t>(set)];
  for (int i = 0; i < im.axis_count; ++i) {
    const char c = im.axis_letter[static_cast<std::size_t>(i)];
    if (!words.has(c)) continue;
    const double mm = im.word_length(words.at(c)) * im.unit_mm();
    if (l == 2) {
      o[i] = mm;  // absolute in G91 too
    } else {
      // The offset that makes the present position read `mm` in system `set`.
      const double others = im.offset_total(i) -
                            im.work_offsets[static_cast<std::size_t>(im.modal.work)][i] -
                            im.work_offsets[0][i];
      o[i] = im.pos[i] * im.axis_scale[static_cast<std::size_t>(i)] - mm - others;
    }
    auto ok =
        im.check_offset(o[i], "G10 L" + std::to_string(l) + " " + c, im.loc(words.at(c).column));
    if (!ok) return ok;
  }
  im.work_offsets.write(static_cast<std::size_t>(set)) = o;
  for (int i = 0; i < im.axis_count; ++i) {
    const char c = im.axis_letter[static_cast<std::size_t>(i)];
    const int j = ngc_axis_index(c);
    if (words.has(c) && j >= 0)
      im.vars.set_ngc_param(5221 + 20 * (set - 1) + j, o[i] / im.stored_mm());
  }
  return {};
}

// G10 L1 Pn: tool n's length (Z) and radius (R), wear cleared.
Flow<void> tool_setting(Impl& im, const Words& words, double pv, SourceLoc p_at) {
  if (pv != std::trunc(pv) || pv < 1 || pv > im.mc.tool_offset_count) {
    return fail(AlarmId::kIllegalOffsetNumber, "G10 L1 P" + std::to_string(pv), p_at);
  }
  auto& t = im.tools.write(static_cast<std::size_t>(pv));
  for (const char c : {'Z', 'R'}) {
    if (!words.has(c)) continue;
    auto ok = im.check_offset(im.word_length(words.at(c)) * im.unit_mm(),
                              std::string("G10 L1 ") + c, im.loc(words.at(c).column));
    if (!ok) return ok;
  }
  if (words.has('Z')) {
    t.length_geometry = im.word_length(words.at('Z')) * im.unit_mm();
    t.length_wear = 0.0;
  }
  if (words.has('R')) {
    t.radius_geometry = im.word_length(words.at('R')) * im.unit_mm();
    t.radius_wear = 0.0;
  }
  // The active tool's length follows the table (LinuxCNC reloads it).
  if (im.modal.length == LengthComp::kPlus && im.modal.h == static_cast<int>(pv)) {
    im.length_offset = t.length_geometry;
  }
  return {};
}

}  // namespace

Flow<void> LinuxcncFamily::own_action(Impl& im, const Words& words, GCode code) {
  auto axis_param = [&](int base, int i) {
    const char c = im.axis_letter[static_cast<std::size_t>(i)];
    const int j = ngc_axis_index(c);
    return j < 0 ? -1 : base + j;
  };
  if (code == GCode(28, 1) || code == GCode(30, 1)) {
    const int base = code == GCode(28, 1) ? 5161 : 5181;
    for (int i = 0; i < im.axis_count; ++i) {
      const int n = axis_param(base, i);
      if (n > 0) im.vars.set_ngc_param(n, im.pos[i] / im.stored_mm());
    }
    return {};
  }
  if (code == GCode(43, 1)) {
    if (!words.has('Z') || im.length_axis < 0) {
      return fail(AlarmId::kBadValue, "G43.1 needs Z, the tool length", im.loc(im.cur_col));
    }
    const double z = im.word_length(words.at('Z')) * im.unit_mm();
    if (auto ok = im.check_offset(z, "G43.1 Z", im.loc(words.at('Z').column)); !ok) return ok;
    im.length_offset = z;
    im.modal.length = LengthComp::kPlus;
    im.modal.h = 0;
    return {};
  }
  if (code == GCode(92, 1) || code == GCode(92, 2)) {
    const bool clear = code == GCode(92, 1);
    for (int i = 0; i < im.axis_count; ++i) {
      im.shifts.write().g92_shift[i] = 0.0;
      const int n = axis_param(5211, i);
      if (clear && n > 0) im.vars.set_ngc_param(n, 0.0);
    }
    if (clear) im.vars.set_ngc_param(5210, 0.0);
    return {};
  }
  if (code == GCode(92, 3)) {
    for (int i = 0; i < im.axis_count; ++i) {
      const int n = axis_param(5211, i);
      im.shifts.write().g92_shift[i] = n > 0 ? im.vars.ngc_param(n) * im.stored_mm() : 0.0;
    }
    im.vars.set_ngc_param(5210, 1.0);
    return {};
  }
  return fail(AlarmId::kInternal, "no action for " + code_name(code), im.loc(im.cur_col));
}

// G92 in RS274NGC: the offset is also kept in #5211.. and #5210 = 1.
void LinuxcncFamily::store_g92(Impl& im) {
  for (int i = 0; i < im.axis_count; ++i) {
    const int j = ngc_axis_index(im.axis_letter[static_cast<std::size_t>(i)]);
    if (j >= 0) im.vars.set_ngc_param(5211 + j, im.shifts.get().g92_shift[i] / im.stored_mm());
  }
  im.vars.set_ngc_param(5210, 1.0);
}

// G28 / G30: to the stored position (#5161.. / #5181..), through the point
// of the block's axis words; without axis words every axis goes there.
Flow<void> LinuxcncFamily::reference_return(Impl& im, const Words& words, int g, CommandSink& out) {
  AxisVec mid;
  AxisMask moved;
  auto t = im.axis_targets(words, false, mid, moved);
  if (!t) return t;
  const int base = g == 28 ? 5161 : 5181;
  AxisVec ref = im.pos;
  for (int i = 0; i < im.axis_count; ++i) {
    if (!moved.empty() && !moved.has(i)) continue;
    const int j = ngc_axis_index(im.axis_letter[static_cast<std::size_t>(i)]);
    ref[i] = j < 0 ? im.pos[i] : im.vars.ngc_param(base + j) * im.stored_mm();
  }
  if (!moved.empty()) im.emit(out, canon::Rapid{mid, true});
  im.emit(out, canon::Rapid{ref, true});
  im.pos = ref;
  im.motion_since_sync = true;
  return {};
}

Flow<void> LinuxcncFamily::data_setting(Impl& im, const Words& words, SourceLoc where) {
  if (!words.has('L')) return fail(AlarmId::kBadValue, "G10 needs L", where);
  // grbl refuses a G10 only without both P and L; P left out is P0, the
  // active system (grbl 1.1 gcode.c, "[G10 Errors]"): sender macros write
  // `G10 L20 Z15.5`. LinuxCNC needs P.
  if (!words.has('P') && !rules.g10_p_optional)
    return fail(AlarmId::kBadValue, "G10 needs P", where);
  const double lv = words.at('L').value;
  const double pv = words.has('P') ? words.at('P').value : 0.0;
  const int l = static_cast<int>(lv);
  const SourceLoc p_at = words.has('P') ? im.loc(words.at('P').column) : where;
  if (l == 2 || l == 20) return work_offset_setting(im, words, l, pv, p_at);
  if (l == 1) return tool_setting(im, words, pv, p_at);
  return fail(AlarmId::kNotSimulated,
              "G10 L" + std::to_string(l) + " is not simulated by skipnc (L1, L2, L20 are)",
              im.loc(words.at('L').column));
}

}  // namespace skipnc::interp
