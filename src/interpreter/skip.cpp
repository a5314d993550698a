// The skip family (G31): the dialect's rules turn a block into a canon::Skip
// (which inputs end it, how they are detected, the feed, how the axes stop),
// and finish_skip() takes back what the machine did and writes the results
// the dialect defines (#5061.., named variables, the report's record).
//
// The decisions are the pure functions of skip_rules.hpp (command form 1-6,
// feed 7-12, signal configuration 13-20, stopping 27, miss 33-36, torque
// limit skip 37-46 of skip-rules.md); skip_block gathers the block's words
// for them and keeps what belongs to the interpreter: the pending skip, the
// modal feed, the report's record. Latched values (21-26) are finish_skip's.
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "config/skip_inputs.hpp"
#include "interpreter/impl.hpp"
#include "interpreter/skip_rules.hpp"

namespace skipnc::interp {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

// G31 is a linear move on every control read (seeds 000-003: "linear
// interpolation"): arc words in its block are refused, not run straight.
Flow<void> Interpreter::Impl::refuse_skip_arc(const Words& words, SourceLoc at) const {
  for (const GCode g : {GCode(2), GCode(3)}) {
    if (words.has_g(g)) {
      return fail(AlarmId::kSkipSyntax,
                  code_name(g, CodeStyle::kManual) +
                      " cannot be commanded with G31: the skip is a linear move",
                  at);
    }
  }
  for (const char c : {'I', 'J', 'R'}) {
    if (words.has(c)) {
      return fail(AlarmId::kSkipSyntax,
                  std::string(1, c) +
                      " (an arc word) is not an address of G31: the skip is a "
                      "linear move",
                  loc(words.at(c).column));
    }
  }
  return {};
}

// What the skip rules read of the block.
skip_rules::BlockWords Interpreter::Impl::skip_words(const Words& words, AxisMask moved,
                                                     SourceLoc at) const {
  skip_rules::BlockWords b;
  auto word = [&](char c) -> std::optional<skip_rules::Word> {
    if (!words.has(c)) return std::nullopt;
    const WordVal& w = words.at(c);
    return skip_rules::Word{w.value, w.has_point, w.is_expr, loc(w.column)};
  };
  b.p = word('P');
  b.q = word('Q');
  b.k = word('K');
  if (words.has('F')) b.f_mm_per_min = feed_to_mm_per_min(words.at('F').value);
  b.g53 = words.has_g(GCode(53));
  b.moved = moved;
  b.step = skip_state.step;
  b.at = at;
  return b;
}

// The inputs that end the skip (and a torque limit skip's axis and limit);
// their names go to the pending skip's record.
Flow<void> Interpreter::Impl::skip_inputs(const skip_rules::BlockWords& b,
                                          const skip_rules::Form& form, canon::SkipSpec& spec) {
  const config::Switches& sw = dialect.sw;
  spec.p = form.p;
  if (form.torque) {
    auto t =
        skip_rules::torque(b, form, std::string_view(axis_letter.data(), axis_count), sw, params);
    SKIPNC_TRY(t);
    spec.torque_axis = t->axis;
    spec.torque_ends = t->ends;
    spec.torque_limit_pct = t->limit_pct;
    spec.torque_delay_s = t->delay_s;
  }
  auto in = skip_rules::inputs(b, form, dialect, params);
  SKIPNC_TRY(in);
  spec.kind = in->kind;
  spec.input_count = in->count;
  for (int i = 0; i < in->count; ++i) {
    const auto n = static_cast<std::size_t>(i);
    spec.inputs[n] = in->addr[n];
    pending_skip.input_names[n] = config::signal_name(in->addr[n]);
  }
  const skip_rules::Detection det = skip_rules::detection(b, *in, length_axis, sw, params, mc);
  spec.active_low = det.active_low;
  spec.edge = det.edge;
  spec.active_at_start_ends = det.active_at_start_ends;
  spec.ignore_inputs = det.ignore_inputs;
  spec.accel = det.accel;
  spec.stop = det.stop;
  spec.feed_fixed = det.feed_fixed;
  spec.override_zero_stops = det.override_zero_stops;
  spec.latch = det.latch;
  spec.latch_delay_s = det.latch_delay_s;
  spec.servo_delay_comp = det.servo_delay_comp;
  spec.locked_stores_command = det.locked_stores_command;
  return {};
}

Flow<Step> Interpreter::Impl::skip_block(const Words& words, const AxisVec& target, AxisMask moved,
                                         CommandSink& out) {
  if (modal.motion == Motion::kProbe && !words.has_g(GCode(31))) {
    return probe_block(target, moved, out);  // probe_g38.cpp
  }
  const SourceLoc at = loc(cur_col);
  const config::Switches& sw = dialect.sw;
  SKIPNC_TRY(refuse_skip_arc(words, at));
  const skip_rules::BlockWords b = skip_words(words, moved, at);
  auto form = skip_rules::form(b, sw, modal.cutter != CutterComp::kOff);
  SKIPNC_TRY(form);
  pending_skip = PendingSkip{};
  canon::Skip sk;
  sk.target = target;
  SKIPNC_TRY(skip_inputs(b, *form, sk.spec));

  const skip_rules::FeedState fs{feed_mm_per_min(), feed_to_mm_per_min(skip_state.last_cut_feed),
                                 mc.inch_machine};
  auto feed = skip_rules::feed(b, fs, sw, params);
  SKIPNC_TRY(feed);
  sk.feed_mm_per_min = *feed;
  if (words.has('F') && skip_rules::block_f_is_modal(sw)) skip_state.last_cut_feed = modal.feed;

  auto k = skip_rules::alarm_on_miss(b, sw, params);
  SKIPNC_TRY(k);
  sk.spec.alarm_on_miss = *k;
  return queue_skip(sk, at, out);
}

// The skip block goes to the machine; the interpreter waits for its answer
// (finish_skip). pending_skip's input names are set.
Flow<Step> Interpreter::Impl::queue_skip(const canon::Skip& sk, SourceLoc at, CommandSink& out) {
  const canon::SkipSpec& spec = sk.spec;
  const AxisVec& target = sk.target;
  // The record the report shows.
  SkipRecord& rec = pending_skip.record;
  rec.line = cur_line;
  rec.context = programs.frames.back().context;
  rec.n = blk.has_n ? static_cast<std::int32_t>(blk.n % 100000000) : -1;
  std::string_view text = raw.text;
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) {
    text.remove_suffix(1);
  }
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  rec.block = std::string(text);
  rec.code = pending_skip.g38 ? code_name(*pending_skip.g38) : "G31";
  rec.kind = spec.kind;
  rec.p = spec.p;
  pending_skip.target = target;
  pending_skip.alarm_on_miss = spec.alarm_on_miss;
  pending_skip.loc = at;
  emit(out, sk);
  pos = target;
  motion_since_sync = true;
  pending = Pending::kSkip;
  return Step::kSync;
}

