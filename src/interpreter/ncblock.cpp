// Address words and the block executor. A block runs in two stages:
//   plan    (plan_block) reads the words, finds every G code in the code
//           table (codes.cpp), checks groups, addresses and values, and
//           builds the block's modal state in a BlockPlan; nothing of the
//           interpreter changes;
//   commit  (commit_block) applies the plan in the control's order, one
//           function per step, emitting into the block's buffer.
// A block that raises an alarm in either stage emits nothing and leaves
// the interpreter as it was (execute_nc: undo record + buffer).
//
// Order of execution inside one block (Fanuc; cf. LinuxCNC convert_g):
//   1. sequence number, (MSG, ...) messages
//   2. G65 / G66 macro call (every other word is an argument)
//   3. F, S, T, D and the modal groups (units, plane, distance, ...)
//   4. tool length offset (group 08); lathe T offset
//   5. spindle M03/M04/M05
//   6. one-shot action: G10 data setting, G50/G92 coordinate setting, G52,
//      G04 dwell, G28/G30 reference return
//   7. motion (group 01, G31 skip, G45-G48)
//   8. other M codes (M00 M01 M02 M30 M98 M99, machine M codes)
//   9. G66 modal macro after a block that moved
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "interpreter/codes.hpp"
#include "interpreter/impl.hpp"
#include "interpreter/offset_units.hpp"

