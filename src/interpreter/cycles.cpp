// Canned cycles: the moves of one hole (see cycles.hpp for the rules and
// their source).
#include "interpreter/cycles.hpp"

#include <algorithm>
#include <cmath>

namespace skipnc::interp::cycles {
namespace {

// Spindle directions of the tapping cycles: down with the first, out with the
// second (B-63944EN 5.1.7 G84: clockwise in, counterclockwise out; 5.1.3
// G74: the reverse).
struct TapDirs {
  int in;
  int out;
};
constexpr TapDirs kRightHandTap{1, -1};
constexpr TapDirs kLeftHandTap{-1, 1};

class Builder {
 public:
  explicit Builder(const std::array<double, 3>& from) : at_(from) {}

  void rapid(const std::array<double, 3>& to) { go(MoveKind::kRapid, to); }
  void feed(const std::array<double, 3>& to) { go(MoveKind::kFeed, to); }
  void rapid_z(double z) { rapid({at_[0], at_[1], z}); }
  void feed_z(double z) { feed({at_[0], at_[1], z}); }
  void rapid_xy(double x, double y) { rapid({x, y, at_[2]}); }
  void dwell(double s) {
    if (s > 0.0) moves_.push_back(Move{MoveKind::kDwell, at_, s, 0});
  }
  void spindle(int dir) { moves_.push_back(Move{MoveKind::kSpindle, at_, 0.0, dir}); }
  void orient() { moves_.push_back(Move{MoveKind::kOrient, at_, 0.0, 0}); }
  const std::array<double, 3>& at() const noexcept { return at_; }
  std::vector<Move> take() { return std::move(moves_); }

