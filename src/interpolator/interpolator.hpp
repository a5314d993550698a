// The per-tick sampler: the real-time path. Every call is noexcept and does
// not allocate. Budget: well under 1 us per tick on a 2-core x86 server (see
// bench/README.md, BM_Tick).
#pragma once

#include <climits>
#include <cstdint>

#include "core/axes.hpp"
#include "planner/planner.hpp"

namespace skipnc::interpolator {

class Interpolator {
 public:
  explicit Interpolator(planner::SegmentQueue& queue) noexcept;

  // Advances the command by one servo period and returns the commanded
  // position at the end of it. Segments end and begin inside a period; the
  // remainder of the period is carried into the next segment.
  const AxisVec& tick() noexcept;

  const AxisVec& position() const noexcept { return pos_; }
  // Commanded velocity at the end of the last tick, mm/s per axis.
  const AxisVec& velocity() const noexcept { return vel_; }
  double path_speed() const noexcept { return speed_; }
  // True when no segment is active, the queue is empty and no in-position
  // check is pending.
  bool idle() const noexcept {  // inline: asked several times a period
    return seg_ == nullptr && !ramp_ && queue_.empty() && !hold_;
  }
  // In-position check: a segment that asks for it has ended (or the next
  // one waits for it), and the command stays at that point, at rest, until
  // release_in_position(). The rest of the period is not carried over: the
  // next segment starts at a period boundary, as on a real control.
  bool holding() const noexcept { return hold_; }
  // Whether the next tick() needs to know if the axes are in position: it
  // holds, or the segment it is about to start waits for the check.
  bool needs_in_position() const noexcept {
    if (hold_) return true;
    const planner::Segment* f = seg_ == nullptr && !ramp_ ? queue_.front() : nullptr;
    return f != nullptr && f->wait_in_position && !f->started;
  }
  // The axes are within the in-position width: the hold ends and the next
  // segment starts in this tick.
  void release_in_position() noexcept {
    hold_ = false;
    released_ = true;
  }
  // Source line and tag of the active segment (of the last one when idle).
  std::uint32_t line() const noexcept { return line_; }
  std::uint32_t tag() const noexcept { return tag_; }
  std::uint32_t source() const noexcept { return source_; }  // its call context

  // Scales the rate at which profile time advances (feed override, feed hold
  // at 0). Takes effect at the next tick.
  void set_time_scale(double scale) noexcept { scale_ = scale; }

  // Skip: the command stops where it is now; the rest of the active segment
  // and everything queued is discarded.
  void stop_now() noexcept;
  // Skip: the command decelerates from its present speed along the present
  // direction at `decel_mm_s2` to rest; the queue is discarded.
  void decelerate(double decel_mm_s2) noexcept;
  // Sets the command position (after a follow-up: torque skip ends the block
  // at the mechanical stop position). Clears the queue.
  void set_position(const AxisVec& pos) noexcept;
  // Start point of the segment being interpolated (the position when idle).
  AxisVec segment_start() const noexcept;
  // End point of the segment being interpolated (the position when idle).
  AxisVec segment_end() const noexcept { return seg_ != nullptr ? seg_->end : pos_; }

  // Periods from now that tick() would run with nothing but its count of
  // periods changing (the same command, velocity and block): all but the
  // last three of a dwell's, or any number (kForever) while the time scale
  // is 0 (feed hold). 0 otherwise.
  static constexpr std::int64_t kForever = INT64_MAX / 4;
  std::int64_t quiet_ticks() const noexcept;
  // Passes n such periods in one step (n <= quiet_ticks()): the state is
  // that of n calls of tick(), bit for bit.
  void pass_quiet(std::int64_t n) noexcept { seg_ticks_ += n; }
  // Periods from now in which tick() would only carry the command on along
  // a feed's straight line at its constant cruise speed, the last tick's
  // command and the one after the n periods included: all but the last
  // three periods of the cruise (and of the segment). 0 otherwise: a ramp,
  // a hold, a time scale other than 1, an arc, a rapid, a dwell, the
  // acceleration and the deceleration, a segment's first two periods.
  std::int64_t cruise_ticks() const noexcept;
  // Passes n such periods in one step (n <= cruise_ticks()): the state is
  // that of n calls of tick(), bit for bit (the command is a closed form of
  // the count of periods); `before` gets the command of the (n-1)th call.
  void pass_cruise(std::int64_t n, AxisVec& before) noexcept;
  // The command's step per period in cruise (direction x speed x period).
  AxisVec cruise_step() const noexcept;
  // A dwell that ended in the last tick without a period of its own (G04
  // X0, or one ended where the next block took the period): its line and
  // call context, so that it is counted as run. Line 0: none.
  std::uint32_t passed_dwell_line() const noexcept { return passed_line_; }
  std::uint32_t passed_dwell_source() const noexcept { return passed_source_; }

 private:
  // The steps of tick(), inlined into it, but for the two that few periods
  // take (a skip stop's ramp, a segment's end): called, so that the common
  // path keeps its registers.
  // The deceleration ramp of a skip stop: the position at this period's end.
  [[gnu::noinline]] const AxisVec& tick_ramp(double period) noexcept;
  // Without an active segment, the queue's front becomes it; false when it
  // waits for the axes in position (the interpolator holds).
  [[gnu::always_inline]] bool start_front() noexcept;
  // A new time scale (override, feed hold) counts again from the time reached.
  [[gnu::always_inline]] void rebase_time_scale(double period) noexcept;
  // Counts the period, ending every segment that ends inside it; true when
  // a segment is active at the period's end.
  [[gnu::always_inline]] bool advance(double period) noexcept;
  // Ends the active segment at `t_end` (the period's end in its time); true
  // when the next one takes the rest of the period.
  [[gnu::noinline]] bool end_segment(double t_end, double slack) noexcept;
  // Position, velocity and block of the active segment (there is one) at
  // this period's end.
  [[gnu::always_inline]] void sample_active() noexcept;

  planner::SegmentQueue& queue_;
  // Time inside the active segment, s: seg_time(). Kept as a count of
  // periods, never as a sum of them (t += dt rounds at every period, and
  // over hours at 1 ms the error reaches a thousandth of a period, enough
  // to end a segment a period early or late).
  double seg_time() const noexcept {
    return static_cast<double>(seg_ticks_) * seg_step_s_ - seg_offset_s_;
  }
  planner::Segment* seg_ = nullptr;
  std::int64_t seg_ticks_ = 0;  // periods counted since the segment started (or rebased)
  double seg_step_s_ = 0.0;     // profile time per period: period * time scale
  double seg_offset_s_ = 0.0;   // the part of its first period the segments before it took
                                // (minus the time reached, after a change of time scale)
  AxisVec pos_;
  AxisVec vel_;
  double speed_ = 0.0;
  double scale_ = 1.0;
  std::uint32_t line_ = 0;
  std::uint32_t source_ = 0;
  std::uint32_t tag_ = 0;
  std::uint32_t passed_line_ = 0;
  std::uint32_t passed_source_ = 0;
  bool hold_ = false;      // waiting for the in-position check (holding())
  bool released_ = false;  // the check passed: the next segment may start
  // Deceleration ramp after a skip (replaces the segment).
  bool ramp_ = false;
  AxisVec ramp_start_;
  AxisVec ramp_dir_;
  double ramp_v0_ = 0.0;
  double ramp_decel_ = 0.0;
  std::int64_t ramp_ticks_ = 0;  // periods since the ramp began: t = ramp_ticks_ * period
};

}  // namespace skipnc::interpolator
