#include "kernel/kernel.hpp"

#include <cassert>
#include <cmath>
#include <type_traits>

namespace skipnc::kernel {

Kernel::Kernel(const KernelConfig& cfg)
    : cfg_(cfg), queue_(cfg.limits, cfg.queue_capacity), interpolator_(queue_) {
  all_axes_ = (1U << cfg_.limits.axis_count) - 1U;
  min_accel_mm_s2_ = 1e300;
  for (int i = 0; i < cfg_.limits.axis_count; ++i) {
    min_accel_mm_s2_ =
        std::fmin(min_accel_mm_s2_, cfg_.limits.axes[static_cast<std::size_t>(i)].max_accel_mm_s2);
  }
}

void Kernel::set_axis_rate(const canon::AxisRate& r) noexcept {
  if (r.axis < 0 || r.axis >= cfg_.limits.axis_count) return;
  planner::AxisLimits& a = cfg_.limits.axes[static_cast<std::size_t>(r.axis)];
  if (r.rate_mm_per_min > 0.0) {
    a.max_velocity_mm_s = r.rate_mm_per_min / 60.0;
    a.rapid_mm_s = r.rate_mm_per_min / 60.0;
  }
  if (r.accel_mm_s2 > 0.0) a.max_accel_mm_s2 = r.accel_mm_s2;
  double feed = 0.0;
  min_accel_mm_s2_ = 1e300;
  for (int i = 0; i < cfg_.limits.axis_count; ++i) {
    const planner::AxisLimits& l = cfg_.limits.axes[static_cast<std::size_t>(i)];
    feed = std::fmax(feed, l.max_velocity_mm_s);
    min_accel_mm_s2_ = std::fmin(min_accel_mm_s2_, l.max_accel_mm_s2);
  }
  cfg_.limits.max_feed_mm_s = feed;
  queue_.set_limits(cfg_.limits);
}

void Kernel::set_position(const AxisVec& machine) noexcept {
  interpolator_.set_position(machine);
  cmd_ = machine;
  cmd_prev_ = machine;
  actual_prev_ = machine;
  in_position_ = true;  // at rest there
  inpos_wait_ = 0;
  fault_ = Fault{};
}

// The servo's faults, on the period that just ended: the axes followed cmd_.
// A locked axis does not move, so it has no following error to check.
bool Kernel::check_servo(const TickInput& in) noexcept {
  const FaultLimits& f = cfg_.faults;
  const int n = cfg_.limits.axis_count;
  // Over all axes without a branch first (locked ones too); the axis is
  // looked for only when one may be out.
  bool over = false;
  for (int i = 0; i < n; ++i) {
    over |= std::fabs(cmd_prev_[i] - in.actual[i]) > f.excess_error[static_cast<std::size_t>(i)];
  }
  for (int i = 0; over && i < n; ++i) {
    const double fe = cmd_prev_[i] - in.actual[i];
    if (!locked_.has(i) && std::fabs(fe) > f.excess_error[static_cast<std::size_t>(i)]) {
      fault_ = Fault{Fault::Kind::kExcessError, i, fe, f.excess_error[static_cast<std::size_t>(i)]};
      return true;
    }
  }
  if (static_cast<double>(inpos_wait_) * cfg_.clock.period_s() > f.in_position_timeout_s) {
    int worst = 0;
    double worst_fe = 0.0;
    for (int i = 0; i < n; ++i) {
      const double fe = cmd_prev_[i] - in.actual[i];
      if (std::fabs(fe) > std::fabs(worst_fe)) {
        worst = i;
        worst_fe = fe;
      }
    }
    fault_ = Fault{Fault::Kind::kInPositionTimeout, worst, worst_fe, f.in_position_timeout_s};
    return true;
  }
  return false;
}

// Whether check_servo or check_stroke could find a fault: some axis's
// following error beyond its limit, the command beyond a stroke end, or the
// in-position wait beyond its timeout (the same comparisons as theirs).
bool Kernel::may_fault(const TickInput& in) const noexcept {
  const FaultLimits& f = cfg_.faults;
  // Comparisons as 0 or 1, or-ed without a branch.
  auto bit = [](bool b) { return static_cast<unsigned>(b); };
  unsigned out =
      bit(static_cast<double>(inpos_wait_) * cfg_.clock.period_s() > f.in_position_timeout_s);
  for (int i = 0; i < cfg_.limits.axis_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out |= bit(std::fabs(cmd_prev_[i] - in.actual[i]) > f.excess_error[k]) |
           bit(cmd_[i] > f.stroke_max[k]) | bit(cmd_[i] < f.stroke_min[k]);
  }
  return out != 0;
}

// The stroke limits on the command for the next period, over all axes
// without a branch; the axis is looked for only when one is out. The command
// beyond the end is not given: the kernel holds the one before.
bool Kernel::check_stroke() noexcept {
  const FaultLimits& f = cfg_.faults;
  const int n = cfg_.limits.axis_count;
  bool beyond = false;
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    beyond = beyond || cmd_[i] > f.stroke_max[k] || cmd_[i] < f.stroke_min[k];
  }
  if (!beyond) return false;
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (cmd_[i] > f.stroke_max[k] || cmd_[i] < f.stroke_min[k]) {
      fault_ = Fault{Fault::Kind::kStrokeLimit, i, cmd_[i],
                     cmd_[i] > f.stroke_max[k] ? f.stroke_max[k] : f.stroke_min[k]};
      break;
    }
  }
  cmd_ = cmd_prev_;
  return true;
}