namespace skipnc::interp {
namespace {

// G codes that G-code system A (a lathe) gives another meaning or does not
// have, with what to write instead. The turning cycles are not modelled.
const char* lathe_refusal(int code) {
  switch (code) {
    case 910:
      return " is not a code of G-code system A: U and W are the incremental X and Z";
    case 920:
      return " is the thread cutting cycle in G-code system A (not supported); G50 sets the "
             "coordinate system";
    case 940:
      return " is the end-face cutting cycle in G-code system A (not supported); G98 is feed per "
             "minute";
    case 950:
      return " is not a code of G-code system A: G99 is feed per revolution";
    case 430:
    case 440:
    case 490:
      return " is not a code of a lathe: the T code offsets the tool";
    case 450:
    case 460:
    case 470:
    case 480:
      return " is not a code of a lathe";
    default:
      return nullptr;
  }
}

std::string g_name(int code) {
  return "G" + std::to_string(code / 10) + (code % 10 ? "." + std::to_string(code % 10) : "");
}

}  // namespace

double Interpreter::Impl::word_length(const WordVal& w, bool rotary) const noexcept {
  (void)rotary;
  if (w.is_expr || w.has_point || params.bit(config::param::kCalculatorDecimal)) return w.value;
  // Without a decimal point a length is in least input increments.
  const double increment = modal.units == Units::kInch ? 0.0001 : 0.001;
  return w.value * increment;
}

double Interpreter::Impl::offset_total(int axis) const noexcept {
  double o = (work_offsets[0][axis] + work_offsets[static_cast<std::size_t>(modal.work)][axis]) *
                 offset_unit_mm(*this) +
             local_shift[axis] + g92_shift[axis] + tool_pos_offset[axis] + lathe_tool_offset[axis];
  if (axis == length_axis) o += length_offset;
  return o;
}

double Interpreter::Impl::work_of(int axis, double machine_mm) const noexcept {
  return (machine_mm * axis_scale[static_cast<std::size_t>(axis)] - offset_total(axis)) / unit_mm();
}

double Interpreter::Impl::tool_offset_total(int axis) const noexcept {
  double o = tool_pos_offset[axis] + lathe_tool_offset[axis];
  if (axis == length_axis) o += length_offset;
  return o;
}

double Interpreter::Impl::position_var(int axis, double machine_mm,
                                       bool tool_offsets) const noexcept {
  const double w = work_of(axis, machine_mm);
  return tool_offsets ? w + tool_offset_total(axis) / unit_mm() : w;
}

double Interpreter::Impl::machine_of(int axis, double work_units) const noexcept {
  return (work_units * unit_mm() + offset_total(axis)) / axis_scale[static_cast<std::size_t>(axis)];
}

// Evaluates the words of an NC block. In a G65/G66 block every address but
// G, P and L is a macro argument (see collect_argument); elsewhere an
// address may appear once.
Flow<void> Interpreter::Impl::collect_words(Words& words) {
  call_block = false;
  for (const gcode::Word& w : blk.words) {
    if (w.letter == 'G' && !w.is_expr && (w.value == 65.0 || w.value == 66.0)) {
      call_block = true;
      call_args.fill(Value::null());
      break;
    }
  }
  int ijk_set = -1, ijk_last = -1;
  for (const gcode::Word& w : blk.words) {
    WordVal v;
    v.column = w.column;
    v.has_point = w.has_point;
    v.is_expr = w.is_expr;
    if (w.is_expr) {
      // ROUND in an address rounds to the address's least input increment
      // (lengths: 0.001 mm, 0.0001 inch); elsewhere to a whole number.
      const bool length = axis_of_letter[static_cast<std::size_t>(w.letter - 'A')] >= 0 ||
                          (mc.lathe() && (w.letter == 'U' || w.letter == 'W')) || w.letter == 'I' ||
                          w.letter == 'J' || w.letter == 'K' || w.letter == 'R' || w.letter == 'Q';
      const double word_inc = modal.units == Units::kInch ? 0.0001 : 0.001;
      word_round_increment = length ? word_inc : 0.0;
      auto e = eval(w.expr);
      word_round_increment = 0.0;
      SKIPNC_TRY(e);
      if (e->vacant) continue;  // a vacant variable in a word: the word is omitted
      if (!std::isfinite(e->v)) {
        return fail(AlarmId::kOverflow, std::string("value of ") + w.letter + " is not finite",
                    loc(w.column));
      }
      v.value = e->v;
      // A computed length is rounded to the address's least input increment,
      // as the control does (#1 = 12.3456, X#1 -> X12.346); macro arguments
      // keep their value.
      if (length && !call_block && lang->rules.round_computed_words) {
        v.value = std::round(v.value / word_inc) * word_inc + 0.0;
      }
    } else {
      v.value = w.value;
    }
    if (call_block && w.letter != 'G' && w.letter != 'P' && w.letter != 'L') {
      auto a = collect_argument(w, v, ijk_set, ijk_last);
      if (!a) return a;
      continue;
    }
    if (w.letter == 'G') {
      if (words.g_count == static_cast<int>(words.g.size())) {
        return fail(AlarmId::kGCodeConflict, "too many G codes in one block", loc(w.column));
      }
      const double code10 = std::round(v.value * 10.0);
      if (std::fabs(v.value * 10.0 - code10) > 1e-6 || code10 < 0 || code10 > 9999) {
        return fail(AlarmId::kUnknownGCode, "G" + fmt::format("{}", v.value), loc(w.column));
      }
      words.g[static_cast<std::size_t>(words.g_count)] = static_cast<int>(code10);
      words.g_col[static_cast<std::size_t>(words.g_count++)] = w.column;
      continue;
    }
    if (w.letter == 'M') {
      if (words.m_count == 3) {
        return fail(AlarmId::kTooManyMCodes, "more than 3 M codes in one block", loc(w.column));
      }
      // A value in brackets is rounded (M[3.5] is M4); a literal must be whole.
      const double m = w.is_expr ? std::round(v.value) : v.value;
      if (m != std::trunc(m) || m < 0 || m > 99999999) {
        return fail(AlarmId::kUnknownMCode, "M" + fmt::format("{}", v.value), loc(w.column));
      }
      words.m[static_cast<std::size_t>(words.m_count++)] = static_cast<int>(m);
      continue;
    }
    auto& slot = words.slot(w.letter);
    if (slot) {
      return fail(AlarmId::kWordRepeated,
                  std::string("address ") + w.letter + " twice in one block", loc(w.column));
    }
    slot = v;
    words.letters |= 1u << (w.letter - 'A');
  }
  return {};
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
      const double v = word_length(words.at(c), false) * unit_mm() / offset_unit_mm(*this);
      o[i] = inc ? o[i] + v : v;
      auto ok = check_offset(o[i] * offset_unit_mm(*this), std::string("G10 ") + c,
                             loc(words.at(c).column));
      if (!ok) return ok;
    }
    work_offsets[static_cast<std::size_t>(set)] = o;
    return {};
  }
  if (l == 1 || (l >= 10 && l <= 13)) {
    if (pv != std::trunc(pv) || pv < 1 || pv > mc.tool_offset_count) {
      return fail(AlarmId::kIllegalOffsetNumber, fmt::format("G10 P{}", pv),
                  loc(words.at('P').column));
    }
    if (!words.has('R'))
      return fail(AlarmId::kBadValue, "G10 L" + std::to_string(l) + " needs R", where);
    auto& t = tools[static_cast<std::size_t>(pv)];
    double* f = l == 10             ? &t.length_geometry
                : l == 11 || l == 1 ? &t.length_wear
                : l == 12           ? &t.radius_geometry
                                    : &t.radius_wear;
    const double v = word_length(words.at('R'), false) * unit_mm() / offset_unit_mm(*this);
    auto ok = check_offset((inc ? *f + v : v) * offset_unit_mm(*this), "G10 R",
                           loc(words.at('R').column));
    if (!ok) return ok;
    *f = inc ? *f + v : v;
    return {};
  }
  return fail(AlarmId::kBadValue, "G10 L" + std::to_string(l) + " is not supported", where);
}

// ---------------------------------------------------------------------------
// Plan: nothing of the interpreter changes here.

