// What a plot shows, independent of how it is drawn: the run's path per
// executed block, the scene reduced to generic shapes, the skip points and
// the scope channels. The SVG writer and the page's script both draw this
// one model, so a new kind of scene object needs only new shapes
// (shapes.cpp), not new drawing code.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/scene.hpp"
#include "plot/recorder.hpp"
#include "sim/simulator.hpp"

namespace skipnc::plot {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
  double operator[](int i) const noexcept { return i == 0 ? x : i == 1 ? y : z; }
  double& operator[](int i) noexcept { return i == 0 ? x : i == 1 ? y : z; }
};

struct Box3 {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
  bool empty() const noexcept { return lo.x > hi.x; }
  void add(const Vec3& p) noexcept;
};

// Drawing styles, one table shared by every renderer (the page gets it as
// data): stroke and fill colours, width in px, dash pattern.
enum class Ink : std::uint8_t {
  kRapid,
  kFeed,
  kSkip,
  kTarget,
  kTrigger,
  kStop,
  kPart,
  kHole,
  kSetter,
  kStock,
  kLatch,
  kMiss,
  kRest,
  kStart,
  kCount
};
struct InkStyle {
  const char* name;  // CSS class and JSON key
  const char* stroke;
  const char* fill;  // "none" for lines
  double width;
  const char* dash;    // SVG dash array, "" for solid
  const char* legend;  // what it means, for the legend
};
const InkStyle& ink(Ink i) noexcept;
// Colour of axis i in the scope (X red, Y green, Z blue, then others).
const char* axis_colour(int i) noexcept;

// Scene geometry in machine coordinates. A plane that is face-on in a view
// (its normal along the viewing direction) is not drawn there; the view
// lists its `note` instead.
struct Shape {
  // kSegments: pts in pairs, one stroke per pair.
  enum class Kind : std::uint8_t { kPolygon, kPolyline, kSegments };
  Kind kind = Kind::kPolygon;
  Ink ink = Ink::kTrigger;
  std::vector<Vec3> pts;
  std::string label;      // drawn next to the shape ("" for none)
  int normal_axis = -1;   // 0/1/2: a plane normal to x/y/z (-1: not a plane)
  std::string note;       // text for views in which the plane is face-on
  bool in_iso = true;     // drawn in the isometric view too
  bool only_iso = false;  // drawn in the isometric view only (a silhouette seen from there)
};

// A projection: screen u = dot(p, u), screen v = dot(p, v) (v up).
struct ViewDef {
  std::string id;  // "xy", "xz", "yz", "iso"
  std::string title;
  Vec3 u, v;
  int look_axis = -1;          // 0/1/2 for views along an axis, -1 for the isometric view
  std::string u_name, v_name;  // axis names on the view's edges ("" for iso)
  // The vertical axis's tick labels are v_scale times the machine value (2:
  // a lathe's X shown in diameter); the geometry stays in machine mm.
  double v_scale = 1.0;
  std::string note;  // added to the axis legend ("X in diameter")
};

// One executed block, for drawing: the path runs from `from` (the previous
// block's end) through samples [s0, s1) to `to`.
struct BlockView {
  std::uint32_t line = 0;
  std::uint32_t ctx = 0;  // call context (PlotModel::contexts)
  MoveKind kind = MoveKind::kNone;
  double t0 = 0.0, t1 = 0.0;
  std::size_t s0 = 0, s1 = 0;
  Vec3 from, to;
  AxisVec end_machine;  // commanded rest position at the end, all axes
};

struct SkipVar {
  std::string name;  // "#5063" or "#<NC.SysVars.G31.LCS.Z>"
  char axis = 'X';
  double value = 0.0;
};

struct SkipMark {
  std::size_t index = 0;
  std::uint32_t line = 0;
  std::uint32_t ctx = 0;
  std::string block, signal, kind;
  std::string code;  // G31, G37, G38.2-G38.5
  bool triggered = false;
  int p = -1;
  double latch_t = 0.0;             // instant of the signal (or of the sync when none came)
  double stop_t = 0.0;              // the axes at rest
  Vec3 latch, rest, start, target;  // machine coordinates (x, y, z of the machine)
  bool has_target = false;
  AxisVec latch_machine, rest_machine, position, end_position;
  std::vector<int> moved_axes;  // axes the skip block moved
  std::vector<SkipVar> vars;    // what went into the skip variables (moved axes)
  double overtravel_mm = 0.0;   // from the latch to the rest point
  bool ended_by_alarm = false;  // the run's alarm stopped it (a probe crash, ...)
  std::string label;            // "L6 #5063=-23.8000"
  std::string rest_label;       // "L6 rest Z-23.8105"
};

struct Series {
  std::string name;
  std::string colour;
  std::vector<double> v;  // one value per sample
};

struct Channel {
  std::string id;
  std::string title;
  std::string unit;
  bool digital = false;
  std::vector<Series> series;
  // Every series stays within min_span over the whole run: drawn as a
  // thin strip with its value.
  bool flat = false;
  double min_span = 1.0;  // smallest value range a strip is scaled to
};