bool Kernel::push(const canon::Stamped& stamped) {
  // Refused before anything changes: a skip command below resets the skip
  // block's state, and the tag is the command's for good once given.
  if (queue_.full()) return false;
  planner::Move m;
  m.line = stamped.line;
  m.source = stamped.source;
  m.tag = next_tag_++;
  if (next_tag_ == 0) next_tag_ = 1;
  std::visit(
      [&](const auto& c) {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, canon::Rapid>) {
          m.kind = c.linear ? planner::Move::Kind::kRapid : planner::Move::Kind::kRapidNonLinear;
          m.target = c.target;
          m.exact_stop = true;
          m.in_position = cfg_.rapid_in_position;
        } else if constexpr (std::is_same_v<T, canon::Feed>) {
          m.kind = planner::Move::Kind::kLine;
          m.target = c.target;
          m.feed_mm_s = c.feed_mm_per_min / 60.0;
          m.exact_stop = c.exact_stop;
          m.in_position = c.exact_stop;
        } else if constexpr (std::is_same_v<T, canon::Arc>) {
          m.kind = planner::Move::Kind::kArc;
          m.target = c.target;
          m.feed_mm_s = c.feed_mm_per_min / 60.0;
          m.center0 = c.center0;
          m.center1 = c.center1;
          m.plane = c.plane;
          m.ccw = c.ccw;
          m.extra_turns = c.extra_turns;
          m.exact_stop = c.exact_stop;
          m.in_position = c.exact_stop;
        } else if constexpr (std::is_same_v<T, canon::Dwell>) {
          m.kind = planner::Move::Kind::kDwell;
          m.target = queue_.tail_position();
          m.dwell_s = c.seconds;
          m.wait_in_position = true;
        } else if constexpr (std::is_same_v<T, canon::Skip>) {
          m.kind = planner::Move::Kind::kLine;
          m.target = c.target;
          m.feed_mm_s = c.feed_mm_per_min / 60.0;
          m.exact_stop = true;
          m.wait_in_position = true;
          m.no_accel = !c.spec.accel;
          skip_ = SkipResult{};
          skip_.active = true;
          skip_.spec = c.spec;
          skip_.target = c.target;
          skip_.line = stamped.line;
          skip_.source = stamped.source;
          skip_tag_ = m.tag;
          skip_started_ = false;
          skip_stopping_ = false;
          skip_latch_pending_ = false;
          torque_since_s_ = -1.0;
          latch_at_stop_ = false;
        } else {
          m.kind = planner::Move::Kind::kDwell;  // not reached: other commands are not queued
          m.dwell_s = 0.0;
          m.target = queue_.tail_position();
        }
      },
      stamped.cmd);
  // The queue had room (checked above), so it takes the move.
  const bool taken = queue_.push(m);
  assert(taken);
  return taken;
}

