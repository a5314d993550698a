// The skip family (G31): the dialect's rules turn a block into a canon::Skip
// (which inputs end it, how they are detected, the feed, how the axes stop),
// and finish_skip() takes back what the machine did and writes the results
// the dialect defines (#5061.., named variables, the report's record).
//
// Rules (../shared/spec/skip-rules.md): command form 1-6, feed 7-12, signal
// configuration 13-20, latched values 21-26, miss 33-36, torque limit skip
// 37-46. Every behaviour that differs between controls is a switch of
// config::Switches, set in data/dialects/<name>.toml.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "config/skip_inputs.hpp"
#include "interpreter/impl.hpp"

namespace skipnc::interp {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

Flow<Step> Interpreter::Impl::skip_block(const Words& words, const AxisVec& target, AxisMask moved,
                                         CommandSink& out) {
  const SourceLoc at = loc(cur_col);
  const config::Switches& sw = dialect.sw;
  auto word_loc = [&](char c) { return words.has(c) ? loc(words.at(c).column) : at; };
  canon::Skip sk;
  sk.target = target;
  canon::SkipSpec& spec = sk.spec;

  // Addresses this control's G31 does not have.
  if (words.has('K') && !sw.skip_k_word) {
    return fail(AlarmId::kSkipSyntax, "K is not an address of G31 on this control", word_loc('K'));
  }
  if (words.has('P') && sw.skip_p_mode == config::SkipPMode::kNone) {
    return fail(AlarmId::kSkipSyntax, "P is not an address of G31 on this control", word_loc('P'));
  }
  if (words.has_g(530) && !sw.skip_g53_allowed) {
    return fail(AlarmId::kSkipSyntax, "G53 cannot be commanded with G31 on this control", at);
  }
  if (sw.skip_requires_axis && moved.empty()) {
    return fail(AlarmId::kSkipSyntax, "G31 without a target (no axis word)", at);
  }
  int p = -1;
  if (words.has('P')) {
    const WordVal& pw = words.at('P');
    if (pw.value != std::trunc(pw.value) || pw.value < 0 || pw.value > 1e6 ||
        (pw.has_point && !pw.is_expr)) {
      return fail(AlarmId::kSkipBadP, "P" + std::to_string(pw.value) + " is not a whole number",
                  word_loc('P'));
    }
    p = static_cast<int>(pw.value);
  }
  spec.p = p;
  const bool torque = sw.torque_skip && (p == 98 || p == 99);
  if (words.has('Q') && !torque) {
    return fail(AlarmId::kSkipSyntax, "Q (torque limit override) needs G31 P98 or P99",
                word_loc('Q'));
  }
  if (modal.cutter != CutterComp::kOff) {
    return fail(torque ? AlarmId::kTorqueSkipCutterComp : AlarmId::kSkipInCutterComp,
                "G31 with cutter radius compensation (G41/G42) active", at);
  }
  auto input_addr = [&](int index) { return config::skip_input_address(dialect, params, index); };
  int last_input = -1;  // the highest input index of the block (SKIP = 0)
  auto add_input = [&](int index) {
    spec.inputs[spec.input_count++] = input_addr(index);
    last_input = std::max(last_input, index);
  };
  pending_skip = PendingSkip{};

  if (torque) {
    // Torque limit skip (seed 000, seed 004, Fanuc 30i): one axis only.
    spec.kind = canon::SkipKind::kTorque;
    if (moved.count() != 1) {
      return fail(AlarmId::kTorqueSkipAxes,
                  "G31 P" + std::to_string(p) + " needs exactly one axis, " +
                      std::to_string(moved.count()) + " given",
                  at);
    }
    for (int i = 0; i < axis_count; ++i) {
      if (moved.has(i)) spec.torque_axis = i;
    }
    if (sw.sync_axes_param != 0) {
      const auto sync = static_cast<long long>(params.get(sw.sync_axes_param));
      if (((sync >> spec.torque_axis) & 1LL) != 0) {
        return fail(AlarmId::kTorqueSkipSyncAxis,
                    std::string("axis ") + axis_letter[static_cast<std::size_t>(spec.torque_axis)] +
                        " is under synchronous control (parameter " +
                        std::to_string(sw.sync_axes_param) + ")",
                    at);
      }
    }
    double q = sw.torque_q_param != 0 ? params.get(sw.torque_q_param) : 100.0;
    if (words.has('Q')) {
      q = words.at('Q').value;
      if (q < 1 || q > 300) {
        return fail(AlarmId::kTorqueSkipBadQ, "Q" + std::to_string(q) + ": the override is 1-300 %",
                    word_loc('Q'));
      }
    }
    // Q omitted and no override in the parameter: no torque limit was
    // commanded, so the limit never ends the block (Fanuc 30i).
    spec.torque_ends = q > 0.0;
    spec.torque_limit_pct = q;
    spec.torque_delay_s =
        sw.torque_delay_param != 0 ? params.get(sw.torque_delay_param) / 1000.0 : 0.0;
    if (p == 99) add_input(0);  // P99: the SKIP signal ends it too; P98: only the torque
  } else if (skip_step != 0) {
    // G31.n (Mitsubishi multi-step skip function 1, M700V/M70V manual
    // 15.3): the logical sum of the skip signals set in the parameter.
    const int cond_param = kSkipStepParam + 2 * (skip_step - 1);
    const int cond = static_cast<int>(params.get(cond_param));
    if (cond <= 0) {
      return fail(AlarmId::kSkipBadP,
                  "G31." + std::to_string(skip_step) + ": no skip signal set in parameter " +
                      std::to_string(cond_param),
                  at);
    }
    for (int i = 0; i < sw.skip_p_count && i < 8; ++i) {
      if (((cond >> i) & 1) != 0) add_input(i);
    }
    spec.kind = canon::SkipKind::kMultiStep;
  } else if (p >= 0) {
    const SourceLoc p_at = word_loc('P');
    if (sw.skip_p_mode == config::SkipPMode::kBitmask) {
      const int max = (1 << sw.skip_p_count) - 1;
      if (p < 1 || p > max) {
        return fail(
            AlarmId::kSkipBadP,
            "P" + std::to_string(p) + ": the skip signal command is P1-P" + std::to_string(max),
            p_at);
      }
      for (int i = 0; i < sw.skip_p_count; ++i) {
        if (((p >> i) & 1) != 0) add_input(i);
      }
      spec.kind = canon::SkipKind::kMultiStep;
    } else {
      const int index = p - sw.skip_p_first;
      if (index < 0 || index >= sw.skip_p_count) {
        return fail(AlarmId::kSkipBadP,
                    "P" + std::to_string(p) + ": skip inputs are P" +
                        std::to_string(sw.skip_p_first) + "-P" +
                        std::to_string(sw.skip_p_first + sw.skip_p_count - 1),
                    p_at);
      }
      add_input(index);
      spec.kind = sw.skip_p_mode == config::SkipPMode::kMultiStep ? canon::SkipKind::kMultiStep
                                                                  : canon::SkipKind::kSkip;
    }
  } else {
    add_input(0);
  }
  for (int i = 0; i < spec.input_count; ++i) {
    pending_skip.input_names[static_cast<std::size_t>(i)] = config::signal_name(spec.inputs[i]);
  }

  // Feed. Parameter feeds are in the machine's unit per minute.
  const double param_unit = mc.inch_machine ? 25.4 : 1.0;
  auto param_feed = [&](int n) { return n != 0 ? params.get(n) * param_unit : 0.0; };
  double feed = 0.0;
  switch (sw.skip_feed) {
    case config::SkipFeedRule::kModal:
      feed = feed_mm_per_min();  // the block's F is already modal (ncblock.cpp)
      break;
    case config::SkipFeedRule::kBlockOrParam:
      // The block's F is not made modal (ncblock.cpp). G31.n: its own
      // feed parameter (the one after its condition).
      feed = words.has('F') ? feed_to_mm_per_min(words.at('F').value)
                            : param_feed(skip_step != 0 ? kSkipStepParam + 2 * skip_step - 1
                                                        : sw.skip_feed_param);
      break;
    case config::SkipFeedRule::kParamSwitch:
      feed = params.get(sw.skip_feed_switch_param) != 0.0 ? param_feed(sw.skip_feed_param)
                                                          : feed_mm_per_min();
      break;
    case config::SkipFeedRule::kLastCutting:
      feed = words.has('F') ? feed_mm_per_min() : feed_to_mm_per_min(last_cut_feed);
      break;
  }
  if (!(feed > 0.0)) return fail(AlarmId::kSkipNoFeed, "G31 without a feed", at);
  sk.feed_mm_per_min = feed;
  if (words.has('F') && sw.skip_feed != config::SkipFeedRule::kBlockOrParam) {
    last_cut_feed = modal.feed;
  }

  // Signal detection, feed override and stopping.
  const int sp = sw.skip_signal_param;
  const bool skf = sp != 0 && params.bit(sp, 7);
  // TSG and SK0 apply to the inputs the dialect says (Fanuc seed 000: SKIP,
  // SKIP2-SKIP4); SKIP5-SKIP12 stay level inputs active at 1.
  const bool bits =
      sp != 0 && (sw.skip_signal_param_inputs == 0 || last_input < sw.skip_signal_param_inputs);
  spec.active_low = bits && params.bit(sp, 1);
  spec.edge = (bits && params.bit(sp, 0)) || sw.skip_edge_rising_only;
  if (sw.skip_edge_rising_only) spec.active_low = false;
  spec.active_at_start_ends = sw.skip_active_at_start_ends;
  switch (sw.skip_accel) {
    case config::SkipAccel::kSkfParam:
      spec.accel = skf;
      break;
    case config::SkipAccel::kNever:
      spec.accel = false;
      break;
    case config::SkipAccel::kAlways:
      spec.accel = true;
      break;
  }
  spec.stop = sw.skip_accel == config::SkipAccel::kSkfParam && skf ? canon::SkipStop::kDecelerate
                                                                   : sw.skip_stop;
  switch (sw.skip_override) {
    case config::SkipOverride::kSkfParam:
      spec.feed_fixed = !skf;
      break;
    case config::SkipOverride::kFixed:
      spec.feed_fixed = true;
      break;
    case config::SkipOverride::kNormal:
      spec.feed_fixed = false;
      break;
  }
  spec.override_zero_stops = sw.skip_override == config::SkipOverride::kFixed;
  spec.latch = mc.latch;
  spec.latch_delay_s = mc.latch_delay_s;
  spec.servo_delay_comp = mc.servo_delay_comp;
  spec.locked_stores_command = sw.skip_locked_stores_command;
  if (sw.skip_ignored_when_locked) {
    // Mitsubishi (8): machine lock, or a Z-only G31 with the Z-axis cancel
    // switch on: the skip signal is ignored and the block runs to its end.
    const bool lock = sw.machine_lock_param != 0 && params.get(sw.machine_lock_param) != 0.0;
    const bool z_cancel = sw.z_cancel_param != 0 && params.get(sw.z_cancel_param) != 0.0;
    const bool z_only = length_axis >= 0 && moved.count() == 1 && moved.has(length_axis);
    spec.ignore_inputs = lock || (z_cancel && z_only);
  }

  // K: alarm when the block ends without a skip (seed 000).
  bool k = sw.skip_miss_param != 0 && params.get(sw.skip_miss_param) != 0.0;
  if (words.has('K')) {
    const double kv = words.at('K').value;
    if (kv != 0.0 && kv != 1.0) {
      return fail(AlarmId::kSkipSyntax, "K" + std::to_string(kv) + ": K is 0 or 1", word_loc('K'));
    }
    k = kv != 0.0;
  }
  spec.alarm_on_miss = k;

  // The record the report shows.
  SkipRecord& rec = pending_skip.record;
  rec.line = cur_line;
  rec.context = frames.back().context;
  rec.n = blk.has_n ? static_cast<std::int32_t>(blk.n % 100000000) : -1;
  std::string_view text = raw.text;
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) {
    text.remove_suffix(1);
  }
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  rec.block = std::string(text);
  rec.kind = spec.kind;
  rec.p = p;
  pending_skip.target = target;
  pending_skip.alarm_on_miss = k;
  pending_skip.loc = at;
  emit(out, sk);
  pos = target;
  motion_since_sync = true;
  pending = Pending::kSkip;
  return Step::kSync;
}

