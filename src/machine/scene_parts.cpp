// Loading of the probing tables of a scene file (docs/scene.md). Strict:
// every unknown key and every value out of range is an error with its
// file, line and column.
#include "machine/scene_parts.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>

#include "config/skip_inputs.hpp"
#include "config/toml_util.hpp"
#include "machine/mesh.hpp"
#include "machine/scene_toml.hpp"
#include "machine/stock.hpp"

namespace skipnc::machine {

using config::check_keys;
using config::config_error;
using config::get_number;
using config::get_string;

namespace {

constexpr double kFar = 1e6;  // mm: "no limit" for the ends of bores

struct Reader {
  std::string_view origin;
  const config::MachineConfig& m;
  const config::Dialect& d;
  const config::Parameters& p;

  Result<double> number(const toml::table& t, std::string_view key, double min, double max,
                        std::optional<double> fallback = std::nullopt) const {
    const auto* n = t.get(key);
    if (n == nullptr) {
      if (fallback) return *fallback;
      return config_error(t, origin, "needs " + std::string(key));
    }
    return get_number(*n, origin, key, min, max);
  }

  Result<std::int64_t> integer(const toml::table& t, std::string_view key, std::int64_t min,
                               std::int64_t max, std::optional<std::int64_t> fallback) const {
    const auto* n = t.get(key);
    if (n == nullptr) {
      if (fallback) return *fallback;
      return config_error(t, origin, "needs " + std::string(key));
    }
    const auto* i = n->as_integer();
    if (i == nullptr) return config_error(*n, origin, std::string(key) + " must be an integer");
    const std::int64_t v = i->get();
    if (v < min || v > max) {
      return config_error(*n, origin,
                          std::string(key) + " = " + std::to_string(v) + " is out of range [" +
                              std::to_string(min) + ", " + std::to_string(max) + "]");
    }
    return v;
  }

  // [x, y] or [x, y, z] of numbers.
  template <std::size_t N>
  Result<std::array<double, N>> vec(const toml::table& t, std::string_view key) const {
    const auto* n = t.get(key);
    if (n == nullptr) return config_error(t, origin, "needs " + std::string(key));
    const auto* arr = n->as_array();
    const std::string shape = N == 2 ? "[x, y]" : "[x, y, z]";
    if (arr == nullptr || arr->size() != N) {
      return config_error(*n, origin, std::string(key) + " must be " + shape + " (mm)");
    }
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
      auto v = get_number(*arr->get(i), origin, key, -kFar, kFar);
      SKIPNC_TRY(v);
      out[i] = *v;
    }
    return out;
  }

  // `min` and `max` of a box-shaped table, max above min on every axis;
  // otherwise the error names `what` and stands at `at`.
  Result<std::pair<geo::Vec3, geo::Vec3>> corners(const toml::table& t, std::string_view what,
                                                  const toml::node& at) const {
    auto lo = vec<3>(t, "min");
    SKIPNC_TRY(lo);
    auto hi = vec<3>(t, "max");
    SKIPNC_TRY(hi);
    for (std::size_t i = 0; i < 3; ++i) {
      if (!((*hi)[i] > (*lo)[i])) {
        return config_error(at, origin, std::string(what) + ": max must exceed min on every axis");
      }
    }
    return std::pair{geo::Vec3{(*lo)[0], (*lo)[1], (*lo)[2]},
                     geo::Vec3{(*hi)[0], (*hi)[1], (*hi)[2]}};
  }

  Result<canon::SignalAddr> signal(const toml::table& t, std::string& name) const {
    return scene_signal(t, origin, d, p, name);
  }
};

const toml::table* single(const toml::table& root, std::string_view key) {
  const auto* n = root.get(key);
  return n != nullptr ? n->as_table() : nullptr;
}

constexpr double kPi = 3.14159265358979323846;

// The frames a scene places things in (docs/scene.md): "machine", the work
// frames G54..G59 of the machine file (EXT + G5x, no rotation), and the
// scene's own [[frame]] tables, each an origin and a turn about Z in a frame
// named before it.
// A frame as the scene places things in it: where it stands (a rotary
// table's frame at the table's zero) and, on a rotary table, how it turns.
struct Frame {
  geo::Placement place;
  geo::Rotary rotary;
};

class Frames {
 public:
  explicit Frames(const config::MachineConfig& m) : m_(m) {
    frames_.emplace("machine", Frame{});
    static constexpr std::string_view kWork[] = {"G54", "G55", "G56", "G57", "G58", "G59"};
    for (std::size_t k = 0; k < 6; ++k) {
      geo::Vec3 o;
      double* xyz[] = {&o.x, &o.y, &o.z};
      for (int a = 0; a < 3; ++a) {
        const int i = m.axis_index("XYZ"[a]);
        if (i >= 0) *xyz[a] = m.work_offsets[0][i] + m.work_offsets[k + 1][i];
      }
      frames_.emplace(std::string(kWork[k]), Frame{geo::Placement{o}, {}});
    }
  }

