#include "plot/model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/utf8.hpp"
#include "report/report.hpp"

namespace skipnc::plot {

void Box3::add(const Vec3& p) noexcept {
  for (int i = 0; i < 3; ++i) {
    lo[i] = std::min(lo[i], p[i]);
    hi[i] = std::max(hi[i], p[i]);
  }
}

namespace {

// Colour choices: path kinds as on a control's graphic screen (rapids dashed,
// feeds solid), skip moves and their points in colours that no axis uses.
constexpr std::array<InkStyle, static_cast<std::size_t>(Ink::kCount)> kInks{{
    {"rapid", "#8a8a8a", "none", 1.2, "5 4", "rapid (G00), dashed"},
    {"feed", "#1f5fbf", "none", 1.6, "", "feed (G01/G02/G03)"},
    {"skip", "#f08c00", "none", 2.6, "", "skip move (G31)"},
    {"target", "#f08c00", "none", 1.2, "2 3", "programmed skip end point, not reached"},
    {"trigger", "#2e9e4f", "#2e9e4f", 1.4, "", "signal trigger plane"},
    {"stop", "#5a4632", "#5a4632", 2.0, "", "rigid stop"},
    {"part", "#6b6b6b", "#9a9a9a", 1.2, "", "part"},
    {"hole", "#6b6b6b", "none", 1.0, "4 3", "bore or pocket in a part"},
    {"setter", "#7a4fa3", "#7a4fa3", 1.2, "", "tool setter"},
    {"stock", "#b07a2a", "none", 1.4, "", "stock: its box, and the deepest cut in the side views"},
    {"latch", "#e0007a", "#e0007a", 1.5, "", "latch: position stored by the skip"},
    {"miss", "#e0007a", "#ffffff", 2.0, "", "skip without a signal: end point stored"},
    {"rest", "#111111", "#ffffff", 1.8, "", "rest: where the axes stopped"},
    {"start", "#2e9e4f", "#ffffff", 1.8, "", "start of the run"},
}};

constexpr std::array<const char*, 8> kAxisColours{"#d62728", "#2ca02c", "#1f77b4", "#9467bd",
                                                  "#8c564b", "#e377c2", "#17becf", "#bcbd22"};

Vec3 to3(const AxisVec& a, const std::array<int, 3>& xyz) {
  Vec3 p;
  for (int k = 0; k < 3; ++k)
    p[k] = xyz[static_cast<std::size_t>(k)] >= 0 ? a[xyz[static_cast<std::size_t>(k)]] : 0.0;
  return p;
}

std::vector<ViewDef> views_for(const std::array<int, 3>& xyz, const std::vector<char>& names,
                               bool lathe, bool x_in_diameter) {
  const bool x = xyz[0] >= 0, y = xyz[1] >= 0, z = xyz[2] >= 0;
  auto nm = [&](int k) {
    return std::string(1, names[static_cast<std::size_t>(xyz[static_cast<std::size_t>(k)])]);
  };
  std::vector<ViewDef> v;
  if (lathe && x && z && !y) {
    // A lathe as its drawings show it: Z horizontal, X up (in diameter when
    // X is programmed in diameter), looking along -Y.
    ViewDef d{"zx", "Lathe view (ZX)", {0, 0, 1}, {1, 0, 0}, 1, nm(2), nm(0), 1.0, ""};
    if (x_in_diameter) {
      d.v_scale = 2.0;
      d.note = nm(0) + " in diameter";
    }
    v.push_back(d);
    return v;
  }
  if (x && y)
    v.push_back(ViewDef{"xy", "Top view (XY)", {1, 0, 0}, {0, 1, 0}, 2, nm(0), nm(1), 1.0, ""});
  if (x && z)
    v.push_back(ViewDef{"xz", "Front view (XZ)", {1, 0, 0}, {0, 0, 1}, 1, nm(0), nm(2), 1.0, ""});
  if (y && z)
    v.push_back(ViewDef{"yz", "Side view (YZ)", {0, 1, 0}, {0, 0, 1}, 0, nm(1), nm(2), 1.0, ""});
  if (x && y && z) {
    // Looking from +X -Y +Z: X runs right and down, Y right and up, Z up.
    const double a = 1.0 / std::sqrt(2.0), b = 1.0 / std::sqrt(6.0);
    v.push_back(ViewDef{"iso", "Isometric view", {a, a, 0}, {-b, b, 2 * b}, -1, "", "", 1.0, ""});
  }
  return v;
}

// Machine position where a skip block's axes came to rest, and when: the end
// of the block run that holds the latch.
const BlockRun* skip_block(const std::vector<BlockRun>& blocks, const record::SkipRecord& s) {
  const BlockRun* best = nullptr;
  for (const auto& b : blocks) {
    if (b.line != s.line || b.source != s.context) continue;
    if (b.t0 > s.time_s + 1e-9) break;
    best = &b;
  }
  return best;
}

std::vector<std::string> split_lines(std::string_view text, std::size_t max_lines) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < text.size() && out.size() < max_lines) {
    const auto nl = text.find('\n', i);
    std::string_view l =
        text.substr(i, nl == std::string_view::npos ? std::string_view::npos : nl - i);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    out.emplace_back(l);
    if (nl == std::string_view::npos) break;
    i = nl + 1;
  }
  return out;
}

