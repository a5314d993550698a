// The probing half of the plant: the parts, the touch probe or tool in the
// spindle, the tool setter and the gauges, advanced once per servo period
// on the actual axis motion (linear inside the period, as the kernel takes
// it). It produces signal edges with their exact instant and detects what
// would damage the machine: a stylus or setter pushed past its over-travel
// (crash), the probe body or a tool touching a part (collision). A tool
// that cuts (set_cutting) removes the stock it passes through instead.
//
// Signal sources, in this order: the probe, the tool setter, each step of
// each gauge. The plant ORs them with its other sources per address.
// advance() is noexcept and does not allocate.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "config/machine_config.hpp"
#include "core/axes.hpp"
#include "machine/geometry.hpp"
#include "machine/probe.hpp"
#include "machine/scene_parts.hpp"
#include "machine/stock.hpp"

namespace skipnc::machine {

// Something that would damage the machine, found in a period.
struct PlantFault {
  enum class Kind : std::uint8_t { kNone, kProbeCrash, kSetterCrash, kCollision };
  Kind kind = Kind::kNone;
  AxisVec at;               // machine (actual) position where it began
  AxisVec latest;           // machine position of the latest period since
  double deflection = 0.0;  // crash: largest deflection of stylus or setter, mm
  double limit = 0.0;       // crash: deflection at which damage begins, mm
  double overshoot = 0.0;   // crash: largest deflection beyond the limit, mm
  int part = -1;            // collision: index into Probing::parts
  bool stock = false;       // collision: with the stock (part is -1)
  int tool = -1;            // collision: the tool, or -1 for the probe body
};

class ProbeScene {
 public:
  ProbeScene(const Probing& spec, const config::MachineConfig& m);
  ProbeScene(const ProbeScene&) = delete;
  ProbeScene& operator=(const ProbeScene&) = delete;

  std::size_t source_count() const noexcept { return sources_.size(); }
  const canon::SignalAddr& source_signal(std::size_t i) const noexcept {
    return sources_[i].signal;
  }
  bool source_on(std::size_t i) const noexcept { return sources_[i].on; }

  void reset(const AxisVec& actual) noexcept;
  // The actual position went from `before` to `after` in this period.
  void advance(const AxisVec& before, const AxisVec& after) noexcept {
    edge_count_ = 0;
    touch_on_ = false;
    if (rest_travel_sq_ > 0.0) {
      // At rest (arm_rest): nothing to do while the spindle stays within
      // the travel that keeps the probe and its body clear of everything.
      const geo::Vec3 d = point(after) - rest_at_;
      if (geo::dot(d, d) < rest_travel_sq_) return;
      rest_travel_sq_ = 0.0;
    }
    if (pending_tool_ || senses_) advance_sensors(before, after);
  }
  // The probe and its body are at rest: the coming periods are passed on a
  // distance test until the spindle has moved too far (arm_rest).
  bool at_rest() const noexcept { return rest_travel_sq_ > 0.0; }
  // Nothing to sense, cut or collide with, and no tool change waiting:
  // advance() does nothing (Plant::can_cruise).
  bool inert() const noexcept { return !pending_tool_ && !senses_; }
  // Whether the tool in the spindle cuts in the next periods: the spindle
  // turns and the running command is a cutting move that ends at `end`
  // (the simulator knows the command; docs/scene.md, [stock]). A tool that
  // cuts lowers the stock it passes through; one that does not collides
  // with it. After a cutting move the tool still cuts while it moves toward
  // that move's end (the servo taking up its lag while a rapid has begun).
  void set_cutting(bool on, const AxisVec& end) noexcept {
    cutting_ = on;
    if (on) {
      settling_ = true;
      cut_end_ = end;
    }
  }
  // A switched probe (ProbeSpec::on_m): whether its input can come on.
  // Takes effect at the next period.
  void set_probe_power(bool on) noexcept {
    pending_power_ = on;
    rest_travel_sq_ = 0.0;
  }

  struct Edge {
    std::size_t source = 0;
    double frac = 1.0;
    bool on = false;
  };
  // The edges of the last period, in each source's time order.
  std::span<const Edge> edges() const noexcept { return {edges_.data(), edge_count_}; }
  // A probe or tool-setter signal switched on in the last period, and where.
  bool touch_switched_on() const noexcept { return touch_on_; }
  const AxisVec& touch_position() const noexcept { return touch_at_; }

  // Tool changes (M06): takes effect at the next period.
  void set_spindle_tool(int tool) noexcept {
    pending_tool_ = tool;
    rest_travel_sq_ = 0.0;
  }
  int spindle_tool() const noexcept { return spindle_tool_; }
  // The tool in the spindle once a change set but not yet made has been made.
  int next_spindle_tool() const noexcept { return pending_tool_ ? *pending_tool_ : spindle_tool_; }
  bool probe_in_spindle() const noexcept {
    return spec_.probe && spindle_tool_ == spec_.probe->tool;
  }
  const ToolSpec* tool_in_spindle() const noexcept {
    return probe_in_spindle() ? nullptr : spec_.tool(spindle_tool_);
  }
  // Gauge line to the tip of what is in the spindle (the probe's ball
  // centre), mm; 0 when the scene gives it no length.
  double spindle_tool_length() const noexcept {
    if (probe_in_spindle()) return spec_.probe->length;
    const ToolSpec* t = spec_.tool(spindle_tool_);
    return t != nullptr ? t->length : 0.0;
  }

