// Per-tick sampler (see interpolator.hpp). Nothing here allocates or throws;
// the only state carried from tick to tick is the time inside the active
// segment (or ramp), never an absolute time, and that time is an integer
// count of periods with a fixed offset, never a running sum.
#include "interpolator/interpolator.hpp"

#include <algorithm>
#include <cmath>

namespace skipnc::interpolator {

namespace {
// The queue's idea of the active segment may change under us only through
// SegmentQueue::reset (called by us, or by the caller before set_position).
bool still_front(planner::SegmentQueue& q, const planner::Segment* seg) noexcept {
  return seg != nullptr && q.front() == seg && seg->started;
}
}  // namespace

Interpolator::Interpolator(planner::SegmentQueue& queue) noexcept
    : queue_(queue), pos_(queue.tail_position()) {}

std::int64_t Interpolator::quiet_ticks() const noexcept {
  if (ramp_ || hold_ || seg_ == nullptr || queue_.front() != seg_ || !seg_->started) return 0;
  const double period = queue_.limits().period_s;
  const double step = scale_ > 0.0 ? period * scale_ : 0.0;
  if (step != seg_step_s_) return 0;  // the next tick rebases the count
  if (step == 0.0) return kForever;   // profile time stands still
  if (seg_->kind != planner::Move::Kind::kDwell) return 0;
  // tick() ends the dwell in the first period whose end reaches
  // duration - slack, at count c with c + 1 >= last; three periods spare.
  const double last = (seg_->duration - period * 1e-6 + seg_offset_s_) / step;
  const double n = std::floor(last) - static_cast<double>(seg_ticks_) - 3.0;
  return n > 0.0 ? static_cast<std::int64_t>(std::fmin(n, 1e18)) : 0;
}

std::int64_t Interpolator::cruise_ticks() const noexcept {
  if (ramp_ || hold_ || seg_ == nullptr || queue_.front() != seg_ || !seg_->started) return 0;
  if (seg_->kind != planner::Move::Kind::kLine || scale_ != 1.0 || seg_ticks_ < 2) return 0;
  const double period = queue_.limits().period_s;
  if (seg_step_s_ != period) return 0;
  // The last tick's command and the one before it, one period back, were
  // both sampled in this segment (seg_ticks_ >= 2); that one must already
  // be in the cruise, and the command n periods on still in it, below the
  // segment's end less tick()'s slack, with two periods spare.
  const double t = seg_time();
  if (!(t - period > seg_->t_acc)) return 0;
  const double end = std::fmin(seg_->t_acc + seg_->t_cruise, seg_->duration - period * 1e-6);
  const double n = std::floor((end - t) / period) - 2.0;
  return n > 0.0 ? static_cast<std::int64_t>(std::fmin(n, 1e15)) : 0;
}

void Interpolator::pass_cruise(std::int64_t n, AxisVec& before) noexcept {
  const int axes = queue_.limits().axis_count;
  AxisVec v;
  double speed = 0.0;
  seg_ticks_ += n - 1;
  seg_->sample(seg_time(), axes, before, v, speed);
  ++seg_ticks_;
  seg_->sample(seg_time(), axes, pos_, vel_, speed_);
  passed_line_ = 0;
}

AxisVec Interpolator::cruise_step() const noexcept {
  const double period = queue_.limits().period_s;
  return seg_ != nullptr ? seg_->unit * (seg_->v_cruise * period) : AxisVec{};
}

// The helpers of tick() are inlined into it (gnu::always_inline in the
// header), but for the ramp and a segment's end (gnu::noinline): split for
// reading, the common path compiles as one function.

const AxisVec& Interpolator::tick_ramp(double period) noexcept {
  ++ramp_ticks_;
  const double t = static_cast<double>(ramp_ticks_) * period;
  const double t_stop = ramp_v0_ / ramp_decel_;
  const double stop_dist = ramp_v0_ * ramp_v0_ / (2.0 * ramp_decel_);
  if (t >= t_stop) {
    pos_ = ramp_start_ + ramp_dir_ * stop_dist;
    vel_ = AxisVec{};
    speed_ = 0.0;
    ramp_ = false;
    // The queue was reset to this point when the ramp began; anything the
    // caller queued since then already starts here.
    if (queue_.empty()) queue_.reset(pos_);
  } else {
    pos_ = ramp_start_ + ramp_dir_ * ((ramp_v0_ - 0.5 * ramp_decel_ * t) * t);
    speed_ = ramp_v0_ - ramp_decel_ * t;
    vel_ = ramp_dir_ * speed_;
  }
  return pos_;
}

inline bool Interpolator::start_front() noexcept {
  if (seg_ != nullptr && !still_front(queue_, seg_)) seg_ = nullptr;
  if (seg_ == nullptr) {
    planner::Segment* f = queue_.front();
    if (f != nullptr && f->wait_in_position && !f->started && !released_) {
      hold_ = true;  // a dwell or skip starts only with the axes in position
      vel_ = AxisVec{};
      speed_ = 0.0;
      return false;
    }
    if (f != nullptr) released_ = false;
    seg_ = f;
    seg_ticks_ = 0;  // starts at this period's start
    seg_offset_s_ = 0.0;
    if (seg_ != nullptr) seg_->started = true;
  }
  return true;
}

inline void Interpolator::rebase_time_scale(double period) noexcept {
  const double step = scale_ > 0.0 ? period * scale_ : 0.0;
  if (step != seg_step_s_) {
    // A new time scale (override, feed hold): count again from the time
    // reached, so the periods before the change keep the step they had.
    seg_offset_s_ = -seg_time();
    seg_ticks_ = 0;
    seg_step_s_ = step;
  }
}

inline bool Interpolator::advance(double period) noexcept {
  // The duration is a closed-form real and the count times the period is
  // rounded once, so a segment meant to end on a period boundary may miss
  // it by a rounding either way: a segment that ends within a millionth of a
  // period after this one ends here.
  const double slack = period * 1e-6;
  while (seg_ != nullptr) {
    const double t_end = static_cast<double>(seg_ticks_ + 1) * seg_step_s_ - seg_offset_s_;
    if (t_end < seg_->duration - slack) {
      ++seg_ticks_;
      return true;
    }
    if (!end_segment(t_end, slack)) return false;
  }
  return false;
}

bool Interpolator::end_segment(double t_end, double slack) noexcept {
  // The segment ends inside this period: land exactly on its end point and
  // carry the rest of the period into the next one.
  const double rest = std::max(0.0, t_end - seg_->duration);
  // A dwell that ends at this period's end ran the whole period: the
  // segment after it starts with the next period (it did not run in this
  // one, and the period is the dwell's: G04 X5. is 5.000 s of its block).
  // A dwell that ended with time to spare was met without a period of
  // its own (G04 X0): it is said (passed_dwell_line).
  const bool dwell = seg_->kind == planner::Move::Kind::kDwell;
  const bool dwell_to_the_end = dwell && rest <= slack;
  if (dwell && !dwell_to_the_end) {
    passed_line_ = seg_->line;
    passed_source_ = seg_->source;
  }
  pos_ = seg_->end;
  line_ = seg_->line;
  source_ = seg_->source;
  tag_ = seg_->tag;
  const bool check = seg_->in_position;
  queue_.pop_front();
  seg_ = nullptr;
  // The next segment began `rest` before the end of this period: its
  // first period is the one that is ending, less what this one took.
  seg_ticks_ = 0;
  seg_offset_s_ = seg_step_s_ - rest;
  const planner::Segment* next = queue_.front();
  if (check || (next != nullptr && next->wait_in_position)) {
    // The in-position check: the next segment waits for release.
    hold_ = true;
    released_ = false;
    return false;
  }
  if (dwell_to_the_end) return false;  // the next starts at the next period's start
  seg_ = queue_.front();
  if (seg_ != nullptr) seg_->started = true;
  return true;
}

inline void Interpolator::sample_active() noexcept {
  seg_->sample(seg_time(), queue_.limits().axis_count, pos_, vel_, speed_);
  if (scale_ != 1.0) {
    vel_ = vel_ * scale_;
    speed_ *= scale_;
  }
  line_ = seg_->line;
  source_ = seg_->source;
  tag_ = seg_->tag;
}

const AxisVec& Interpolator::tick() noexcept {
  const double period = queue_.limits().period_s;
  passed_line_ = 0;
  if (ramp_) [[unlikely]] {
    return tick_ramp(period);
  }
  if (hold_) [[unlikely]] {
    vel_ = AxisVec{};
    speed_ = 0.0;
    return pos_;
  }
  if (!start_front()) return pos_;
  rebase_time_scale(period);
  if (advance(period)) {
    sample_active();
  } else {
    vel_ = AxisVec{};
    speed_ = 0.0;
  }
  if (passed_line_ == line_ && passed_source_ == source_) passed_line_ = 0;  // it has the period
  return pos_;
}

void Interpolator::stop_now() noexcept {
  hold_ = false;
  released_ = false;
  seg_ = nullptr;
  seg_ticks_ = 0;
  seg_offset_s_ = 0.0;
  ramp_ = false;
  vel_ = AxisVec{};
  speed_ = 0.0;
  queue_.reset(pos_);
}

void Interpolator::decelerate(double decel_mm_s2) noexcept {
  const double v0 = norm(vel_, kMaxAxes);
  if (!(v0 > 0.0) || !(decel_mm_s2 > 0.0) || !std::isfinite(decel_mm_s2)) {
    stop_now();
    return;
  }
  hold_ = false;
  ramp_ = true;
  ramp_start_ = pos_;
  ramp_dir_ = vel_ * (1.0 / v0);
  ramp_v0_ = v0;
  ramp_decel_ = decel_mm_s2;
  ramp_ticks_ = 0;
  seg_ = nullptr;
  seg_ticks_ = 0;
  seg_offset_s_ = 0.0;
  speed_ = v0;
  queue_.reset(ramp_start_ + ramp_dir_ * (v0 * v0 / (2.0 * decel_mm_s2)));
}

AxisVec Interpolator::segment_start() const noexcept {
  return seg_ != nullptr ? seg_->start : pos_;
}

void Interpolator::set_position(const AxisVec& pos) noexcept {
  pos_ = pos;
  stop_now();
}

}  // namespace skipnc::interpolator