// Finds each G word in the code table, puts it in its group's slot and
// takes the group-00 action. Two codes of one modal group: the dialect's
// alarm, or the last one wins where the control says so
// (g_same_group_last_wins). Two group-00 actions (G04 G31, G31 G28,
// G31 G92) are always refused: the block could do only one of them.
Flow<void> Interpreter::Impl::plan_g_codes(const Words& words, BlockPlan& plan) {
  const bool lathe = mc.lathe();
  for (int i = 0; i < words.g_count; ++i) {
    const int code = words.g[static_cast<std::size_t>(i)];
    const std::uint32_t col = words.g_col[static_cast<std::size_t>(i)];
    const SourceLoc at = loc(col);
    if (std::find(dialect.absent_g.begin(), dialect.absent_g.end(), code) !=
        dialect.absent_g.end()) {
      return fail(AlarmId::kUnknownGCode, g_name(code) + " is not a code of this control", at);
    }
    if (std::find(dialect.not_simulated_g.begin(), dialect.not_simulated_g.end(), code) !=
        dialect.not_simulated_g.end()) {
      return fail(AlarmId::kNotSimulated,
                  g_name(code) + " is a code of this control that skipnc does not simulate", at);
    }
    const CodeDef* def = find_g(code, lathe);
    if (def == nullptr) {
      auto mill = mill_code(code, at, plan.mill);  // mill_codes.cpp
      SKIPNC_TRY(mill);
      if (*mill) continue;
      if (lathe) {
        if (const char* why = lathe_refusal(code))
          return fail(AlarmId::kUnknownGCode, g_name(code) + why, at);
      } else if (find_g(code, true) != nullptr) {
        return fail(AlarmId::kUnknownGCode,
                    g_name(code) + " is a code of the lathe (G-code system A) only", at);
      }
      return fail(AlarmId::kUnknownGCode, g_name(code), at);
    }
    if ((def->avail & kG38Dialect) != 0 && !dialect.sw.probe_g38) {
      // Named as itself: G38.x is the straight probe, G92.1 and its kin
      // are the codes of the G38 controls they are (their summary).
      const bool probe = code >= 382 && code <= 385;
      return fail(AlarmId::kUnknownGCode,
                  g_name(code) + " (" + (probe ? std::string("straight probe") : def->summary) +
                      ") is not a code of this control" + (probe ? "; it probes with G31" : ""),
                  at);
    }
    if (code == 310 && !dialect.sw.skip_g31) {
      return fail(AlarmId::kUnknownGCode,
                  g_name(code) +
                      " (skip function) is not a code of this control; it probes with "
                      "G38.2-G38.5",
                  at);
    }
    if ((def->avail & kToolPosOffsetDialect) != 0 && !dialect.sw.tool_position_offset) {
      return fail(AlarmId::kUnknownGCode,
                  g_name(code) + " (tool position offset) is not a code of this control", at);
    }
    if (def->group == Group::k00) {
      auto r = plan_one_shot(*def, col, plan);
      if (!r) return r;
      continue;
    }
    const auto g = static_cast<std::size_t>(def->group);
    if (plan.group[g] != nullptr && plan.group[g]->code != code &&
        !dialect.sw.g_same_group_last_wins) {
      return fail(AlarmId::kGCodeConflict,
                  g_name(plan.group[g]->code) + " and " + g_name(code) + " are both of group " +
                      std::to_string(static_cast<int>(def->group)),
                  at);
    }
    plan.group[g] = def;
    plan.column[g] = col;
  }
  return {};
}

Flow<void> Interpreter::Impl::plan_one_shot(const CodeDef& def, std::uint32_t col,
                                            BlockPlan& plan) {
  switch (def.action) {
    case Action::kExactStop:
      plan.exact_stop = true;
      return {};
    case Action::kMachineCoord:
      plan.machine_coord = true;
      return {};
    default:
      break;
  }
  if (plan.action != Action::kNone && plan.action_code != def.code) {
    return fail(AlarmId::kGCodeConflict,
                g_name(plan.action_code) + " and " + g_name(def.code) +
                    " are both one-shot (group 00) commands",
                loc(col));
  }
  plan.action = def.action;
  plan.action_code = def.code;
  if (def.action == Action::kToolPosOffset) plan.tool_pos_offset = def.code / 10;
  return {};
}

// G65/G66 block: G, P and L are its own words, every other one an argument.
Flow<void> Interpreter::Impl::plan_call(const Words& words, BlockPlan& plan) {
  const SourceLoc at = loc(cur_col);
  if (!call_block) {
    return fail(AlarmId::kMacroFormat, "G65/G66 must be written as a number (G65, not G#i)", at);
  }
  for (int i = 0; i < words.g_count; ++i) {
    const int code = words.g[static_cast<std::size_t>(i)];
    if (code != 650 && code != 660) {
      return fail(AlarmId::kIllegalArgumentAddress,
                  g_name(code) + " in a G65/G66 block: G cannot be an argument",
                  loc(words.g_col[static_cast<std::size_t>(i)]));
    }
  }
  const bool g65 = plan.action == Action::kMacroCall;
  if (!words.has('P')) {
    return fail(AlarmId::kProgramNotFound,
                g65 ? "G65 needs P (program number)" : "G66 needs P (program number)", at);
  }
  const double p = words.at('P').value;
  const double l = words.has('L') ? words.at('L').value : 1.0;
  if (p != std::trunc(p) || p < 1 || p > 99999999) {
    return fail(AlarmId::kProgramNotFound, "P" + std::to_string(p) + " is not a program number",
                loc(words.at('P').column));
  }
  if (l != std::trunc(l) || l < 0 || l > 9999) {
    return fail(AlarmId::kBadValue, "L" + std::to_string(l) + ": repetitions are 0-9999",
                loc(words.at('L').column));
  }
  plan.call_program = static_cast<std::int64_t>(p);
  plan.call_repeats = static_cast<int>(l);
  return {};
}

