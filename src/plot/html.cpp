// The page: the model as JSON inside a <script type="application/json">, and
// the script and styles that draw it (assets/plot_*.js, assets/plot.css,
// compiled in by src/plot/embed_assets.cmake). Nothing is fetched.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "plot/assets.hpp"
#include "plot/plot.hpp"

namespace skipnc::plot {
namespace {

struct Json {
  std::string s;
  void raw(std::string_view t) { s += t; }
  // Compact number: 6 decimals at most, trailing zeros dropped.
  void num(double v) {
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
    if (!std::isfinite(v)) {
      s += "null";
      return;
    }
    fmt::format_to(std::back_inserter(s), "{}", v + 0.0);
  }
  void str(std::string_view text) {
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
  void key(std::string_view k) {
    str(k);
    s += ':';
  }
  void vec3(const Vec3& p) {
    s += '[';
    num(p.x);
    s += ',';
    num(p.y);
    s += ',';
    num(p.z);
    s += ']';
  }
  void axes(const AxisVec& a, int n) {
    s += '[';
    for (int i = 0; i < n; ++i) {
      if (i > 0) s += ',';
      exact(a[i]);
    }
    s += ']';
  }
  template <class T, class F>
  void array(const std::vector<T>& v, F&& f) {
    s += '[';
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i > 0) s += ',';
      f(v[i]);
    }
    s += ']';
  }
};

void write_meta(Json& j, const PlotModel& m) {
  j.key("meta");
  j.raw("{");
  j.key("program");
  j.str(m.program);
  j.raw(",");
  j.key("machine");
  j.str(m.machine);
  j.raw(",");
  j.key("dialect");
  j.str(m.dialect);
  j.raw(",");
  j.key("status");
  j.str(m.status);
  j.raw(",");
  j.key("alarm");
  j.str(m.alarm);
  j.raw(",");
  j.key("time");
  j.exact(m.time_s);
  j.raw(",");
  j.key("periods");
  j.raw(std::to_string(m.periods));
  j.raw(",");
  j.key("axes");
  j.array(m.axis_names, [&](char c) { j.str(std::string(1, c)); });
  j.raw(",");
  j.key("tipPath");
  j.raw(m.tip_path ? "true" : "false");
  j.raw(",");
  j.key("xyz");
  j.raw(fmt::format("[{},{},{}]", m.xyz[0], m.xyz[1], m.xyz[2]));
  j.raw("},");
  j.key("inks");
  j.raw("{");
  for (std::size_t i = 0; i < static_cast<std::size_t>(Ink::kCount); ++i) {
    const InkStyle& st = ink(static_cast<Ink>(i));
    if (i > 0) j.raw(",");
    j.key(st.name);
    j.raw("{");
    j.key("stroke");
    j.str(st.stroke);
    j.raw(",");
    j.key("fill");
    j.str(st.fill);
    j.raw(",");
    j.key("width");
    j.num(st.width);
    j.raw(",");
    j.key("dash");
    std::string dash = st.dash;
    std::replace(dash.begin(), dash.end(), ' ', ',');
    j.raw("[" + dash + "]");
    j.raw(",");
    j.key("legend");
    j.str(st.legend);
    j.raw("}");
  }
  j.raw("},");
}

void write_geometry(Json& j, const PlotModel& m) {
  j.key("views");
  j.array(m.views, [&](const ViewDef& v) {
    j.raw("{");
    j.key("id");
    j.str(v.id);
    j.raw(",");
    j.key("title");
    j.str(v.title);
    j.raw(",");
    j.key("u");
    j.vec3(v.u);
    j.raw(",");
    j.key("v");
    j.vec3(v.v);
    j.raw(",");
    j.key("look");
    j.raw(std::to_string(v.look_axis));
    j.raw(",");
    j.key("uName");
    j.str(v.u_name);
    j.raw(",");
    j.key("vName");
    j.str(v.v_name);
    j.raw("}");
  });
  j.raw(",");
  j.key("extent");
  j.raw("{");
  j.key("lo");
  j.vec3(m.extent.lo);
  j.raw(",");
  j.key("hi");
  j.vec3(m.extent.hi);
  j.raw("},");
  j.key("shapes");
  j.array(m.shapes, [&](const Shape& s) {
    j.raw("{");
    j.key("kind");
    j.str(s.kind == Shape::Kind::kPolygon    ? "polygon"
          : s.kind == Shape::Kind::kPolyline ? "polyline"
                                             : "segments");
    j.raw(",");
    j.key("ink");
    j.str(ink(s.ink).name);
    j.raw(",");
    j.key("pts");
    j.array(s.pts, [&](const Vec3& p) { j.vec3(p); });
    j.raw(",");
    j.key("label");
    j.str(s.label);
    j.raw(",");
    j.key("normal");
    j.raw(std::to_string(s.normal_axis));
    j.raw(",");
    j.key("note");
    j.str(s.note);
    j.raw(",");
    j.key("inIso");
    j.raw(s.in_iso ? "true" : "false");
    j.raw(",");
    j.key("onlyIso");
    j.raw(s.only_iso ? "true" : "false");
    j.raw("}");
  });
  j.raw(",");
}

void write_samples(Json& j, const PlotModel& m) {
  const int n = static_cast<int>(m.axis_names.size());
  j.key("t");
  j.array(m.t, [&](double v) { j.num(v); });
  j.raw(",");
  j.key("line");
  j.array(m.line, [&](std::uint32_t v) { j.raw(std::to_string(v)); });
  j.raw(",");
  for (int k = 0; k < 3; ++k) {
    j.key(k == 0 ? "px" : k == 1 ? "py" : "pz");
    j.array(m.path, [&](const Vec3& p) { j.num(p[k]); });
    j.raw(",");
  }
  j.key("blocks");
  j.array(m.blocks, [&](const BlockView& b) {
    j.raw("{");
    j.key("line");
    j.raw(std::to_string(b.line));
    j.raw(",");
    j.key("kind");
    j.str(move_kind_name(b.kind));
    j.raw(",");
    j.key("t0");
    j.num(b.t0);
    j.raw(",");
    j.key("t1");
    j.num(b.t1);
    j.raw(",");
    j.key("s0");
    j.raw(std::to_string(b.s0));
    j.raw(",");
    j.key("s1");
    j.raw(std::to_string(b.s1));
    j.raw(",");
    j.key("from");
    j.vec3(b.from);
    j.raw(",");
    j.key("to");
    j.vec3(b.to);
    j.raw(",");
    j.key("end");
    j.axes(b.end_machine, n);
    j.raw("}");
  });
  j.raw(",");
  j.key("channels");
  j.array(m.channels, [&](const Channel& c) {
    j.raw("{");
    j.key("id");
    j.str(c.id);
    j.raw(",");
    j.key("title");
    j.str(c.title);
    j.raw(",");
    j.key("unit");
    j.str(c.unit);
    j.raw(",");
    j.key("digital");
    j.raw(c.digital ? "true" : "false");
    j.raw(",");
    j.key("flat");
    j.raw(c.flat ? "true" : "false");
    j.raw(",");
    j.key("minSpan");
    j.num(c.min_span);
    j.raw(",");
    j.key("series");
    j.array(c.series, [&](const Series& s) {
      j.raw("{");
      j.key("name");
      j.str(s.name);
      j.raw(",");
      j.key("colour");
      j.str(s.colour);
      j.raw(",");
      j.key("v");
      j.array(s.v, [&](double v) { j.num(v); });
      j.raw("}");
    });
    j.raw("}");
  });
  j.raw(",");
}

void write_skips(Json& j, const PlotModel& m) {
  const int n = static_cast<int>(m.axis_names.size());
  j.key("skips");
  j.array(m.skips, [&](const SkipMark& s) {
    j.raw("{");
    j.key("index");
    j.raw(std::to_string(s.index));
    j.raw(",");
    j.key("line");
    j.raw(std::to_string(s.line));
    j.raw(",");
    j.key("block");
    j.str(s.block);
    j.raw(",");
    j.key("signal");
    j.str(s.signal);
    j.raw(",");
    j.key("kind");
    j.str(s.kind);
    j.raw(",");
    j.key("triggered");
    j.raw(s.triggered ? "true" : "false");
    j.raw(",");
    j.key("p");
    j.raw(std::to_string(s.p));
    j.raw(",");
    j.key("latchT");
    j.exact(s.latch_t);
    j.raw(",");
    j.key("stopT");
    j.exact(s.stop_t);
    for (const auto& [k, p] : {std::pair{"latch", &s.latch}, std::pair{"rest", &s.rest},
                               std::pair{"start", &s.start}, std::pair{"target", &s.target}}) {
      j.raw(",");
      j.key(k);
      j.vec3(*p);
    }
    j.raw(",");
    j.key("hasTarget");
    j.raw(s.has_target ? "true" : "false");
    for (const auto& [k, a] :
         {std::pair{"latchMachine", &s.latch_machine}, std::pair{"restMachine", &s.rest_machine},
          std::pair{"position", &s.position}, std::pair{"endPosition", &s.end_position}}) {
      j.raw(",");
      j.key(k);
      j.axes(*a, n);
    }
    j.raw(",");
    j.key("moved");
    j.array(s.moved_axes, [&](int a) { j.raw(std::to_string(a)); });
    j.raw(",");
    j.key("vars");
    j.array(s.vars, [&](const SkipVar& v) {
      j.raw("{");
      j.key("name");
      j.str(v.name);
      j.raw(",");
      j.key("axis");
      j.str(std::string(1, v.axis));
      j.raw(",");
      j.key("value");
      j.exact(v.value);
      j.raw("}");
    });
    j.raw(",");
    j.key("overtravel");
    j.exact(s.overtravel_mm);
    j.raw(",");
    j.key("label");
    j.str(s.label);
    j.raw(",");
    j.key("restLabel");
    j.str(s.rest_label);
    j.raw("}");
  });
  j.raw(",");
}

}  // namespace

std::string to_json(const PlotModel& m) {
  Json j;
  j.raw("{");
  j.key("format");
  j.str("skipnc-plot/1");
  j.raw(",");
  write_meta(j, m);
  write_geometry(j, m);
  write_samples(j, m);
  write_skips(j, m);
  j.key("signals");
  j.array(m.signal_names, [&](const std::string& s) { j.str(s); });
  j.raw(",");
  j.key("source");
  j.array(m.source, [&](const std::string& s) { j.str(s); });
  j.raw(",");
  j.key("variables");
  j.array(m.variables, [&](const std::pair<std::string, std::optional<double>>& v) {
    j.raw("[");
    j.str(v.first);
    j.raw(",");
    if (v.second) {
      j.exact(*v.second);
    } else {
      j.raw("null");
    }
    j.raw("]");
  });
  j.raw(",");
  j.key("messages");
  j.array(m.messages, [&](const std::string& s) { j.str(s); });
  j.raw("}");
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