// The files of the run for the listing, one per distinct file of its call
// contexts ([0] the main program, with the text the caller gave), and for
// each context the file its lines are in. At most kListingLines lines are
// kept over all files.
constexpr std::size_t kListingLines = 200000;

void build_listing(const PlotInput& in, PlotModel& pm) {
  const auto& contexts = in.result->contexts;
  pm.files.push_back(ListingFile{in.program, split_lines(in.source, kListingLines)});
  std::size_t lines = pm.files[0].lines.size();
  std::vector<std::string> paths{contexts.empty() ? std::string() : contexts[0].path};
  pm.contexts.push_back(PlaceContext{0, ""});
  for (std::size_t c = 1; c < contexts.size(); ++c) {
    const record::CallContext& cc = contexts[c];
    std::uint32_t f = 0;
    while (f < pm.files.size() && !(pm.files[f].name == cc.file && paths[f] == cc.path)) ++f;
    if (f == pm.files.size()) {
      ListingFile lf{cc.file, {}};
      if (in.read_file && !cc.path.empty() && lines < kListingLines) {
        lf.lines = split_lines(in.read_file(cc.path), kListingLines - lines);
        lines += lf.lines.size();
      }
      pm.files.push_back(std::move(lf));
      paths.push_back(cc.path);
    }
    // where() names a line: "O9810.nc:0 (O9810) called from ..."; the
    // context alone is the same without the ":0".
    std::string where = report::where(contexts, static_cast<std::uint32_t>(c), 0);
    where.erase(cc.file.size(), 2);
    pm.contexts.push_back(PlaceContext{f, std::move(where)});
  }
}

// Length (gauge line to tip, mm) of the tool in the spindle at time t, from
// the scene's tools and probe and the tool changes the run made.
class ToolLengths {
 public:
  ToolLengths(const machine::Scene* scene, const std::vector<ToolChange>& changes)
      : scene_(scene), changes_(changes) {}
  double at(double t) const {
    if (scene_ == nullptr) return 0.0;
    // The last change at or before t (the changes are in time order).
    const auto after = std::upper_bound(changes_.begin(), changes_.end(), t,
                                        [](double x, const ToolChange& c) { return x < c.t; });
    const int tool = after == changes_.begin() ? scene_->probing.spindle_tool : (after - 1)->tool;
    const auto& pr = scene_->probing;
    if (pr.probe && pr.probe->tool == tool) return pr.probe->length;
    const machine::ToolSpec* ts = pr.tool(tool);
    return ts != nullptr ? ts->length : 0.0;
  }

 private:
  const machine::Scene* scene_;
  const std::vector<ToolChange>& changes_;
};

