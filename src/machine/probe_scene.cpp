#include "machine/probe_scene.hpp"

#include <algorithm>
#include <cmath>

namespace skipnc::machine {
namespace {

constexpr double kCollisionTol = 1e-9;  // mm of overlap that counts as touching

// The first t in [0, 1] where pred(t) holds, given that it holds at 1.
template <class P>
double first_true(P&& pred) noexcept {
  if (pred(0.0)) return 0.0;
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (pred(mid)) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  return hi;
}

// The middle of a column, the centre of the sphere column_clear keeps clear.
geo::Vec3 column_mid(const geo::Column& c) noexcept {
  return geo::Vec3{c.x, c.y, c.bottom + 0.5 * (c.top - c.bottom)};
}

}  // namespace

ProbeScene::ProbeScene(const Probing& spec, const config::MachineConfig& m)
    : spec_(spec),
      material_(spec_.parts),
      stock_(spec_.stock ? geo::Stock(spec_.stock->lo, spec_.stock->hi, spec_.stock->resolution)
                         : geo::Stock()) {
  ix_ = m.axis_index('X');
  iy_ = m.axis_index('Y');
  iz_ = m.axis_index('Z');
  if (spec_.probe) {
    probe_.emplace(*spec_.probe, material_, &stock_);
    probe_source_ = sources_.size();
    sources_.push_back(Source{Kind::kProbe, spec_.probe->signal, 0, 0, false});
  }
  if (spec_.tool_setter) {
    setter_.emplace(*spec_.tool_setter);
    setter_source_ = sources_.size();
    sources_.push_back(Source{Kind::kSetter, spec_.tool_setter->signal, 0, 0, false});
  }
  gauges_.reserve(spec_.gauges.size());
  for (std::size_t g = 0; g < spec_.gauges.size(); ++g) {
    gauges_.emplace_back(spec_.gauges[g]);
    for (std::size_t s = 0; s < spec_.gauges[g].steps.size(); ++s) {
      sources_.push_back(Source{Kind::kGauge, spec_.gauges[g].steps[s].signal, g, s, false});
    }
  }
  edges_.resize(sources_.size() * 2 + 2);
  spindle_tool_ = spec_.spindle_tool;
  senses_ = probe_ || setter_ || !gauges_.empty() || !material_.empty() || !stock_.empty();
}

// An edge at the start of the period (a tool change, a switch).
constexpr double kAtOnce = 1e-9;

void ProbeScene::push_edge(std::size_t source, double frac, bool on) noexcept {
  if (edge_count_ < edges_.size()) edges_[edge_count_++] = Edge{source, frac, on};
  sources_[source].on = on;
  if (on && sources_[source].kind != Kind::kGauge && !touch_on_) {
    touch_on_ = true;
    touch_frac_ = frac;
  }
}

void ProbeScene::reset(const AxisVec& actual) noexcept {
  fault_ = PlantFault{};
  stock_.reset();
  cutting_ = settling_ = cuts_now_ = false;
  edge_count_ = 0;
  touch_on_ = false;
  column_margin_ = -1.0;
  rest_travel_sq_ = 0.0;
  pending_tool_.reset();
  pending_power_.reset();
  powered_ = !(spec_.probe && spec_.probe->on_m != 0);
  if (material_.turns()) material_.set_turns(actual.v.data(), actual.v.data());
  if (probe_) {
    const bool in = probe_in_spindle();
    if (in) probe_->reset(ball_at(actual));
    sources_[probe_source_].on = powered_ && in && probe_->on();
  }
  if (setter_) {
    const ToolSpec* t = tool_in_spindle();
    const geo::Column c = t != nullptr ? tool_column(*t, actual) : geo::Column{};
    setter_->reset(t != nullptr ? &c : nullptr);
    sources_[setter_source_].on = setter_->on();
  }
  for (auto& s : sources_) {
    if (s.kind != Kind::kGauge) continue;
    GaugeSensor& g = gauges_[s.gauge];
    if (s.step == 0) g.reset(actual[g.spec().axis]);
    s.on = g.step_on(s.step);
  }
}

void ProbeScene::change_tool(const AxisVec& at) noexcept {
  spindle_tool_ = *pending_tool_;
  pending_tool_.reset();
  column_margin_ = -1.0;
  if (probe_) {
    bool now = false;
    if (probe_in_spindle()) {
      probe_->reset(ball_at(at));
      now = probe_->on();
    }
    if (now != sources_[probe_source_].on) probe_edge(kAtOnce, now);
  }
  if (setter_) {
    const ToolSpec* t = tool_in_spindle();
    const geo::Column c = t != nullptr ? tool_column(*t, at) : geo::Column{};
    setter_->reset(t != nullptr ? &c : nullptr);
    if (setter_->on() != sources_[setter_source_].on)
      push_edge(setter_source_, kAtOnce, setter_->on());
  }
}

// Switched on, the input shows at once whether the stylus is deflected;
// switched off, it goes off.
void ProbeScene::apply_power() noexcept {
  powered_ = *pending_power_;
  pending_power_.reset();
  const bool now = powered_ && probe_in_spindle() && probe_->on();
  if (now != sources_[probe_source_].on) push_edge(probe_source_, kAtOnce, now);
}

void ProbeScene::advance_sensors(const AxisVec& before, const AxisVec& after) noexcept {
  // Parts on rotary tables turn with their axes over the period.
  if (material_.turns()) material_.set_turns(before.v.data(), after.v.data());
  if (pending_tool_) change_tool(before);
  if (pending_power_ && probe_) apply_power();
  if (!senses_) return;
  SensorEdge e[2];
  if (probe_ && probe_in_spindle()) {
    const int n = probe_->advance(ball_at(before), ball_at(after), e);
    for (int i = 0; i < n; ++i) probe_edge(e[i].frac, e[i].on);
  }
  if (setter_) {
    const ToolSpec* t = tool_in_spindle();
    const geo::Column c = t != nullptr ? tool_column(*t, before) : geo::Column{};
    const int n = setter_->advance(t != nullptr ? &c : nullptr, point(after) - point(before), e);
    for (int i = 0; i < n; ++i) push_edge(setter_source_, e[i].frac, e[i].on);
  }
  if (!gauges_.empty()) {
    std::size_t first = 0;  // source index of the gauge's first step
    for (std::size_t g = 0; g < gauges_.size(); ++g) {
      while (first < sources_.size() &&
             !(sources_[first].kind == Kind::kGauge && sources_[first].gauge == g)) {
        ++first;
      }
      const int axis = gauges_[g].spec().axis;
      gauges_[g].advance(before[axis], after[axis], [&](std::size_t step, double frac) {
        push_edge(first + step, frac, true);
      });
    }
  }
  if (touch_on_) touch_at_ = lerp(before, after, touch_frac_);
  cuts_now_ = cut_stock(before, after);
  // Most periods: no fault yet and nothing pressed beyond its overtravel.
  if (fault_.kind != PlantFault::Kind::kNone || (probe_ && probe_->overshoot() > 0.0) ||
      (setter_ && setter_->overshoot() > 0.0)) {
    check_crash(before, after);
  }
  check_collision(before, after);
  arm_rest(after);
}

void ProbeScene::check_crash(const AxisVec& before, const AxisVec& after) noexcept {
  const bool probe_crash = probe_ && probe_in_spindle() && probe_->overshoot() > 0.0;
  const ToolSpec* tool = tool_in_spindle();
  const bool setter_crash = setter_ && tool != nullptr && setter_->overshoot() > 0.0;
  if (fault_.kind == PlantFault::Kind::kProbeCrash ||
      fault_.kind == PlantFault::Kind::kSetterCrash) {
    // The axes are still coming to rest: keep the worst.
    const bool is_probe = fault_.kind == PlantFault::Kind::kProbeCrash;
    const double defl = is_probe ? (probe_ && probe_in_spindle() ? probe_->deflection() : 0.0)
                                 : (setter_ ? setter_->deflection() : 0.0);
    fault_.latest = after;
    if (defl > fault_.deflection) {
      fault_.deflection = defl;
      fault_.overshoot = defl - fault_.limit;
    }
    return;
  }
  if (fault_.kind != PlantFault::Kind::kNone || (!probe_crash && !setter_crash)) return;
  PlantFault f;
  if (probe_crash) {
    f.kind = PlantFault::Kind::kProbeCrash;
    f.limit = probe_->switch_deflection() + probe_->spec().max_overtravel;
    f.deflection = probe_->deflection();
    const geo::Vec3 a = ball_at(before), b = ball_at(after);
    const double t =
        first_true([&](double s) { return probe_->deflection_at(geo::lerp(a, b, s)) > f.limit; });
    f.at = lerp(before, after, t);
  } else {
    f.kind = PlantFault::Kind::kSetterCrash;
    f.limit = std::max(setter_->spec().pre_travel, 1e-6) + setter_->spec().max_overtravel;
    f.deflection = setter_->deflection();
    const geo::Column disc = setter_->disc();
    const double t = first_true([&](double s) {
      return geo::column_overlap(tool_column(*tool, lerp(before, after, s)), disc) > f.limit;
    });
    f.at = lerp(before, after, t);
    f.tool = tool->number;
  }
  f.overshoot = f.deflection - f.limit;
  f.latest = after;
  fault_ = f;
}

bool ProbeScene::cut_stock(const AxisVec& before, const AxisVec& after) noexcept {
  const ToolSpec* t = tool_in_spindle();
  if (t == nullptr || stock_.empty()) return false;
  if (!cutting_) {
    if (!settling_) return false;
    // Once the tool turns away from the cutting move's end it is the rapid
    // (or skip) that moves it: no more cutting until the next cutting move.
    settling_ = geo::dot(point(after) - point(before), point(cut_end_) - point(before)) > 0.0;
    if (!settling_) return false;
  }
  // The tip's centre: the whole column below the gauge line cuts, so its
  // lowest point is what lowers the stock.
  const geo::Vec3 down{0.0, 0.0, t->length};
  stock_.cut(point(before) - down, point(after) - down, t->radius);
  return true;
}

void ProbeScene::check_collision(const AxisVec& before, const AxisVec& after) noexcept {
  if (fault_.kind != PlantFault::Kind::kNone || (material_.empty() && stock_.empty())) return;
  // A cutting tool has just removed the stock in its way (cut_stock).
  const bool stock_hits = !stock_.empty() && !cuts_now_;
  // The column that must not touch a part: the probe body or the tool.
  auto column_at = [&](const AxisVec& at, geo::Column& c) {
    if (probe_in_spindle()) return probe_body(ball_at(at), c);
    const ToolSpec* t = tool_in_spindle();
    if (t == nullptr) return false;
    c = tool_column(*t, at);
    return true;
  };
  auto hits = [&](const geo::Column& col) {
    return material_.column_hits(col, kCollisionTol) >= 0 ||
           (stock_hits && stock_.column_hits(col, kCollisionTol));
  };
  geo::Column c;
  if (!column_at(after, c) || column_clear(c) || !hits(c)) return;
  const int part = material_.column_hits(c, kCollisionTol);
  const double t = first_true([&](double s) {
    geo::Column cs;
    return column_at(lerp(before, after, s), cs) && hits(cs);
  });
  fault_.kind = PlantFault::Kind::kCollision;
  fault_.at = lerp(before, after, t);
  fault_.latest = after;
  fault_.part = part;
  fault_.stock = part < 0;
  const ToolSpec* tool = tool_in_spindle();
  fault_.tool = tool != nullptr ? tool->number : -1;
}

// The column lies inside the sphere about its middle of radius
// sqrt(half height^2 + radius^2); a point moved by s from the anchor has a
// clearance of at least the anchor's less s (Material::clearance is a lower
// bound of the distance to the parts' bounding boxes; the stock's likewise,
// and cutting only removes stock). Parts on a turning table have none.
bool ProbeScene::column_clear(const geo::Column& c) noexcept {
  const double h = 0.5 * (c.top - c.bottom);
  const geo::Vec3 mid = column_mid(c);
  if (column_margin_ > 0.0) {
    const geo::Vec3 d = mid - column_anchor_;
    if (geo::dot(d, d) < column_margin_sq_) return true;
  }
  // A new anchor here; the column's size is the same until the tool changes.
  constexpr double kSpare = 1e-6;  // mm
  const double need = std::sqrt(h * h + c.radius * c.radius) + kCollisionTol + kSpare;
  double clear = material_.clearance(mid);
  if (!stock_.empty()) clear = std::min(clear, stock_.clearance(mid));
  column_anchor_ = mid;
  column_margin_ = clear - need;
  column_margin_sq_ = column_margin_ * column_margin_;
  return column_margin_ > 0.0;
}

bool ProbeScene::probe_body(geo::Vec3 ball, geo::Column& c) const noexcept {
  const ProbeSpec& p = *spec_.probe;
  if (p.body_radius <= 0.0 || p.length <= p.stylus_length) return false;
  c = geo::Column{ball.x, ball.y, p.body_radius, ball.z + p.stylus_length, ball.z + p.length};
  return true;
}

// The probe, its body, the setter and a switch can change only through
// advance_sensors' searches, a tool change or a power switch (which disarm
// the rest). The ball and the body move with the spindle: moved by less
// than the travel left to either anchor (TouchProbe::free_travel, and
// column_clear's), the ball stays farther than its radius from the
// material (no contact, no deflection: its advance() returns at its far
// test) and the body stays clear (check_collision returns at column_clear);
// the setter, with no tool in the spindle, stays off and unpressed. 1 nm is
// taken off for the rounding of the points (the anchors keep 1e-6 mm and
// more to spare besides).
void ProbeScene::arm_rest(const AxisVec& after) noexcept {
  constexpr double kRounding = 1e-9;  // mm
  if (!probe_ || !probe_in_spindle() || fault_.kind != PlantFault::Kind::kNone || touch_on_ ||
      !gauges_.empty() || !stock_.empty() || material_.turns() || (setter_ && setter_->on())) {
    return;
  }
  const geo::Vec3 ball = ball_at(after);
  double travel = probe_->free_travel(ball);
  geo::Column c;
  if (!material_.empty() && probe_body(ball, c)) {
    if (!(column_margin_ > 0.0)) return;
    travel = std::min(travel, column_margin_ - geo::length(column_mid(c) - column_anchor_));
  }
  travel -= kRounding;
  if (!(travel > 0.0)) return;
  rest_at_ = point(after);
  rest_travel_sq_ = travel * travel;
}

}  // namespace skipnc::machine
