// Motion blocks: rapid, linear, circular, dwell, reference return and the
// skip family. Targets are computed in the block's modes and emitted in
// machine coordinates.
#include <cmath>
#include <string>

#include "config/skip_inputs.hpp"
#include "interpreter/impl.hpp"

namespace skipnc::interp {

Result<void> Interpreter::Impl::dwell(const Words& words, CommandSink& out) {
  double seconds = 0.0;
  if (words.has('P')) {
    const WordVal& p = words.at('P');
    if (p.has_point) {
      return fail(AlarmId::kBadDecimalPoint, "G04 P is in milliseconds, without decimal point",
                  loc(p.column));
    }
    seconds = p.value / 1000.0;
  } else if (words.has('X')) {
    seconds = word_length(words.at('X'), false);
  } else if (words.has('U')) {
    seconds = word_length(words.at('U'), false);
  }
  if (seconds < 0) return fail(AlarmId::kBadValue, "negative dwell", loc(cur_col));
  emit(out, canon::Dwell{seconds});
  motion_since_sync = true;
  return {};
}

Result<void> Interpreter::Impl::reference_return(const Words& words, int g, CommandSink& out) {
  (void)g;
  AxisVec mid = pos;
  AxisVec ref = pos;
  bool any = false;
  for (int i = 0; i < axis_count; ++i) {
    const char c = axis_letter[static_cast<std::size_t>(i)];
    if (!words.has(c)) continue;
    any = true;
    const double v = word_length(words.at(c), false);
    mid[i] = modal.distance == Distance::kAbsolute ? machine_of(i, v) : pos[i] + v * unit_mm();
    ref[i] = 0.0;  // reference position: machine zero
  }
  if (!any) return {};
  const bool linear = params.bit(1401, 1);
  emit(out, canon::Rapid{mid, linear});
  emit(out, canon::Rapid{ref, linear});
  pos = ref;
  motion_since_sync = true;
  return {};
}

Result<Step> Interpreter::Impl::motion(const Words& words, CommandSink& out, bool skip, bool g53) {
  AxisVec target = pos;
  AxisMask moved;
  for (int i = 0; i < axis_count; ++i) {
    const char c = axis_letter[static_cast<std::size_t>(i)];
    if (!words.has(c)) continue;
    const double v = word_length(words.at(c), false);
    if (g53 && modal.distance == Distance::kAbsolute) {
      target[i] = v * unit_mm();
    } else if (modal.distance == Distance::kAbsolute) {
      target[i] = machine_of(i, v);
    } else {
      target[i] = pos[i] + v * unit_mm();
    }
    moved.set(i);
  }
  if (skip) return skip_block(words, target, moved, out);
  const bool exact = modal.path == PathMode::kExactStop || words.has_g(90);
  switch (modal.motion) {
    case Motion::kRapid:
      emit(out, canon::Rapid{target, params.bit(1401, 1)});
      break;
    case Motion::kLinear:
      if (feed_mm_per_min() <= 0.0) {
        return fail(AlarmId::kNoFeed, "G01 without a feed (F)", loc(cur_col));
      }
      emit(out, canon::Feed{target, feed_mm_per_min(), exact});
      break;
    case Motion::kCwArc:
    case Motion::kCcwArc: {
      auto r = arc(words, target, out);
      if (!r) return std::unexpected(r.error());
      break;
    }
  }
  pos = target;
  motion_since_sync = true;
  return Step::kContinue;
}

Result<void> Interpreter::Impl::arc(const Words& words, const AxisVec& target, CommandSink& out) {
  canon::Plane pl;
  char ci = 'I', cj = 'J';
  auto idx = [&](char c) { return axis_of_letter[static_cast<std::size_t>(c - 'A')]; };
  switch (modal.plane) {
    case PlaneSel::kXY: pl = {idx('X'), idx('Y'), idx('Z')}; ci = 'I'; cj = 'J'; break;
    case PlaneSel::kZX: pl = {idx('Z'), idx('X'), idx('Y')}; ci = 'K'; cj = 'I'; break;
    case PlaneSel::kYZ: pl = {idx('Y'), idx('Z'), idx('X')}; ci = 'J'; cj = 'K'; break;
  }
  const SourceLoc at = loc(cur_col);
  if (pl.a0 < 0 || pl.a1 < 0) {
    return fail(AlarmId::kIllegalPlaneAxis, "the selected plane's axes are not on this machine", at);
  }
  if (feed_mm_per_min() <= 0.0) return fail(AlarmId::kNoFeed, "G02/G03 without a feed (F)", at);
  const double sx = pos[pl.a0], sy = pos[pl.a1];
  const double ex = target[pl.a0], ey = target[pl.a1];
  const bool ccw = modal.motion == Motion::kCcwArc;
  const double tol = params.get(3410) > 0 ? params.get(3410) : 0.02;
  double cx = 0, cy = 0;
  if (words.has('R')) {
    const double r = word_length(words.at('R'), false) * unit_mm();
    const double dx = ex - sx, dy = ey - sy;
    const double d = std::hypot(dx, dy);
    if (d < 1e-9) {
      return fail(AlarmId::kArcBadCenter, "a full circle cannot be programmed with R; use I, J or K", at);
    }
    if (r == 0.0) return fail(AlarmId::kArcBadCenter, "R0", loc(words.at('R').column));
    const double half = d / 2.0;
    if (half > std::fabs(r) + tol) {
      return fail(AlarmId::kArcRadiusMismatch,
                  "R" + std::to_string(std::fabs(r)) + " is smaller than half the chord " +
                      std::to_string(half),
                  loc(words.at('R').column));
    }
    const double h = std::sqrt(std::max(0.0, r * r - half * half));
    // Left of the chord for a short ccw arc; right for cw; R < 0 takes the long way.
    double side = ccw ? 1.0 : -1.0;
    if (r < 0) side = -side;
    cx = sx + dx / 2.0 - side * h * dy / d;
    cy = sy + dy / 2.0 + side * h * dx / d;
  } else if (words.has(ci) || words.has(cj)) {
    cx = sx + (words.has(ci) ? word_length(words.at(ci), false) * unit_mm() : 0.0);
    cy = sy + (words.has(cj) ? word_length(words.at(cj), false) * unit_mm() : 0.0);
    const double r0 = std::hypot(sx - cx, sy - cy);
    const double r1 = std::hypot(ex - cx, ey - cy);
    if (r0 < 1e-9) return fail(AlarmId::kArcBadCenter, "the arc's centre is its start point", at);
    if (std::fabs(r1 - r0) > tol) {
      return fail(AlarmId::kArcRadiusMismatch,
                  "start radius " + std::to_string(r0 / unit_mm()) + ", end radius " +
                      std::to_string(r1 / unit_mm()),
                  at);
    }
  } else {
    return fail(AlarmId::kArcBadCenter, "G02/G03 needs R or the centre (I, J, K)", at);
  }
  canon::Arc a;
  a.target = target;
  a.center0 = cx;
  a.center1 = cy;
  a.plane = pl;
  a.ccw = ccw;
  a.feed_mm_per_min = feed_mm_per_min();
  a.exact_stop = modal.path == PathMode::kExactStop || words.has_g(90);
  emit(out, a);
  return {};
}

Result<Step> Interpreter::Impl::skip_block(const Words& words, const AxisVec& target,
                                           AxisMask moved, CommandSink& out) {
  const SourceLoc at = loc(cur_col);
  const config::Switches& sw = dialect.sw;
  canon::Skip sk;
  sk.target = target;
  canon::SkipSpec& spec = sk.spec;
  int p = -1;
  if (words.has('P')) {
    const double pv = words.at('P').value;
    if (pv != std::trunc(pv) || pv < 0 || pv > 1e6) {
      return fail(AlarmId::kSkipBadP, "P" + std::to_string(pv), loc(words.at('P').column));
    }
    p = static_cast<int>(pv);
  }
  spec.p = p;
  const bool torque = sw.torque_skip && (p == 98 || p == 99);
  if (modal.cutter != CutterComp::kOff) {
    return fail(torque ? AlarmId::kTorqueSkipCutterComp : AlarmId::kSkipInCutterComp,
                "G31 with cutter radius compensation (G41/G42) active", at);
  }
  auto input_addr = [&](int index) { return config::skip_input_address(dialect, params, index); };
  pending_skip = PendingSkip{};
  if (torque) {
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
    double q = params.get(6280);
    if (words.has('Q')) q = words.at('Q').value;
    if (q < 1 || q > 300) {
      return fail(AlarmId::kTorqueSkipBadQ, "Q" + std::to_string(q) + ": the override is 1-300 %",
                  words.has('Q') ? loc(words.at('Q').column) : at);
    }
    spec.torque_ends = true;
    spec.torque_limit_pct = q;
    spec.torque_delay_s = params.get(6281) / 1000.0;
    if (p == 99) {
      spec.input_count = 1;
      spec.inputs[0] = input_addr(0);
    }
  } else {
    int index = 0;
    if (p >= 0) {
      if (!sw.multi_step) return fail(AlarmId::kSkipBadP, "this control has no multi-step skip", loc(words.at('P').column));
      index = p - sw.skip_p_first;
      if (index < 0 || index >= sw.skip_p_count) {
        return fail(AlarmId::kSkipBadP,
                    "P" + std::to_string(p) + ": skip inputs are P" + std::to_string(sw.skip_p_first) +
                        "-P" + std::to_string(sw.skip_p_first + sw.skip_p_count - 1),
                    loc(words.at('P').column));
      }
      spec.kind = canon::SkipKind::kMultiStep;
    }
    spec.input_count = 1;
    spec.inputs[0] = input_addr(index);
  }
  for (int i = 0; i < spec.input_count; ++i) {
    pending_skip.input_names[static_cast<std::size_t>(i)] = config::signal_name(spec.inputs[i]);
  }
  // Feed.
  double feed = 0.0;
  switch (sw.skip_feed) {
    case config::SkipFeedRule::kModal:
      feed = feed_mm_per_min();
      break;
    case config::SkipFeedRule::kBlockOrParam:
      feed = words.has('F') ? words.at('F').value * unit_mm() : params.get(sw.skip_feed_param) * unit_mm();
      break;
    case config::SkipFeedRule::kParamSwitch:
      feed = params.get(sw.skip_feed_switch_param) != 0.0 ? params.get(sw.skip_feed_param) * unit_mm()
                                                          : feed_mm_per_min();
      break;
  }
  if (feed <= 0.0) return fail(AlarmId::kSkipNoFeed, "G31 without a feed", at);
  sk.feed_mm_per_min = feed;
  // Signal detection and stopping.
  spec.active_low = params.bit(6200, 1);
  spec.edge = params.bit(6200, 0) || sw.skip_edge_rising_only;
  if (sw.skip_edge_rising_only) spec.active_low = false;
  spec.active_at_start_ends = sw.skip_active_at_start_ends;
  const bool skf = params.bit(6200, 7);
  spec.accel = skf;
  spec.stop = skf ? canon::SkipStop::kDecelerate : sw.skip_stop;
  spec.latch = mc.latch;
  spec.latch_delay_s = mc.latch_delay_s;
  spec.servo_delay_comp = mc.servo_delay_comp;
  bool k = sw.skip_miss_alarm_default || params.get(90001) != 0.0;
  if (words.has('K')) k = words.at('K').value != 0.0;
  spec.alarm_on_miss = k;
  // The record the report shows.
  SkipRecord& rec = pending_skip.record;
  rec.line = cur_line;
  std::string_view text = raw_text;
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
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

}  // namespace skipnc::interp