// A file the run executed blocks of, with its text for the listing.
struct ListingFile {
  std::string name;                // as the report names it
  std::vector<std::string> lines;  // 1-based: lines[line - 1]; empty when unknown
};

// A call context of the run (record::CallContext): the file its lines are
// in, and how a place in it is named ("L12" in the main program,
// "O9810.nc:12" in another file).
struct PlaceContext {
  std::uint32_t file = 0;  // PlotModel::files
  std::string where;       // "O9810.nc (O9810) called from probe.nc:9 (G65 P9810)"; "" for the main
};

struct PlotModel {
  std::string program, machine, dialect, status, alarm;
  double time_s = 0.0;
  std::uint64_t periods = 0;
  std::vector<char> axis_names;
  std::array<int, 3> xyz{-1, -1, -1};  // machine axis index of X, Y, Z (-1: absent)
  std::vector<double> t;               // sample instants
  std::vector<std::uint32_t> line;     // sample lines
  std::vector<std::uint32_t> ctx;      // sample call contexts
  std::vector<Vec3> path;              // actual position per sample (x, y, z)
  std::vector<BlockView> blocks;
  std::vector<Channel> channels;
  std::vector<Shape> shapes;
  std::vector<SkipMark> skips;
  std::vector<ViewDef> views;
  Box3 extent;                         // what the views are framed on: where the run worked
  Box3 full_extent;                    // everything: the whole path and the scene
  std::vector<ListingFile> files;      // [0] the main program
  std::vector<PlaceContext> contexts;  // [0] the main program
  std::vector<std::pair<std::string, std::optional<double>>> variables;
  std::vector<std::string> messages;
  std::vector<std::string> signal_names;
  // The path is the tool tip (ball centre for a probe): the spindle's gauge
  // point minus the length of the tool in the spindle along Z. True when a
  // tool with a length was in the spindle at some time.
  bool tip_path = false;
  // What the header says of the path: "path of the tool tip", with "(probe:
  // ball centre)" only when the scene has a probe; "" when not tip_path.
  std::string tip_note;
  // The legend of the skip ink: the codes of the skip moves that ran
  // ("skip move (G31)", "probe move (G38.2, G38.4)").
  std::string skip_legend;
  // A probe crash, collision or probe-protection alarm: where it happened
  // (x, y, z of the machine, the tool tip as the path), drawn as a marker.
  std::optional<Vec3> alarm_at;
  std::string alarm_key;  // "probe_crash", "collision", "probe_protection"
};

struct PlotInput {
  std::string program;      // name shown in the title
  std::string_view source;  // program text ("" when unknown)
  // Reads the text of a file a call went to (a macro, a subprogram file),
  // by the path the interpreter read it from; null: those files are listed
  // without text.
  std::function<std::string(const std::string& path)> read_file;
  const config::MachineConfig* machine = nullptr;
  const config::Dialect* dialect = nullptr;
  const machine::Scene* scene = nullptr;
  const sim::RunResult* result = nullptr;
  const Recorder* recorder = nullptr;
  std::vector<std::pair<std::string, std::optional<double>>> variables;
  bool x_in_diameter = false;  // a lathe's X programmed in diameter (1006#3)
};

[[nodiscard]] PlotModel build_model(const PlotInput& in);

// The scene as shapes, sized to `extent` (shapes.cpp).
std::vector<Shape> scene_shapes(const machine::Scene& scene, const config::MachineConfig& m,
                                const std::array<int, 3>& xyz, const Box3& extent);
// The stock's deepest cut at the end of the run, in the side views: along X
// on its front face, along Y on its left face (shapes.cpp).
void add_stock_cut(const sim::StockResult& st, const machine::Scene& scene,
                   std::vector<Shape>& out);
// What of the scene has a size of its own (parts, tool setter): the views
// show all of it.
void add_scene_extent(const machine::Scene& scene, Box3& extent);

// A block's place in a label: "L12" in the main program's file,
// "O9810.nc:12" in another, with " N30" when `n` >= 0.
std::string place_label(const PlotModel& pm, std::uint32_t ctx, std::uint32_t line, int n = -1);
// The same for people: "line 12" in the main program, else the report's
// where ("O9810.nc:12 (O9810) called from probe.nc:9 (G65 P9810)").
std::string place_text(const PlotModel& pm, std::uint32_t ctx, std::uint32_t line);

// "#5063" (Fanuc-style numbered) or the dialect's named variable.
std::string skip_var_name(const config::Dialect& d, int axis_index, char axis_name);

// The text with every ill-formed part of UTF-8 replaced by U+FFFD
// (utf8::make_valid; program comments may be Latin-1).
std::string clean_utf8(std::string_view text);

// Number text for labels: fixed decimals, no "-0".
std::string num(double v, int decimals = 4);

}  // namespace skipnc::plot