bool Kernel::axes_in_position(const AxisVec& actual) const noexcept {
  // One bit per axis, no branch per axis.
  unsigned inpos = locked_.bits;
  for (int i = 0; i < cfg_.limits.axis_count; ++i) {
    inpos |= static_cast<unsigned>(std::fabs(cmd_[i] - actual[i]) <= cfg_.in_position_mm) << i;
  }
  return (inpos & all_axes_) == all_axes_;
}

bool Kernel::input_active(bool level) const noexcept {
  return level != skip_.spec.active_low;
}

void Kernel::trigger(double frac, const TickInput& in, int input, bool torque) noexcept {
  skip_.triggered = true;
  skip_.input_index = input;
  skip_.torque_reached = torque;
  skip_.time_s = cfg_.clock.seconds(tick_, frac);
  skip_.latch_actual = lerp(actual_prev_, in.actual, frac);
  skip_.latch_command = lerp(cmd_prev_, cmd_, frac);
  handshake_.skip = input >= 0;
  if (torque) {
    // The block ends from the mechanical stop position: the command follows
    // up to where the axis is held, and that is what is stored.
    skip_.latch_machine = in.actual;
    interpolator_.set_position(in.actual);
    cmd_ = in.actual;
    followed_up_ = true;
    skip_stopping_ = true;
    handshake_.recorded = true;
    return;
  }
  skip_.latch_machine = stored_latch();
  // Torque limit skip ended by the SKIP signal (P99): the variables hold the
  // coordinates where the machine stopped, not those at the signal (Fanuc 30i).
  latch_at_stop_ = skip_.spec.kind == canon::SkipKind::kTorque;
  if (skip_.spec.latch == canon::SkipLatch::kSampled && skip_.spec.latch_delay_s > 0.0 &&
      !latch_at_stop_) {
    // The control learns of the signal only after the detection delay: the
    // latch and the stop both wait for it (monitor_skip), and the axes keep
    // moving meanwhile.
    skip_latch_pending_ = true;
    skip_latch_due_s_ = skip_.time_s + skip_.spec.latch_delay_s;
    return;
  }
  if (!latch_at_stop_) handshake_.recorded = true;
  begin_stop();
}

// The point the control stores for a signal: the actual position (servo
// delay compensated) or the command. An axis that does not move (machine
// lock, Z-axis cancel) stores its command when the dialect says so: the
// position the control counts, as its work position does
// (docs/skip-dialects.md, `skip_locked_stores_command`).
AxisVec Kernel::stored_latch() const noexcept {
  const canon::SkipSpec& spec = skip_.spec;
  AxisVec p = spec.servo_delay_comp ? skip_.latch_actual : skip_.latch_command;
  if (spec.locked_stores_command && !locked_.empty()) {
    for (int i = 0; i < kMaxAxes; ++i) {
      if (locked_.has(i)) p[i] = skip_.latch_command[i];
    }
  }
  return p;
}

void Kernel::begin_stop() noexcept {
  if (skip_.spec.stop == canon::SkipStop::kImmediate) {
    interpolator_.stop_now();
  } else {
    // Linear deceleration at the path's acceleration limit (the smallest
    // a_i / |u_i| over the moving axes).
    const AxisVec& v = interpolator_.velocity();
    const double speed = norm(v, cfg_.limits.axis_count);
    double a = 0.0;
    if (speed > 0.0) {
      a = 1e300;
      for (int i = 0; i < cfg_.limits.axis_count; ++i) {
        const double u = std::fabs(v[i]) / speed;
        if (u > 1e-12)
          a = std::fmin(a, cfg_.limits.axes[static_cast<std::size_t>(i)].max_accel_mm_s2 / u);
      }
    }
    if (a > 0.0 && a < 1e300) {
      interpolator_.decelerate(a);
    } else {
      interpolator_.stop_now();
    }
  }
  skip_stopping_ = true;
}

