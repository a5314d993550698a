// The kernel: motion queue, interpolator and skip monitor behind one call per
// servo period. This is the real-time boundary: tick() is noexcept, does not
// allocate and does no I/O; its capacity is fixed at construction.
//
// Timing contract, per servo period k (time t_k = k * period):
//   inputs:  actual axis positions at t_k, motor torque at t_k, and every
//            input-signal edge in (t_{k-1}, t_k] with its exact instant;
//   outputs: the commanded position for t_{k+1}.
// Between samples the kernel takes actual and commanded positions as linear
// in time, so a latch is placed at the edge's instant inside the period.
//
// Threading contract: a Kernel is used from one thread. push(), tick() and
// every other call run on the same thread, or the caller synchronises them
// so that no two overlap (and each sees the effects of the one before). The
// kernel has no lock and no atomic, because:
//   - push() and tick() share the segment queue: push writes a new segment
//     and replans the profiles of every segment not yet started, while tick
//     starts the front one (marks it started, reads its profile) and pops
//     it. Overlapping, a tick could start a segment whose profile is half
//     rewritten: a data race, undefined behaviour.
//   - a skip command's push resets the skip block's state that tick()
//     monitors and writes; set_operator() and set_position() change what
//     the next tick reads.
//   - a lock inside would make the real-time tick wait for a push, which
//     replans up to the whole queue: the tick's budget would depend on the
//     producer. The caller knows its loop and chooses where to push.
// The simulator and examples/embedding push between ticks in one loop. A
// servo loop on its own thread takes the commands from its producer (a
// single-producer queue of canon::Stamped, say) and pushes them itself
// between ticks (docs/embedding.md).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "canon/canon.hpp"
#include "core/axes.hpp"
#include "core/time.hpp"
#include "interpolator/interpolator.hpp"
#include "kernel/signals.hpp"
#include "planner/planner.hpp"

namespace skipnc::kernel {

struct SignalEdge {
  canon::SignalAddr addr;
  bool level = false;  // the level after the edge
  double frac = 1.0;   // instant inside the period: t_{k-1} + frac * period, frac in (0, 1]
};

struct TickInput {
  AxisVec actual;
  AxisVec torque_pct;
  static constexpr int kMaxEdges = 32;
  int edge_count = 0;
  std::array<SignalEdge, kMaxEdges> edges{};
};

// The skip block's handshake, as a PLC sees it (CompassNC's G31SkipMove):
// Active from the start of the skip move until the axes are at rest after
// it; Skip when an input ended it; PositionsRecorded when the latched
// position is stored; Done when the block is finished. Skip, recorded and
// done stay set until the next skip block starts.
struct SkipHandshake {
  bool active = false;
  bool skip = false;
  bool recorded = false;
  bool done = false;
};

// What the kernel watches in its own tick, so that a caller driving it from
// its own servo loop gets the same protection as the simulator
// (docs/embedding.md, "Faults"). Infinite limits are not checked.
struct FaultLimits {
  static constexpr double kNone = std::numeric_limits<double>::infinity();
  static constexpr std::array<double, kMaxAxes> filled(double v) noexcept {
    std::array<double, kMaxAxes> a{};
    for (auto& x : a) x = v;
    return a;
  }
  // Stroke limits on the command, machine coordinates, mm.
  std::array<double, kMaxAxes> stroke_min = filled(-kNone);
  std::array<double, kMaxAxes> stroke_max = filled(kNone);
  // Excess following error (command - actual), mm, per axis.
  std::array<double, kMaxAxes> excess_error = filled(kNone);
  // At rest away from the command (held by a stop): the wait, s.
  double in_position_timeout_s = kNone;
};

// The first fault the kernel found. From then on the kernel holds its
// command where it was (the command beyond a stroke end is never output)
// until set_position() starts it again.
struct Fault {
  enum class Kind : std::uint8_t { kNone, kStrokeLimit, kExcessError, kInPositionTimeout };
  Kind kind = Kind::kNone;
  int axis = -1;
  double value = 0.0;  // the command beyond the stroke end; the following error
  double limit = 0.0;  // the stroke end or the excess limit crossed; the timeout, s
  explicit operator bool() const noexcept { return kind != Kind::kNone; }
};

struct TickOutput {
  AxisVec commanded;  // position for the next period
  AxisVec velocity;   // commanded velocity, mm/s
  double path_speed = 0.0;
  std::uint32_t line = 0;    // source line of the active motion
  std::uint32_t source = 0;  // and its call context (canon::Stamped::source)
  std::uint32_t tag = 0;     // its command's number in push order (Kernel::next_tag)
  bool skip_active = false;
  SkipHandshake handshake;
  // Torque limit the servo applies, % per axis (0: the servo's own limit).
  // Set on the axis of a torque limit skip while it runs.
  AxisVec torque_limit_pct;
  bool torque_limited = false;  // some axis of torque_limit_pct is set
  double time_scale = 1.0;      // feed override / feed hold as applied this period
  // The command was moved to where the axes are held (the follow-up that
  // ends a torque-limit skip): `commanded` jumped without motion, so the
  // next period starts from it, not from the previous period's command. A
  // servo with velocity feedforward must not take the jump as a velocity.
  bool followed_up = false;
  // A dwell passed in this period without a period of its own (G04 X0):
  // its line (0: none) and call context.
  std::uint32_t passed_dwell_line = 0;
  std::uint32_t passed_dwell_source = 0;
  // The kernel's first fault (kind kNone while there is none); set in the
  // tick that found it and in every tick after, while the command is held.
  Fault fault;
};

// What the operator does at the machine (scene [[operator]], see
// docs/skip-dialects.md): feed hold, interlock, feed override, dry run.
struct OperatorState {
  bool feed_hold = false;
  bool interlock = false;
  double override_pct = 100.0;  // 0-200 %
  bool dry_run = false;
  double dry_run_feed_mm_min = 0.0;
};

struct SkipResult {
  bool active = false;  // a skip block is queued or running
  bool done = false;    // finished: triggered or reached its end point, and at rest
  bool triggered = false;
  bool torque_reached = false;
  // An input was active when the block started and spec.active_at_start_fails:
  // the block ended there without moving (not a trigger).
  bool active_at_start = false;
  int input_index = -1;
  double time_s = 0.0;    // instant of the latch
  AxisVec latch_machine;  // stored position (machine coordinates)
  AxisVec latch_actual;   // actual position at the signal instant
  AxisVec latch_command;  // commanded position at the signal instant
  AxisVec stop_position;  // commanded position where the axes came to rest
  canon::SkipSpec spec;
  AxisVec target;
  std::uint32_t line = 0;
  std::uint32_t source = 0;
};

struct KernelConfig {
  planner::Limits limits;
  ServoClock clock;
  std::size_t queue_capacity = 256;
  double in_position_mm = 0.0005;
  FaultLimits faults;
  // In-position check at the end of a rapid (Fanuc 1601#5 NCI = 0). G09,
  // G61 and skip blocks always check; a dwell and a skip block start only
  // with the axes in position.
  bool rapid_in_position = true;
};

class Kernel {
 public:
  explicit Kernel(const KernelConfig& cfg);

