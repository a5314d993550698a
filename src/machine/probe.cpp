#include "machine/probe.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skipnc::machine {
namespace {

// An edge instant is inside (0, 1]: the kernel reads 0 as "the previous period".
double edge_frac(double t) noexcept {
  return std::clamp(t, std::nextafter(0.0, 1.0), 1.0);
}

}  // namespace

// --- Scatter ------------------------------------------------------------------

double Scatter::uniform() noexcept {
  // splitmix64 (Steele, Lea, Flood 2014): one 64-bit state, full period.
  state_ += 0x9E3779B97F4A7C15ULL;
  std::uint64_t z = state_;
  z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
  z ^= z >> 31U;
  // 53 random bits, shifted off zero.
  return (static_cast<double>(z >> 11U) + 0.5) * 0x1.0p-53;
}

double Scatter::normal() noexcept {
  if (have_spare_) {
    have_spare_ = false;
    return spare_;
  }
  const double u1 = uniform(), u2 = uniform();
  const double r = std::sqrt(-2.0 * std::log(u1));
  const double phi = 2.0 * std::numbers::pi * u2;
  spare_ = r * std::sin(phi);
  have_spare_ = true;
  return r * std::cos(phi);
}

// --- TouchProbe ---------------------------------------------------------------

TouchProbe::TouchProbe(const ProbeSpec& spec, const geo::Material& material,
                       const geo::Stock* stock) noexcept
    : spec_(spec), solids_(material, stock), scatter_(spec.seed) {}

double TouchProbe::pre_travel_for(geo::Vec3 n) const noexcept {
  const double nxy = std::sqrt(n.x * n.x + n.y * n.y);
  double d = spec_.pre_travel;
  if (spec_.lobing != 0.0 && nxy > 0.0) {
    // The probe moves against the normal: the approach direction's angle.
    const double approach = std::atan2(-n.y, -n.x);
    const double phase = spec_.lobing_phase_deg * std::numbers::pi / 180.0;
    d += spec_.lobing * 0.5 * (1.0 - std::cos(spec_.lobes * (approach - phase))) * nxy;
  }
  return d;
}

void TouchProbe::start_contact(geo::Vec3 normal) noexcept {
  double d = pre_travel_for(normal);
  if (spec_.repeatability > 0.0) d += spec_.repeatability * scatter_.normal();
  // The switch point stays inside the ball (the scene checks pre_travel < radius).
  delta_ = std::clamp(d, 0.0, spec_.ball_radius * 0.999);
}

double TouchProbe::signed_deflection(geo::Vec3 p) const noexcept {
  // Only the sign and values up to the deflection matter: a ball farther
  // than its radius is clear, by however much (the distance search can stop
  // early; a mesh of a million triangles costs a few boxes then).
  const double d = solids_.distance(p, 2.0 * spec_.ball_radius);
  return d > 0.0 ? spec_.ball_radius - d : spec_.ball_radius + solids_.depth(p);
}

double TouchProbe::deflection_at(geo::Vec3 p) const noexcept {
  return std::max(0.0, signed_deflection(p));
}

void TouchProbe::reset(geo::Vec3 ball) noexcept {
  anchor_margin_ = -1.0;
  raw_ = signed_deflection(ball);
  deflection_ = std::max(0.0, raw_);
  state_ = State::kFree;
  if (raw_ >= 0.0) {
    start_contact(geo::Vec3{0, 0, 1});
    state_ = raw_ >= delta_ ? State::kOn : State::kTouching;
  }
}

// True when every point of the path a -> b is farther than the ball's
// radius from the material, with some spare: then the ball of radius r can
// touch nothing in the period (first_contact finds no contact) and it ends
// clear (signed_deflection < 0), which is all advance() takes from those
// searches while the ball is free. The spare covers the contact searches'
// own tolerances (a point within kOnSurface of a solid, a rim's contact
// within 1e-6 (1 + r) of the radius) many times over. The clearance of a
// point moved by s is at least its clearance less s, and the point of a
// segment farthest from the anchor is one of its ends.
bool TouchProbe::far_from_material(geo::Vec3 a, geo::Vec3 b) noexcept {
  // Both ends within the margin of the anchor (squared: no root).
  const auto holds = [&] {
    const geo::Vec3 da = a - anchor_, db = b - anchor_;
    return std::max(geo::dot(da, da), geo::dot(db, db)) < anchor_margin_sq_;
  };
  if (anchor_margin_ > 0.0 && holds()) return true;
  const double need = spec_.ball_radius + 1e-5 * (1.0 + spec_.ball_radius);
  anchor_ = a;
  anchor_margin_ = solids_.clearance(a) - need;
  anchor_margin_sq_ = anchor_margin_ * anchor_margin_;
  return anchor_margin_ > 0.0 && holds();
}