// Addresses that mean nothing here are refused, so a typo is not ignored.
Flow<void> Interpreter::Impl::plan_addresses(const Words& words) const {
  for (std::uint32_t rest = words.letters & ~axis_letters; rest != 0; rest &= rest - 1) {
    const char letter = static_cast<char>('A' + std::countr_zero(rest));
    if (mc.lathe() && (letter == 'U' || letter == 'W')) continue;
    if (mc.lathe() && letter == 'H' && axis_of_letter['C' - 'A'] < 0) {
      // H is the incremental C of system A; a lathe has no tool length offset.
      return fail(AlarmId::kIllegalAddress, "address H (incremental C) on a lathe without a C axis",
                  loc(words.at(letter).column));
    }
    if (letter == 'E' && lang->rules.e_word_for_m67_only) {
      // RS274NGC reads E only for G70, G76, M66, M67 and M68; of those skipnc
      // passes on M67/M68. `G1 X1e-05` is X1 and an E word: refused, as
      // LinuxCNC 2.9's rs274 refuses it (measured, tests/rs274).
      if (has_m(words, 67) || has_m(words, 68)) continue;
      return fail(AlarmId::kIllegalAddress, "E word with no G70, G76, M66, M67 or M68 to use it",
                  loc(words.at(letter).column));
    }
    // grbl 1.1 reads F I J K L N P R S T and the axes; any other letter is
    // error:20 (gcode.c, "Non-Command Words"): no D, E, H or Q.
    const std::string_view known = lang->rules.addresses;
    if (known.find(letter) != std::string_view::npos) continue;
    return fail(AlarmId::kIllegalAddress,
                std::string("address ") + letter + " is not an address of this " +
                    lang->rules.address_owner,
                loc(words.at(letter).column));
  }
  return {};
}

bool Interpreter::Impl::has_m(const Words& words, int code) {
  for (int i = 0; i < words.m_count; ++i) {
    if (words.m[static_cast<std::size_t>(i)] == code) return true;
  }
  return false;
}

// An offset number word (D, H): whole, 0 to the machine's offset count.
Flow<int> Interpreter::Impl::offset_number(const Words& words, char letter) const {
  const double v = words.at(letter).value;
  if (v != std::trunc(v) || v < 0 || v > mc.tool_offset_count) {
    return fail(AlarmId::kIllegalOffsetNumber, std::string(1, letter) + fmt::format("{}", v),
                loc(words.at(letter).column));
  }
  return static_cast<int>(v);
}

// G31.n (mill_codes.cpp) is the block's skip.
Flow<void> Interpreter::Impl::plan_mill(BlockPlan& plan) const {
  if (plan.mill.skip_step != 0) {
    if (plan.action != Action::kNone && plan.action != Action::kSkip) {
      return fail(AlarmId::kGCodeConflict,
                  g_name(plan.action_code) + " and G31." + std::to_string(plan.mill.skip_step) +
                      " are both one-shot (group 00) commands",
                  loc(cur_col));
    }
    plan.action = Action::kSkip;
    plan.action_code = 310;
  }
  return {};
}

void Interpreter::Impl::plan_cycle(BlockPlan& plan) const {
  if (plan.group[static_cast<std::size_t>(Group::k01)] != nullptr && !mc.lathe()) {
    plan.next.cycle = Cycle::kNone;
  }
  if (plan.mill.cycle) plan.next.cycle = *plan.mill.cycle;
}

// The block's modal state: the group codes, then F S T D.
Flow<void> Interpreter::Impl::plan_modal(const Words& words, BlockPlan& plan) {
  ModalState& next = plan.next;
  for (const CodeDef* def : plan.group) {
    if (def != nullptr && def->set != nullptr) def->set(next);
  }
  if (const CodeDef* w = plan.group[static_cast<std::size_t>(Group::k14)];
      w != nullptr && w->code == 541) {
    // G54.1 Pn: additional work coordinate system n (1-300), after EXT and
    // G54-G59 in work_offsets. P omitted: P1.
    const double pn = words.has('P') ? words.at('P').value : 1.0;
    if (pn != std::trunc(pn) || pn < 1 || pn > kExtraWorkSystems) {
      return fail(AlarmId::kIllegalOffsetNumber, "G54.1 P" + std::to_string(pn) + ": P1-P300",
                  loc(words.has('P') ? words.at('P').column
                                     : plan.column[static_cast<std::size_t>(Group::k14)]));
    }
    next.work = 6 + static_cast<int>(pn);
  }
  if (words.has('F')) {
    const double f = words.at('F').value;
    if (f < 0) return fail(AlarmId::kBadValue, "negative F", loc(words.at('F').column));
    const bool block_only =
        plan.action == Action::kSkip && !skip_rules::block_f_is_modal(dialect.sw);
    if (!block_only) next.feed = f;
  }
  plan.spindle_changed = next.spindle_mode != modal.spindle_mode;
  if (words.has('S')) {
    const WordVal& sw = words.at('S');
    if (mc.lathe() && sw.value < 0) return fail(AlarmId::kBadValue, "negative S", loc(sw.column));
    if (mc.lathe() && plan.action == Action::kLatheCoordSet) {
      next.spindle_clamp_rpm = sw.value;  // G50 S: the G96 speed limit
    } else {
      next.spindle = sw.value;
      plan.spindle_changed = plan.spindle_changed || mc.lathe();
    }
  }
  if (words.has('T') && !mc.lathe()) next.tool = static_cast<int>(words.at('T').value);
  if (words.has('D')) {
    auto d = offset_number(words, 'D');
    SKIPNC_TRY(d);
    next.d = *d;
  }
  if (words.has('H') && !mc.lathe()) {
    auto h = offset_number(words, 'H');
    SKIPNC_TRY(h);
  }
  if (next.plane != modal.plane && modal.cutter != CutterComp::kOff) {
    return fail(AlarmId::kPlaneChangeInComp, "plane change with G41/G42 active", loc(cur_col));
  }
  if (next.cutter != CutterComp::kOff && frame.tilted()) {
    // The offset would lie in the tilted program plane (conversion_3d.cpp).
    return fail(AlarmId::kNotSimulated,
                "G41/G42 under a tilted G68 I J K or G54.4 is not simulated by skipnc",
                loc(cur_col));
  }
  return {};
}