Vec3 tip(Vec3 p, double length) {
  p.z -= length;
  return p;
}

void build_skips(const PlotInput& in, PlotModel& pm) {
  const auto& m = *in.machine;
  const auto& rec = *in.recorder;
  const auto& moves = rec.skip_moves();
  const auto& blocks = rec.blocks();
  std::size_t next_move = 0;
  for (std::size_t k = 0; k < in.result->skips.size(); ++k) {
    const record::SkipRecord& s = in.result->skips[k];
    SkipMark sk;
    sk.index = k;
    sk.line = s.line;
    sk.ctx = s.context;
    sk.block = s.block;
    sk.code = s.code;
    sk.signal = s.signal;
    sk.triggered = s.triggered;
    sk.ended_by_alarm = s.ended_by_alarm;
    sk.p = s.p;
    sk.kind = s.kind == canon::SkipKind::kTorque      ? "torque"
              : s.kind == canon::SkipKind::kMultiStep ? "multi_step"
              : s.kind == canon::SkipKind::kProbe     ? "probe"
                                                      : "skip";
    sk.latch_t = s.time_s;
    sk.latch_machine = s.machine_position;
    sk.position = s.position;
    sk.end_position = s.end_position;
    sk.rest_machine = s.machine_position;
    sk.stop_t = s.time_s;
    AxisVec start = s.machine_position;
    if (const BlockRun* b = skip_block(blocks, s)) {
      sk.rest_machine = b->end_cmd;
      sk.stop_t = std::max(b->t1, s.time_s);
      start = b->start_act;
    }
    while (next_move < moves.size() &&
           (moves[next_move].line != s.line || moves[next_move].source != s.context)) {
      ++next_move;
    }
    AxisVec target = s.machine_position;
    if (next_move < moves.size()) {
      target = moves[next_move].target;
      start = moves[next_move].start;
      sk.has_target = true;
      ++next_move;
    }
    for (int i = 0; i < m.axis_count(); ++i) {
      if (std::fabs(target[i] - start[i]) > 1e-6) sk.moved_axes.push_back(i);
    }
    if (sk.moved_axes.empty()) {
      for (int i = 0; i < m.axis_count(); ++i) sk.moved_axes.push_back(i);
    }
    const ToolLengths tools(in.scene, rec.tool_changes());
    const double len = tools.at(sk.latch_t);
    sk.latch = tip(to3(sk.latch_machine, pm.xyz), len);
    sk.rest = tip(to3(sk.rest_machine, pm.xyz), len);
    sk.start = tip(to3(start, pm.xyz), len);
    sk.target = tip(to3(target, pm.xyz), len);
    double d2 = 0.0;
    for (int i : sk.moved_axes) {
      const double d = sk.rest_machine[i] - sk.latch_machine[i];
      d2 += d * d;
    }
    sk.overtravel_mm = std::sqrt(d2);
    std::string vars, rest;
    for (int i : sk.moved_axes) {
      const char a = m.axes[static_cast<std::size_t>(i)].name;
      SkipVar v{skip_var_name(*in.dialect, i, a), a, s.position[i]};
      const std::string shown = v.name.size() > 8 ? std::string(1, a) : v.name;
      vars += fmt::format(" {}={}", shown, num(v.value));
      rest += fmt::format(" {}{}", a, num(s.end_position[i]));
      sk.vars.push_back(std::move(v));
    }
    const std::string at = place_label(pm, s.context, s.line, s.n);
    sk.label = fmt::format("{}{}{}", at, s.triggered ? "" : " no signal,", vars);
    sk.rest_label = fmt::format("{} {}{}", at, s.ended_by_alarm ? "ALARM at" : "rest", rest);
    pm.skips.push_back(std::move(sk));
  }
}