  Result<void> load(const toml::table& root, const Reader& rd) {
    return config::each_table(root, "frame", rd.origin, [&](const toml::table& t) -> Result<void> {
      auto k = check_keys(t, {"name", "base", "origin", "rotation", "rotary", "rotary_sign"},
                          rd.origin, "[[frame]]");
      if (!k) return k;
      const auto* n = t.get("name");
      if (n == nullptr) return config_error(t, rd.origin, "[[frame]] needs a name");
      auto name = get_string(*n, rd.origin, "name");
      SKIPNC_TRY(name);
      if (name->empty() || frames_.contains(*name)) {
        return config_error(*n, rd.origin,
                            "frame '" + *name + "' is " +
                                (name->empty() ? "not a name" : "defined already") +
                                " (machine and G54..G59 are built in)");
      }
      auto base = resolve(t, rd.origin, "base");
      SKIPNC_TRY(base);
      geo::Vec3 o;
      if (t.get("origin") != nullptr) {
        auto v = rd.vec<3>(t, "origin");
        SKIPNC_TRY(v);
        o = {(*v)[0], (*v)[1], (*v)[2]};
      }
      auto turn = rotation(t, rd.origin);
      SKIPNC_TRY(turn);
      const auto& deg = *turn;
      const geo::Placement local = geo::Placement::turned_by(
          o, deg[0] * kPi / 180.0, deg[1] * kPi / 180.0, deg[2] * kPi / 180.0);
      Frame f{base->place.then(local), base->rotary};
      if (f.rotary.turns()) f.rotary.inner = base->rotary.inner.then(local);
      auto table = rotary(t, rd.origin, *base);
      SKIPNC_TRY(table);
      if (table->turns()) {
        f.rotary = *table;
        f.rotary.table = f.place;
      }
      frames_.emplace(*name, f);
      return {};
    });
  }

  // `rotary`: the frame is a rotary table's, turned about its own X, Y or Z
  // by the machine's A, B or C axis (ISO 841); `rotary_sign`: -1 (a table
  // axis: a positive move turns the table clockwise seen from the axis'
  // plus side, so that the tool turns positive about the part) or 1.
  Result<geo::Rotary> rotary(const toml::table& t, std::string_view origin,
                             const Frame& base) const {
    geo::Rotary r;
    const auto* n = t.get("rotary");
    if (n == nullptr) {
      if (t.get("rotary_sign") != nullptr) {
        return config_error(*t.get("rotary_sign"), origin, "rotary_sign needs rotary");
      }
      return r;
    }
    auto name = get_string(*n, origin, "rotary");
    SKIPNC_TRY(name);
    if (*name != "A" && *name != "B" && *name != "C") {
      return config_error(*n, origin, "rotary must be \"A\", \"B\" or \"C\" (about X, Y, Z)");
    }
    r.axis = m_.axis_index((*name)[0]);
    if (r.axis < 0) {
      return config_error(*n, origin, "rotary axis " + *name + " is not an axis of this machine");
    }
    if (base.rotary.turns()) {
      return config_error(*n, origin,
                          "frame's base is on a rotary table already: one rotary axis per "
                          "part (a table on a table is not modelled)");
    }
    r.about = (*name)[0] - 'A';
    if (const auto* sn = t.get("rotary_sign")) {
      const auto* i = sn->as_integer();
      if (i == nullptr || (i->get() != 1 && i->get() != -1)) {
        return config_error(*sn, origin, "rotary_sign must be -1 or 1");
      }
      r.sign = static_cast<double>(i->get());
    }
    return r;
  }

