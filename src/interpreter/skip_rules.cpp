// The skip block's rules (skip_rules.hpp). Every behaviour that differs
// between controls is a switch of config::Switches, set in
// data/dialects/<name>.toml; the functions read nothing else but their
// arguments.
#include "interpreter/skip_rules.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "config/skip_inputs.hpp"

namespace skipnc::interp::skip_rules {

Result<Form> form(const BlockWords& b, const config::Switches& sw, bool cutter_comp) {
  // Addresses this control's G31 does not have.
  if (b.k && !sw.skip_k_word) {
    return fail(AlarmId::kSkipSyntax, "K is not an address of G31 on this control", b.k->at);
  }
  if (b.p && sw.skip_p_mode == config::SkipPMode::kNone) {
    return fail(AlarmId::kSkipSyntax, "P is not an address of G31 on this control", b.p->at);
  }
  if (b.g53 && !sw.skip_g53_allowed) {
    return fail(AlarmId::kSkipSyntax, "G53 cannot be commanded with G31 on this control", b.at);
  }
  if (sw.skip_requires_axis && b.moved.empty()) {
    return fail(AlarmId::kSkipSyntax, "G31 without a target (no axis word)", b.at);
  }
  Form f;
  if (b.p) {
    // P1. is refused as a decimal P, P#1 (= 1.) is a number like any other.
    const Word& pw = *b.p;
    if (pw.value != std::trunc(pw.value) || pw.value < 0 || pw.value > 1e6 ||
        (pw.has_point && !pw.is_expr)) {
      // P5. is a whole number written with a decimal point, which the
      // control refuses; P5.5 is no whole number.
      const bool whole = pw.value == std::trunc(pw.value);
      return fail(AlarmId::kSkipBadP,
                  whole ? fmt::format("P{}. is written with a decimal point: P is a whole number "
                                      "without one (P{})",
                                      pw.value, pw.value)
                        : fmt::format("P{} is not a whole number", pw.value),
                  pw.at);
    }
    f.p = static_cast<int>(pw.value);
  }
  f.torque = sw.torque_skip && (f.p == 98 || f.p == 99);
  if (b.q && !f.torque) {
    return fail(AlarmId::kSkipSyntax, "Q (torque limit override) needs G31 P98 or P99", b.q->at);
  }
  // Rules 6 and 41: the dialect may number the two differently.
  if (cutter_comp) {
    return fail(f.torque ? AlarmId::kTorqueSkipCutterComp : AlarmId::kSkipInCutterComp,
                "G31 with cutter radius compensation (G41/G42) active", b.at);
  }
  return f;
}

Result<Torque> torque(const BlockWords& b, const Form& f, std::string_view axis_names,
                      const config::Switches& sw, const config::Parameters& params) {
  // Seed 000, seed 004, Fanuc 30i: one axis only.
  if (b.moved.count() != 1) {
    return fail(AlarmId::kTorqueSkipAxes,
                "G31 P" + std::to_string(f.p) + " needs exactly one axis, " +
                    std::to_string(b.moved.count()) + " given",
                b.at);
  }
  Torque t;
  t.axis = std::countr_zero(b.moved.bits);
  if (sw.sync_axes_param != 0) {
    const auto sync = static_cast<long long>(params.get(sw.sync_axes_param));
    if (((sync >> t.axis) & 1LL) != 0) {
      return fail(AlarmId::kTorqueSkipSyncAxis,
                  std::string("axis ") + axis_names[static_cast<std::size_t>(t.axis)] +
                      " is under synchronous control (parameter " +
                      std::to_string(sw.sync_axes_param) + ")",
                  b.at);
    }
  }
  double q = sw.torque_q_param != 0 ? params.get(sw.torque_q_param) : 100.0;
  if (b.q) {
    q = b.q->value;
    if (q < 1 || q > 300) {
      return fail(AlarmId::kTorqueSkipBadQ, "Q" + std::to_string(q) + ": the override is 1-300 %",
                  b.q->at);
    }
  }
  // Q omitted and no override in the parameter: no torque limit was
  // commanded, so the limit never ends the block (Fanuc 30i).
  t.ends = q > 0.0;
  t.limit_pct = q;
  t.delay_s = sw.torque_delay_param != 0 ? params.get(sw.torque_delay_param) / 1000.0 : 0.0;
  return t;
}

Result<Inputs> inputs(const BlockWords& b, const Form& f, const config::Dialect& d,
                      const config::Parameters& params) {
  const config::Switches& sw = d.sw;
  Inputs in;
  auto add = [&](int index) {
    in.addr[static_cast<std::size_t>(in.count++)] = config::skip_input_address(d, params, index);
    in.highest = std::max(in.highest, index);
  };
  if (f.torque) {
    // P98: only the torque ends it; P99: the SKIP signal too (rules 38, 39).
    in.kind = canon::SkipKind::kTorque;
    if (f.p == 99) add(0);
    return in;
  }
  if (b.step != 0) {
    // G31.n (Mitsubishi multi-step skip function 1, M700V/M70V manual
    // 15.3): the logical sum of the skip signals set in the parameter.
    const int cond_param = kStepParam + 2 * (b.step - 1);
    const int cond = static_cast<int>(params.get(cond_param));
    if (cond <= 0) {
      return fail(AlarmId::kSkipBadP,
                  "G31." + std::to_string(b.step) + ": no skip signal set in parameter " +
                      std::to_string(cond_param),
                  b.at);
    }
    for (int i = 0; i < sw.skip_p_count && i < 8; ++i) {
      if (((cond >> i) & 1) != 0) add(i);
    }
    in.kind = canon::SkipKind::kMultiStep;
    return in;
  }
  if (f.p < 0) {
    add(0);  // no P: SKIP, input 1
    return in;
  }
  const SourceLoc p_at = b.p ? b.p->at : b.at;
  if (sw.skip_p_mode == config::SkipPMode::kBitmask) {
    const int max = (1 << sw.skip_p_count) - 1;
    if (f.p < 1 || f.p > max) {
      return fail(
          AlarmId::kSkipBadP,
          "P" + std::to_string(f.p) + ": the skip signal command is P1-P" + std::to_string(max),
          p_at);
    }
    for (int i = 0; i < sw.skip_p_count; ++i) {
      if (((f.p >> i) & 1) != 0) add(i);
    }
    in.kind = canon::SkipKind::kMultiStep;
    return in;
  }
  const int index = f.p - sw.skip_p_first;
  if (index < 0 || index >= sw.skip_p_count) {
    return fail(AlarmId::kSkipBadP,
                "P" + std::to_string(f.p) + ": skip inputs are P" +
                    std::to_string(sw.skip_p_first) + "-P" +
                    std::to_string(sw.skip_p_first + sw.skip_p_count - 1),
                p_at);
  }
  add(index);
  in.kind = sw.skip_p_mode == config::SkipPMode::kMultiStep ? canon::SkipKind::kMultiStep
                                                            : canon::SkipKind::kSkip;
  return in;
}

bool block_f_is_modal(const config::Switches& sw) noexcept {
  return sw.skip_feed != config::SkipFeedRule::kBlockOrParam;
}

Result<double> feed(const BlockWords& b, const FeedState& s, const config::Switches& sw,
                    const config::Parameters& params) {
  // Parameter feeds are in the machine's unit per minute.
  const double param_unit = s.inch_machine ? 25.4 : 1.0;
  auto param_feed = [&](int n) { return n != 0 ? params.get(n) * param_unit : 0.0; };
  double f = 0.0;
  switch (sw.skip_feed) {
    case config::SkipFeedRule::kModal:
      f = s.modal_mm_per_min;
      break;
    case config::SkipFeedRule::kBlockOrParam:
      // G31.n: its own feed parameter, the one after its condition.
      f = b.f_mm_per_min
              ? *b.f_mm_per_min
              : param_feed(b.step != 0 ? kStepParam + 2 * b.step - 1 : sw.skip_feed_param);
      break;
    case config::SkipFeedRule::kParamSwitch:
      f = params.get(sw.skip_feed_switch_param) != 0.0 ? param_feed(sw.skip_feed_param)
                                                       : s.modal_mm_per_min;
      break;
    case config::SkipFeedRule::kLastCutting:
      f = b.f_mm_per_min ? s.modal_mm_per_min : s.last_cutting_mm_per_min;
      break;
  }
  if (!(f > 0.0)) return fail(AlarmId::kSkipNoFeed, "G31 without a feed", b.at);
  return f;
}

Detection detection(const BlockWords& b, const Inputs& in, int length_axis,
                    const config::Switches& sw, const config::Parameters& params,
                    const config::MachineConfig& mc) {
  Detection r;
  const int sp = sw.skip_signal_param;
  const bool skf = sp != 0 && params.bit(sp, 7);
  // TSG and SK0 apply to the inputs the dialect says (Fanuc seed 000: SKIP,
  // SKIP2-SKIP4); SKIP5-SKIP12 stay level inputs active at 1.
  const bool bits =
      sp != 0 && (sw.skip_signal_param_inputs == 0 || in.highest < sw.skip_signal_param_inputs);
  r.active_low = bits && params.bit(sp, 1);
  r.edge = (bits && params.bit(sp, 0)) || sw.skip_edge_rising_only;
  if (sw.skip_edge_rising_only) r.active_low = false;
  r.active_at_start_ends = sw.skip_active_at_start_ends;
  switch (sw.skip_accel) {
    case config::SkipAccel::kSkfParam:
      r.accel = skf;
      break;
    case config::SkipAccel::kNever:
      r.accel = false;
      break;
    case config::SkipAccel::kAlways:
      r.accel = true;
      break;
  }
  r.stop = sw.skip_accel == config::SkipAccel::kSkfParam && skf ? canon::SkipStop::kDecelerate
                                                                : sw.skip_stop;
  switch (sw.skip_override) {
    case config::SkipOverride::kSkfParam:
      r.feed_fixed = !skf;
      break;
    case config::SkipOverride::kFixed:
      r.feed_fixed = true;
      break;
    case config::SkipOverride::kNormal:
      r.feed_fixed = false;
      break;
  }
  r.override_zero_stops = sw.skip_override == config::SkipOverride::kFixed;
  // How the position is latched is the machine's (its skip hardware), not
  // the dialect's.
  r.latch = mc.latch;
  r.latch_delay_s = mc.latch_delay_s;
  r.servo_delay_comp = mc.servo_delay_comp;
  r.locked_stores_command = sw.skip_locked_stores_command;
  if (sw.skip_ignored_when_locked) {
    // Mitsubishi (8): machine lock, or a Z-only G31 with the Z-axis cancel
    // switch on: the skip signal is ignored and the block runs to its end.
    const bool lock = sw.machine_lock_param != 0 && params.get(sw.machine_lock_param) != 0.0;
    const bool z_cancel = sw.z_cancel_param != 0 && params.get(sw.z_cancel_param) != 0.0;
    const bool z_only = length_axis >= 0 && b.moved.count() == 1 && b.moved.has(length_axis);
    r.ignore_inputs = lock || (z_cancel && z_only);
  }
  return r;
}

Result<bool> alarm_on_miss(const BlockWords& b, const config::Switches& sw,
                           const config::Parameters& params) {
  // K: alarm when the block ends without a skip (seed 000); K omitted: the
  // parameter, as the seed leaves the default open.
  bool k = sw.skip_miss_param != 0 && params.get(sw.skip_miss_param) != 0.0;
  if (b.k) {
    const double kv = b.k->value;
    if (kv != 0.0 && kv != 1.0) {
      return fail(AlarmId::kSkipSyntax, "K" + std::to_string(kv) + ": K is 0 or 1", b.k->at);
    }
    k = kv != 0.0;
  }
  return k;
}

}  // namespace skipnc::interp::skip_rules