Flow<void> Interpreter::Impl::plan_block(const Words& words, BlockPlan& plan) {
  plan.next = modal;
  auto g = plan_g_codes(words, plan);
  if (!g) return g;
  for (int i = 0; i < words.m_count; ++i) {
    const int m = words.m[static_cast<std::size_t>(i)];
    if (std::find(dialect.absent_m.begin(), dialect.absent_m.end(), m) != dialect.absent_m.end()) {
      return fail(AlarmId::kUnknownMCode,
                  "M" + std::to_string(m) + " is not a code of this control", loc(cur_col));
    }
    if (std::find(dialect.not_simulated_m.begin(), dialect.not_simulated_m.end(), m) !=
        dialect.not_simulated_m.end()) {
      return fail(
          AlarmId::kNotSimulated,
          "M" + std::to_string(m) + " is a code of this control that skipnc does not simulate",
          loc(cur_col));
    }
  }
  auto m = plan_mill(plan);
  if (!m) return m;
  const CodeDef* g12 = plan.group[static_cast<std::size_t>(Group::k12)];
  plan.call = plan.action == Action::kMacroCall || (g12 != nullptr && g12->code == 660);
  if (plan.call) return plan_call(words, plan);
  auto a = plan_addresses(words);
  if (!a) return a;
  auto md = plan_modal(words, plan);
  if (!md) return md;
  plan_cycle(plan);
  return {};
}

// ---------------------------------------------------------------------------
// Commit: the steps of one block in the control's order.

void Interpreter::Impl::commit_messages() {
  for (const auto& c : blk.comments) {
    const std::string& t = blk.names[static_cast<std::size_t>(c.text)];
    if (t.size() >= 4 && t.compare(0, 4, "MSG,") == 0) add_message(t.substr(4));
  }
  if (blk.has_n) modal.seq = static_cast<int>(blk.n % 100000000);
}

// G65: call now; G66: remember the macro for the blocks that move.
Flow<Step> Interpreter::Impl::commit_call(const BlockPlan& plan) {
  if (plan.action == Action::kMacroCall) {
    if (plan.call_repeats == 0) return Step::kContinue;
    auto c = macro_call(plan.call_program, plan.call_repeats, false, loc(cur_col));
    SKIPNC_TRY(c);
    return Step::kContinue;
  }
  modal_macro_program = plan.call_program;
  modal_macro_args = call_args;
  modal.modal_macro = true;
  return Step::kContinue;
}

// F S T D and the modal groups. From here on the block's words are read in
// its own modes (G20/G21, G90/G91, G54...).
void Interpreter::Impl::commit_modal(const Words& words, const BlockPlan& plan, CommandSink& out) {
  if (words.has('E')) last_e = words.at('E').value;
  // A new speed keeps the direction: M03/M04/M05 of the block follow it.
  if (words.has('S') && !mc.lathe()) {
    emit(out, canon::Spindle{plan.next.spindle, modal.spindle_dir});
  }
  if (words.has('T') && !mc.lathe()) emit(out, canon::ToolSelect{plan.next.tool});
  const int seq = modal.seq;
  // LinuxCNC: selecting another coordinate system loads it from #5221..
  // (the same one again: "continuing to use same coordinate system").
  if (lang->rules.offsets_in_params && plan.next.work != modal.work && plan.next.work >= 1 &&
      plan.next.work <= 9) {
    ngc_load_work(plan.next.work);
  }
  modal = plan.next;
  modal.seq = seq;
}

Flow<void> Interpreter::Impl::commit_tool(const Words& words, const BlockPlan& plan,
                                          const ModalState& before, CommandSink& out) {
  (void)plan;
  if (modal.length != before.length || (words.has('H') && modal.length != LengthComp::kOff)) {
    auto r = set_tool_length(words, modal.length);
    if (!r) return r;
  }
  if (words.has('T') && mc.lathe()) {
    auto r = lathe_tool(words, modal);
    if (!r) return r;
    emit(out, canon::ToolSelect{modal.tool / 100});
  }
  return {};
}

void Interpreter::Impl::commit_spindle(const Words& words, bool changed, CommandSink& out) {
  for (int i = 0; i < words.m_count; ++i) {
    const MAction a = m_action(words.m[static_cast<std::size_t>(i)]);
    if (a != MAction::kSpindleCw && a != MAction::kSpindleCcw && a != MAction::kSpindleStop) {
      continue;
    }
    modal.spindle_dir = a == MAction::kSpindleCw ? 1 : a == MAction::kSpindleCcw ? -1 : 0;
    if (mc.lathe()) {
      changed = true;
    } else {
      emit(out, canon::Spindle{modal.spindle, modal.spindle_dir});
    }
  }
  if (changed) emit_spindle(out);
}