  // `rotation`: degrees about Z, or [about X, about Y, about Z] turned in
  // that order about the base frame's axes (a part tilted on an angle
  // plate, a vise off square).
  static Result<std::array<double, 3>> rotation(const toml::table& t, std::string_view origin) {
    std::array<double, 3> deg{};
    const auto* n = t.get("rotation");
    if (n == nullptr) return deg;
    const auto* arr = n->as_array();
    if (arr == nullptr) {
      auto z = get_number(*n, origin, "rotation", -360.0, 360.0);
      SKIPNC_TRY(z);
      deg[2] = *z;
      return deg;
    }
    if (arr->size() != 3) {
      return config_error(*n, origin,
                          "rotation must be degrees about Z, or [about X, about Y, about Z]");
    }
    for (std::size_t i = 0; i < 3; ++i) {
      auto v = get_number(*arr->get(i), origin, "rotation", -360.0, 360.0);
      SKIPNC_TRY(v);
      deg[i] = *v;
    }
    return deg;
  }

  // The frame `key` of table t names ("machine" when absent).
  Result<Frame> resolve(const toml::table& t, std::string_view origin,
                        std::string_view key = "frame") const {
    const auto* n = t.get(key);
    if (n == nullptr) return Frame{};
    auto name = get_string(*n, origin, key);
    SKIPNC_TRY(name);
    auto it = frames_.find(*name);
    if (it == frames_.end()) {
      std::string known;
      for (const auto& [k, v] : frames_) known += (known.empty() ? "" : ", ") + k;
      return config_error(*n, origin,
                          "no frame '" + *name + "' (known here: " + known +
                              "; a [[frame]] must come before what it places)");
    }
    return it->second;
  }

 private:
  const config::MachineConfig& m_;
  std::map<std::string, Frame> frames_;
};

// Parts are grouped by name; a part's holes cut only its own solids. Every
// table of a part places it in the same frame.
class PartSet {
 public:
  explicit PartSet(const Frames& frames) : frames_(frames) {}
  std::vector<std::string> mesh_files;

  geo::Part& get(const toml::table& t, std::string_view origin, Result<void>& err) {
    std::string name;
    if (const auto* n = t.get("part")) {
      auto s = get_string(*n, origin, "part");
      if (!s) {
        err = std::unexpected(s.error());
        return scratch_;
      }
      name = *s;
    }
    auto place = frames_.resolve(t, origin);
    if (!place) {
      err = std::unexpected(place.error());
      return scratch_;
    }
    const std::string frame =
        t.get("frame") != nullptr ? *t.get("frame")->value<std::string>() : std::string("machine");
    auto it = index_.find(name);
    if (it == index_.end()) {
      it = index_.emplace(name, parts_.size()).first;
      parts_.push_back(geo::Part{name, {}, {}, place->place, {}, place->rotary});
      first_.push_back(&t);
      frame_.push_back(frame);
    } else if (frame_[it->second] != frame) {
      err = config_error(
          t.get("frame") != nullptr ? *t.get("frame") : static_cast<const toml::node&>(t), origin,
          "part '" + name + "' is placed in frame '" + frame_[it->second] +
              "' by its first table (line " +
              std::to_string(first_[it->second]->source().begin.line) +
              "): every table of a part uses the same frame");
      return scratch_;
    }
    return parts_[it->second];
  }
  // A part with holes and no solid is refused at the first table that names it.
  Result<void> check_solids(std::string_view origin) const {
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      if (parts_[i].solids.empty() && parts_[i].meshes.empty()) {
        return config_error(
            *first_[i], origin,
            "part '" + parts_[i].name + "' has holes but no solid to cut them from");
      }
    }
    return {};
  }
  std::vector<geo::Part> take() { return std::move(parts_); }

 private:
  const Frames& frames_;
  std::vector<geo::Part> parts_;
  std::vector<const toml::table*> first_;  // per part, the first table that names it
  std::vector<std::string> frame_;         // per part, the frame it is placed in
  std::map<std::string, std::size_t> index_;
  geo::Part scratch_;
};

// [[box]] (a solid) or [[pocket]] (a hole): min and max corners.
Result<void> parse_boxes(const toml::table& root, const Reader& rd, PartSet& parts,
                         std::string_view key, bool hole) {
  const auto origin = rd.origin;
  return config::each_table(root, key, origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"part", "frame", "min", "max"}, origin, "[[" + std::string(key) + "]]");
    if (!k) return k;
    auto box = rd.corners(t, "[[" + std::string(key) + "]]", t);
    SKIPNC_TRY(box);
    Result<void> err;
    geo::Part& part = parts.get(t, origin, err);
    if (!err) return err;
    const geo::Shape s = geo::make_box(box->first, box->second);
    (hole ? part.holes : part.solids).push_back(s);
    return {};
  });
}

