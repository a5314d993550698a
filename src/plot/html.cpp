// The page: the model as JSON inside a <script type="application/json">, and
// the script and styles that draw it (assets/plot_*.js, assets/plot.css,
// compiled in by src/plot/embed_assets.cmake). Nothing is fetched.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "plot/assets.hpp"
#include "plot/plot.hpp"
#include "plot/svg_util.hpp"

namespace skipnc::plot {
namespace {

// A JSON writer for the page's data: values are written in order and the
// separators come by themselves (a comma before every value or key but the
// first of its object or array). Numbers are compact (num, 6 decimals) or
// exact (exact, reads back the same double).
struct Json {
  std::string s;

  void open(char c) {
    sep();
    s += c;
    first_.push_back(true);
  }
  void close(char c) {
    s += c;
    first_.pop_back();
  }
  void key(std::string_view k) {
    sep();
    quoted(k);
    s += ':';
    after_key_ = true;
  }
  // Compact number: 6 decimals at most, trailing zeros dropped.
  void num(double v) {
    sep();
    if (!std::isfinite(v)) {
      s += "null";
      return;
    }
    std::string t = fmt::format("{:.6f}", v);
    while (t.back() == '0') t.pop_back();
    if (t.back() == '.') t.pop_back();
    if (t == "-0") t = "0";
    s += t;
  }
  // Exact number (shortest text that reads back the same double).
  void exact(double v) {
    sep();
    if (!std::isfinite(v)) {
      s += "null";
      return;
    }
    fmt::format_to(std::back_inserter(s), "{}", v + 0.0);
  }
  void integer(long long v) {
    sep();
    s += std::to_string(v);
  }
  void boolean(bool b) {
    sep();
    s += b ? "true" : "false";
  }
  void null() {
    sep();
    s += "null";
  }
  void str(std::string_view text) {
    sep();
    quoted(text);
  }
  // A value already in JSON form.
  void value_raw(std::string_view json) {
    sep();
    s += json;
  }
  void vec3(const Vec3& p) {
    open('[');
    num(p.x);
    num(p.y);
    num(p.z);
    close(']');
  }
  void axes(const AxisVec& a, int n) {
    open('[');
    for (int i = 0; i < n; ++i) exact(a[i]);
    close(']');
  }
  template <class T, class F>
  void array(const std::vector<T>& v, F&& f) {
    open('[');
    for (const auto& x : v) f(x);
    close(']');
  }
  // "key": value, in one call.
  void str(std::string_view k, std::string_view v) {
    key(k);
    str(v);
  }
  void num(std::string_view k, double v) {
    key(k);
    num(v);
  }
  void exact(std::string_view k, double v) {
    key(k);
    exact(v);
  }
  void integer(std::string_view k, long long v) {
    key(k);
    integer(v);
  }
  void boolean(std::string_view k, bool b) {
    key(k);
    boolean(b);
  }
  void value_raw(std::string_view k, std::string_view json) {
    key(k);
    value_raw(json);
  }
  void vec3(std::string_view k, const Vec3& p) {
    key(k);
    vec3(p);
  }
  void axes(std::string_view k, const AxisVec& a, int n) {
    key(k);
    axes(a, n);
  }

 private:
  // Writes the comma that goes before a key or value, if any.
  void sep() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (!first_.back()) s += ',';
    first_.back() = false;
  }
  void quoted(std::string_view text);

  std::vector<bool> first_{true};  // per open object or array: nothing in it yet
  bool after_key_ = false;
};

void Json::quoted(std::string_view text) {
  s += '"';
  for (const char c : clean_utf8(text)) {
    switch (c) {
      case '"':
        s += "\\\"";
        break;
      case '\\':
        s += "\\\\";
        break;
      case '\n':
        s += "\\n";
        break;
      case '\r':
        s += "\\r";
        break;
      case '\t':
        s += "\\t";
        break;
      // Never "</script>" or "<!--" inside the page's script element.
      case '<':
        s += "\\u003c";
        break;
      case '>':
        s += "\\u003e";
        break;
      case '&':
        s += "\\u0026";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          fmt::format_to(std::back_inserter(s), "\\u{:04x}",
                         static_cast<unsigned>(static_cast<unsigned char>(c)));
        } else {
          s += c;
        }
    }
  }
  s += '"';
}