// G52 / G92 axis words: every shift checked before any is set.
Flow<void> Interpreter::Impl::commit_shift(const Words& words, bool local) {
  AxisVec shift = local ? local_shift : g92_shift;
  for (int i = 0; i < axis_count; ++i) {
    const char c = axis_letter[static_cast<std::size_t>(i)];
    if (!words.has(c)) continue;
    const double v = word_length(words.at(c), false) * unit_mm();
    if (local) {
      shift[i] = v;
    } else {
      // G92: the current position becomes v in the work system.
      const double saved = g92_shift[i];
      g92_shift[i] = 0.0;
      shift[i] = pos[i] * axis_scale[static_cast<std::size_t>(i)] - v - offset_total(i);
      g92_shift[i] = saved;
    }
    auto ok =
        check_offset(shift[i], std::string(local ? "G52 " : "G92 ") + c, loc(words.at(c).column));
    if (!ok) return ok;
  }
  (local ? local_shift : g92_shift) = shift;
  if (!local && lang->rules.offsets_in_params) ngc_store_g92();
  return {};
}

// G45-G48: the move is extended (G45, G47) or shortened (G46, G48) by the
// D offset; G47/G48 by twice the offset. The direction is that of the
// programmed move (from the previous programmed point in G90; a zero move
// counts as positive). The shift stays with the axis: later positions and
// #5061.. are in programmed coordinates.
void Interpreter::Impl::commit_tool_pos_offset(const Words& words, int g) {
  const auto& t = tools[static_cast<std::size_t>(modal.d)];
  const double r = modal.d == 0 ? 0.0 : (t.radius_geometry + t.radius_wear) * offset_unit_mm(*this);
  const double k = (g == 45 ? 1.0 : g == 46 ? -1.0 : g == 47 ? 2.0 : -2.0) * r;
  const bool inc = modal.distance == Distance::kIncremental;
  for (int i = 0; i < axis_count; ++i) {
    const char c = axis_letter[static_cast<std::size_t>(i)];
    if (!words.has(c)) continue;
    const double v = word_length(words.at(c), false);
    const double dist = inc ? v : v - work_of(i, pos[i]);
    const double shift = (dist < 0.0 ? -1.0 : 1.0) * k;
    tool_pos_offset[i] += shift;
    if (inc) g45_delta[i] = shift;
  }
}

// The one-shot action or the motion of the block. `moved`: the block moved
// (for G66).
Flow<Step> Interpreter::Impl::commit_action(const Words& words, const BlockPlan& plan,
                                            CommandSink& out, bool& moved) {
  const SourceLoc at = loc(cur_col);
  switch (plan.action) {
    case Action::kNgc:
      SKIPNC_TRY(ngc_action(words, plan.action_code, out));
      return Step::kContinue;
    case Action::kDataSetting:
      SKIPNC_TRY(data_setting(words, at));
      return Step::kContinue;
    case Action::kLatheCoordSet:
      SKIPNC_TRY(lathe_coordinate_setting(words));
      return Step::kContinue;
    case Action::kLocalShift:
    case Action::kCoordSet:
      SKIPNC_TRY(commit_shift(words, plan.action == Action::kLocalShift));
      return Step::kContinue;
    case Action::kDwell:
      SKIPNC_TRY(dwell(words, out));
      return Step::kContinue;
    case Action::kRefReturn:
    case Action::kRefReturn2:
      SKIPNC_TRY(reference_return(words, plan.action_code / 10, out));
      moved = true;
      return Step::kContinue;
    default:
      break;
  }
  // G38.n: a probe move when the block has axis words or names the code
  // (then without axis words it is refused: probe_no_axis).
  const bool skip =
      plan.action == Action::kSkip ||
      (modal.motion == Motion::kProbe && plan.action == Action::kNone &&
       (has_axis_word(words) || plan.group[static_cast<std::size_t>(Group::k01)] != nullptr));
  const bool arc_words = (modal.motion == Motion::kCwArc || modal.motion == Motion::kCcwArc) &&
                         (words.has('I') || words.has('J') || words.has('K') || words.has('R'));
  if (!skip && !has_axis_word(words) && !arc_words && plan.tool_pos_offset == 0) {
    return Step::kContinue;
  }
  if (plan.tool_pos_offset != 0) commit_tool_pos_offset(words, plan.tool_pos_offset);
  if (!skip) {
    auto c = check_nose_radius_comp(at);
    SKIPNC_TRY(c);
  }
  auto m = motion(words, out, skip, plan.machine_coord);
  if (!m) return m;
  moved = true;
  return *m;
}

Flow<Step> Interpreter::Impl::commit_sub_call(const Words& words) {
  const SourceLoc at = loc(cur_col);
  if (!words.has('P')) return fail(AlarmId::kProgramNotFound, "M98 needs P", at);
  const double p = words.at('P').value;
  if (p != std::trunc(p) || p < 1 || p > 99999999) {
    return fail(AlarmId::kProgramNotFound, "M98 P" + std::to_string(p), loc(words.at('P').column));
  }
  auto program = static_cast<std::int64_t>(p);
  int repeats = 1;
  if (words.has('L')) {
    repeats = static_cast<int>(words.at('L').value);
  } else if (program > 9999) {
    // M98 Pxxxxyyyy: the first digits repeat, the last four name the program.
    repeats = static_cast<int>(program / 10000);
    program %= 10000;
  }
  if (repeats < 1) return Step::kContinue;
  auto c = call(program, repeats, false, at);
  SKIPNC_TRY(c);
  return Step::kContinue;
}