// [[cylinder]] (a solid) or [[bore]] (a hole, open at both ends by default).
Result<void> parse_rounds(const toml::table& root, const Reader& rd, PartSet& parts,
                          std::string_view key, bool hole) {
  const auto origin = rd.origin;
  return config::each_table(root, key, origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"part", "frame", "center", "radius", "bottom", "top"}, origin,
                        "[[" + std::string(key) + "]]");
    if (!k) return k;
    auto c = rd.vec<2>(t, "center");
    SKIPNC_TRY(c);
    auto radius = rd.number(t, "radius", 1e-6, kFar);
    SKIPNC_TRY(radius);
    const std::optional<double> lo_def = hole ? std::optional<double>(-kFar) : std::nullopt;
    const std::optional<double> hi_def = hole ? std::optional<double>(kFar) : std::nullopt;
    auto bottom = rd.number(t, "bottom", -kFar, kFar, lo_def);
    SKIPNC_TRY(bottom);
    auto top = rd.number(t, "top", -kFar, kFar, hi_def);
    SKIPNC_TRY(top);
    if (!(*top > *bottom))
      return config_error(t, origin, "[[" + std::string(key) + "]]: top must exceed bottom");
    Result<void> err;
    geo::Part& part = parts.get(t, origin, err);
    if (!err) return err;
    const geo::Shape s = geo::make_cylinder((*c)[0], (*c)[1], *radius, *bottom, *top);
    (hole ? part.holes : part.solids).push_back(s);
    return {};
  });
}

Result<void> parse_spheres(const toml::table& root, const Reader& rd, PartSet& parts) {
  const auto origin = rd.origin;
  return config::each_table(root, "sphere", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"part", "frame", "center", "radius"}, origin, "[[sphere]]");
    if (!k) return k;
    auto c = rd.vec<3>(t, "center");
    SKIPNC_TRY(c);
    auto radius = rd.number(t, "radius", 1e-6, kFar);
    SKIPNC_TRY(radius);
    Result<void> err;
    geo::Part& part = parts.get(t, origin, err);
    if (!err) return err;
    part.solids.push_back(geo::make_sphere({(*c)[0], (*c)[1], (*c)[2]}, *radius));
    return {};
  });
}

// [[mesh]]: an STL file, relative to the scene file's folder.
Result<void> parse_meshes(const toml::table& root, const Reader& rd, PartSet& parts) {
  const auto origin = rd.origin;
  return config::each_table(root, "mesh", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"part", "frame", "file", "scale"}, origin, "[[mesh]]");
    if (!k) return k;
    const auto* fn = t.get("file");
    if (fn == nullptr) return config_error(t, origin, "[[mesh]] needs file = \"part.stl\"");
    auto file = get_string(*fn, origin, "file");
    SKIPNC_TRY(file);
    auto scale = rd.number(t, "scale", 1e-6, 1e6, 1.0);
    SKIPNC_TRY(scale);
    // Relative to the scene file's folder.
    std::filesystem::path path(*file);
    if (path.is_relative()) path = std::filesystem::path(origin).parent_path() / path;
    parts.mesh_files.push_back(path.string());
    auto tris = geo::read_stl(path.string(), *scale);
    if (!tris) return config_error(*fn, origin, tris.error().detail);
    auto mesh = std::make_shared<const geo::TriMesh>(std::move(*tris));
    if (mesh->size() == 0) {
      return config_error(*fn, origin, "STL '" + path.string() + "' has no triangle with an area");
    }
    Result<void> err;
    geo::Part& part = parts.get(t, origin, err);
    if (!err) return err;
    part.meshes.push_back(std::move(mesh));
    return {};
  });
}

Result<void> parse_planes(const toml::table& root, const Reader& rd, PartSet& parts) {
  const auto origin = rd.origin;
  return config::each_table(root, "plane", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"part", "frame", "point", "normal"}, origin, "[[plane]]");
    if (!k) return k;
    auto pt = rd.vec<3>(t, "point");
    SKIPNC_TRY(pt);
    auto n = rd.vec<3>(t, "normal");
    SKIPNC_TRY(n);
    const geo::Vec3 nv{(*n)[0], (*n)[1], (*n)[2]};
    if (geo::length(nv) < 1e-9)
      return config_error(t, origin, "[[plane]]: normal must not be zero");
    Result<void> err;
    geo::Part& part = parts.get(t, origin, err);
    if (!err) return err;
    part.solids.push_back(geo::make_half_space({(*pt)[0], (*pt)[1], (*pt)[2]}, nv));
    return {};
  });
}