void build_channels(const PlotInput& in, PlotModel& pm) {
  const auto& m = *in.machine;
  const auto& samples = in.recorder->samples();
  const int n = m.axis_count();
  auto per_axis = [&](std::string id, std::string title, std::string unit, auto value) {
    Channel c{std::move(id), std::move(title), std::move(unit), false, {}};
    for (int i = 0; i < n; ++i) {
      Series s{std::string(1, m.axes[static_cast<std::size_t>(i)].name), axis_colour(i), {}};
      s.v.reserve(samples.size());
      for (const auto& smp : samples) s.v.push_back(value(smp, i));
      c.series.push_back(std::move(s));
    }
    pm.channels.push_back(std::move(c));
  };
  // One strip per axis position, each scaled to its own travel (as a scope
  // channel is), so that a latch on one axis is not flattened by another's.
  for (int i = 0; i < n; ++i) {
    const char a = m.axes[static_cast<std::size_t>(i)].name;
    Channel c{
        fmt::format("pos_{}", a), fmt::format("{} position (actual, machine)", a), "mm", false, {}};
    Series s{std::string(1, a), axis_colour(i), {}};
    s.v.reserve(samples.size());
    for (const auto& smp : samples) s.v.push_back(smp.act[i]);
    c.series.push_back(std::move(s));
    pm.channels.push_back(std::move(c));
  }
  Channel speed{"speed", "Path speed (commanded)", "mm/min", false, {}};
  Series sp{"F", "#333333", {}};
  sp.v.reserve(samples.size());
  for (const auto& s : samples) sp.v.push_back(s.feed_mm_min);
  speed.series.push_back(std::move(sp));
  pm.channels.push_back(std::move(speed));
  per_axis("following_error", "Following error (command - actual)", "mm",
           [](const Sample& s, int i) { return s.cmd[i] - s.act[i]; });
  per_axis("torque", "Motor torque", "%", [](const Sample& s, int i) { return s.torque[i]; });
  for (auto& c : pm.channels) {
    c.min_span = c.unit == "mm" ? (c.id == "following_error" ? 0.001 : 0.01) : 1.0;
    double lo = 1e300, hi = -1e300;
    for (const auto& s : c.series) {
      for (double v : s.v) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
    c.flat = hi - lo < c.min_span;
  }
  const auto& names = in.recorder->signal_names();
  for (std::size_t k = 0; k < names.size(); ++k) {
    Channel c{"signal_" + names[k], "Input " + names[k], "", true, {}};
    Series s{names[k], "#2e9e4f", {}};
    s.v.reserve(samples.size());
    for (const auto& smp : samples) s.v.push_back(((smp.signals >> k) & 1U) != 0 ? 1.0 : 0.0);
    c.series.push_back(std::move(s));
    pm.channels.push_back(std::move(c));
  }
}

}  // namespace

const InkStyle& ink(Ink i) noexcept {
  return kInks[static_cast<std::size_t>(i)];
}

const char* axis_colour(int i) noexcept {
  return kAxisColours[static_cast<std::size_t>(i) % kAxisColours.size()];
}

