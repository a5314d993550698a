// Commit (commit_block): the steps of one NC block in the control's order,
// one function per step, emitting into the block's buffer.
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

void Interpreter::Impl::comment_messages() {
  for (const auto& c : blk.comments) {
    const std::string& t = blk.names[static_cast<std::size_t>(c.text)];
    if (t.size() >= 4 && t.compare(0, 4, "MSG,") == 0) add_message(t.substr(4));
  }
}

// G65: call now; G66: remember the macro for the blocks that move.
Flow<Step> Interpreter::Impl::commit_call(const BlockPlan& plan) {
  if (plan.action == Action::kMacroCall) {
    if (plan.call_repeats == 0) return Step::kContinue;
    auto c = macro_call(plan.call_program, plan.call_repeats, false, loc(cur_col));
    SKIPNC_TRY(c);
    return Step::kContinue;
  }
  g66.set(plan.call_program, call_args.values);
  modal.modal_macro = true;
  return Step::kContinue;
}

// F S T D and the modal groups. From here on the block's words are read in
// its own modes (G20/G21, G90/G91, G54...).
void Interpreter::Impl::commit_modal(const Words& words, const BlockPlan& plan, CommandSink& out) {
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
    lang->select_work(*this, plan.next.work);  // ngc_params.cpp
  }
  modal = plan.next;
  modal.seq = seq;
  if (words.has('E')) modal.e = words.at('E').value;
}

Flow<void> Interpreter::Impl::commit_tool(const Words& words, const ModalState& before,
                                          CommandSink& out) {
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
  AxisVec shift = local ? shifts.get().local_shift : shifts.get().g92_shift;
  for (int i = 0; i < axis_count; ++i) {
    const char c = axis_letter[static_cast<std::size_t>(i)];
    if (!words.has(c)) continue;
    const double v = word_length(words.at(c)) * unit_mm();
    if (local) {
      shift[i] = v;
    } else {
      // G92: the current position becomes v in the work system.
      const double saved = shifts.get().g92_shift[i];
      shifts.write().g92_shift[i] = 0.0;
      shift[i] = pos[i] * axis_scale[static_cast<std::size_t>(i)] - v - offset_total(i);
      shifts.write().g92_shift[i] = saved;
    }
    auto ok =
        check_offset(shift[i], std::string(local ? "G52 " : "G92 ") + c, loc(words.at(c).column));
    if (!ok) return ok;
  }
  (local ? shifts.write().local_shift : shifts.write().g92_shift) = shift;
  if (!local && lang->rules.offsets_in_params) lang->store_g92(*this);  // ngc_codes.cpp
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
    const double v = word_length(words.at(c));
    const double dist = inc ? v : v - work_of(i, pos[i]);
    const double shift = (dist < 0.0 ? -1.0 : 1.0) * k;
    shifts.write().tool_pos_offset[i] += shift;
    if (inc) shifts.write().g45_delta[i] = shift;
  }
}

// The one-shot action or the motion of the block. `moved`: the block moved
// (for G66).
Flow<Step> Interpreter::Impl::commit_action(const Words& words, const BlockPlan& plan,
                                            CommandSink& out, bool& moved) {
  switch (plan.action) {
    case Action::kNgc:
      SKIPNC_TRY(lang->own_action(*this, words, plan.action_code));  // ngc_codes.cpp
      return Step::kContinue;
    case Action::kDataSetting:
      SKIPNC_TRY(data_setting(words, loc(cur_col)));
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
      SKIPNC_TRY(reference_return(words, plan.action_code.number(), out));
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
  if (!skip && mc.lathe()) {  // the column's text is built only for a lathe's check
    auto c = check_nose_radius_comp(loc(cur_col));
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
      xform::to_program(frame(), {x >= 0 ? work_of(x, pos[x]) : 0.0,
                                  y >= 0 ? work_of(y, pos[y]) : 0.0, work_of(z, pos[z])})[2];
}

// The mill codes' action, in place of the group-00 action or motion: G68
// G51 G51.1 take the axis words as their data (no move), a cycle mode
// drills at the block's position. nullopt: the block goes on to
// commit_action.
Flow<std::optional<Step>> Interpreter::Impl::commit_mill(const Words& words, const BlockPlan& plan,
                                                         CommandSink& out, bool& moved) {
  if (plan.mill.lookahead) {
    auto limit = lookahead_limit(words);
    SKIPNC_TRY(limit);
    emit(out, canon::LookAhead{*limit});
  }
  if (!plan.mill.no_effect.empty()) {
    auto w = warn("no_effect",
                  plan.mill.no_effect + " is accepted and changes nothing in the simulation",
                  loc(cur_col));
    SKIPNC_TRY(w);
  }
  if (plan.mill.frame != nullptr) {
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
  SKIPNC_TRY(commit_tool(words, before, out));
  commit_spindle(words, plan.spindle_changed, out);
  if (lang->rules.state_codes) {
    SKIPNC_TRY(lang->state_codes(*this, words, before, loc(cur_col)));  // ngc_room.cpp
  }
  if (plan.mill.polar) frame_codes.polar = *plan.mill.polar;
  skip_state.step = plan.mill.skip_step;
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
  if (moved && modal.modal_macro && g66.armed() && !in_modal_call()) {
    auto c = macro_call(g66.program, 1, true, loc(cur_col));
    SKIPNC_TRY(c);
  }
  return Step::kContinue;
}

}  // namespace skipnc::interp
