// The NC block: its words collected by address (collect_words), then run
// in two stages:
//   plan    (block_plan.cpp plan_block) finds every G code in the code
//           table (codes.cpp), checks groups, addresses and values, and
//           builds the block's modal state in a BlockPlan; nothing of the
//           interpreter changes;
//   commit  (block_commit.cpp commit_block) applies the plan in the
//           control's order, one function per step, emitting into the
//           block's buffer.
// A block that raises an alarm in either stage emits nothing and leaves
// the interpreter as it was (run_block, below: the block's small state
// is copied before and put back, the tables' journals rolled back, the
// buffer dropped; docs/architecture.md "The block transaction").
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "interpreter/codes.hpp"
#include "interpreter/impl.hpp"
#include "interpreter/offset_units.hpp"

namespace skipnc::interp {

// A G or M word of the block, its value evaluated.
Flow<void> Interpreter::Impl::code_word(Words& words, const gcode::Word& w, double value) const {
  if (w.letter == 'G') {
    if (words.g_count == static_cast<int>(words.g.size())) {
      return fail(AlarmId::kGCodeConflict, "too many G codes in one block", loc(w.column));
    }
    // G0-G999 whole as GCode::of_value finds them, without its rounding.
    const bool small = value >= 0.0 && value < 1000.0;
    const int whole = small ? static_cast<int>(value) : 0;
    const std::optional<GCode> code =
        small && whole == value ? std::optional<GCode>(GCode(whole)) : GCode::of_value(value);
    if (!code) return fail(AlarmId::kUnknownGCode, "G" + fmt::format("{}", value), loc(w.column));
    words.g[static_cast<std::size_t>(words.g_count)] = *code;
    words.g_col[static_cast<std::size_t>(words.g_count++)] = w.column;
    return {};
  }
  if (words.m_count == 3) {
    return fail(AlarmId::kTooManyMCodes, "more than 3 M codes in one block", loc(w.column));
  }
  // A value in brackets is rounded (M[3.5] is M4); a literal must be whole.
  const double m = w.is_expr ? std::round(value) : value;
  if (m != std::trunc(m) || m < 0 || m > 99999999) {
    return fail(AlarmId::kUnknownMCode, "M" + fmt::format("{}", value), loc(w.column));
  }
  words.m[static_cast<std::size_t>(words.m_count++)] = static_cast<int>(m);
  return {};
}

// Evaluates the words of an NC block. In a G65/G66 block every address but
// G, P and L is a macro argument (see collect_argument); elsewhere an
// address may appear once.
Flow<void> Interpreter::Impl::collect_words(Words& words) {
  call_args.in_block = false;
  for (const gcode::Word& w : blk.words) {
    if (w.letter == 'G' && !w.is_expr && (w.value == 65.0 || w.value == 66.0)) {
      call_args.begin();
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
      functions.word_round_increment = length ? word_inc : 0.0;
      auto e = eval(w.expr);
      functions.word_round_increment = 0.0;
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
      if (length && !call_args.in_block && lang->rules.round_computed_words) {
        v.value = std::round(v.value / word_inc) * word_inc + 0.0;
      }
    } else {
      v.value = w.value;
    }
    if (call_args.in_block && w.letter != 'G' && w.letter != 'P' && w.letter != 'L') {
      auto a = collect_argument(w, v, ijk_set, ijk_last);
      if (!a) return a;
      continue;
    }
    if (w.letter == 'G' || w.letter == 'M') {
      SKIPNC_TRY(code_word(words, w, v.value));
      continue;
    }
    if (words.has(w.letter)) {
      return fail(AlarmId::kWordRepeated,
                  std::string("address ") + w.letter + " twice in one block", loc(w.column));
    }
    words.set(w.letter, v);
  }
  return {};
}

// ---------------------------------------------------------------------------
// The block as a transaction (docs/architecture.md "The block transaction").

// A block that may open or close a call level: G65/G66, M98, M97, M99, or
// any block while a G66 modal macro is on.
bool Interpreter::Impl::block_calls(const Words& words, const BlockPlan& plan) const noexcept {
  if (plan.call || modal.modal_macro) return true;
  for (int i = 0; i < words.m_count; ++i) {
    const MAction a = m_action(words.m[static_cast<std::size_t>(i)]);
    if (a == MAction::kSubCall || a == MAction::kSubReturn || a == MAction::kLocalSubCall) {
      return true;
    }
  }
  return false;
}

// The tables start recording the block's writes; the call stack and the
// G66 macro, when the block may change them, are copied.
void Interpreter::Impl::begin_tables(bool calls) {
  begin_offsets();
  shifts.begin_block();
  program_frame.begin_block();
  vars.begin_block();
  if (lang->rules.state_codes) lang->begin_block();  // M70-M73's saved states (ngc_room.cpp)
  if (!calls) return;
  before_block.frames = programs.frames;
  before_block.g66 = g66;
}

void Interpreter::Impl::commit_tables() noexcept {
  commit_offsets();
  shifts.commit();
  program_frame.commit();
  vars.commit();
}

// Every table as before the block. The running program's reader goes back
// to the block after the alarmed one, where a call or return had moved it
// (a seek to a block the source has already returned cannot fail).
void Interpreter::Impl::roll_back_tables(bool calls) {
  roll_back_offsets();
  shifts.roll_back();
  program_frame.roll_back();
  vars.roll_back();
  if (lang->rules.state_codes) lang->roll_back_block();
  if (!calls) return;
  programs.frames = before_block.frames;
  g66 = before_block.g66;
  const Frame& top = programs.frames.back();
  static_cast<void>(top.file->src->seek(top.resume));
}

// Plan, then run the block on the interpreter's state: the buffer reaches
// `out` only when the whole block succeeded. An alarmed block puts back
// the small state it started from by one assignment, truncates the logs it
// appended to and rolls the tables' journals back.
Flow<Step> Interpreter::Impl::run_block(const Words& words, CommandSink& out) {
  BlockPlan plan;
  SKIPNC_TRY(plan_block(words, plan));
  const BlockState before = *this;
  const std::size_t message_count = messages.size();
  const std::size_t warning_count = warnings.size();
  const bool calls = block_calls(words, plan);
  begin_tables(calls);
  // Commit into the block's buffer, then pass the buffer on through cutter
  // compensation from the position before the block.
  block_buffer.cmds.clear();
  auto r = [&]() -> Flow<Step> {
    auto c = commit_block(words, plan, block_buffer);
    SKIPNC_TRY(c);
    SKIPNC_TRY(pass_block(plan, before.pos, out));
    return c;
  }();
  block_buffer.cmds.clear();
  if (r) {
    commit_tables();
    return r;
  }
  static_cast<BlockState&>(*this) = before;
  messages.resize(message_count);
  warnings.resize(warning_count);
  roll_back_tables(calls);
  return r;
}

// ---------------------------------------------------------------------------
// The plain motion block: G00-G03 or no G code, axis words, F, I J K R and
// nothing else, in the plain modes (a mill without cutter compensation,
// canned cycle, G16/G68/G51 frame, G66, G45-G48 shift, in feed per minute).
// Of the transaction's steps only these do something for it: the modal
// motion and F (plan_modal), the N number and messages (commit_messages),
// the skip state's step, the move (commit_action) and the sink (pass_block).
// plain_block makes the move first and changes nothing until it is known to
// succeed without a warning; a block it does not take, or whose move would
// alarm or warn, runs through the transaction, which finds the same alarm.

// What the plain block needs, once at the start of the run.
void Interpreter::Impl::init_plain() {
  block_params.linear_rapid = params.bit(config::param::kLinearRapid);
  block_params.calculator_decimal = params.bit(config::param::kCalculatorDecimal);
  const double tol = params.get(config::param::kArcRadiusTolerance);
  block_params.arc_tolerance = tol > 0 ? tol : 0.02;
  plain.slowest_feed = mc.axes[0].max_feed_mm_min;
  for (int i = 1; i < axis_count; ++i) {
    plain.slowest_feed =
        std::min(plain.slowest_feed, mc.axes[static_cast<std::size_t>(i)].max_feed_mm_min);
  }
  if (mc.lathe()) return;
  plain.letters = axis_letters;
  for (const char c : std::string_view("FIJKR")) {
    if (lang->rules.addresses.find(c) != std::string_view::npos) plain.letters |= 1u << (c - 'A');
  }
  for (int g = 0; g < 4; ++g) plain.motion_code[static_cast<std::size_t>(g)] = plain_code(GCode(g));
  plain.on = true;
}

// G00-G03: the control has the code (plan_g_codes finds it) and it sets
// the modal motion and nothing else.
bool Interpreter::Impl::plain_code(GCode code) const {
  auto def = g_code_def(code, 0);
  if (!def || !(*def)->modal_state() || (*def)->group != Group::k01 || (*def)->set == nullptr) {
    return false;
  }
  ModalState set, want;
  (*def)->set(set);
  want.motion = static_cast<Motion>(code.number());
  return set == want;
}

// The plain block's move into `cmd`, changing nothing: its target; null
// when the block does not move, `fallback` when the move would alarm or warn.
const AxisVec* Interpreter::Impl::plain_move(const Words& words, canon::Command& cmd,
                                             const AxisVec& fallback) {
  const bool arc = modal.motion == Motion::kCwArc || modal.motion == Motion::kCcwArc;
  const bool arc_words =
      arc && (words.has('I') || words.has('J') || words.has('K') || words.has('R'));
  if ((words.letters & axis_letters) == 0 && !arc_words) return nullptr;
  // axis_targets without a frame, G53 or U W H: the axis words one by one.
  auto targets = [&](AxisVec& target) -> AxisVec* {
    target = pos;
    AxisMask moved;
    mill_axis_words(words, words.letters & axis_letters, false, target, moved);
    return &target;
  };
  if (arc) {
    canon::Arc& a = cmd.emplace<canon::Arc>();
    return arc_move(words, *targets(a.target), a) ? &a.target : &fallback;
  }
  if (modal.motion == Motion::kRapid) {
    return targets(cmd.emplace<canon::Rapid>(canon::Rapid{{}, block_params.linear_rapid}).target);
  }
  // G01: without a feed, or faster than an axis may go (check_feeds' warning).
  const double f = feed_mm_per_min();
  if (f <= 0.0 || f > plain.slowest_feed) return &fallback;
  return targets(
      cmd.emplace<canon::Feed>(canon::Feed{{}, f, modal.path == PathMode::kExactStop}).target);
}

// True when the block was a plain block and has run, its command sent to
// `out`; false when nothing was done.
bool Interpreter::Impl::plain_block(const Words& words, CommandSink& out) {
  if (!plain.on || words.m_count != 0 || words.g_count > 1 ||
      (words.letters & ~plain.letters) != 0) {
    return false;
  }
  Motion motion = modal.motion;
  if (words.g_count == 1) {
    const int tenths = words.g[0].tenths();
    if (tenths < 0 || tenths % 10 != 0 || tenths > 30 ||
        !plain.motion_code[static_cast<std::size_t>(tenths / 10)]) {
      return false;
    }
    motion = static_cast<Motion>(tenths / 10);
  }
  if (motion > Motion::kCcwArc || modal.cycle != Cycle::kNone || modal.cutter != CutterComp::kOff ||
      !comp.idle() || modal.modal_macro || modal.feed_mode != FeedMode::kPerMinute ||
      frame_codes.polar) {
    return false;
  }
  if (shifts.take_changed()) plain.moves_pending = shifts.get().moves_pending();
  if (program_frame.take_changed()) plain.framed = frame().active();
  if (plain.moves_pending || plain.framed) return false;
  double feed = modal.feed;
  if (words.has('F')) {
    feed = words.at('F').value;
    if (feed < 0) return false;
  }
  const Motion was_motion = modal.motion;
  const double was_feed = modal.feed;
  modal.motion = motion;
  modal.feed = feed;
  const AxisVec* target = plain_move(words, plain_out.cmd, pos);
  if (target == &pos) {
    modal.motion = was_motion;
    modal.feed = was_feed;
    return false;
  }
  commit_messages();
  skip_state.step = 0;
  if (target == nullptr) return true;
  if (motion != Motion::kRapid) skip_state.last_cut_feed = feed;
  pos = *target;
  motion_since_sync = true;
  stamp(plain_out);
  out.emit(plain_out);
  return true;
}

void Interpreter::Impl::emit(CommandSink& out, canon::Command cmd) {
  canon::Stamped st{std::move(cmd)};
  stamp(st);
  out.emit(st);
}

}  // namespace skipnc::interp