// The parts' shapes, kind by kind (an error in an earlier kind is reported first).
Result<void> parse_parts(const toml::table& root, const Reader& rd, PartSet& parts) {
  SKIPNC_TRY(parse_boxes(root, rd, parts, "box", false));
  SKIPNC_TRY(parse_boxes(root, rd, parts, "pocket", true));
  SKIPNC_TRY(parse_rounds(root, rd, parts, "cylinder", false));
  SKIPNC_TRY(parse_rounds(root, rd, parts, "bore", true));
  SKIPNC_TRY(parse_spheres(root, rd, parts));
  SKIPNC_TRY(parse_meshes(root, rd, parts));
  return parse_planes(root, rd, parts);
}

// The probe's length, gauge line to ball centre: the scene's `length` (the
// physical stylus), else the machine file's tool offset H`offset` (the
// probe's T number by default; geometry + wear, as G43 applies it). The two
// may differ, as on a machine whose H has not been calibrated yet, or holds
// Renishaw's length to the ball's lowest point: the difference is kept in
// `p` (h_number, h_length) and said once as a warning (probe_length_differs).
Result<double> probe_length(const toml::table& t, const Reader& rd, int tool, ProbeSpec& p) {
  std::optional<int> h;
  if (t.get("offset") != nullptr) {
    auto o = rd.integer(t, "offset", 1, rd.m.tool_offset_count, std::nullopt);
    SKIPNC_TRY(o);
    h = static_cast<int>(*o);
  } else if (tool >= 1 && tool <= rd.m.tool_offset_count) {
    h = tool;
  }
  const auto it = h ? rd.m.tool_offsets.find(*h) : rd.m.tool_offsets.end();
  const auto* scene = t.get("length");
  if (it == rd.m.tool_offsets.end()) {
    if (t.get("offset") != nullptr) {
      return config_error(*t.get("offset"), rd.origin,
                          "offset = " + std::to_string(*h) +
                              ": the machine file has no tool offset of that number "
                              "([tool_offsets] " +
                              std::to_string(*h) + " = { length = ... })");
    }
    return scene != nullptr ? get_number(*scene, rd.origin, "length", 0.0, kFar) : 0.0;
  }
  const double table = it->second.length_geometry + it->second.length_wear;
  if (scene == nullptr) {
    if (!(table >= 0.0 && table <= kFar)) {
      return config_error(t, rd.origin,
                          "the probe's length from H" + std::to_string(it->first) + " (" +
                              std::to_string(table) + " mm) must be between 0 and 1e6 mm");
    }
    return table;
  }
  auto v = get_number(*scene, rd.origin, "length", 0.0, kFar);
  if (!v) return v;
  if (std::fabs(*v - table) > 1e-6) {
    p.h_number = it->first;
    p.h_length = table;
  }
  return *v;
}

// on_m, off_m, start_time: the M codes that switch the probe on and off.
Result<void> parse_probe_switching(const toml::table& t, const Reader& rd, ProbeSpec& p) {
  auto on_m = rd.integer(t, "on_m", 0, 9999, 0);
  SKIPNC_TRY(on_m);
  auto off_m = rd.integer(t, "off_m", 0, 9999, 0);
  SKIPNC_TRY(off_m);
  auto start = rd.number(t, "start_time", 0.0, 60.0, 0.0);
  SKIPNC_TRY(start);
  if (*on_m == 0 && (*off_m != 0 || *start != 0.0)) {
    return config_error(*t.get(*off_m != 0 ? "off_m" : "start_time"), rd.origin,
                        "off_m and start_time need on_m: the M code that switches the probe on");
  }
  if (*on_m != 0 && *on_m == *off_m) {
    return config_error(*t.get("off_m"), rd.origin, "off_m must differ from on_m");
  }
  p.on_m = static_cast<int>(*on_m);
  p.off_m = static_cast<int>(*off_m);
  p.start_time_s = *start;
  return {};
}