void write_meta(Json& j, const PlotModel& m) {
  j.key("meta");
  j.open('{');
  j.str("program", m.program);
  j.str("machine", m.machine);
  j.str("dialect", m.dialect);
  j.str("status", m.status);
  j.str("alarm", m.alarm);
  j.exact("time", m.time_s);
  j.integer("periods", m.periods);
  j.key("axes");
  j.array(m.axis_names, [&](char c) { j.str(std::string(1, c)); });
  j.boolean("tipPath", m.tip_path);
  j.str("tipNote", m.tip_note);
  j.str("skipLegend", m.skip_legend);
  j.value_raw("xyz", fmt::format("[{},{},{}]", m.xyz[0], m.xyz[1], m.xyz[2]));
  // Where a crash, collision or protection alarm came: a marker in each view
  // and the legend, as the SVG has.
  if (m.alarm_at) {
    j.vec3("alarmAt", *m.alarm_at);
    j.str("alarmLegend", alarm_marker_legend(m.alarm_key));
  }
  j.close('}');
  j.key("inks");
  j.open('{');
  for (std::size_t i = 0; i < static_cast<std::size_t>(Ink::kCount); ++i) {
    const InkStyle& st = ink(static_cast<Ink>(i));
    j.key(st.name);
    j.open('{');
    j.str("stroke", st.stroke);
    j.str("fill", st.fill);
    j.num("width", st.width);
    j.key("dash");
    std::string dash = st.dash;
    std::replace(dash.begin(), dash.end(), ' ', ',');
    j.value_raw("[" + dash + "]");
    j.str("legend", st.legend);
    j.close('}');
  }
  j.close('}');
}

void write_geometry(Json& j, const PlotModel& m) {
  j.key("views");
  j.array(m.views, [&](const ViewDef& v) {
    j.open('{');
    j.str("id", v.id);
    j.str("title", v.title);
    j.vec3("u", v.u);
    j.vec3("v", v.v);
    j.integer("look", v.look_axis);
    j.str("uName", v.u_name);
    j.str("vName", v.v_name);
    j.num("vScale", v.v_scale);
    j.str("note", v.note);
    j.close('}');
  });
  j.key("extent");
  j.open('{');
  j.vec3("lo", m.extent.lo);
  j.vec3("hi", m.extent.hi);
  j.close('}');
  j.key("fullExtent");
  j.open('{');
  j.vec3("lo", m.full_extent.lo);
  j.vec3("hi", m.full_extent.hi);
  j.close('}');
  j.key("shapes");
  j.array(m.shapes, [&](const Shape& s) {
    j.open('{');
    j.key("kind");
    j.str(s.kind == Shape::Kind::kPolygon    ? "polygon"
          : s.kind == Shape::Kind::kPolyline ? "polyline"
                                             : "segments");
    j.str("ink", ink(s.ink).name);
    j.key("pts");
    j.array(s.pts, [&](const Vec3& p) { j.vec3(p); });
    j.str("label", s.label);
    j.integer("normal", s.normal_axis);
    j.str("note", s.note);
    j.boolean("inIso", s.in_iso);
    j.boolean("onlyIso", s.only_iso);
    j.close('}');
  });
}

void write_samples(Json& j, const PlotModel& m) {
  const int n = static_cast<int>(m.axis_names.size());
  j.key("t");
  j.array(m.t, [&](double v) { j.num(v); });
  j.key("line");
  j.array(m.line, [&](std::uint32_t v) { j.integer(v); });
  j.key("ctx");
  j.array(m.ctx, [&](std::uint32_t v) { j.integer(v); });
  for (int k = 0; k < 3; ++k) {
    j.key(k == 0 ? "px" : k == 1 ? "py" : "pz");
    j.array(m.path, [&](const Vec3& p) { j.num(p[k]); });
  }
  j.key("blocks");
  j.array(m.blocks, [&](const BlockView& b) {
    j.open('{');
    j.integer("line", b.line);
    j.integer("ctx", b.ctx);
    j.str("kind", move_kind_name(b.kind));
    j.num("t0", b.t0);
    j.num("t1", b.t1);
    j.integer("s0", b.s0);
    j.integer("s1", b.s1);
    j.vec3("from", b.from);
    j.vec3("to", b.to);
    j.axes("end", b.end_machine, n);
    j.close('}');
  });
  j.key("channels");
  j.array(m.channels, [&](const Channel& c) {
    j.open('{');
    j.str("id", c.id);
    j.str("title", c.title);
    j.str("unit", c.unit);
    j.boolean("digital", c.digital);
    j.boolean("flat", c.flat);
    j.num("minSpan", c.min_span);
    j.key("series");
    j.array(c.series, [&](const Series& s) {
      j.open('{');
      j.str("name", s.name);
      j.str("colour", s.colour);
      j.key("v");
      j.array(s.v, [&](double v) { j.num(v); });
      j.close('}');
    });
    j.close('}');
  });
}