// The skip block has just become the active segment (in this period). A
// level input already active then (Fanuc TSG = 0, NCT, Mitsubishi) ends the
// block with no motion at all: the command goes back to the block's start
// point before it reaches the servo, and that point and this period's time
// are the latch. Under active_at_start_fails (G38) the block ends the same
// way, not triggered, and the interpreter raises the alarm. A block shorter
// than one period's travel, or of no length, is no exception: with the input
// on it ends at its start point, a detected signal.
void Kernel::start_skip_block(const TickInput& in) noexcept {
  skip_started_ = true;
  handshake_ = SkipHandshake{true, false, false, false};
  const canon::SkipSpec& spec = skip_.spec;
  const bool fails = spec.active_at_start_fails;  // G38: an error, not a trigger
  if (spec.ignore_inputs || (!fails && (spec.edge || !spec.active_at_start_ends))) return;
  for (int i = 0; i < spec.input_count; ++i) {
    if (!input_active(signals_.get(spec.inputs[i]))) continue;
    // A block already run to its end in this period started where the
    // command was before it.
    const AxisVec start = interpolator_.idle() ? cmd_prev_ : interpolator_.segment_start();
    interpolator_.set_position(start);
    cmd_ = start;
    skip_.input_index = i;
    skip_.time_s = cfg_.clock.seconds(tick_ - 1);  // the period this command starts
    skip_.latch_machine = start;
    skip_stopping_ = true;
    if (fails) {
      skip_.active_at_start = true;
      return;
    }
    skip_.triggered = true;
    skip_.latch_actual = in.actual;
    skip_.latch_command = start;
    handshake_.skip = true;
    handshake_.recorded = true;
    return;
  }
}

void Kernel::monitor_skip(const TickInput& in) noexcept {
  if (!skip_.active || skip_.done) return;
  const canon::SkipSpec& spec = skip_.spec;
  if (!skip_started_) {
    if (interpolator_.idle()) {
      // The skip move had no length: it ends at once, with the signal if
      // an input is already on (start_skip_block), else without one.
      start_skip_block(in);
    } else {
      return;
    }
  }
  if (!skip_.triggered && !skip_.active_at_start) {
    if (!spec.ignore_inputs) {
      for (int e = 0; e < in.edge_count; ++e) {
        const SignalEdge& edge = in.edges[static_cast<std::size_t>(e)];
        for (int i = 0; i < spec.input_count; ++i) {
          if (!(edge.addr == spec.inputs[i]) || !input_active(edge.level)) continue;
          // An edge into the active state: level and edge detection alike.
          const double frac = spec.latch == canon::SkipLatch::kExact ? edge.frac : 1.0;
          trigger(frac, in, i, false);
          return;
        }
      }
    }
    if (spec.torque_ends && spec.torque_axis >= 0) {
      const double torque = std::fabs(in.torque_pct[spec.torque_axis]);
      const double now_s = cfg_.clock.seconds(tick_);
      if (torque >= spec.torque_limit_pct) {
        if (torque_since_s_ < 0.0) torque_since_s_ = now_s;
        if (now_s - torque_since_s_ >= spec.torque_delay_s - 1e-12) {
          trigger(1.0, in, -1, true);
          return;
        }
      } else {
        torque_since_s_ = -1.0;
      }
    }
  }
  if (skip_latch_pending_) {
    const double t0 = cfg_.clock.seconds(tick_ - 1);
    const double t1 = cfg_.clock.seconds(tick_);
    if (skip_latch_due_s_ <= t1) {
      const double frac = std::fmin(1.0, std::fmax(0.0, (skip_latch_due_s_ - t0) / (t1 - t0)));
      skip_.latch_actual = lerp(actual_prev_, in.actual, frac);
      skip_.latch_command = lerp(cmd_prev_, cmd_, frac);
      skip_.latch_machine = stored_latch();
      skip_.time_s = skip_latch_due_s_;
      skip_latch_pending_ = false;
      handshake_.recorded = true;
      begin_stop();
    }
  }
}