// lobing = { amplitude, lobes, phase }: the probe's trigger force by direction.
Result<void> parse_lobing(const toml::table& t, const Reader& rd, ProbeSpec& p) {
  if (const auto* n = t.get("lobing")) {
    const auto* lt = n->as_table();
    if (lt == nullptr) {
      return config_error(*n, rd.origin,
                          "lobing must be a table: { amplitude = 0.002, lobes = 3, phase = 0 }");
    }
    auto lk = check_keys(*lt, {"amplitude", "lobes", "phase"}, rd.origin, "lobing");
    SKIPNC_TRY(lk);
    auto amp = rd.number(*lt, "amplitude", 0.0, p.ball_radius);
    SKIPNC_TRY(amp);
    p.lobing = *amp;
    auto lobes = rd.integer(*lt, "lobes", 1, 24, 3);
    SKIPNC_TRY(lobes);
    p.lobes = static_cast<int>(*lobes);
    auto phase = rd.number(*lt, "phase", -360.0, 360.0, 0.0);
    SKIPNC_TRY(phase);
    p.lobing_phase_deg = *phase;
    if (p.pre_travel + p.lobing >= p.ball_radius) {
      return config_error(*n, rd.origin,
                          "pre_travel + lobing amplitude must be smaller than ball_radius");
    }
  }
  return {};
}

Result<ProbeSpec> parse_probe(const toml::table& t, const Reader& rd) {
  const auto origin = rd.origin;
  auto k = check_keys(t,
                      {"signal", "tool", "offset", "ball_radius", "length", "stylus_length",
                       "body_radius", "pre_travel", "max_overtravel", "lobing", "repeatability",
                       "seed", "on_m", "off_m", "start_time"},
                      origin, "[probe]");
  SKIPNC_TRY(k);
  ProbeSpec p;
  auto sig = rd.signal(t, p.signal_name);
  SKIPNC_TRY(sig);
  p.signal = *sig;
  auto tool = rd.integer(t, "tool", 0, 99999999, 0);
  SKIPNC_TRY(tool);
  p.tool = static_cast<int>(*tool);
  const std::pair<std::string_view, double*> lengths[] = {{"stylus_length", &p.stylus_length},
                                                          {"body_radius", &p.body_radius},
                                                          {"repeatability", &p.repeatability}};
  for (const auto& [key, field] : lengths) {
    auto v = rd.number(t, key, 0.0, kFar, *field);
    SKIPNC_TRY(v);
    *field = *v;
  }
  auto length = probe_length(t, rd, p.tool, p);
  SKIPNC_TRY(length);
  p.length = *length;
  auto ball = rd.number(t, "ball_radius", 1e-3, 1000.0);
  SKIPNC_TRY(ball);
  p.ball_radius = *ball;
  auto pre = rd.number(t, "pre_travel", 0.0, kFar, 0.0);
  SKIPNC_TRY(pre);
  if (*pre >= p.ball_radius) {
    return config_error(*t.get("pre_travel"), origin,
                        "pre_travel must be smaller than ball_radius");
  }
  p.pre_travel = *pre;
  auto over = rd.number(t, "max_overtravel", 0.0, kFar);
  SKIPNC_TRY(over);
  p.max_overtravel = *over;
  auto seed = rd.integer(t, "seed", 0, std::numeric_limits<std::int64_t>::max(), 1);
  SKIPNC_TRY(seed);
  p.seed = static_cast<std::uint64_t>(*seed);
  SKIPNC_TRY(parse_probe_switching(t, rd, p));
  SKIPNC_TRY(parse_lobing(t, rd, p));
  return p;
}

Result<ToolSetterSpec> parse_setter(const toml::table& t, const Reader& rd, const Frames& frames) {
  auto k = check_keys(
      t,
      {"signal", "frame", "center", "top", "radius", "thickness", "pre_travel", "max_overtravel"},
      rd.origin, "[tool_setter]");
  SKIPNC_TRY(k);
  ToolSetterSpec s;
  auto sig = rd.signal(t, s.signal_name);
  SKIPNC_TRY(sig);
  s.signal = *sig;
  auto c = rd.vec<2>(t, "center");
  SKIPNC_TRY(c);
  s.x = (*c)[0];
  s.y = (*c)[1];
  auto top = rd.number(t, "top", -kFar, kFar);
  SKIPNC_TRY(top);
  s.top = *top;
  auto radius = rd.number(t, "radius", 1e-3, 1000.0);
  SKIPNC_TRY(radius);
  s.radius = *radius;
  auto thick = rd.number(t, "thickness", 1e-3, 1000.0, 5.0);
  SKIPNC_TRY(thick);
  s.thickness = *thick;
  auto pre = rd.number(t, "pre_travel", 0.0, 10.0, 0.0);
  SKIPNC_TRY(pre);
  s.pre_travel = *pre;
  auto over = rd.number(t, "max_overtravel", 0.0, 1000.0, 1.0);
  SKIPNC_TRY(over);
  s.max_overtravel = *over;
  // A disc: only its centre and top move with the frame.
  auto place = frames.resolve(t, rd.origin);
  SKIPNC_TRY(place);
  if (place->rotary.turns()) {
    return config_error(*t.get("frame"), rd.origin,
                        "the tool setter cannot stand on a rotary table (its frame turns)");
  }
  const geo::Vec3 c0 = place->place.to_machine({s.x, s.y, s.top});
  s.x = c0.x;
  s.y = c0.y;
  s.top = c0.z;
  return s;
}

