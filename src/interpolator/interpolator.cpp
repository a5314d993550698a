// Per-tick sampler (see interpolator.hpp). Nothing here allocates or throws;
// the only state carried from tick to tick is the time inside the active
// segment (or ramp), never an absolute time.
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

bool Interpolator::idle() const noexcept {
  return seg_ == nullptr && !ramp_ && queue_.empty() && !hold_;
}

const AxisVec& Interpolator::tick() noexcept {
  const double period = queue_.limits().period_s;

  if (ramp_) {
    ramp_t_ += period;
    const double t_stop = ramp_v0_ / ramp_decel_;
    const double stop_dist = ramp_v0_ * ramp_v0_ / (2.0 * ramp_decel_);
    if (ramp_t_ >= t_stop) {
      pos_ = ramp_start_ + ramp_dir_ * stop_dist;
      vel_ = AxisVec{};
      speed_ = 0.0;
      ramp_ = false;
      // The queue was reset to this point when the ramp began; anything the
      // caller queued since then already starts here.
      if (queue_.empty()) queue_.reset(pos_);
    } else {
      const double t = ramp_t_;
      pos_ = ramp_start_ + ramp_dir_ * ((ramp_v0_ - 0.5 * ramp_decel_ * t) * t);
      speed_ = ramp_v0_ - ramp_decel_ * t;
      vel_ = ramp_dir_ * speed_;
    }
    return pos_;
  }

  if (hold_) {
    vel_ = AxisVec{};
    speed_ = 0.0;
    return pos_;
  }
  if (seg_ != nullptr && !still_front(queue_, seg_)) seg_ = nullptr;
  if (seg_ == nullptr) {
    planner::Segment* f = queue_.front();
    if (f != nullptr && f->wait_in_position && !f->started && !released_) {
      hold_ = true;  // a dwell or skip starts only with the axes in position
      vel_ = AxisVec{};
      speed_ = 0.0;
      return pos_;
    }
    if (f != nullptr) released_ = false;
    seg_ = f;
    seg_time_ = 0.0;
    if (seg_ != nullptr) seg_->started = true;
  }

  double remaining = scale_ > 0.0 ? period * scale_ : 0.0;
  // Time inside a segment is a sum of periods, so it drifts by rounding (a
  // 1.05 s dwell was 1050 periods plus 2e-13 s, and took 1051): a segment
  // that ends within a millionth of a period after this one ends here.
  const double slack = period * 1e-6;
  while (seg_ != nullptr) {
    const double left = seg_->duration - seg_time_;
    if (remaining < left - slack) {
      seg_time_ += remaining;
      break;
    }
    // The segment ends inside this period: land exactly on its end point and
    // carry the rest of the period into the next one.
    remaining = std::max(0.0, remaining - left);
    pos_ = seg_->end;
    line_ = seg_->line;
    source_ = seg_->source;
    tag_ = seg_->tag;
    const bool check = seg_->in_position;
    queue_.pop_front();
    seg_ = nullptr;
    seg_time_ = 0.0;
    const planner::Segment* next = queue_.front();
    if (check || (next != nullptr && next->wait_in_position)) {
      // The in-position check: the next segment waits for release.
      hold_ = true;
      released_ = false;
      break;
    }
    seg_ = queue_.front();
    if (seg_ != nullptr) seg_->started = true;
  }

  if (seg_ != nullptr) {
    seg_->sample(seg_time_, queue_.limits().axis_count, pos_, vel_, speed_);
    if (scale_ != 1.0) {
      vel_ = vel_ * scale_;
      speed_ *= scale_;
    }
    line_ = seg_->line;
    source_ = seg_->source;
    tag_ = seg_->tag;
  } else {
    vel_ = AxisVec{};
    speed_ = 0.0;
  }
  return pos_;
}

void Interpolator::stop_now() noexcept {
  hold_ = false;
  released_ = false;
  seg_ = nullptr;
  seg_time_ = 0.0;
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
  ramp_t_ = 0.0;
  seg_ = nullptr;
  seg_time_ = 0.0;
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