// The rate at which profile time advances this period. Two factors ramp at
// the slowest axis's acceleration (at the active segment's nominal speed):
// the hold factor (0 in feed hold or interlock, and for a fixed-feed skip
// block whose control stops at override 0 %) and the override factor. Dry
// run replaces a cutting move's feed at once (the ratio is per segment). A
// skip block with a fixed feed runs at 100 % whatever the override says.
double Kernel::advance_time_scale() noexcept {
  if (full_rate_) return 1.0;  // the ramps are settled (quiet_ticks)
  const planner::Segment* seg = queue_.front();
  const bool cutting = seg != nullptr && (seg->kind == planner::Move::Kind::kLine ||
                                          seg->kind == planner::Move::Kind::kArc);
  const bool fixed =
      cutting && skip_.active && !skip_.done && seg->tag == skip_tag_ && skip_.spec.feed_fixed;
  const double ovr = override_;
  const bool hold =
      op_.feed_hold || op_.interlock || (fixed && skip_.spec.override_zero_stops && ovr <= 0.0);
  const double v_nom = seg != nullptr ? seg->v_max : 0.0;
  if (v_nom != ramp_v_nom_) {  // a new segment's speed: the step once, not every period
    ramp_v_nom_ = v_nom;
    ramp_step_ = v_nom > 0.0 ? min_accel_mm_s2_ * cfg_.clock.period_s() / v_nom : 1e300;
  }
  const double step = ramp_step_;
  auto ramp = [&](double& x, double target) {
    x = target > x ? std::min(target, x + step) : std::max(target, x - step);
  };
  ramp(hold_factor_, hold ? 0.0 : 1.0);
  ramp(override_factor_, ovr);
  ramps_settled_ = hold_factor_ == (hold ? 0.0 : 1.0) && override_factor_ == ovr;
  double scale = hold_factor_;
  if (cutting && !fixed) {
    scale *= override_factor_;
    if (op_.dry_run && op_.dry_run_feed_mm_min > 0.0 && seg->v_max > 0.0) {
      scale *= std::fmin(op_.dry_run_feed_mm_min / 60.0, cfg_.limits.max_feed_mm_s) / seg->v_max;
    }
  }
  update_full_rate();
  return scale;
}

std::int64_t Kernel::quiet_ticks() const noexcept {
  if (fault_ || followed_up_ || !(full_rate_ || ramps_settled_) || skip_latch_pending_) return 0;
  if ((skip_.active && !skip_.done) || interpolator_.needs_in_position()) return 0;
  return interpolator_.quiet_ticks();
}

std::int64_t Kernel::cruise_ticks() const noexcept {
  if (fault_ || followed_up_ || !full_rate_ || skip_latch_pending_ || skip_.active) return 0;
  if (interpolator_.needs_in_position()) return 0;
  const std::int64_t n = interpolator_.cruise_ticks();
  if (n <= 0) return 0;
  // A straight line: within the stroke all along when its end is (its
  // start, the command already checked, is).
  const AxisVec end = interpolator_.segment_end();
  const FaultLimits& f = cfg_.faults;
  for (int i = 0; i < cfg_.limits.axis_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (end[i] > f.stroke_max[k] || end[i] < f.stroke_min[k]) return 0;
  }
  return n;
}

void Kernel::pass_cruise(std::int64_t n, TickOutput& out) noexcept {
  tick_ += n;
  interpolator_.pass_cruise(n, cmd_prev_);
  cmd_ = interpolator_.position();
  out.commanded = cmd_;
  out.velocity = interpolator_.velocity();
  out.path_speed = interpolator_.path_speed();
  out.passed_dwell_line = 0;
}

