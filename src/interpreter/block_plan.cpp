// Plan (plan_block): the NC block's G and M codes found in the code table,
// their groups, addresses and values checked, the block's modal state built
// in a BlockPlan. Nothing of the interpreter changes here.
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "interpreter/codes.hpp"
#include "interpreter/impl.hpp"
#include "interpreter/offset_units.hpp"

namespace skipnc::interp {
namespace {

// The unknown_g_code message of a code this machine does not read: what to
// write instead on a lathe (a refusal of the table), or that it is a code
// of the lathe only.
std::string improper_g(GCode code, const CodeDef* refusal, bool lathe) {
  if (refusal != nullptr) return code_name(code) + refusal->summary;
  if (!lathe) {
    const CodeDef* l = find_g(code, true);
    if (l != nullptr && l->handler != Handler::kRefused) {
      return code_name(code) + " is a code of the lathe (G-code system A) only";
    }
  }
  return code_name(code);
}

// A code this control does not have (absent: `unknown`) or that skipnc does
// not simulate, by the dialect's lists; `name` writes the code.
template <class Code, class Name>
Flow<void> refuse_listed(const Interpreter::Impl& im, const std::vector<Code>& absent,
                         const std::vector<Code>& not_simulated, Code code, Name name,
                         AlarmId unknown, std::uint32_t col) {
  if (std::find(absent.begin(), absent.end(), code) != absent.end()) {
    return fail(unknown, name(code) + " is not a code of this control", im.loc(col));
  }
  if (std::find(not_simulated.begin(), not_simulated.end(), code) != not_simulated.end()) {
    return fail(AlarmId::kNotSimulated,
                name(code) + " is a code of this control that skipnc does not simulate",
                im.loc(col));
  }
  return {};
}

}  // namespace

// Finds each G word in the code table, puts it in its group's slot and
// takes the group-00 action. Two codes of one modal group: the dialect's
// alarm, or the last one wins where the control says so
// (g_same_group_last_wins). Two group-00 actions (G04 G31, G31 G28,
// G31 G92) are always refused: the block could do only one of them.
Flow<void> Interpreter::Impl::plan_g_codes(const Words& words, BlockPlan& plan) {
  const bool lathe = mc.lathe();
  for (int i = 0; i < words.g_count; ++i) {
    const GCode code = words.g[static_cast<std::size_t>(i)];
    const std::uint32_t col = words.g_col[static_cast<std::size_t>(i)];
    auto found = g_code_def(code, col);
    SKIPNC_TRY(found);
    const CodeDef* def = *found;
    if (!def->modal_state()) {
      auto mill = mill_code(*def, loc(col), plan.mill);  // mill_codes.cpp
      SKIPNC_TRY(mill);
      if (*mill) continue;
      return fail(AlarmId::kUnknownGCode, improper_g(code, nullptr, lathe), loc(col));
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
                  code_name(plan.group[g]->code) + " and " + code_name(code) +
                      " are both of group " + std::to_string(static_cast<int>(def->group)),
                  loc(col));
    }
    plan.group[g] = def;
    plan.named |= 1u << g;
    plan.column[g] = col;
  }
  return {};
}

// A G code's entry in the code table (codes.cpp), or the alarm of a code
// this control does not have or skipnc does not simulate.
Flow<const CodeDef*> Interpreter::Impl::g_code_def(GCode code, std::uint32_t col) const {
  const bool lathe = mc.lathe();
  SKIPNC_TRY(refuse_listed(
      *this, dialect.absent_g, dialect.not_simulated_g, code, [](GCode c) { return code_name(c); },
      AlarmId::kUnknownGCode, col));
  const CodeDef* def = find_g(code, lathe);
  if (def == nullptr || def->handler == Handler::kRefused) {
    return fail(AlarmId::kUnknownGCode, improper_g(code, def, lathe), loc(col));
  }
  if (auto why = not_in_dialect(*def, dialect.sw)) {
    return fail(AlarmId::kUnknownGCode, std::move(*why), loc(col));
  }
  return def;
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
                code_name(plan.action_code) + " and " + code_name(def.code) +
                    " are both one-shot (group 00) commands",
                loc(col));
  }
  plan.action = def.action;
  plan.action_code = def.code;
  if (def.action == Action::kToolPosOffset) plan.tool_pos_offset = def.code.number();
  return {};
}

// G65/G66 block: G, P and L are its own words, every other one an argument.
Flow<void> Interpreter::Impl::plan_call(const Words& words, BlockPlan& plan) {
  const SourceLoc at = loc(cur_col);
  if (!call_args.in_block) {
    return fail(AlarmId::kMacroFormat, "G65/G66 must be written as a number (G65, not G#i)", at);
  }
  for (int i = 0; i < words.g_count; ++i) {
    const GCode code = words.g[static_cast<std::size_t>(i)];
    if (code != GCode(65) && code != GCode(66)) {
      return fail(AlarmId::kIllegalArgumentAddress,
                  code_name(code) + " in a G65/G66 block: G cannot be an argument",
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
                  code_name(plan.action_code) + " and G31." + std::to_string(plan.mill.skip_step) +
                      " are both one-shot (group 00) commands",
                  loc(cur_col));
    }
    plan.action = Action::kSkip;
    plan.action_code = GCode(31);
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
  // The groups the block names, in the order of their numbers.
  for (std::uint32_t bits = plan.named; bits != 0; bits &= bits - 1) {
    const CodeDef* def = plan.group[static_cast<std::size_t>(std::countr_zero(bits))];
    if (def->set != nullptr) def->set(next);
  }
  if (const CodeDef* w = plan.group[static_cast<std::size_t>(Group::k14)];
      w != nullptr && w->code == GCode(54, 1)) {
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
  if (next.cutter != CutterComp::kOff && frame().tilted()) {
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
    SKIPNC_TRY(refuse_listed(
        *this, dialect.absent_m, dialect.not_simulated_m, words.m[static_cast<std::size_t>(i)],
        [](int m) { return m_code_name(m); }, AlarmId::kUnknownMCode, cur_col));
  }
  auto m = plan_mill(plan);
  if (!m) return m;
  const CodeDef* g12 = plan.group[static_cast<std::size_t>(Group::k12)];
  plan.call = plan.action == Action::kMacroCall || (g12 != nullptr && g12->code == GCode(66));
  if (plan.call) return plan_call(words, plan);
  auto a = plan_addresses(words);
  if (!a) return a;
  auto md = plan_modal(words, plan);
  if (!md) return md;
  plan_cycle(plan);
  return {};
}

}  // namespace skipnc::interp