 private:
  void go(MoveKind k, const std::array<double, 3>& to) {
    if (to == at_) return;
    moves_.push_back(Move{k, to, 0.0, 0});
    at_ = to;
  }
  std::array<double, 3> at_;
  std::vector<Move> moves_;
};

double return_level(const Hole& h) {
  // G87 starts below the work from the initial level and always returns
  // there (B-63944EN 5.1.10: point R cannot be the return level).
  if (h.kind == Cycle::kG87) return h.initial;
  if (h.ret == ReturnLevel::kR) return h.r;
  return h.linuxcnc_levels ? std::max(h.initial, h.r) : h.initial;
}

// Depth after one more peck of q from `reached`, not past the bottom.
double next_peck(const Hole& h, double reached, double dir) {
  if (!(h.q > 0.0)) return h.bottom;  // no peck depth: one cut (the caller alarms first)
  const double next = reached + dir * h.q;
  return dir * (next - h.bottom) >= 0.0 ? h.bottom : next;
}

// Orient the spindle, move away from the cut by the shift, and the reverse.
void shift_away(Builder& b, const Hole& h) {
  b.orient();
  b.rapid_xy(h.at[0] + h.q * h.shift_dir[0], h.at[1] + h.q * h.shift_dir[1]);
}
void shift_back(Builder& b, const Hole& h) {
  b.rapid_xy(h.at[0], h.at[1]);
  b.spindle(h.spindle_dir);
}

// G73 / G83: peck to the bottom, then out to the return level.
void peck_moves(Builder& b, const Hole& h, double dir, double back) {
  double reached = h.r;
  if (h.kind == Cycle::kG73) {
    // High-speed peck: after each peck a rapid retraction of d (5114).
    for (;;) {
      reached = next_peck(h, reached, dir);
      b.feed_z(reached);
      if (reached == h.bottom) break;
      b.rapid_z(reached - dir * h.peck_clearance);
    }
  } else {
    // Peck: after each peck back to R, then rapid down to d (5115) short of
    // the depth reached.
    for (;;) {
      const double start = reached;
      reached = next_peck(h, reached, dir);
      if (start != h.r) b.rapid_z(start - dir * h.peck_clearance);
      b.feed_z(reached);
      if (reached == h.bottom) break;
      b.rapid_z(h.r);
    }
  }
  b.rapid_z(back);
}

// G76 / G87: the shifted boring cycles.
void shifted_bore_moves(Builder& b, const Hole& h, double back) {
  if (h.kind == Cycle::kG76) {
    b.feed_z(h.bottom);
    b.dwell(h.dwell_s);
    shift_away(b, h);
    b.rapid_z(back);
    shift_back(b, h);
    return;
  }
  // Back boring: shifted down through the bore to R, back on the axis,
  // spindle on, bore upward to Z, then out the same way.
  shift_away(b, h);
  b.rapid_z(h.r);
  shift_back(b, h);
  b.feed_z(h.bottom);
  b.dwell(h.dwell_s);
  shift_away(b, h);
  b.rapid_z(h.initial);
  shift_back(b, h);
}

// Operation 3 on: the hole itself, from R (G87: from the initial level).
void cycle_moves(Builder& b, const Hole& h, double back) {
  const double dir = h.bottom < h.r ? -1.0 : 1.0;  // the drilling direction
  switch (h.kind) {
    case Cycle::kNone:
      break;
    case Cycle::kG73:
    case Cycle::kG83:
      peck_moves(b, h, dir, back);
      break;
    case Cycle::kG74:
    case Cycle::kG84: {
      const TapDirs t = h.kind == Cycle::kG84 ? kRightHandTap : kLeftHandTap;
      b.feed_z(h.bottom);
      b.dwell(h.dwell_s);
      b.spindle(t.out);
      b.feed_z(h.linuxcnc_levels ? back : h.r);
      b.dwell(h.dwell_s);
      b.spindle(t.in);
      b.rapid_z(back);
      break;
    }
    case Cycle::kG76:
    case Cycle::kG87:
      shifted_bore_moves(b, h, back);
      break;
    case Cycle::kG81:
    case Cycle::kG82:
      b.feed_z(h.bottom);
      if (h.kind == Cycle::kG82) b.dwell(h.dwell_s);
      b.rapid_z(back);
      break;
    case Cycle::kG85:
    case Cycle::kG89:
      b.feed_z(h.bottom);
      if (h.kind == Cycle::kG89) b.dwell(h.dwell_s);
      b.feed_z(h.r);
      b.rapid_z(back);
      break;
    case Cycle::kG86:
    case Cycle::kG88:
      // G88 stops for manual operation at the bottom; the simulation has no
      // manual mode and goes on with the retraction at once.
      b.feed_z(h.bottom);
      if (h.kind == Cycle::kG88) b.dwell(h.dwell_s);
      b.spindle(0);
      b.rapid_z(back);
      b.spindle(h.spindle_dir);
      break;
  }
}

}  // namespace

std::vector<Move> hole_moves(const Hole& h) {
  Builder b(h.from);
  const double back = return_level(h);
  // LinuxCNC: up to the clearance level before the positioning.
  if (h.linuxcnc_levels && h.from[2] < back) b.rapid_z(back);
  // Operations 1 and 2: positioning at the present level, then down to R
  // (G87: to the initial level, the tool goes down to R with its shift).
  b.rapid_xy(h.at[0], h.at[1]);
  if (h.kind == Cycle::kG87) {
    b.rapid_z(h.initial);
  } else {
    b.rapid_z(h.r);
  }
  cycle_moves(b, h, back);
  return b.take();
}

Levels resolve_levels(const Data& d, bool incremental) noexcept {
  Levels l;
  if (incremental) {
    l.r = d.initial + (d.have_r ? d.r : 0.0);
    l.bottom = l.r + (d.have_z ? d.z : 0.0);
  } else {
    l.r = d.have_r ? d.r : d.initial;
    l.bottom = d.have_z ? d.z : l.r;
  }
  return l;
}

std::array<double, 2> shift_direction(int rd) noexcept {
  constexpr std::array<std::array<double, 2>, 4> kDirs{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
  return kDirs[static_cast<std::size_t>(rd & 3)];
}

bool uses_q(Cycle c) noexcept {
  return c == Cycle::kG73 || c == Cycle::kG83 || c == Cycle::kG76 || c == Cycle::kG87;
}
bool uses_p(Cycle c) noexcept {
  return c == Cycle::kG74 || c == Cycle::kG76 || c == Cycle::kG82 || c == Cycle::kG84 ||
         c == Cycle::kG87 || c == Cycle::kG88 || c == Cycle::kG89;
}
bool pecks(Cycle c) noexcept {
  return c == Cycle::kG73 || c == Cycle::kG83;
}

}  // namespace skipnc::interp::cycles
