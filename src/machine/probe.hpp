// The scene's sensors: a spindle touch probe, a tool setter and an
// in-process diameter gauge. Each is advanced once per servo period along
// the straight segment the plant's actual position follows in that period,
// and reports its signal's edges with their exact instant in the period.
// Nothing here allocates after construction.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "machine/geometry.hpp"
#include "machine/scene.hpp"
#include "machine/stock.hpp"

namespace skipnc::machine {

struct SensorEdge {
  double frac = 1.0;  // instant inside the period, (0, 1]
  bool on = false;
};

// A seeded source of normal deviates that gives the same sequence on every
// platform (splitmix64 and the Box-Muller transform; the standard library's
// distributions are implementation-defined).
class Scatter {
 public:
  explicit Scatter(std::uint64_t seed = 1) noexcept : state_(seed) {}
  double uniform() noexcept;  // (0, 1)
  double normal() noexcept;   // mean 0, standard deviation 1

 private:
  std::uint64_t state_;
  bool have_spare_ = false;
  double spare_ = 0.0;
};

class TouchProbe {
 public:
  // The ball touches the material's parts and, when given, the stock.
  TouchProbe(const ProbeSpec& spec, const geo::Material& material,
             const geo::Stock* stock = nullptr) noexcept;

  // State from a ball position with no motion (start-up).
  void reset(geo::Vec3 ball) noexcept;
  // The ball centre moves from a to b during the period. Writes up to two
  // edges (switch on, switch off) in time order; returns how many.
  int advance(geo::Vec3 a, geo::Vec3 b, SensorEdge* edges) noexcept;

  bool on() const noexcept { return state_ == State::kOn; }
  bool touching() const noexcept { return state_ != State::kFree; }
  // Deflection of the stylus at the end of the period (0 when free), mm.
  double deflection() const noexcept { return deflection_; }
  // Deflection at which the present contact switched (or will switch), mm.
  double switch_deflection() const noexcept { return delta_; }
  // Deflection past the maximum over-travel (> 0: the stylus is damaged).
  double overshoot() const noexcept { return deflection_ - delta_ - spec_.max_overtravel; }
  const geo::Contact& contact() const noexcept { return contact_; }
  const ProbeSpec& spec() const noexcept { return spec_; }
  // Pre-travel for a contact whose normal (surface toward ball) is `normal`,
  // lobing included, scatter not.
  double pre_travel_for(geo::Vec3 normal) const noexcept;
  // How far the ball, free and centred at b, may still move (any way) and
  // stay clear of the material by more than its radius, by the anchor of
  // far_from_material; <= 0: not known to be clear. Within that travel its
  // advance() finds nothing and changes nothing (ProbeScene's rest).
  double free_travel(geo::Vec3 b) const noexcept {
    if (state_ != State::kFree || !(anchor_margin_ > 0.0)) return 0.0;
    return anchor_margin_ - geo::length(b - anchor_);
  }
  // Deflection of a free ball centred at p (0 when not touching).
  double deflection_at(geo::Vec3 p) const noexcept;
  // The same, negative by the gap when the ball is clear of the material.
  double signed_deflection(geo::Vec3 p) const noexcept;

 private:
  enum class State : std::uint8_t { kFree, kTouching, kOn };
  void start_contact(geo::Vec3 normal) noexcept;
  bool far_from_material(geo::Vec3 a, geo::Vec3 b) noexcept;

  ProbeSpec spec_;
  geo::Solids solids_;
  Scatter scatter_;
  State state_ = State::kFree;
  double delta_ = 0.0;
  double deflection_ = 0.0;
  double raw_ = -1.0;
  geo::Contact contact_;
  // A point and how far the ball may go from it while it stays clear of the
  // material by more than its radius (Solids::clearance less the radius and
  // a spare; <= 0: none), with its square (far_from_material). While it
  // does, a free ball needs no search.
  geo::Vec3 anchor_;
  double anchor_margin_ = -1.0;
  double anchor_margin_sq_ = 0.0;
};

class SetterSensor {
 public:
  explicit SetterSensor(const ToolSetterSpec& spec) noexcept;
  geo::Column disc() const noexcept { return disc_; }
  // `tool`: the tool's column at the start of the period (none: radius < 0).
  void reset(const geo::Column* tool) noexcept;
  int advance(const geo::Column* tool, geo::Vec3 move, SensorEdge* edges) noexcept;
  bool on() const noexcept { return on_; }
  double deflection() const noexcept { return pressed_; }
  double overshoot() const noexcept { return pressed_ - switch_ - spec_.max_overtravel; }
  const ToolSetterSpec& spec() const noexcept { return spec_; }

 private:
  ToolSetterSpec spec_;
  geo::Column disc_;
  double switch_ = 0.0;  // overlap at which it switches
  bool on_ = false;
  double pressed_ = 0.0;
};

class GaugeSensor {
 public:
  explicit GaugeSensor(const GaugeSpec& spec);
  void reset(double position) noexcept;
  // The wheel moves from p0 to p1 along the gauge's axis. Calls
  // f(step index, frac) for each step that switches on, in step order.
  template <class F>
  void advance(double p0, double p1, F&& f) noexcept {
    for (std::size_t i = 0; i < spec_.steps.size(); ++i) {
      if (on_[i]) continue;
      double frac = 0.0;
      if (reaches(p0, p1, spec_.steps[i].diameter, frac)) {
        on_[i] = true;
        f(i, frac);
      }
    }
    diameter_ = std::min(diameter_, swept_diameter(p0, p1));
  }
  double diameter() const noexcept { return diameter_; }
  bool step_on(std::size_t i) const noexcept { return on_[i] != 0; }
  const GaugeSpec& spec() const noexcept { return spec_; }

 private:
  bool reaches(double p0, double p1, double size, double& frac) const noexcept;
  double swept_diameter(double p0, double p1) const noexcept;
  GaugeSpec spec_;
  std::vector<char> on_;
  double diameter_ = 0.0;
};

}  // namespace skipnc::machine