int TouchProbe::advance(geo::Vec3 a, geo::Vec3 b, SensorEdge* edges) noexcept {
  int n = 0;
  const double r = spec_.ball_radius;
  if (state_ == State::kFree && far_from_material(a, b)) {
    // What the searches below give there: no contact, clear of the
    // material (raw_ is only ever compared with 0 and the switch point).
    raw_ = -r;
    deflection_ = 0.0;
    return 0;
  }
  double t_from = 0.0;
  if (state_ == State::kFree) {
    geo::Contact c;
    if (solids_.first_contact(a, b, r, c)) {
      contact_ = c;
      start_contact(c.normal);
      state_ = State::kTouching;
      t_from = c.t;
    }
  }
  if (state_ == State::kTouching) {
    // The switch: the ball centre comes within r - delta of the surface.
    // Solved over the whole period (a ball of r - delta did not touch at
    // its start either), so that a zero pre-travel gives the touch itself.
    geo::Contact c;
    if (solids_.first_contact(a, b, r - delta_, c)) {
      state_ = State::kOn;
      edges[n++] = SensorEdge{edge_frac(std::max(c.t, t_from)), true};
    }
  }
  // Signed: negative while the ball is clear of the material.
  raw_ = signed_deflection(b);
  deflection_ = std::max(0.0, raw_);
  if (state_ == State::kOn && raw_ < delta_) {
    // Released during the period: the last instant the switch was held is
    // the first contact met going backwards from b.
    geo::Contact c;
    double t = 1.0;
    if (solids_.first_contact(b, a, r - delta_, c, /*backward=*/true)) t = 1.0 - c.t;
    if (n > 0) t = std::max(t, edges[0].frac);
    edges[n++] = SensorEdge{edge_frac(t), false};
    state_ = raw_ >= 0.0 ? State::kTouching : State::kFree;
  } else if (state_ == State::kTouching && raw_ < 0.0) {
    state_ = State::kFree;  // left without switching: the next touch draws anew
  } else if (state_ == State::kFree && raw_ >= 0.0) {
    // A contact the segment solution did not see (grazing at the end).
    start_contact(geo::Vec3{0, 0, 1});
    state_ = State::kTouching;
  }
  if (state_ == State::kTouching && raw_ >= delta_ && n == 0) {
    state_ = State::kOn;
    edges[n++] = SensorEdge{1.0, true};
  }
  return n;
}

// --- SetterSensor ---------------------------------------------------------------

SetterSensor::SetterSensor(const ToolSetterSpec& spec) noexcept : spec_(spec) {
  disc_ = spec.disc();
  // A zero pre-travel switches at first contact (1 nm of overlap).
  switch_ = std::max(spec.pre_travel, 1e-6);
}

void SetterSensor::reset(const geo::Column* tool) noexcept {
  pressed_ = tool != nullptr ? std::max(0.0, geo::column_overlap(*tool, disc_)) : 0.0;
  on_ = pressed_ >= switch_;
}

int SetterSensor::advance(const geo::Column* tool, geo::Vec3 move, SensorEdge* edges) noexcept {
  int n = 0;
  if (tool == nullptr) {
    pressed_ = 0.0;
    if (on_) {
      on_ = false;
      edges[n++] = SensorEdge{1.0, false};
    }
    return n;
  }
  double t = 0.0;
  if (!on_ && geo::column_first_overlap(*tool, move, disc_, switch_, t)) {
    on_ = true;
    edges[n++] = SensorEdge{edge_frac(t), true};
  }
  geo::Column end = *tool;
  end.x += move.x;
  end.y += move.y;
  end.bottom += move.z;
  end.top += move.z;
  pressed_ = std::max(0.0, geo::column_overlap(end, disc_));
  if (on_ && pressed_ < switch_) {
    double back = 0.0;
    double off = 1.0;
    if (geo::column_first_overlap(end, move * -1.0, disc_, switch_, back)) off = 1.0 - back;
    if (n > 0) off = std::max(off, edges[0].frac);
    on_ = false;
    edges[n++] = SensorEdge{edge_frac(off), false};
  } else if (!on_ && pressed_ >= switch_) {
    on_ = true;
    edges[n++] = SensorEdge{1.0, true};
  }
  return n;
}

// --- GaugeSensor ----------------------------------------------------------------

GaugeSensor::GaugeSensor(const GaugeSpec& spec) : spec_(spec), on_(spec.steps.size(), 0) {}

void GaugeSensor::reset(double position) noexcept {
  diameter_ = std::min(spec_.raw_diameter, 2.0 * std::fabs(position - spec_.center));
  for (std::size_t i = 0; i < spec_.steps.size(); ++i) {
    on_[i] = diameter_ <= spec_.steps[i].diameter ? 1 : 0;
  }
}

double GaugeSensor::swept_diameter(double p0, double p1) const noexcept {
  const double c = spec_.center;
  if ((p0 - c) * (p1 - c) <= 0.0) return 0.0;  // the wheel crossed the axis
  return 2.0 * std::min(std::fabs(p0 - c), std::fabs(p1 - c));
}

bool GaugeSensor::reaches(double p0, double p1, double size, double& frac) const noexcept {
  if (size >= diameter_) {
    frac = edge_frac(0.0);
    return true;
  }
  const double half = size * 0.5, c = spec_.center;
  double bound;
  if (p0 > c + half) {
    bound = c + half;
    if (p1 > bound) return false;
  } else if (p0 < c - half) {
    bound = c - half;
    if (p1 < bound) return false;
  } else {
    frac = edge_frac(0.0);
    return true;
  }
  frac = edge_frac((p0 - bound) / (p0 - p1));
  return true;
}

}  // namespace skipnc::machine