// What every skip and probe block stores of the machine's answer: the
// latch (or without a signal the programmed end point) in machine and work
// coordinates, the position the next block starts from, the report's
// record. Returns the latch, machine coordinates.
AxisVec Interpreter::Impl::record_skip(const SyncState& s) {
  const PendingSkip& ps = pending_skip;
  const AxisVec latch = s.triggered ? s.latch_machine : ps.target;
  skip_result.machine = latch;
  // Controls that count in whole increments store the increment nearest
  // the latch (skip_position_increment); the report shows the same number.
  const double inc = modal.units == Units::kInch ? 0.0001 : 0.001;
  for (int i = 0; i < axis_count; ++i) {
    const double v = position_var(i, latch[i], dialect.sw.skip_tool_offsets);
    skip_result.work[i] = dialect.sw.skip_position_increment ? std::round(v / inc) * inc + 0.0 : v;
  }
  skip_result.have = true;
  pos = s.machine_position;
  SkipRecord rec = ps.record;
  rec.triggered = s.triggered;
  rec.time_s = s.time_s;
  rec.position = skip_result.work;
  rec.position_has_tool_offsets = dialect.sw.skip_tool_offsets;
  rec.machine_position = latch;
  // Machine lock / Z-axis cancel: #5061.. store the command at the signal
  // for a held axis, but the machine is where it stands (as #5021..).
  const bool lock =
      dialect.sw.machine_lock_param != 0 && params.get(dialect.sw.machine_lock_param) != 0.0;
  const bool z_cancel =
      dialect.sw.z_cancel_param != 0 && params.get(dialect.sw.z_cancel_param) != 0.0;
  for (int i = 0; i < axis_count; ++i) {
    if (lock || (z_cancel && axis_letter[static_cast<std::size_t>(i)] == 'Z'))
      rec.machine_position[i] = s.actual_position[i];
  }
  for (int i = 0; i < axis_count; ++i) rec.end_position[i] = work_of(i, pos[i]);
  if (s.triggered && s.input_index >= 0 && s.input_index < canon::SkipSpec::kMaxInputs) {
    rec.signal = ps.input_names[static_cast<std::size_t>(s.input_index)];
  } else if (s.triggered && s.torque_reached) {
    rec.signal = "TORQUE";
  }
  skips.push_back(rec);
  // A miss stores the end point: reading it as a touch is worth a warning.
  skip_state.missed_unread = !s.triggered && !g37.active() && !s.no_machine;
  skip_missed_line = rec.line;
  return latch;
}

// The machine's answer to a skip block. The latched position is stored in
// the dialect's variables, in work coordinates of the offsets active now,
// with the tool offsets in them or not as the dialect says (skip_tool_offsets:
// the tool reference point, Fanuc-class); without a signal the programmed end
// point is stored. The next block starts where the axes came to rest
// (#5001..), which differs from the latch by the stopping distance.
Flow<void> Interpreter::Impl::finish_skip(const SyncState& s) {
  PendingSkip& ps = pending_skip;
  if (ps.g38) return finish_probe(s);  // probe_g38.cpp
  const AxisVec latch = record_skip(s);
  const auto& sv = dialect.skip_vars;
  if (sv.success_flag > 0) vars.set(sv.success_flag, Value::of(s.triggered ? 1.0 : 0.0));
  if (!sv.named_machine.empty() || !sv.named_local.empty()) {
    // Named variables are stored as the parser reads them: upper case.
    int aux = 0;
    for (int i = 0; i < axis_count; ++i) {
      const char letter = axis_letter[static_cast<std::size_t>(i)];
      const std::string axis =
          letter == 'X' || letter == 'Y' || letter == 'Z' || sv.named_aux.empty()
              ? std::string(1, letter)
              : sv.named_aux + std::to_string(++aux);
      if (!sv.named_machine.empty()) {
        vars.set_named(upper(sv.named_machine + axis),
                       Value::of(latch[i] * axis_scale[static_cast<std::size_t>(i)] / unit_mm()));
      }
      if (!sv.named_local.empty()) {
        vars.set_named(upper(sv.named_local + axis), Value::of(skip_result.work[i]));
      }
    }
  }
  if (!s.triggered && ps.alarm_on_miss) {
    return fail(AlarmId::kSkipMiss, "the block reached its end point without a skip signal",
                ps.loc);
  }
  if (g37.active()) return finish_g37(s);  // mill_codes.cpp
  return {};
}

}  // namespace skipnc::interp