  const PlantFault& fault() const noexcept { return fault_; }
  const Probing& spec() const noexcept { return spec_; }
  const geo::Material& material() const noexcept { return material_; }
  const geo::Stock& stock() const noexcept { return stock_; }
  // What the probe's ball can touch: the parts and the stock.
  geo::Solids solids() const noexcept { return geo::Solids(material_, &stock_); }
  const TouchProbe* probe() const noexcept { return probe_ ? &*probe_ : nullptr; }
  const SetterSensor* setter() const noexcept { return setter_ ? &*setter_ : nullptr; }
  const std::vector<GaugeSensor>& gauges() const noexcept { return gauges_; }

  // A machine position's X, Y, Z (0 for an axis the machine lacks). Inline:
  // the sensors ask for it several times a period.
  geo::Vec3 point(const AxisVec& machine) const noexcept {
    return geo::Vec3{ix_ >= 0 ? machine[ix_] : 0.0, iy_ >= 0 ? machine[iy_] : 0.0,
                     iz_ >= 0 ? machine[iz_] : 0.0};
  }
  // Where the ball centre is for a machine position.
  geo::Vec3 ball_at(const AxisVec& machine) const noexcept {
    geo::Vec3 b = point(machine);
    if (spec_.probe) b.z -= spec_.probe->length;
    return b;
  }
  // The tool's column for a machine position (tool in the spindle).
  geo::Column tool_column(const ToolSpec& t, const AxisVec& machine) const noexcept {
    const geo::Vec3 p = point(machine);
    return geo::Column{p.x, p.y, t.radius, p.z - t.length, p.z};
  }

 private:
  // advance() after its bookkeeping: tool change and the sensors.
  void advance_sensors(const AxisVec& before, const AxisVec& after) noexcept;
  enum class Kind : std::uint8_t { kProbe, kSetter, kGauge };
  struct Source {
    Kind kind = Kind::kProbe;
    canon::SignalAddr signal;
    std::size_t gauge = 0;
    std::size_t step = 0;
    bool on = false;
  };
  void push_edge(std::size_t source, double frac, bool on) noexcept;
  // The probe's input follows its switch only while it is powered.
  void probe_edge(double frac, bool on) noexcept {
    if (powered_) push_edge(probe_source_, frac, on);
  }
  void apply_power() noexcept;
  void change_tool(const AxisVec& at) noexcept;
  void check_collision(const AxisVec& before, const AxisVec& after) noexcept;
  // The probe's body, a column above the stylus, for a ball centred at
  // `ball`; false when the probe has none.
  bool probe_body(geo::Vec3 ball, geo::Column& c) const noexcept;
  // After a period that found nothing: arms the rest (rest_travel_sq_) when
  // every sensor is idle and the probe and its body are known clear.
  void arm_rest(const AxisVec& after) noexcept;
  // True when the column cannot touch a part or the stock: its bounding
  // sphere is inside the clearance of an anchor point it has not left (as
  // TouchProbe::far_from_material does for the ball).
  bool column_clear(const geo::Column& c) noexcept;
  // Whether the tool cuts in this period; if so, the stock it passes through
  // is removed.
  bool cut_stock(const AxisVec& before, const AxisVec& after) noexcept;
  void check_crash(const AxisVec& before, const AxisVec& after) noexcept;

  Probing spec_;
  geo::Material material_;
  geo::Stock stock_;       // empty without [stock]; cut in place, never reallocated
  bool cutting_ = false;   // the running command cuts
  bool settling_ = false;  // still moving toward the last cutting command's end
  AxisVec cut_end_;
  bool cuts_now_ = false;  // the tool cut in this period
  int ix_ = -1, iy_ = -1, iz_ = -1;
  std::optional<TouchProbe> probe_;
  std::optional<SetterSensor> setter_;
  std::vector<GaugeSensor> gauges_;
  std::vector<Source> sources_;
  std::size_t probe_source_ = 0, setter_source_ = 0;
  std::vector<Edge> edges_;  // capacity fixed at construction
  std::size_t edge_count_ = 0;
  int spindle_tool_ = 0;
  std::optional<int> pending_tool_;
  bool powered_ = true;  // a switched probe starts off (ProbeSpec::on_m)
  std::optional<bool> pending_power_;
  bool touch_on_ = false;
  // Something to sense or to hit: a probe, a setter, gauges or parts.
  bool senses_ = false;
  double touch_frac_ = 1.0;
  // column_clear's anchor, and how far the column may go from it (its
  // clearance less the column's bounding radius; <= 0: none, and reset when
  // what is in the spindle changes), with its square.
  geo::Vec3 column_anchor_;
  double column_margin_ = -1.0;
  double column_margin_sq_ = 0.0;
  AxisVec touch_at_;
  PlantFault fault_;
  // The rest: the probe in the spindle, free, clear of the material by more
  // than its radius and its body clear of it; the setter off; no gauge,
  // stock, turning part or fault. advance() is then a test of the distance
  // from rest_at_ (the spindle's X, Y, Z when armed), against the travel
  // that keeps it so, squared (0: not at rest).
  geo::Vec3 rest_at_;
  double rest_travel_sq_ = 0.0;
};

}  // namespace skipnc::machine