std::string num(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.starts_with('-') && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string clean_utf8(std::string_view text) {
  // One rule for every text skipnc writes as UTF-8: U+FFFD for each maximal
  // ill-formed subpart (core/utf8.hpp).
  return utf8::make_valid(text);
}

std::string place_label(const PlotModel& pm, std::uint32_t ctx, std::uint32_t line, int n) {
  const std::uint32_t f = ctx < pm.contexts.size() ? pm.contexts[ctx].file : 0;
  std::string out =
      f == 0 ? fmt::format("L{}", line) : fmt::format("{}:{}", pm.files[f].name, line);
  if (n >= 0) out += fmt::format(" N{}", n);
  return out;
}

std::string place_text(const PlotModel& pm, std::uint32_t ctx, std::uint32_t line) {
  if (ctx == 0 || ctx >= pm.contexts.size()) return fmt::format("line {}", line);
  std::string where = pm.contexts[ctx].where;
  where.insert(pm.files[pm.contexts[ctx].file].name.size(), fmt::format(":{}", line));
  return where;
}

std::string skip_var_name(const config::Dialect& d, int axis_index, char axis_name) {
  if (d.skip_vars.work_base > 0) return fmt::format("#{}", d.skip_vars.work_base + axis_index);
  if (!d.skip_vars.named_local.empty())
    return fmt::format("#<{}{}>", d.skip_vars.named_local, axis_name);
  return std::string(1, axis_name);
}

namespace {

// The extents the views are fitted to: `full_extent` everything (the path,
// the skips, the scene), `extent` where the run worked (the feed, arc and
// skip moves and the skip points, a margin around them). Rapids to and from
// home, and the parts and tool setter away from the work, are drawn where
// they fall in that frame (the page zooms out to them).
void frame_views(const PlotInput& in, PlotModel& pm) {
  for (const auto& s : pm.skips) {
    pm.extent.add(s.latch);
    pm.extent.add(s.rest);
    if (s.has_target) pm.extent.add(s.target);
  }
  if (pm.extent.empty()) pm.extent.add(to3(in.result->final_machine, pm.xyz));
  if (in.scene != nullptr) {
    add_scene_extent(*in.scene, pm.extent);
    // Planes of the scene widen the extent along their normal only.
    const auto widen = [&](int axis, double at) {
      for (int k = 0; k < 3; ++k) {
        if (pm.xyz[static_cast<std::size_t>(k)] == axis) {
          pm.extent.lo[k] = std::min(pm.extent.lo[k], at);
          pm.extent.hi[k] = std::max(pm.extent.hi[k], at);
        }
      }
    };
    for (const auto& t : in.scene->triggers) widen(t.axis, t.at);
    for (const auto& st : in.scene->stops) widen(st.axis, st.at);
  }
  // Every side of the extent at least 2 mm, so that a one-axis run (a
  // probe going straight down) still has a frame around it.
  const auto at_least_2mm = [](Box3& b) {
    for (int k = 0; k < 3; ++k) {
      const double span = b.hi[k] - b.lo[k];
      if (span < 2.0) {
        const double c = 0.5 * (b.hi[k] + b.lo[k]);
        b.lo[k] = c - 1.0;
        b.hi[k] = c + 1.0;
      }
    }
  };
  at_least_2mm(pm.extent);
  pm.full_extent = pm.extent;
  Box3 work;
  for (const BlockView& b : pm.blocks) {
    if (b.kind != MoveKind::kFeed && b.kind != MoveKind::kArc && b.kind != MoveKind::kSkip) {
      continue;
    }
    for (std::size_t i = b.s0; i < b.s1 && i < pm.path.size(); ++i) work.add(pm.path[i]);
    work.add(b.to);
  }
  for (const auto& sk : pm.skips) {
    work.add(sk.start);
    work.add(sk.latch);
    work.add(sk.rest);
    if (!sk.triggered && sk.has_target) work.add(sk.target);
  }
  if (!work.empty()) {
    constexpr double kMarginMm = 5.0;
    for (int k = 0; k < 3; ++k) {
      work.lo[k] = std::max(work.lo[k] - kMarginMm, pm.full_extent.lo[k]);
      work.hi[k] = std::min(work.hi[k] + kMarginMm, pm.full_extent.hi[k]);
    }
    at_least_2mm(work);
    pm.extent = work;
  }
}

}  // namespace

// The header's words on the path, the skip ink's legend with the codes that
// ran, and where a crash, collision or protection alarm happened.
void describe_path(const PlotInput& in, const ToolLengths& tools, PlotModel& pm) {
  const bool probe = in.scene != nullptr && in.scene->probing.probe.has_value();
  if (pm.tip_path)
    pm.tip_note = probe ? "path of the tool tip (probe: ball centre)" : "path of the tool tip";
  std::vector<std::string> codes;
  bool g38 = false;
  for (const auto& s : pm.skips) {
    g38 = g38 || s.code.starts_with("G38");
    if (std::find(codes.begin(), codes.end(), s.code) == codes.end()) codes.push_back(s.code);
  }
  std::sort(codes.begin(), codes.end());
  std::string list;
  for (const auto& c : codes) list += (list.empty() ? "" : ", ") + c;
  if (list.empty()) list = in.dialect != nullptr && in.dialect->sw.probe_g38 ? "G38.n" : "G31";
  pm.skip_legend = fmt::format("{} move ({})", g38 ? "probe" : "skip", list);
  const sim::RunResult& r = *in.result;
  if (r.alarm && r.alarm_position) {
    pm.alarm_at = tip(to3(*r.alarm_position, pm.xyz), tools.at(r.time_s));
    pm.alarm_key = std::string(alarm_key(r.alarm->id));
    pm.extent.add(*pm.alarm_at);
  }
}

PlotModel build_model(const PlotInput& in) {
  PlotModel pm;
  const auto& m = *in.machine;
  const auto& r = *in.result;
  const auto& rec = *in.recorder;
  pm.program = in.program;
  pm.machine = m.name;
  pm.dialect = in.dialect != nullptr ? in.dialect->name : m.dialect;
  pm.time_s = r.time_s;
  pm.periods = rec.periods_seen();
  pm.status = report::status_name(r.status);
  if (r.alarm) {
    const report::AlarmView v = report::view_alarm(*r.alarm, in.dialect);
    pm.alarm = fmt::format("{} ({}): {}", v.code, v.number, v.message);
    if (r.alarm->loc.line > 0) {
      pm.alarm += " at " + report::where(r.contexts, r.alarm_context, r.alarm->loc.line);
    }
  }
  for (const auto& a : m.axes) pm.axis_names.push_back(a.name);
  pm.xyz = {m.axis_index('X'), m.axis_index('Y'), m.axis_index('Z')};
  pm.views = views_for(pm.xyz, pm.axis_names, m.lathe(), in.x_in_diameter);
  pm.signal_names = rec.signal_names();
  pm.messages = r.messages;
  pm.variables = in.variables;
  build_listing(in, pm);

  const auto& samples = rec.samples();
  pm.t.reserve(samples.size());
  pm.line.reserve(samples.size());
  pm.path.reserve(samples.size());
  const ToolLengths tools(in.scene, rec.tool_changes());
  for (const auto& s : samples) {
    pm.t.push_back(s.t);
    pm.line.push_back(s.line);
    pm.ctx.push_back(s.source);
    const double len = tools.at(s.t);
    pm.tip_path = pm.tip_path || len != 0.0;
    pm.path.push_back(tip(to3(s.act, pm.xyz), len));
    pm.extent.add(pm.path.back());
  }
  const auto& blocks = rec.blocks();
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const BlockRun& b = blocks[i];
    BlockView v;
    v.line = b.line;
    v.ctx = b.source;
    v.kind = b.kind;
    v.t0 = b.t0;
    v.t1 = b.t1;
    v.s0 =
        static_cast<std::size_t>(std::lower_bound(pm.t.begin(), pm.t.end(), b.t0) - pm.t.begin());
    v.s1 =
        static_cast<std::size_t>(std::upper_bound(pm.t.begin(), pm.t.end(), b.t1) - pm.t.begin());
    v.from = tip(to3(i > 0 ? blocks[i - 1].end_act : b.start_act, pm.xyz),
                 tools.at(i > 0 ? blocks[i - 1].t1 : b.t0));
    v.to = tip(to3(b.end_act, pm.xyz), tools.at(b.t1));
    v.end_machine = b.end_cmd;
    pm.extent.add(v.from);
    pm.extent.add(v.to);
    pm.blocks.push_back(v);
  }
  build_skips(in, pm);
  describe_path(in, tools, pm);
  frame_views(in, pm);
  if (in.scene != nullptr) {
    pm.shapes = scene_shapes(*in.scene, m, pm.xyz, pm.full_extent);
    if (in.result != nullptr && in.result->stock) {
      add_stock_cut(*in.result->stock, *in.scene, pm.shapes);
    }
  }
  build_channels(in, pm);
  return pm;
}

}  // namespace skipnc::plot
