// Cutter radius compensation C: see cutter_comp.hpp for the rules.
#include "interpreter/cutter_comp.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

namespace skipnc::interp::crc {

namespace {

constexpr double kSamePoint = 1e-9;  // mm: points closer are one point
constexpr double kParallel = 1e-9;   // |sin| of the angle between two directions

V2 operator+(V2 a, V2 b) noexcept {
  return {a.x + b.x, a.y + b.y};
}
V2 operator-(V2 a, V2 b) noexcept {
  return {a.x - b.x, a.y - b.y};
}
V2 operator*(V2 a, double k) noexcept {
  return {a.x * k, a.y * k};
}
double dot(V2 a, V2 b) noexcept {
  return a.x * b.x + a.y * b.y;
}
double cross(V2 a, V2 b) noexcept {
  return a.x * b.y - a.y * b.x;
}
double length(V2 a) noexcept {
  return std::hypot(a.x, a.y);
}
V2 unit(V2 a) noexcept {
  const double l = length(a);
  return l > 0.0 ? a * (1.0 / l) : V2{};
}
V2 left(V2 t) noexcept {
  return {-t.y, t.x};
}  // +90 degrees, seen from the plane's normal

const AxisVec* target_of(const canon::Command& c) noexcept {
  if (const auto* r = std::get_if<canon::Rapid>(&c)) return &r->target;
  if (const auto* f = std::get_if<canon::Feed>(&c)) return &f->target;
  if (const auto* a = std::get_if<canon::Arc>(&c)) return &a->target;
  if (const auto* s = std::get_if<canon::Skip>(&c)) return &s->target;
  return nullptr;
}
AxisVec* target_of(canon::Command& c) noexcept {
  return const_cast<AxisVec*>(target_of(std::as_const(c)));
}
bool is_path_move(const canon::Command& c) noexcept {
  return std::holds_alternative<canon::Rapid>(c) || std::holds_alternative<canon::Feed>(c) ||
         std::holds_alternative<canon::Arc>(c);
}

std::string mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

}  // namespace

void Compensator::begin(const AxisVec& pos) noexcept {
  prog_ = pos;
  tool_ = pos;
  has_vector_ = false;
  held_.reset();
  deferred_.clear();
  quiet_ = 0;
}

AxisVec Compensator::vector() const noexcept {
  AxisVec v;
  if (!has_vector_ || held_ || !deferred_.empty()) return v;  // only between flushes
  v[a0_] = tool_[a0_] - prog_[a0_];
  v[a1_] = tool_[a1_] - prog_[a1_];
  return v;
}

Compensator::Entity Compensator::make(const canon::Stamped& cmd, const BlockMode& mode) const {
  Entity e;
  e.cmd = cmd;
  e.p0 = plane(prog_);
  e.p1 = plane(*target_of(cmd.cmd));
  e.s = mode.side * mode.radius;
  if (const auto* a = std::get_if<canon::Arc>(&cmd.cmd)) {
    e.arc = true;
    e.c = {a->center0, a->center1};
    e.ccw = a->ccw;
  }
  return e;
}

namespace {

// Direction of travel at the start or the end of a move.
V2 tangent(bool arc, V2 p0, V2 p1, V2 c, bool ccw, bool at_end) noexcept {
  if (!arc) return unit(p1 - p0);
  const V2 u = unit((at_end ? p1 : p0) - c);
  return ccw ? V2{-u.y, u.x} : V2{u.y, -u.x};
}

// The offset path of a move: a line (point q, unit direction d) or a circle
// (centre c, radius rho).
struct Path {
  bool arc = false;
  V2 q, d;
  V2 c;
  double rho = 0.0;
};

// The intersection of two offset paths nearest `ref`, if any.
std::optional<V2> meet(const Path& a, const Path& b, V2 ref) {
  auto nearest = [&](V2 p, V2 q) { return length(p - ref) <= length(q - ref) ? p : q; };
  if (!a.arc && !b.arc) {
    const double den = cross(a.d, b.d);
    if (std::fabs(den) < kParallel) return std::nullopt;
    const double t = cross(b.q - a.q, b.d) / den;
    return a.q + a.d * t;
  }
  if (a.arc != b.arc) {
    const Path& l = a.arc ? b : a;
    const Path& k = a.arc ? a : b;
    const V2 f = l.q - k.c;
    const double bb = dot(f, l.d);
    double disc = bb * bb - (dot(f, f) - k.rho * k.rho);
    if (disc < 0.0) {
      if (disc < -1e-9 * (1.0 + k.rho * k.rho)) return std::nullopt;
      disc = 0.0;
    }
    const double r = std::sqrt(disc);
    return nearest(l.q + l.d * (-bb + r), l.q + l.d * (-bb - r));
  }
  const V2 dc = b.c - a.c;
  const double d = length(dc);
  if (d < kSamePoint) return std::nullopt;
  const double x = (a.rho * a.rho - b.rho * b.rho + d * d) / (2.0 * d);
  double h2 = a.rho * a.rho - x * x;
  if (h2 < 0.0) {
    if (h2 < -1e-9 * (1.0 + a.rho * a.rho)) return std::nullopt;
    h2 = 0.0;
  }
  const V2 e = dc * (1.0 / d);
  const V2 mid = a.c + e * x;
  const V2 n = left(e) * std::sqrt(h2);
  return nearest(mid + n, mid - n);
}

}  // namespace

namespace {

// The offset path of an entity's move, `s` to its left.
Path offset_path(bool arc, V2 p0, V2 p1, V2 c, bool ccw, double s) {
  Path p;
  p.arc = arc;
  if (arc) {
    p.c = c;
    p.rho = length(p0 - c) + (ccw ? -s : s);
  } else {
    p.d = unit(p1 - p0);
    p.q = p0 + left(p.d) * s;
  }
  return p;
}

}  // namespace

// What a corner is: the two moves' directions and offsets at the point
// where they meet.
struct Compensator::Turn {
  V2 c;       // the programmed corner
  V2 t1, t2;  // directions of travel at the end of the first, the start of the second
  double s1 = 0.0, s2 = 0.0;
  V2 o1, o2;  // the offset vectors
  V2 ref;     // between the two offset points: the intersection nearest it
  double dt = 0.0;
  int sign = 0;
  bool straight = false, flip = false, inner = false;
  Path p1, p2;  // the offset paths
};

Compensator::Turn Compensator::turn(const Entity& e1, const Entity& e2, Join join) {
  Turn g;
  g.c = e1.p1;
  g.t1 = tangent(e1.arc, e1.p0, e1.p1, e1.c, e1.ccw, true);
  g.t2 = tangent(e2.arc, e2.p0, e2.p1, e2.c, e2.ccw, false);
  // At a cancel the second move's offset (type B) is taken with the first's.
  g.s1 = e1.s;
  g.s2 = join == Join::kCancel ? e1.s : e2.s;
  g.o1 = left(g.t1) * g.s1;
  g.o2 = left(g.t2) * g.s2;
  const double sref = join == Join::kCancel ? g.s1 : g.s2;
  const double cr = cross(g.t1, g.t2);
  g.dt = dot(g.t1, g.t2);
  g.sign = sref > 0.0 ? 1 : sref < 0.0 ? -1 : 0;
  g.straight = std::fabs(cr) < kParallel && g.dt > 0.0;
  g.flip = join == Join::kNormal && g.s1 * g.s2 < 0.0;
  g.inner = !g.straight && g.sign * cr > 0.0;
  g.ref = (g.c + g.o1 + g.c + g.o2) * 0.5;
  g.p1 = offset_path(e1.arc, e1.p0, e1.p1, e1.c, e1.ccw, g.s1);
  g.p2 = offset_path(e2.arc, e2.p0, e2.p1, e2.c, e2.ccw, g.s2);
  return g;
}

// Round an outer corner under 90 degrees: the two vectors extended by the
// radius along each move, joined by a line (Fanuc's L, r, r, L).
void Compensator::acute(const Turn& g, const Entity& e1, const Entity& e2, Join join, Corner& k) {
  const V2 p1 = g.c + g.o1 + g.t1 * std::fabs(g.s1);
  const V2 p2 = g.c + g.o2 - g.t2 * std::fabs(g.s2);
  if (e1.arc) {
    k.end1 = g.c + g.o1;
    k.inserts.push_back(p1);
  } else {
    k.end1 = p1;
  }
  if (join == Join::kCancel || !e2.arc) {
    k.inserts.push_back(p2);
    k.start2 = p2;
  } else {
    k.inserts.push_back(p2);
    k.start2 = g.c + g.o2;
  }
}

// A corner between two compensated moves.
Result<void> Compensator::normal_corner(const Turn& g, const Entity& e1, const Entity& e2,
                                        Corner& k) {
  if (g.straight || g.flip || g.sign == 0) {
    k.end1 = g.c + g.o1;
    k.start2 = g.c + g.o2;
  } else if (g.inner) {
    auto p = meet(g.p1, g.p2, g.ref);
    if (!p) {
      return fail(AlarmId::kCompNoSolution,
                  "cutter compensation: the offset paths of the two moves do not meet at "
                  "the inner corner (" +
                      mm(g.c.x) + ", " + mm(g.c.y) + ")");
    }
    k.end1 = k.start2 = *p;
  } else if (g.dt >= 0.0) {
    auto p = meet(g.p1, g.p2, g.ref);
    if (p) {
      k.end1 = k.start2 = *p;
    } else {
      acute(g, e1, e2, Join::kNormal, k);
    }
  } else {
    acute(g, e1, e2, Join::kNormal, k);
  }
  return {};
}

Result<Compensator::Corner> Compensator::corner(const Entity& e1, const Entity& e2, Join join,
                                                bool type_b) const {
  const Turn g = turn(e1, e2, join);
  Corner k;
  const bool perpendicular = !type_b || g.inner || g.straight || g.sign == 0;
  switch (join) {
    case Join::kStartup:
      if (perpendicular) {
        k.end1 = k.start2 = g.c + g.o2;  // perpendicular to the next move's start
      } else if (g.dt >= 0.0) {
        auto p = meet(g.p1, g.p2, g.ref);
        k.end1 = k.start2 = p ? *p : g.c + g.o2;
      } else {
        acute(g, e1, e2, join, k);
      }
      break;
    case Join::kCancel:
      if (perpendicular) {
        k.end1 = g.c + g.o1;  // perpendicular to the last move's end
      } else if (g.dt >= 0.0) {
        auto p = meet(g.p1, g.p2, g.ref);
        k.end1 = p ? *p : g.c + g.o1;
      } else {
        acute(g, e1, e2, join, k);
      }
      k.start2 = k.inserts.empty() ? k.end1 : k.inserts.back();
      break;
    case Join::kNormal:
      SKIPNC_TRY(normal_corner(g, e1, e2, k));
      break;
  }
  return k;
}

void Compensator::send(canon::Stamped c, std::vector<canon::Stamped>& out) {
  if (const AxisVec* t = target_of(c.cmd)) tool_ = *t;
  out.push_back(std::move(c));
}

void Compensator::send_line(const canon::Stamped& like, V2 to, std::vector<canon::Stamped>& out) {
  if (length(to - plane(tool_)) < kSamePoint) return;
  AxisVec target = tool_;
  set_plane(target, to);
  canon::Stamped s{canon::Feed{}, like.line, like.source, like.n};
  if (const auto* r = std::get_if<canon::Rapid>(&like.cmd)) {
    s.cmd = canon::Rapid{target, r->linear};
  } else if (const auto* f = std::get_if<canon::Feed>(&like.cmd)) {
    s.cmd = canon::Feed{target, f->feed_mm_per_min, false};
  } else if (const auto* a = std::get_if<canon::Arc>(&like.cmd)) {
    s.cmd = canon::Feed{target, a->feed_mm_per_min, false};
  }
  send(std::move(s), out);
}

Result<void> Compensator::send_entity(const Entity& e, V2 end, std::vector<canon::Stamped>& out,
                                      bool check) {
  // Into the move's own start (an arc starts on its offset circle).
  send_line(e.cmd, e.start, out);
  if (check && !e.arc && !e.startup) {
    // A compensated line that runs against its programmed direction cuts
    // into the part (FANUC PS0041 interference check).
    const V2 d = e.p1 - e.p0;
    const V2 m = end - plane(tool_);
    if (length(m) >= kSamePoint && dot(m, d) < 0.0) {
      return fail(AlarmId::kCompInterference,
                  "cutter compensation: the tool centre path of the move to (" + mm(e.p1.x) + ", " +
                      mm(e.p1.y) + ") runs against its programmed direction (the radius " +
                      mm(std::fabs(e.s)) + " is too large for it)");
    }
  }
  canon::Stamped c = e.cmd;
  set_plane(*target_of(c.cmd), end);
  send(std::move(c), out);
  return {};
}

Result<void> Compensator::send_held(const Corner& k, const canon::Stamped* next,
                                    std::vector<canon::Stamped>& out, bool check) {
  const Entity e = *held_;
  held_.reset();
  auto r = send_entity(e, k.end1, out, check);
  if (!r) return r;
  for (canon::Stamped& d : deferred_) {
    if (AxisVec* t = target_of(d.cmd)) set_plane(*t, plane(tool_));
    send(std::move(d), out);
  }
  deferred_.clear();
  const canon::Stamped& like = next != nullptr ? *next : e.cmd;
  for (V2 p : k.inserts) send_line(like, p, out);
  quiet_ = 0;
  return {};
}

std::uint32_t Compensator::flush(std::vector<canon::Stamped>& out) {
  const std::uint32_t line = held_ ? held_->cmd.line : 0;
  if (held_) {
    const Entity& e = *held_;
    const V2 t1 = tangent(e.arc, e.p0, e.p1, e.c, e.ccw, true);
    Corner k;
    k.end1 = e.p1 + left(t1) * e.s;
    // Without the check it cannot fail: the held move and what follows it
    // go out (before, a failed check here dropped them without a word).
    (void)send_held(k, nullptr, out, false);
  }
  for (canon::Stamped& d : deferred_) send(std::move(d), out);
  deferred_.clear();
  quiet_ = 0;
  has_vector_ = length(plane(tool_) - plane(prog_)) >= kSamePoint;
  return line;
}

Result<void> Compensator::offset_move(Entity e, const canon::Stamped& c, const BlockMode& mode,
                                      std::vector<canon::Stamped>& out) {
  if (e.arc) {
    const double rho = length(e.p0 - e.c) + (e.ccw ? -e.s : e.s);
    if (rho <= kSamePoint) {
      return fail(AlarmId::kCompInterference,
                  "cutter compensation: the arc of radius " + mm(length(e.p0 - e.c)) +
                      " is inside the tool (offset " + mm(std::fabs(e.s)) + ")");
    }
  }
  if (held_) {
    auto k = corner(*held_, e, held_->startup ? Join::kStartup : Join::kNormal, mode.type_b);
    SKIPNC_TRY(k);
    auto s = send_held(*k, &c, out);
    if (!s) return s;
    e.start = k->start2;
  } else if (!has_vector_) {
    if (e.arc) {
      return fail(AlarmId::kCompArcStartup,
                  "cutter compensation start-up (G41/G42) in a G02/G03 block: start it with "
                  "G00 or G01");
    }
    e.startup = true;
    e.start = plane(tool_);
  } else {
    // The lookahead was broken: a line goes from where the tool is; an
    // arc starts on its offset circle, joined by a line.
    e.start =
        e.arc ? e.p0 + left(tangent(true, e.p0, e.p1, e.c, e.ccw, false)) * e.s : plane(tool_);
  }
  held_ = e;
  quiet_ = 0;
  return {};
}

Result<void> Compensator::cancel_move(const Entity& e, const canon::Stamped& c,
                                      const BlockMode& mode, std::vector<canon::Stamped>& out) {
  if (e.arc && (held_ || has_vector_)) {
    return fail(AlarmId::kCompArcStartup,
                "cutter compensation cancel (G40) in a G02/G03 block: cancel it with G00 or "
                "G01");
  }
  if (held_) {
    auto k = corner(*held_, e, Join::kCancel, mode.type_b);
    SKIPNC_TRY(k);
    auto s = send_held(*k, &c, out);
    if (!s) return s;
  }
  send(c, out);  // from where the tool is to the programmed point
  has_vector_ = false;
  return {};
}

Result<void> Compensator::block_command(const canon::Stamped& c, const BlockMode& mode,
                                        std::vector<canon::Stamped>& out, bool& plane_move) {
  const bool path_move = is_path_move(c.cmd);
  const bool ends_lookahead =
      std::holds_alternative<canon::Skip>(c.cmd) || std::holds_alternative<canon::Stop>(c.cmd);
  if (ends_lookahead || (path_move && mode.suspend)) {
    // G31, M00/M01/M02/M30, G28/G30/G53: what is held ends perpendicular;
    // the move itself goes to its programmed point and the vector is gone
    // (G28 in offset mode: cancelled at the intermediate point, restored by
    // a start-up at the next move).
    flush(out);
    send(c, out);
    if (const AxisVec* t = target_of(c.cmd)) prog_ = *t;
    has_vector_ = false;
    return {};
  }
  if (!path_move) {
    if (held_) {
      deferred_.push_back(c);
    } else {
      send(c, out);
    }
    return {};
  }
  const AxisVec& target = *target_of(c.cmd);
  const bool is_arc = std::holds_alternative<canon::Arc>(c.cmd);
  if (!is_arc && length(plane(target) - plane(prog_)) < kSamePoint) {
    // No move in the offset plane (a Z move): the tool stays offset.
    canon::Stamped m = c;
    if (held_) {
      deferred_.push_back(m);
    } else {
      set_plane(*target_of(m.cmd), plane(tool_));
      send(std::move(m), out);
    }
    prog_ = target;
    return {};
  }
  plane_move = true;
  const Entity e = make(c, mode);
  SKIPNC_TRY(mode.side != 0 ? offset_move(e, c, mode, out) : cancel_move(e, c, mode, out));
  prog_ = target;
  return {};
}

Result<void> Compensator::block(const std::vector<canon::Stamped>& cmds, const BlockMode& mode,
                                std::vector<canon::Stamped>& out) {
  a0_ = mode.a0;
  a1_ = mode.a1;
  broke_ = 0;
  bool plane_move = false;
  for (const canon::Stamped& c : cmds) SKIPNC_TRY(block_command(c, mode, out, plane_move));
  if (held_ && !plane_move) {
    // Blocks without a plane move: one is looked past, more end the held
    // move perpendicular (as does G40 in a block without a plane move).
    if (mode.side == 0) {
      flush(out);
    } else if (++quiet_ > mode.max_quiet_blocks) {
      broke_ = flush(out);
    }
  }
  if (!held_) {
    has_vector_ = length(plane(tool_) - plane(prog_)) >= kSamePoint;
  }
  return {};
}

}  // namespace skipnc::interp::crc