// M97 Pn Ll (Haas, local_sub_call_m97): the block at sequence number n of
// the running program, l times (L omitted: once), back with M99.
Flow<Step> Interpreter::Impl::commit_local_sub_call(const Words& words) {
  const SourceLoc at = loc(cur_col);
  if (!words.has('P')) return fail(AlarmId::kSequenceNotFound, "M97 needs P", at);
  const double p = words.at('P').value;
  if (p != std::trunc(p) || p < 1 || p > 99999) {
    return fail(AlarmId::kIllegalSequenceNumber,
                "M97 P" + fmt::format("{}", p) + ": sequence numbers are 1 to 99999",
                loc(words.at('P').column));
  }
  int repeats = 1;
  if (words.has('L')) {
    const double l = words.at('L').value;
    if (l != std::trunc(l) || l < 0 || l > 9999) {
      return fail(AlarmId::kBadValue, "M97 L" + fmt::format("{}", l) + ": 0 to 9999 repetitions",
                  loc(words.at('L').column));
    }
    repeats = static_cast<int>(l);
  }
  if (repeats < 1) return Step::kContinue;
  auto c = local_call(static_cast<std::int64_t>(p), repeats, at);
  SKIPNC_TRY(c);
  return Step::kContinue;
}

Flow<Step> Interpreter::Impl::commit_sub_return(const Words& words) {
  std::optional<std::int64_t> label;
  if (words.has('P')) {
    const double pv = std::round(words.at('P').value);
    if (pv < 1 || pv > 99999) {
      return fail(
          AlarmId::kIllegalSequenceNumber,
          "M99 P" + fmt::format("{}", words.at('P').value) + ": sequence numbers are 1 to 99999",
          loc(words.at('P').column));
    }
    label = static_cast<std::int64_t>(pv);
  }
  return return_from_sub(label, loc(cur_col));
}

// M codes after the motion. nullopt: go on with the next step of the block.
Flow<std::optional<Step>> Interpreter::Impl::commit_m_codes(const Words& words, CommandSink& out) {
  for (int i = 0; i < words.m_count; ++i) {
    const int m = words.m[static_cast<std::size_t>(i)];
    modal.last_m = m;
    if (lang->rules.state_codes && m >= 70 && m <= 73) continue;  // ngc_state_codes
    switch (m_action(m)) {
      case MAction::kProgramStop:
        emit(out, canon::Stop{canon::StopKind::kProgramStop});
        break;
      case MAction::kOptionalStop:
        emit(out, canon::Stop{canon::StopKind::kOptionalStop});
        break;
      case MAction::kProgramEnd:
      case MAction::kRewindEnd:
        emit(out, canon::Stop{m_action(m) == MAction::kProgramEnd ? canon::StopKind::kProgramEnd
                                                                  : canon::StopKind::kRewindEnd});
        ++parts_count;
        ended = true;
        return Step::kEnd;
      case MAction::kSubCall:
        return commit_sub_call(words);
      case MAction::kSubReturn:
        return commit_sub_return(words);
      case MAction::kLocalSubCall:
        if (dialect.sw.local_sub_call_m97) return commit_local_sub_call(words);
        emit(out, canon::MCode{m});
        break;
      case MAction::kSpindleCw:
      case MAction::kSpindleCcw:
      case MAction::kSpindleStop:
        break;
      case MAction::kMachine:
        emit(out, canon::MCode{m});
        break;
    }
  }
  return std::optional<Step>{};
}

// A new cycle mode: the initial level is the present Z (B-63944EN 5.1).
void Interpreter::Impl::commit_cycle_start(const ModalState& before) {
  if (modal.cycle == Cycle::kNone || before.cycle != Cycle::kNone) return;
  cycle_data = cycles::Data{};
  const int z = axis_of_letter['Z' - 'A'];
  if (z < 0) return;
  const int x = axis_of_letter['X' - 'A'], y = axis_of_letter['Y' - 'A'];
  cycle_data.initial =
      xform::to_program(frame, {x >= 0 ? work_of(x, pos[x]) : 0.0,
                                y >= 0 ? work_of(y, pos[y]) : 0.0, work_of(z, pos[z])})[2];
}

// The mill codes' action, in place of the group-00 action or motion: G68
// G51 G51.1 take the axis words as their data (no move), a cycle mode
// drills at the block's position. nullopt: the block goes on to
// commit_action.
Flow<std::optional<Step>> Interpreter::Impl::commit_mill(const Words& words, const BlockPlan& plan,
                                                         CommandSink& out, bool& moved) {
  if (plan.mill.lookahead) {
    auto r = set_lookahead(words);
    SKIPNC_TRY(r);
    emit(out, canon::LookAhead{lookahead_limit});
  }
  if (!plan.mill.no_effect.empty()) {
    auto w = warn("no_effect",
                  plan.mill.no_effect + " is accepted and changes nothing in the simulation",
                  loc(cur_col));
    SKIPNC_TRY(w);
  }
  if (plan.mill.frame_code != 0) {
    auto r = apply_frame_code(words, plan.mill);
    SKIPNC_TRY(r);
    if (*r) return Step::kContinue;
  }
  if (plan.action != Action::kNone) return std::optional<Step>{};
  if (modal.cycle != Cycle::kNone && (has_axis_word(words) || words.has('R'))) {
    auto m = canned_cycle(words, out);
    SKIPNC_TRY(m);
    moved = true;
    return std::optional<Step>{Step::kContinue};
  }
  return std::optional<Step>{};
}