void write_skips(Json& j, const PlotModel& m) {
  const int n = static_cast<int>(m.axis_names.size());
  j.key("skips");
  j.array(m.skips, [&](const SkipMark& s) {
    j.open('{');
    j.integer("index", s.index);
    j.integer("line", s.line);
    j.integer("ctx", s.ctx);
    j.str("block", s.block);
    j.str("signal", s.signal);
    j.str("kind", s.kind);
    j.boolean("triggered", s.triggered);
    j.boolean("endedByAlarm", s.ended_by_alarm);
    j.integer("p", s.p);
    j.exact("latchT", s.latch_t);
    j.exact("stopT", s.stop_t);
    for (const auto& [k, p] : {std::pair{"latch", &s.latch}, std::pair{"rest", &s.rest},
                               std::pair{"start", &s.start}, std::pair{"target", &s.target}}) {
      j.vec3(k, *p);
    }
    j.boolean("hasTarget", s.has_target);
    for (const auto& [k, a] :
         {std::pair{"latchMachine", &s.latch_machine}, std::pair{"restMachine", &s.rest_machine},
          std::pair{"position", &s.position}, std::pair{"endPosition", &s.end_position}}) {
      j.axes(k, *a, n);
    }
    j.key("moved");
    j.array(s.moved_axes, [&](int a) { j.integer(a); });
    j.key("vars");
    j.array(s.vars, [&](const SkipVar& v) {
      j.open('{');
      j.str("name", v.name);
      j.str("axis", std::string(1, v.axis));
      j.exact("value", v.value);
      j.close('}');
    });
    j.exact("overtravel", s.overtravel_mm);
    j.str("label", s.label);
    j.str("restLabel", s.rest_label);
    j.close('}');
  });
}

}  // namespace

std::string to_json(const PlotModel& m) {
  Json j;
  j.open('{');
  j.str("format", "skipnc-plot/2");
  write_meta(j, m);
  write_geometry(j, m);
  write_samples(j, m);
  write_skips(j, m);
  j.key("signals");
  j.array(m.signal_names, [&](const std::string& s) { j.str(s); });
  j.key("files");
  j.array(m.files, [&](const ListingFile& f) {
    j.open('{');
    j.str("name", f.name);
    j.key("source");
    j.array(f.lines, [&](const std::string& s) { j.str(s); });
    j.close('}');
  });
  j.key("contexts");
  j.array(m.contexts, [&](const PlaceContext& c) {
    j.open('{');
    j.integer("file", c.file);
    j.str("where", c.where);
    j.close('}');
  });
  j.key("variables");
  j.array(m.variables, [&](const std::pair<std::string, std::optional<double>>& v) {
    j.open('[');
    j.str(v.first);
    if (v.second) {
      j.exact(*v.second);
    } else {
      j.null();
    }
    j.close(']');
  });
  j.key("messages");
  j.array(m.messages, [&](const std::string& s) { j.str(s); });
  j.close('}');
  return std::move(j.s);
}

std::string to_html(const PlotModel& m) {
  std::string title;
  for (const char c : clean_utf8("skipnc plot: " + m.program)) {
    if (c == '<')
      title += "&lt;";
    else if (c == '&')
      title += "&amp;";
    else if (c == '>')
      title += "&gt;";
    else
      title += c;
  }
  std::string out;
  out.reserve(m.t.size() * 120 + 200000);
  out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out +=
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
      "script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src data:\">\n";
  out += "<title>" + title + "</title>\n<style>\n";
  out += assets::plot_css();
  out += "</style>\n</head>\n<body>\n<div id=\"app\"></div>\n";
  out += "<script type=\"application/json\" id=\"plot-data\">";
  out += to_json(m);
  out += "</script>\n<script>\n";
  out += assets::plot_js();
  out += "</script>\n</body>\n</html>\n";
  return out;
}

}  // namespace skipnc::plot