  // --- outside the tick -------------------------------------------------
  // Room for one more block of the usual kind (a block may queue a few
  // moves, e.g. G28), and no skip block pending. A hint for when to read the
  // next block, not a promise: a canned cycle's block may queue hundreds of
  // moves, more than the queue holds. push() is what says whether a command
  // was taken.
  bool can_accept() const noexcept {
    return queue_.size() + 4 <= cfg_.queue_capacity && !skip_.active;
  }
  // Room for one more command: the next push() takes it.
  bool can_push() const noexcept { return !queue_.full(); }
  // Room for a command that may see at most `window` commands ahead of the
  // one in motion (canon::LookAhead; 0: no limit).
  bool can_push(int window) const noexcept { return queue_.has_room(window); }
  // Queues a motion or dwell command (other commands are not the kernel's).
  // Returns false when the queue is full, and then changes nothing (the
  // queue, the skip block's state and next_tag() are as they were): the
  // command was not taken, and the caller keeps it and pushes it again after
  // a tick has made room (can_push()).
  [[nodiscard]] bool push(const canon::Stamped& cmd);
  // The number the next pushed command gets (1, 2, ...; TickOutput::tag
  // names the running one), for callers that keep data per command.
  std::uint32_t next_tag() const noexcept { return next_tag_; }
  // Sets the position of an idle machine (start-up, after a follow-up).
  void set_position(const AxisVec& machine) noexcept;
  // One axis's rate (mm/min: rapid and highest feed) and acceleration for
  // the moves pushed from now on; 0 leaves a value as it is (canon::AxisRate).
  void set_axis_rate(const canon::AxisRate& r) noexcept;
  // The operator's switches; they act from the next tick. Feed hold,
  // interlock and override 0 % bring the path to rest at the axes'
  // acceleration; override and dry run do not act on a skip block whose
  // spec says feed_fixed.
  void set_operator(const OperatorState& op) noexcept {
    op_ = op;
    override_ = std::fmax(0.0, op_.override_pct) / 100.0;
    update_full_rate();
  }
  const OperatorState& operator_state() const noexcept { return op_; }
  // Axes that do not move (machine lock, Z-axis cancel): their actual
  // position is not compared with the command.
  void set_locked_axes(AxisMask axes) noexcept { locked_ = axes; }
  const Fault& fault() const noexcept { return fault_; }

  // --- the tick -----------------------------------------------------------
  void tick(const TickInput& in, TickOutput& out) noexcept;
  // Periods from now whose ticks would each give the last tick's output
  // again, the time aside (a dwell, a feed hold: the command stands, no
  // skip, no fault, the time scale settled), given the same input. 0: none.
  std::int64_t quiet_ticks() const noexcept;
  // Passes n such periods at once (n <= quiet_ticks()): as n ticks whose
  // input was the last one.
  void pass_quiet(std::int64_t n) noexcept {
    tick_ += n;
    interpolator_.pass_quiet(n);
  }