// The machine's answer to a skip block. The latched position is stored in
// the dialect's variables, in work coordinates of the offsets active now,
// with the tool offsets in them or not as the dialect says (skip_tool_offsets:
// the tool reference point, Fanuc-class); without a signal the programmed end
// point is stored. The next block starts where the axes came to rest
// (#5001..), which differs from the latch by the stopping distance.
Flow<void> Interpreter::Impl::finish_skip(const SyncState& s) {
  PendingSkip& ps = pending_skip;
  const AxisVec latch = s.triggered ? s.latch_machine : ps.target;
  skip_machine = latch;
  for (int i = 0; i < axis_count; ++i) {
    skip_work[i] = position_var(i, latch[i], dialect.sw.skip_tool_offsets);
  }
  have_skip = true;
  pos = s.machine_position;
  SkipRecord rec = ps.record;
  rec.triggered = s.triggered;
  rec.time_s = s.time_s;
  rec.position = skip_work;
  rec.position_has_tool_offsets = dialect.sw.skip_tool_offsets;
  rec.machine_position = latch;
  for (int i = 0; i < axis_count; ++i) rec.end_position[i] = work_of(i, pos[i]);
  if (s.triggered && s.input_index >= 0 && s.input_index < canon::SkipSpec::kMaxInputs) {
    rec.signal = ps.input_names[static_cast<std::size_t>(s.input_index)];
  } else if (s.triggered && s.torque_reached) {
    rec.signal = "TORQUE";
  }
  skips.push_back(rec);
  // A miss stores the end point: reading it as a touch is worth a warning.
  skip_missed_unread = !s.triggered && ps.g37_axis < 0;
  skip_missed_line = rec.line;
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
        vars.set_named(upper(sv.named_local + axis), Value::of(skip_work[i]));
      }
    }
  }
  if (!s.triggered && ps.alarm_on_miss) {
    return fail(AlarmId::kSkipMiss, "the block reached its end point without a skip signal",
                ps.loc);
  }
  if (ps.g37_axis >= 0) return finish_g37(s);  // mill_codes.cpp
  return {};
}

}  // namespace skipnc::interp
