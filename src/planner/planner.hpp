// Lookahead planner: turns moves (machine coordinates) into a queue of
// segments with closed-form trapezoidal profiles. Planning (push) happens
// outside the servo tick; the interpolator only evaluates segments.
//
// Limits respected: per-axis velocity and acceleration, path feed, the
// centripetal acceleration of arcs (v^2/r within the smallest acceleration of
// the plane's axes), and at each junction a velocity change per axis of at
// most a_i * period (so the per-sample acceleration never exceeds a_i).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "canon/canon.hpp"
#include "core/axes.hpp"

namespace skipnc::planner {

struct AxisLimits {
  double max_velocity_mm_s = 500.0;  // cutting-feed upper limit of the axis
  double rapid_mm_s = 500.0;         // rapid traverse rate of the axis
  double max_accel_mm_s2 = 2000.0;
};

struct Limits {
  int axis_count = 3;
  std::array<AxisLimits, kMaxAxes> axes{};
  double period_s = 0.001;
  double max_feed_mm_s = 20000.0 / 60.0;  // path cutting-feed clamp
};

struct Move {
  enum class Kind : std::uint8_t { kLine, kRapid, kRapidNonLinear, kArc, kDwell };
  Kind kind = Kind::kLine;
  AxisVec target;          // machine coordinates, mm
  double feed_mm_s = 0.0;  // kLine and kArc: requested path speed
  // kArc:
  double center0 = 0.0;
  double center1 = 0.0;
  canon::Plane plane;
  bool ccw = false;
  int extra_turns = 0;
  // kDwell:
  double dwell_s = 0.0;
  bool exact_stop = false;  // velocity is zero at the end of this move
  bool no_accel = false;    // no automatic acc/dec: the path speed steps to the feed
                            // at the start and stays there (G31 with SKF = 0)
  // In-position check (the interpolator holds at the segment boundary until
  // the caller releases it): at the end of this move (G00, G09, G61), or
  // before this move starts (dwell, skip). Either makes the junction a stop.
  bool in_position = false;
  bool wait_in_position = false;
  std::uint32_t line = 0;
  std::uint32_t source = 0;  // canon::Stamped::source, carried to the segment
  std::uint32_t tag = 0;     // caller's identifier, carried to the segment
};

// A planned segment. Geometry is fixed at push time; the profile (entry and
// exit speed) may still be raised by lookahead until the segment starts.
struct Segment {
  Move::Kind kind = Move::Kind::kLine;
  AxisVec start;
  AxisVec end;
  AxisVec unit;         // kLine/kRapid: direction; kRapidNonLinear: per-axis sign
  double length = 0.0;  // path length, mm (kRapidNonLinear: longest axis time basis)
  // kArc geometry
  canon::Plane plane;
  double center0 = 0.0, center1 = 0.0, radius = 0.0;
  double start_angle = 0.0, sweep = 0.0;  // radians, signed (ccw positive)
  double helix_per_rad = 0.0;             // normal-axis travel per radian
  AxisVec linear_per_mm;                  // other axes' travel per mm of path (arcs)
  // Profile
  double v_entry = 0.0, v_exit = 0.0, v_cruise = 0.0;  // mm/s
  double accel = 0.0;  // mm/s^2 along the path (infinite when no_accel)
  double t_acc = 0.0, t_cruise = 0.0, t_dec = 0.0;
  double duration = 0.0;  // seconds
  double v_max = 0.0;     // requested speed after limits
  double v_entry_max = 0.0;
  bool exact_stop = false;
  bool no_accel = false;
  bool in_position = false;       // Move::in_position
  bool wait_in_position = false;  // Move::wait_in_position
  bool started = false;
  // kRapidNonLinear: one trapezoid per axis, all starting together.
  std::array<double, kMaxAxes> axis_t_acc{}, axis_t_total{}, axis_v{}, axis_a{};
  std::uint32_t line = 0;
  std::uint32_t source = 0;
  std::uint32_t tag = 0;
  double d_acc = 0.0;        // path length of the acceleration phase, mm
  double radius_end = 0.0;   // kArc: radius at the end point (`radius` is the start's);
                             // the radius varies linearly with the swept angle
  double centripetal = 0.0;  // kArc: centripetal acceleration of the plane at v_max, mm/s^2
  int basis_axis = 0;        // kRapidNonLinear: the axis that takes longest

  // Distance along the path at time t in [0, duration].
  double distance_at(double t) const noexcept;
  // Path speed at time t.
  double speed_at(double t) const noexcept;
  // Machine position at time t in [0, duration].
  AxisVec position_at(double t) const noexcept;
  // Unit tangent (direction of motion per mm of path) at time t.
  AxisVec tangent_at(double t) const noexcept;
  // Machine velocity at time t, mm/s per axis (speed_at * tangent_at, or the
  // per-axis profiles of kRapidNonLinear).
  AxisVec velocity_at(double t) const noexcept;
  // position_at, velocity_at and speed_at together, the profile read once
  // (the interpolator's sample of each servo period). Axes from axis_count
  // on are left as they are in position and velocity (a machine's unused
  // axes never move).
  void sample(double t, int axis_count, AxisVec& position, AxisVec& velocity,
              double& speed) const noexcept;
};

// The queue of planned segments: a fixed-capacity ring with lookahead. A push
// (producer, outside the tick) plans the new segment and replans the ones not
// yet started; the interpolator (consumer, inside the tick) takes segments
// from the front. Not the whole planning stage, which is the free functions
// above it and in planner.cpp, so it is named for what it holds.
class SegmentQueue {
 public:
  SegmentQueue(const Limits& limits, std::size_t capacity = 256);

  const Limits& limits() const noexcept { return limits_; }
  // New limits for the moves pushed from now on (the queued ones keep theirs).
  void set_limits(const Limits& limits) noexcept { limits_ = limits; }
  bool full() const noexcept { return count_ == ring_.size(); }
  // Room for one more segment when the planner may know at most `window`
  // segments beyond the one in motion (0: no limit but the ring's size).
  // The front is popped when its end is reached and the next one starts in
  // the same tick, before the producer pushes again: so that a segment
  // starts with `window` segments known beyond it, the queue holds up to
  // window + 2 (the one ending, the one starting, the window).
  bool has_room(int window) const noexcept {
    return !full() && (window <= 0 || count_ < static_cast<std::size_t>(window) + 2);
  }
  bool empty() const noexcept { return count_ == 0; }
  std::size_t size() const noexcept { return count_; }

  // Appends a move that starts where the previous one ends (or at `start`
  // for the first one / after reset). Zero-length moves are dropped (a zero
  // dwell likewise); that is not a refusal. Returns false when the ring is
  // full, and then changes nothing: the move was not taken, and the caller
  // offers it again once the interpolator has popped a segment.
  [[nodiscard]] bool push(const Move& move);
  // The position the next pushed move starts from.
  const AxisVec& tail_position() const noexcept { return tail_; }
  // Forgets all queued segments and sets the start of the next move.
  void reset(const AxisVec& position) noexcept;

  // Consumer side (noexcept, no allocation).
  Segment* front() noexcept { return count_ ? &ring_[head_] : nullptr; }
  void pop_front() noexcept;

 private:
  void replan() noexcept;
  Segment& at(std::size_t k) noexcept { return ring_[(head_ + k) % ring_.size()]; }
  Limits limits_;
  std::vector<Segment> ring_;
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  AxisVec tail_;
  double front_entry_ = 0.0;  // exit speed of the last popped segment (entry of the front)
};

}  // namespace skipnc::planner