Flow<Step> Interpreter::Impl::commit_block(const Words& words, const BlockPlan& plan,
                                           CommandSink& out) {
  commit_messages();
  if (plan.call) return commit_call(plan);
  const ModalState before = modal;
  commit_modal(words, plan, out);
  SKIPNC_TRY(commit_tool(words, plan, before, out));
  commit_spindle(words, plan.spindle_changed, out);
  if (lang->rules.state_codes) {
    SKIPNC_TRY(ngc_state_codes(words, before, loc(cur_col)));
  }
  if (plan.mill.polar) polar = *plan.mill.polar;
  skip_step = plan.mill.skip_step;
  commit_cycle_start(before);
  bool moved = false;
  auto mill = commit_mill(words, plan, out, moved);
  SKIPNC_TRY(mill);
  if (plan.mill.g37) return g37_block(words, out);  // the block's last step
  auto a = *mill ? Result<Step>{**mill} : commit_action(words, plan, out, moved);
  if (!a || *a == Step::kSync) return a;
  auto m = commit_m_codes(words, out);
  SKIPNC_TRY(m);
  if (*m) return **m;
  // G66: the modal macro runs after each block that moved, but not for the
  // moves of the macro it calls (nor of what that macro calls).
  if (moved && modal.modal_macro && modal_macro_program != 0 && !in_modal_call()) {
    auto c = macro_call(modal_macro_program, 1, true, loc(cur_col));
    SKIPNC_TRY(c);
  }
  return Step::kContinue;
}

// ---------------------------------------------------------------------------
// The block as a transaction.

BlockUndo Interpreter::Impl::save_block_state() const {
  BlockUndo u;
  u.modal = modal;
  u.pos = pos;
  u.tool_pos_offset = tool_pos_offset;
  u.g45_delta = g45_delta;
  u.lathe_tool_offset = lathe_tool_offset;
  u.tool_offset_pending = tool_offset_pending;
  u.local_shift = local_shift;
  u.g92_shift = g92_shift;
  u.length_offset = length_offset;
  u.last_e = last_e;
  u.last_cut_feed = last_cut_feed;
  u.turning_cycle_z = turning_cycle_z;
  u.have_turning_cycle_z = have_turning_cycle_z;
  u.wear_offset = wear_offset;
  u.motion_since_sync = motion_since_sync;
  u.messages = messages.size();
  u.warnings = warnings.size();
  u.pending = pending;
  u.parts_count = parts_count;
  u.ended = ended;
  u.cycle_data = cycle_data;
  u.frame = frame;
  u.polar = polar;
  u.polar_angle = polar_angle;
  u.rotation_angle = rotation_angle;
  u.skip_step = skip_step;
  u.skip_missed_unread = skip_missed_unread;
  return u;
}

void Interpreter::Impl::restore_block_state(const BlockUndo& u) {
  modal = u.modal;
  pos = u.pos;
  tool_pos_offset = u.tool_pos_offset;
  g45_delta = u.g45_delta;
  lathe_tool_offset = u.lathe_tool_offset;
  tool_offset_pending = u.tool_offset_pending;
  local_shift = u.local_shift;
  g92_shift = u.g92_shift;
  length_offset = u.length_offset;
  last_e = u.last_e;
  last_cut_feed = u.last_cut_feed;
  turning_cycle_z = u.turning_cycle_z;
  have_turning_cycle_z = u.have_turning_cycle_z;
  wear_offset = u.wear_offset;
  motion_since_sync = u.motion_since_sync;
  messages.resize(u.messages);
  warnings.resize(u.warnings);
  pending = u.pending;
  parts_count = u.parts_count;
  ended = u.ended;
  cycle_data = u.cycle_data;
  frame = u.frame;
  polar = u.polar;
  polar_angle = u.polar_angle;
  rotation_angle = u.rotation_angle;
  skip_step = u.skip_step;
  skip_missed_unread = u.skip_missed_unread;
}

// Plan, then commit into the block's buffer; the buffer reaches `out` only
// when the whole block succeeded. G10 changes the offset tables only after
// every check of its words has passed, and a call (M98, G65, M99) is the
// block's last step, so they need no undo.
Flow<Step> Interpreter::Impl::execute_nc(const Words& words, CommandSink& out) {
  BlockPlan plan;
  auto p = plan_block(words, plan);
  SKIPNC_TRY(p);
  const BlockUndo undo = save_block_state();
  block_buffer.cmds.clear();
  auto r = commit_block(words, plan, block_buffer);
  if (!r) {
    restore_block_state(undo);
    block_buffer.cmds.clear();
    return r;
  }
  auto passed = pass_block(plan, undo.pos, out);
  block_buffer.cmds.clear();
  if (!passed) {
    restore_block_state(undo);
    return std::unexpected(passed.error());
  }
  return r;
}

void Interpreter::Impl::emit(CommandSink& out, canon::Command cmd) {
  out.emit(canon::Stamped{std::move(cmd), cur_line, frames.back().context,
                          blk.has_n ? static_cast<std::int32_t>(blk.n % 100000000) : -1});
}

}  // namespace skipnc::interp