  // Periods from now in which each tick would only carry the command on
  // along a feed's straight line at its cruise speed (Interpolator::
  // cruise_ticks): no skip block, no fault, full rate, the segment's end
  // within the stroke. 0: none.
  std::int64_t cruise_ticks() const noexcept;
  // Passes n such periods at once (n <= cruise_ticks()): the command, the
  // time and `out` are those of n ticks (the same block, speed and state);
  // previous_command() is the command of the (n-1)th. The caller then gives
  // the axes' position at the end (cruised()).
  void pass_cruise(std::int64_t n, TickOutput& out) noexcept;
  void cruised(const AxisVec& actual) noexcept { actual_prev_ = actual; }
  const AxisVec& previous_command() const noexcept { return cmd_prev_; }
  // The command's step per period in cruise.
  AxisVec cruise_step() const noexcept { return interpolator_.cruise_step(); }
  // The following error past which an axis alarms (excess error), mm.
  double excess_error_mm(int axis) const noexcept {
    return cfg_.faults.excess_error[static_cast<std::size_t>(axis)];
  }

  // --- state ---------------------------------------------------------------
  Tick now() const noexcept { return tick_; }
  const ServoClock& clock() const noexcept { return cfg_.clock; }
  // No motion queued or running and every axis within the in-position width.
  bool idle() const noexcept { return motion_idle() && in_position_; }
  // Periods the command has been at rest (idle or at an in-position hold)
  // with some axis outside the width: an axis held away from its command.
  std::int64_t in_position_wait() const noexcept { return inpos_wait_; }
  bool motion_idle() const noexcept { return interpolator_.idle(); }
  const SkipResult& skip() const noexcept { return skip_; }
  void clear_skip() noexcept { skip_ = SkipResult{}; }
  const AxisVec& command() const noexcept { return cmd_; }
  const SignalImage& signals() const noexcept { return signals_; }
  const SkipHandshake& handshake() const noexcept { return handshake_; }
  // Sets a signal outside the tick (initial scene state).
  void preset_signal(const canon::SignalAddr& a, bool on) noexcept { signals_.set(a, on); }

 private:
  bool input_active(bool level) const noexcept;
  // Every axis within the in-position width of the command, or locked.
  bool axes_in_position(const AxisVec& actual) const noexcept;
  void monitor_skip(const TickInput& in) noexcept;
  void start_skip_block(const TickInput& in) noexcept;
  void trigger(double frac, const TickInput& in, int input, bool torque) noexcept;
  AxisVec stored_latch() const noexcept;
  void begin_stop() noexcept;  // the skip's stop, once the control has seen the signal
  double advance_time_scale() noexcept;
  // Most periods: no hold, no dry run, override 100 % and both ramp factors
  // settled at 1. The time scale is 1 whatever the segment.
  void update_full_rate() noexcept {
    full_rate_ = override_ == 1.0 && hold_factor_ == 1.0 && override_factor_ == 1.0 &&
                 !op_.feed_hold && !op_.interlock && !op_.dry_run;
  }

  KernelConfig cfg_;
  planner::SegmentQueue queue_;
  interpolator::Interpolator interpolator_;
  SignalImage signals_;
  Tick tick_ = 0;
  AxisVec cmd_;       // command for t_k (output at tick k-1)
  AxisVec cmd_prev_;  // command for t_{k-1}
  AxisVec actual_prev_;
  bool in_position_ = true;      // motion idle and every axis in position (tick)
  std::int64_t inpos_wait_ = 0;  // see in_position_wait()
  std::uint32_t next_tag_ = 1;
  std::uint32_t skip_tag_ = 0;
  SkipResult skip_;
  bool skip_started_ = false;
  bool skip_stopping_ = false;
  bool followed_up_ = false;  // this tick moved the command to the actual position
  Fault fault_;
  // The fault checks of tick(): true when one was found (fault_ set).
  [[gnu::always_inline]] inline bool may_fault(const TickInput& in) const noexcept;
  bool check_servo(const TickInput& in) noexcept;
  bool check_stroke() noexcept;
  bool skip_latch_pending_ = false;  // sampled latch: waiting for the delay
  double skip_latch_due_s_ = 0.0;
  double torque_since_s_ = -1.0;
  bool latch_at_stop_ = false;  // torque skip ended by SKIP: store where it stopped
  SkipHandshake handshake_;
  OperatorState op_;
  AxisMask locked_;
  unsigned all_axes_ = 0;  // one bit per axis of limits.axis_count
  double time_scale_ = 1.0;
  double hold_factor_ = 1.0;      // ramps to 0 in feed hold / interlock
  double override_factor_ = 1.0;  // ramps to the feed override
  double min_accel_mm_s2_ = 0.0;  // smallest axis acceleration: feed hold ramps
  double override_ = 1.0;         // op_.override_pct as a factor (set_operator)
  double ramp_v_nom_ = 0.0;       // the path speed ramp_step_ was computed for
  double ramp_step_ = 1e300;      // change of the hold and override factors per period
  bool full_rate_ = true;         // see update_full_rate
  bool ramps_settled_ = true;     // both factors at their targets (quiet_ticks)
};

}  // namespace skipnc::kernel
