// Lathe-type programming (G-code system A, docs/lathe.md): X and Z absolute,
// U and W (H for C) incremental; X in diameter with 1006#3; the spindle
// model behind feed per revolution and constant surface speed; the T code
// with geometry and wear offsets; G50 coordinate system setting and speed
// clamp. The axis-word rules apply to mills too (without U/W/H).
#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>

#include "interpreter/impl.hpp"
#include "interpreter/offset_units.hpp"

namespace skipnc::interp {
namespace {

// +0.0 to the bit (-0.0 is not: a write of +0.0 over it changes it).
bool zero_bits(double v) noexcept {
  return std::bit_cast<std::uint64_t>(v) == 0;
}

}  // namespace

char Interpreter::Impl::incremental_letter(int axis) const noexcept {
  if (!mc.lathe()) return 0;
  switch (axis_letter[static_cast<std::size_t>(axis)]) {
    case 'X':
      return 'U';
    case 'Z':
      return 'W';
    case 'C':
      return 'H';
    default:
      return 0;
  }
}

bool Interpreter::Impl::has_axis_word(const Words& words) const noexcept {
  for (int i = 0; i < axis_count; ++i) {
    if (words.has(axis_letter[static_cast<std::size_t>(i)])) return true;
    const char inc = incremental_letter(i);
    if (inc != 0 && words.has(inc)) return true;
  }
  return false;
}

// X and U (Z and W) in one block: refused rather than guessed, for the
// first axis (in the machine's order) that has both.
Flow<void> Interpreter::Impl::lathe_axis_words(const Words& words) const {
  for (int i = 0; i < axis_count; ++i) {
    const char c = axis_letter[static_cast<std::size_t>(i)];
    const char inc = incremental_letter(i);
    if (inc == 0 || !words.has(c) || !words.has(inc)) continue;
    const WordVal& later = words.at(c).column > words.at(inc).column ? words.at(c) : words.at(inc);
    return fail(
        AlarmId::kWordRepeated,
        std::string(1, c) + " and " + inc + " in one block: the same axis absolute and incremental",
        loc(later.column));
  }
  return {};
}

// One axis word's target, machine coordinates; `inc_word`: U W H.
[[gnu::always_inline]] inline void Interpreter::Impl::axis_target(int i, const WordVal& w,
                                                                  bool inc_word, bool g53,
                                                                  AxisVec& target) {
  const double scale = axis_scale[static_cast<std::size_t>(i)];
  const bool incremental = inc_word || modal.distance == Distance::kIncremental;
  const double v = word_length(w);
  if (g53 && !incremental) {
    target[i] = v * unit_mm() / scale;
  } else if (!incremental) {
    target[i] = machine_of(i, v);
  } else {
    // G45-G48 (ncblock.cpp) lengthen or shorten an incremental move; a T
    // offset changed since the axis last moved is moved with it.
    target[i] = pos[i] + v * unit_mm() / scale + shifts.get().g45_delta[i] +
                shifts.get().tool_offset_pending[i];
  }
  if (!zero_bits(shifts.get().tool_offset_pending[i])) {
    shifts.write().tool_offset_pending[i] = 0.0;
  }
}

// A mill's axis words of `letters` (an axis word is its axis's letter), one
// by one.
void Interpreter::Impl::mill_axis_words(const Words& words, std::uint32_t letters, bool g53,
                                        AxisVec& target, AxisMask& moved) {
  for (std::uint32_t rest = letters; rest != 0; rest &= rest - 1) {
    const int letter = std::countr_zero(rest);
    const int i = axis_of_letter[static_cast<std::size_t>(letter)];
    axis_target(i, words.at(static_cast<char>('A' + letter)), false, g53, target);
    moved.set(i);
  }
}

Flow<void> Interpreter::Impl::axis_targets(const Words& words, bool g53, AxisVec& target,
                                           AxisMask& moved) {
  target = pos;
  // G16, G68, G51, G51.1 (mill_codes.cpp) place X, Y and Z.
  const bool framed = !g53 && !mc.lathe() && frame_active();
  if (framed) {
    auto f = frame_targets(words, target, moved);
    if (!f) return f;
  }
  if (mc.lathe()) {
    SKIPNC_TRY(lathe_axis_words(words));
    for (int i = 0; i < axis_count; ++i) {
      const char c = axis_letter[static_cast<std::size_t>(i)];
      const char inc = incremental_letter(i);
      const bool has_inc = inc != 0 && words.has(inc);
      if (!has_inc && !words.has(c)) continue;
      axis_target(i, words.at(has_inc ? inc : c), has_inc, g53, target);
      moved.set(i);
    }
  } else {
    constexpr std::uint32_t kXyz = 1u << ('X' - 'A') | 1u << ('Y' - 'A') | 1u << ('Z' - 'A');
    mill_axis_words(words, words.letters & axis_letters & (framed ? ~kXyz : ~0u), g53, target,
                    moved);
  }
  // Written only when it is not already all +0.0: a write copies the shifts
  // for the block's undo (BlockSaved), and nearly every block has none.
  if (!AxisShifts::plus_zero(shifts.get().g45_delta)) shifts.write().g45_delta = AxisVec{};
  return {};
}

// Spindle speed at a machine position: the programmed S in G97; in G96 the
// speed that gives the surface speed S at the diameter of the work's X
// there, limited by the G50 clamp. Always limited by the machine's maximum.
double Interpreter::Impl::spindle_rpm_at(const AxisVec& machine) const noexcept {
  if (modal.spindle_dir == 0 || modal.spindle <= 0.0) return 0.0;
  double rpm = modal.spindle;
  if (modal.spindle_mode == SpindleMode::kSurfaceSpeed) {
    const int x = axis_of_letter['X' - 'A'];
    const double program_x = x >= 0 ? std::fabs(work_of(x, machine[x])) : 0.0;
    const double diameter_mm =
        program_x * unit_mm() *
        (x >= 0 && axis_scale[static_cast<std::size_t>(x)] == 2.0 ? 1.0 : 2.0);
    const double surface_mm_per_min =
        modal.spindle * (modal.units == Units::kInch ? 304.8 : 1000.0);
    rpm = diameter_mm > 0.0 ? surface_mm_per_min / (std::numbers::pi * diameter_mm)
                            : mc.spindle_max_rpm;
    if (modal.spindle_clamp_rpm > 0.0) rpm = std::min(rpm, modal.spindle_clamp_rpm);
  }
  return std::min(rpm, mc.spindle_max_rpm);
}

double Interpreter::Impl::feed_to_mm_per_min(double f) const noexcept {
  const double per_unit = f * unit_mm();
  if (modal.feed_mode != FeedMode::kPerRev) return per_unit;
  return per_unit * spindle_rpm_at(pos);
}

Flow<void> Interpreter::Impl::need_spindle_for_feed(std::uint32_t column) const {
  if (modal.feed_mode == FeedMode::kPerRev && spindle_rpm_at(pos) <= 0.0) {
    // A Fanuc control waits for the spindle; a program that would hang is
    // stopped with an alarm instead.
    return fail(AlarmId::kFeedPerRevNoSpindle,
                std::string("feed per revolution (") + (modal.lathe ? "G99" : "G95") +
                    ") with the spindle stopped (S0 or M05)",
                loc(column));
  }
  return {};
}

// T code of a lathe: the upper digits select the tool and its geometry
// offset, the lower two digits the wear offset (T0101; T0100: no wear
// offset; T0: none). The offsets shift the coordinate system: the next
// absolute move takes the tool tip to the programmed point, an incremental
// move carries the change with it.
Flow<void> Interpreter::Impl::lathe_tool(const Words& words, ModalState& next) {
  const WordVal& t = words.at('T');
  if (t.value != std::trunc(t.value) || t.value < 0 || t.value > 99999999) {
    return fail(AlarmId::kIllegalOffsetNumber, "T" + fmt::format("{}", t.value), loc(t.column));
  }
  const auto code = static_cast<int>(t.value);
  const int tool = code / 100;
  const int wear = code % 100;
  if (tool > mc.tool_offset_count || wear > mc.tool_offset_count) {
    return fail(AlarmId::kIllegalOffsetNumber,
                "T" + std::to_string(code) + ": offset numbers are 0-" +
                    std::to_string(mc.tool_offset_count),
                loc(t.column));
  }
  next.tool = code;
  lathe_state.set_wear_offset(wear);
  const auto& g = tools[static_cast<std::size_t>(tool)];
  const auto& w = tools[static_cast<std::size_t>(wear)];
  AxisVec off;
  const double per = offset_unit_mm(*this);
  if (const int x = mc.axis_index('X'); x >= 0) {
    off[x] = ((tool != 0 ? g.x_geometry : 0.0) + (wear != 0 ? w.x_wear : 0.0)) * per;
  }
  if (const int z = mc.axis_index('Z'); z >= 0) {
    off[z] = ((tool != 0 ? g.z_geometry : 0.0) + (wear != 0 ? w.z_wear : 0.0)) * per;
  }
  AxisShifts& s = shifts.write();
  for (int i = 0; i < axis_count; ++i) {
    s.tool_offset_pending[i] +=
        (off[i] - s.lathe_tool_offset[i]) / axis_scale[static_cast<std::size_t>(i)];
  }
  s.lathe_tool_offset = off;
  return {};
}

// G50 X Z (U W): the present position gets these program values (U W: the
// present values plus these). The S word of the block is the speed clamp
// (ncblock.cpp).
Flow<void> Interpreter::Impl::lathe_coordinate_setting(const Words& words) {
  for (int i = 0; i < axis_count; ++i) {
    const char c = axis_letter[static_cast<std::size_t>(i)];
    const char inc = incremental_letter(i);
    const bool has_abs = words.has(c);
    const bool has_inc = inc != 0 && words.has(inc);
    if (has_abs && has_inc) {
      return fail(AlarmId::kWordRepeated, std::string(1, c) + " and " + inc + " in one G50 block",
                  loc(words.at(inc).column));
    }
    if (!has_abs && !has_inc) continue;
    const double now = work_of(i, pos[i]) * unit_mm();
    const double v = word_length(words.at(has_inc ? inc : c)) * unit_mm();
    const double want = has_inc ? now + v : v;
    auto ok = check_offset(shifts.get().g92_shift[i] + now - want, std::string("G50 ") + c,
                           loc(words.at(has_inc ? inc : c).column));
    if (!ok) return ok;
    shifts.write().g92_shift[i] += now - want;
  }
  return {};
}

void Interpreter::Impl::emit_spindle(CommandSink& out) {
  canon::Spindle s;
  s.direction = modal.spindle_dir;
  s.rpm = modal.spindle_dir == 0 ? modal.spindle : spindle_rpm_at(pos);
  if (modal.spindle_mode == SpindleMode::kSurfaceSpeed) {
    s.rpm = spindle_rpm_at(pos);
    s.surface_speed = modal.spindle;
    s.max_rpm = modal.spindle_clamp_rpm;
  }
  emit(out, s);
}

// G90 X(U) Z(W) [R] F: the outer-diameter cutting cycle of system A. From
// the start point: (1) rapid in X to the cut's start (the end X, plus R in
// radius for a taper), (2) feed to the end point, (3) feed in X back to the
// start X, (4) rapid in Z back to the start point. Modal: a later block with
// only X (U) cuts the next pass to the same Z.
Flow<void> Interpreter::Impl::turning_cycle(const Words& words, AxisVec& target, AxisMask moved,
                                            CommandSink& out) {
  const int x = axis_of_letter['X' - 'A'];
  const int z = axis_of_letter['Z' - 'A'];
  const SourceLoc at = loc(cur_col);
  if (!moved.has(z)) {
    const std::optional<double> cycle_z = lathe_state.cycle_z();
    if (!cycle_z) {
      return fail(AlarmId::kBadValue, "G90 needs Z or W (the end of the cut) in its first block",
                  at);
    }
    target[z] = *cycle_z;
  }
  const double feed = feed_mm_per_min();
  if (feed <= 0.0) return fail(AlarmId::kNoFeed, "G90 without a feed (F)", at);
  const double taper = words.has('R') ? word_length(words.at('R')) * unit_mm() : 0.0;
  const AxisVec start = pos;
  AxisVec p = start;
  p[x] = target[x] + taper;
  emit(out, canon::Rapid{p, block_params.linear_rapid});
  p = target;
  emit(out, canon::Feed{p, feed, false});
  p[x] = start[x];
  emit(out, canon::Feed{p, feed, false});
  emit(out, canon::Rapid{start, block_params.linear_rapid});
  lathe_state.set_cycle_z(target[z]);
  target = start;
  return {};
}

// G10 P X(U) Z(W) R Q on a lathe: P1-P99 a wear offset, P10001-P10099
// (10000 + n) a geometry offset; X Z R set the value, U W add to it (X and U
// in diameter with 1006#3), Q is the imaginary tip. The active offset
// changes at the next T code.
Flow<void> Interpreter::Impl::lathe_offset_setting(const Words& words, SourceLoc where) {
  if (!words.has('P')) return fail(AlarmId::kBadValue, "G10 needs P (offset number)", where);
  const WordVal& pw = words.at('P');
  const bool geometry = pw.value > 10000;
  const double n = geometry ? pw.value - 10000 : pw.value;
  if (pw.value != std::trunc(pw.value) || n < 1 || n > mc.tool_offset_count) {
    return fail(AlarmId::kIllegalOffsetNumber,
                "G10 P" + fmt::format("{}", pw.value) + ": wear offsets are P1-P" +
                    std::to_string(mc.tool_offset_count) + ", geometry offsets P10001-P" +
                    std::to_string(10000 + mc.tool_offset_count),
                loc(pw.column));
  }
  auto& t = tools.write(static_cast<std::size_t>(n));
  struct Field {
    char set, add;
    double* value;
  };
  const Field fields[] = {
      {'X', 'U', geometry ? &t.x_geometry : &t.x_wear},
      {'Z', 'W', geometry ? &t.z_geometry : &t.z_wear},
      {'R', 0, geometry ? &t.radius_geometry : &t.radius_wear},
  };
  for (const Field& f : fields) {
    if (f.add != 0 && words.has(f.set) && words.has(f.add)) {
      return fail(AlarmId::kWordRepeated,
                  std::string(1, f.set) + " and " + f.add + " in one G10 block",
                  loc(words.at(f.add).column));
    }
    const double per = unit_mm() / offset_unit_mm(*this);  // stored numbers (offset_units.hpp)
    if (words.has(f.set)) *f.value = word_length(words.at(f.set)) * per;
    if (f.add != 0 && words.has(f.add)) *f.value += word_length(words.at(f.add)) * per;
  }
  if (words.has('Q')) {
    const WordVal& q = words.at('Q');
    if (q.value != std::trunc(q.value) || q.value < 0 || q.value > 9) {
      return fail(AlarmId::kBadValue, "G10 Q" + fmt::format("{}", q.value) + ": the tip is 0-9",
                  loc(q.column));
    }
    t.tip = static_cast<int>(q.value);
  }
  return {};
}

}  // namespace skipnc::interp