// The most cells a stock's grid may have: 4 million (32 MB of tops).
constexpr double kMaxStockCells = 4e6;

Result<StockSpec> parse_stock(const toml::table& t, const Reader& rd, const Frames& frames) {
  const auto origin = rd.origin;
  auto k = check_keys(t, {"frame", "min", "max", "resolution"}, origin, "[stock]");
  SKIPNC_TRY(k);
  const toml::node* at_max = t.get("max");
  auto box = rd.corners(t, "[stock]", at_max != nullptr ? *at_max : t);
  SKIPNC_TRY(box);
  auto res = rd.number(t, "resolution", 1e-3, 100.0, 0.5);
  SKIPNC_TRY(res);
  // The cells are columns along the machine's Z on a grid along its X and
  // Y: a frame may move the stock, not turn it.
  auto frame = frames.resolve(t, origin);
  SKIPNC_TRY(frame);
  if (frame->rotary.turns()) {
    return config_error(*t.get("frame"), origin,
                        "[stock]: the stock cannot stand on a rotary table (its frame turns)");
  }
  const geo::Placement& place = frame->place;
  const geo::Vec3 o = place.to_machine({0.0, 0.0, 0.0});
  for (const geo::Vec3 e : {geo::Vec3{1, 0, 0}, geo::Vec3{0, 1, 0}, geo::Vec3{0, 0, 1}}) {
    if (geo::length(place.to_machine(e) - o - e) > 1e-12) {
      return config_error(*t.get("frame"), origin,
                          "[stock]: frame '" + *t.get("frame")->value<std::string>() +
                              "' is turned; the stock's cells are axis-aligned, so it may only "
                              "be moved (machine, G54..G59, or a [[frame]] without rotation)");
    }
  }
  StockSpec s;
  s.lo = box->first + o;
  s.hi = box->second + o;
  s.resolution = *res;
  const double cells = geo::Stock::cell_count(s.lo, s.hi, s.resolution);
  if (cells > kMaxStockCells) {
    const auto* at = t.get("resolution");
    return config_error(
        at != nullptr ? *at : static_cast<const toml::node&>(t), origin,
        fmt::format("[stock]: a {:g} mm grid over {:g} x {:g} mm is {:.0f} cells, "
                    "more than {:.0f}: use a coarser resolution",
                    s.resolution, s.hi.x - s.lo.x, s.hi.y - s.lo.y, cells, kMaxStockCells));
  }
  return s;
}

Result<GaugeSpec> parse_gauge(const toml::table& t, const Reader& rd) {
  const auto origin = rd.origin;
  auto k = check_keys(t, {"axis", "center", "raw_diameter", "steps"}, origin, "[[gauge]]");
  SKIPNC_TRY(k);
  GaugeSpec g;
  const auto* an = t.get("axis");
  if (an == nullptr) return config_error(t, origin, "needs axis = \"X\" (the infeed axis)");
  auto as = get_string(*an, origin, "axis");
  SKIPNC_TRY(as);
  g.axis = as->size() == 1 ? rd.m.axis_index((*as)[0]) : -1;
  if (g.axis < 0)
    return config_error(*an, origin, "axis '" + *as + "' is not an axis of this machine");
  auto c = rd.number(t, "center", -kFar, kFar);
  SKIPNC_TRY(c);
  g.center = *c;
  auto raw = rd.number(t, "raw_diameter", 1e-6, kFar);
  SKIPNC_TRY(raw);
  g.raw_diameter = *raw;
  const auto* sn = t.get("steps");
  const auto* arr = sn != nullptr ? sn->as_array() : nullptr;
  if (arr == nullptr || arr->empty()) {
    return config_error(sn != nullptr ? *sn : static_cast<const toml::node&>(t), origin,
                        "needs steps = [{ signal = \"SKIP2\", diameter = 50.2 }, ...]");
  }
  for (const auto& e : *arr) {
    const auto* st = e.as_table();
    if (st == nullptr)
      return config_error(e, origin, "each step is { signal = ..., diameter = ... }");
    auto sk = check_keys(*st, {"signal", "diameter"}, origin, "a gauge step");
    SKIPNC_TRY(sk);
    GaugeStep step;
    auto sig = rd.signal(*st, step.signal_name);
    SKIPNC_TRY(sig);
    step.signal = *sig;
    auto dia = rd.number(*st, "diameter", 0.0, g.raw_diameter);
    SKIPNC_TRY(dia);
    step.diameter = *dia;
    g.steps.push_back(step);
  }
  return g;
}

}  // namespace