void Kernel::tick(const TickInput& in, TickOutput& out) noexcept {
  ++tick_;
  followed_up_ = false;
  if (fault_) {
    // Faulted: the command stays where it was.
    out.commanded = cmd_;
    out.velocity = AxisVec{};
    out.path_speed = 0.0;
    out.followed_up = false;
    out.fault = fault_;
    return;
  }
  if (skip_.active && !skip_.done) monitor_skip(in);  // most periods: no skip block
  for (int e = 0; e < in.edge_count; ++e) {
    const SignalEdge& edge = in.edges[static_cast<std::size_t>(e)];
    signals_.set(edge.addr, edge.level);
  }
  // At full rate (no hold, override 100 %, no dry run) without a call.
  const double scale = full_rate_ ? 1.0 : advance_time_scale();
  if (scale != time_scale_) {
    time_scale_ = scale;
    interpolator_.set_time_scale(time_scale_);
  }
  // The in-position check between blocks (G00, G09, G61, before a dwell or
  // a skip): the next segment starts in the first period that finds every
  // axis within the width of the command.
  if (interpolator_.needs_in_position() && axes_in_position(in.actual))
    interpolator_.release_in_position();
  cmd_prev_ = cmd_;
  cmd_ = interpolator_.tick();
  // The skip block starts this period; one that ran whole within it (shorter
  // than one period's travel) or had no length leaves the interpolator idle,
  // and starts (is checked for an input already on) all the same.
  if (skip_.active && !skip_.done && !skip_started_ &&
      (interpolator_.tag() == skip_tag_ || interpolator_.idle())) {
    start_skip_block(in);
  }
  actual_prev_ = in.actual;
  // In position: every axis within the width, or locked (one bit per axis,
  // no branch per axis). It matters only once the motion has ended (idle(),
  // the end of a skip block), so it is not looked at before.
  const bool at_rest = interpolator_.idle() || interpolator_.holding();
  const bool inpos = at_rest && axes_in_position(in.actual);
  in_position_ = inpos && interpolator_.idle();
  inpos_wait_ = at_rest && !inpos ? inpos_wait_ + 1 : 0;
  if (skip_.active && !skip_.done && skip_started_ && !skip_latch_pending_ && in_position_) {
    skip_.done = true;
    skip_.stop_position = cmd_;
    if (latch_at_stop_) {
      skip_.latch_machine = cmd_;
      handshake_.recorded = true;
    }
    handshake_.active = false;
    handshake_.done = true;
  }
  out.commanded = cmd_;
  out.velocity = interpolator_.velocity();
  out.path_speed = interpolator_.path_speed();
  out.line = interpolator_.line();
  out.source = interpolator_.source();
  out.tag = interpolator_.tag();
  out.skip_active = skip_.active && !skip_.done;
  out.handshake = handshake_;
  out.torque_limit_pct = AxisVec{};
  out.torque_limited = false;
  if (out.skip_active && skip_.spec.torque_ends && skip_.spec.torque_axis >= 0) {
    out.torque_limit_pct[skip_.spec.torque_axis] = skip_.spec.torque_limit_pct;
    out.torque_limited = skip_.spec.torque_limit_pct > 0.0;
  }
  out.time_scale = time_scale_;
  out.followed_up = followed_up_;
  out.passed_dwell_line = interpolator_.passed_dwell_line();
  out.passed_dwell_source = interpolator_.passed_dwell_source();
  // Faults last: the servo's on the period that ended, then the stroke on
  // the command for the next one. Most periods have none: one pass over the
  // axes without a branch says so, and only then are they looked at in turn.
  if (may_fault(in) && (check_servo(in) || check_stroke())) out.commanded = cmd_;
  out.fault = fault_;
}

}  // namespace skipnc::kernel