Result<canon::SignalAddr> scene_signal(const toml::table& t, std::string_view origin,
                                       const config::Dialect& d, const config::Parameters& p,
                                       std::string& name) {
  const auto* n = t.get("signal");
  if (n == nullptr)
    return config_error(t, origin, "needs signal = \"X0.4\" (or SKIP, SKIP1..SKIP12)");
  auto s = get_string(*n, origin, "signal");
  SKIPNC_TRY(s);
  auto a = config::parse_signal_name(*s, d, p);
  if (!a) {
    return config_error(
        *n, origin,
        "signal '" + *s + "' is not X<0-127>.<0-7>, G<0-511>.<0-7>, SKIP or SKIP1..SKIP12");
  }
  name = *s;
  return *a;
}

Result<Probing> parse_probing(const toml::table& root, std::string_view origin,
                              const config::MachineConfig& m, const config::Dialect& d,
                              const config::Parameters& p) {
  const Reader rd{origin, m, d, p};
  Probing out;
  Frames frames(m);
  auto r = frames.load(root, rd);
  SKIPNC_TRY(r);
  PartSet parts(frames);
  r = parse_parts(root, rd, parts);
  SKIPNC_TRY(r);
  r = parts.check_solids(origin);
  SKIPNC_TRY(r);
  out.mesh_files = parts.mesh_files;
  out.parts = parts.take();
  for (const char* key : {"probe", "tool_setter", "stock"}) {
    const auto* n = root.get(key);
    if (n != nullptr && n->as_table() == nullptr) {
      return config_error(*n, origin, "[" + std::string(key) + "] must be a table (one per scene)");
    }
  }
  if (const auto* t = single(root, "probe")) {
    auto probe = parse_probe(*t, rd);
    SKIPNC_TRY(probe);
    out.probe = *probe;
  }
  if (const auto* t = single(root, "tool_setter")) {
    auto setter = parse_setter(*t, rd, frames);
    SKIPNC_TRY(setter);
    out.tool_setter = *setter;
  }
  if (const auto* t = single(root, "stock")) {
    auto stock = parse_stock(*t, rd, frames);
    SKIPNC_TRY(stock);
    out.stock = *stock;
  }
  r = config::each_table(root, "tool", origin, [&](const toml::table& t) -> Result<void> {
    auto k = check_keys(t, {"number", "length", "radius"}, origin, "[[tool]]");
    if (!k) return k;
    ToolSpec tool;
    auto num = rd.integer(t, "number", 1, 99999999, std::nullopt);
    SKIPNC_TRY(num);
    tool.number = static_cast<int>(*num);
    if (out.tool(tool.number) != nullptr || (out.probe && out.probe->tool == tool.number)) {
      return config_error(t, origin, "tool " + std::to_string(tool.number) + " is defined twice");
    }
    auto len = rd.number(t, "length", 0.0, kFar);
    SKIPNC_TRY(len);
    tool.length = *len;
    auto radius = rd.number(t, "radius", 0.0, 1000.0);
    SKIPNC_TRY(radius);
    tool.radius = *radius;
    out.tools.push_back(tool);
    return {};
  });
  SKIPNC_TRY(r);
  r = config::each_table(root, "gauge", origin, [&](const toml::table& t) -> Result<void> {
    auto g = parse_gauge(t, rd);
    SKIPNC_TRY(g);
    out.gauges.push_back(*g);
    return {};
  });
  SKIPNC_TRY(r);
  out.spindle_tool = out.probe ? out.probe->tool : 0;
  if (const auto* n = root.get("spindle_tool")) {
    auto v = rd.integer(root, "spindle_tool", 0, 99999999, std::nullopt);
    SKIPNC_TRY(v);
    const int tool = static_cast<int>(*v);
    if (tool != 0 && out.tool(tool) == nullptr && !(out.probe && out.probe->tool == tool)) {
      return config_error(
          *n, origin,
          "spindle_tool = " + std::to_string(tool) + " is neither a [[tool]] nor the probe's tool");
    }
    out.spindle_tool = tool;
  }
  return out;
}

}  // namespace skipnc::machine
