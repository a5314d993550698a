// The static picture: one SVG document, laid out as
//   header                                   (program, machine, status)
//   2 x 2 views (XY, XZ, YZ, isometric) | legend, skips with latch zooms
//   timeline (positions, speed, following error, torque, signals)
// Every view group carries data-frame="u0 u1 v0 v1 x y w h" (its world
// window and pixel rectangle) so that tests can find a point in it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "plot/plot.hpp"
#include "plot/svg_util.hpp"
#include "plot/view.hpp"

namespace skipnc::plot {
namespace {

constexpr double kWidth = 1600;
constexpr double kMargin = 16;
constexpr double kCellW = 500, kCellH = 380, kGap = 12;
constexpr double kHeaderH = 64;
// Characters of the alarm's 13 px bold text on one line of the picture's
// width (text_width's 0.6 em per character, 0.66 for bold).
constexpr std::size_t kAlarmChars = static_cast<std::size_t>((kWidth - 2 * kMargin) / (0.66 * 13));

// `text` in lines of at most `n` characters, broken at spaces (a longer
// word is cut).
std::vector<std::string> wrap_words(const std::string& text, std::size_t n) {
  std::vector<std::string> lines;
  std::string cur;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t j = text.find(' ', i);
    if (j == std::string::npos) j = text.size();
    std::string word = text.substr(i, j - i);
    i = j + 1;
    while (word.size() > n) {
      if (!cur.empty()) lines.push_back(std::move(cur));
      cur.clear();
      lines.push_back(word.substr(0, n));
      word.erase(0, n);
    }
    if (!cur.empty() && cur.size() + 1 + word.size() > n) {
      lines.push_back(std::move(cur));
      cur.clear();
    }
    cur += (cur.empty() ? "" : " ") + word;
  }
  if (!cur.empty()) lines.push_back(std::move(cur));
  return lines;
}

void draw_path(Svg& o, const PlotModel& m, const ViewDef& v, const Frame& f, LabelPlacer& labels) {
  // One <path> per kind, rapids under feeds under skips.
  for (const auto kind : {MoveKind::kRapid, MoveKind::kFeed, MoveKind::kSkip}) {
    std::string d;
    for (const auto& b : m.blocks) {
      const MoveKind k = b.kind == MoveKind::kArc ? MoveKind::kFeed : b.kind;
      if (k != kind) continue;
      std::vector<Pt> pts;
      auto add = [&](const Vec3& p) { pts.push_back(Pt{f.px(dot(p, v.u)), f.py(dot(p, v.v))}); };
      add(b.from);
      for (std::size_t i = b.s0; i < b.s1 && i < m.path.size(); ++i) add(m.path[i]);
      add(b.to);
      pts = simplify(pts, 0.3);
      if (pts.size() == 2 && std::hypot(pts[0].x - pts[1].x, pts[0].y - pts[1].y) < 0.05) continue;
      for (std::size_t i = 1; i < pts.size(); ++i) labels.line(pts[i - 1], pts[i]);
      append_path(d, pts);
    }
    if (d.empty()) continue;
    const Ink ik = kind == MoveKind::kRapid  ? Ink::kRapid
                   : kind == MoveKind::kSkip ? Ink::kSkip
                                             : Ink::kFeed;
    o.add("<path class=\"path {}\" d=\"{}\" {}/>\n", ink(ik).name, d, stroke_attrs(ik));
  }
}

struct LabelRequest {
  Pt anchor;
  std::string text;
  const char* colour;
  const char* cls;
};

void draw_shapes(Svg& o, const PlotModel& m, const ViewDef& v, const Frame& f,
                 std::vector<std::string>& notes, LabelPlacer& labels,
                 std::vector<LabelRequest>& requests) {
  for (const auto& s : m.shapes) {
    if (s.normal_axis >= 0 && s.normal_axis == v.look_axis) {
      if (!s.note.empty()) notes.push_back(s.note);
      continue;
    }
    if (v.look_axis < 0 ? !s.in_iso : s.only_iso) continue;
    std::vector<Pt> pts;
    for (const auto& p : s.pts) pts.push_back(Pt{f.px(dot(p, v.u)), f.py(dot(p, v.v))});
    const InkStyle& st = ink(s.ink);
    if (s.kind == Shape::Kind::kSegments) {
      std::string d;
      for (std::size_t i = 0; i + 1 < pts.size(); i += 2) {
        d += fmt::format("M{:.1f} {:.1f}L{:.1f} {:.1f}", pts[i].x, pts[i].y, pts[i + 1].x,
                         pts[i + 1].y);
      }
      o.add("<path class=\"shape {}\" d=\"{}\" stroke=\"{}\" stroke-width=\"1\" fill=\"none\"/>\n",
            st.name, d, st.stroke);
    } else {
      std::string d;
      append_path(d, pts);
      if (s.kind == Shape::Kind::kPolygon) d += "Z";
      o.add(
          "<path class=\"shape {}\" d=\"{}\" stroke=\"{}\" stroke-width=\"{}\" fill=\"{}\" "
          "fill-opacity=\"{}\" stroke-opacity=\"{}\"{}/>\n",
          st.name, d, st.stroke, st.width, s.kind == Shape::Kind::kPolygon ? st.fill : "none",
          v.look_axis < 0 ? 0.05 : 0.10, v.look_axis < 0 ? 0.6 : 1.0,
          st.dash[0] != '\0' ? fmt::format(" stroke-dasharray=\"{}\"", st.dash) : std::string());
    }
    if (s.kind == Shape::Kind::kSegments) {
      for (std::size_t i = 0; i + 1 < pts.size(); i += 2) labels.line(pts[i], pts[i + 1]);
    } else {
      for (std::size_t i = 1; i < pts.size(); ++i) labels.line(pts[i - 1], pts[i]);
      if (s.kind == Shape::Kind::kPolygon && pts.size() > 2) labels.line(pts.back(), pts.front());
    }
    if (!s.label.empty() && !pts.empty()) {
      // Beside the right-most visible point of the outline (the top one of
      // equals); a shape wholly outside the view gets no label.
      const Box2 view{f.x, f.y, f.w, f.h};
      std::optional<Pt> r;
      const std::size_t n = s.kind == Shape::Kind::kPolygon ? pts.size() : pts.size() - 1;
      for (std::size_t e = 0; e < n; ++e) {
        const auto seg = clip_segment(pts[e], pts[(e + 1) % pts.size()], view);
        if (!seg) continue;
        for (const Pt& p : {seg->first, seg->second}) {
          if (!r || p.x > r->x + 0.5 || (std::fabs(p.x - r->x) <= 0.5 && p.y < r->y)) r = p;
        }
      }
      if (r) {
        requests.push_back(LabelRequest{
            Pt{std::min(r->x, f.x + f.w - 4), std::clamp(r->y, f.y + 8, f.y + f.h - 8)}, s.label,
            st.stroke, "shape-label"});
      }
    }
  }
}

void draw_ticks(Svg& o, const ViewDef& v, const Frame& f) {
  if (v.look_axis < 0) {
    // Isometric: a scale bar and the axis directions.
    const double mm_per_px = (f.u1 - f.u0) / f.w;
    const double len = nice_step(mm_per_px * 90, 1);
    const double px = len / mm_per_px;
    const double x0 = f.x + 12, y0 = f.y + f.h - 14;
    o.add(
        "<path d=\"M{:.1f} {:.1f}h{:.1f}M{:.1f} {:.1f}v6M{:.1f} {:.1f}v6\" stroke=\"#444\" "
        "fill=\"none\"/>\n",
        x0, y0, px, x0, y0 - 3, x0 + px, y0 - 3);
    o.add("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" fill=\"#444\">{} mm</text>\n",
          x0 + px + 6, y0 + 4, num(len, len < 1 ? 3 : 0));
    const double cx = f.x + f.w - 44, cy = f.y + f.h - 34;
    const char* names[3] = {"X", "Y", "Z"};
    for (int k = 0; k < 3; ++k) {
      Vec3 e;
      e[k] = 1.0;
      const double dx = dot(e, v.u) * 24, dy = -dot(e, v.v) * 24;
      o.add(
          "<path d=\"M{:.1f} {:.1f}l{:.1f} {:.1f}\" stroke=\"{}\" stroke-width=\"1.5\"/>"
          "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" fill=\"{}\">{}</text>\n",
          cx, cy, dx, dy, axis_colour(k), cx + dx * 1.3 - 3, cy + dy * 1.3 + 4, axis_colour(k),
          names[k]);
    }
    return;
  }
  const double su = nice_step((f.u1 - f.u0), 6);
  const double sv = nice_step((f.v1 - f.v0) * v.v_scale, 5) / v.v_scale;
  const int du = su < 1 ? static_cast<int>(std::ceil(-std::log10(su))) : 0;
  const double sv_shown = sv * v.v_scale;
  const int dv = sv_shown < 1 ? static_cast<int>(std::ceil(-std::log10(sv_shown))) : 0;
  std::string grid;
  for (double u = std::ceil(f.u0 / su) * su; u <= f.u1; u += su) {
    const double x = f.px(u);
    grid += fmt::format("M{:.1f} {:.1f}V{:.1f}", x, f.y, f.y + f.h);
    o.add(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#666\" "
        "text-anchor=\"middle\">{}</text>\n",
        x, f.y + f.h + 12, num(u, du));
  }
  for (double w = std::ceil(f.v0 / sv) * sv; w <= f.v1; w += sv) {
    const double y = f.py(w);
    grid += fmt::format("M{:.1f} {:.1f}H{:.1f}", f.x, y, f.x + f.w);
    o.add(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#666\" "
        "text-anchor=\"end\">{}</text>\n",
        f.x - 4, y + 3, num(w * v.v_scale, dv));
  }
  o.add("<path class=\"grid\" d=\"{}\" stroke=\"#ececec\" fill=\"none\"/>\n", grid);
  o.add(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" font-weight=\"bold\" fill=\"#444\">"
      "{} \u2192  {} \u2191  (mm, machine{}; labels in work coordinates)</text>\n",
      f.x - 44, f.y + f.h + 26, v.u_name, v.v_name, v.note.empty() ? "" : ", " + v.note);
}

void draw_markers(Svg& o, const PlotModel& m, const ViewDef& v, const Frame& f, LabelPlacer& labels,
                  const std::vector<LabelRequest>& shape_labels) {
  auto P = [&](const Vec3& p) { return Pt{f.px(dot(p, v.u)), f.py(dot(p, v.v))}; };
  // Programmed end points that the skip did not reach.
  for (const auto& s : m.skips) {
    if (!s.has_target || !s.triggered) continue;
    const Pt a = P(s.rest), b = P(s.target);
    if (std::hypot(a.x - b.x, a.y - b.y) < 1.0) continue;
    labels.line(a, b);
    o.add(
        "<path class=\"target\" d=\"M{:.1f} {:.1f}L{:.1f} {:.1f}M{:.1f} {:.1f}l6 6m0 -6l-6 6\" "
        "{}/>\n",
        a.x, a.y, b.x, b.y, b.x - 3, b.y - 3, stroke_attrs(Ink::kTarget));
  }
  // Labels: the skip points first, then the scene's; the markers go on top.
  auto label = [&](const Pt& a, const std::string& text, const char* colour, const char* cls) {
    bool leader = false;
    const double w = text_width(text, 11);
    const Box2 b = labels.place(a.x, a.y, w, 13, leader);
    if (b.w <= 0) return;  // no room left in the view: the marker's tooltip has it
    if (leader) {
      const double lx = std::clamp(a.x, b.x, b.x + b.w), ly = std::clamp(a.y, b.y, b.y + b.h);
      o.add("<path d=\"M{:.1f} {:.1f}L{:.1f} {:.1f}\" stroke=\"{}\" stroke-width=\"0.8\"/>\n", a.x,
            a.y, lx, ly, colour);
    }
    o.add(
        "<text class=\"{}\" x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" fill=\"{}\" {}>{}</text>\n",
        cls, b.x, b.y + 10.5, colour, kHalo, esc(text));
  };
  for (const auto& s : m.skips) label(P(s.latch), s.label, "#b0005f", "latch-label");
  for (const auto& s : m.skips) label(P(s.rest), s.rest_label, "#111", "rest-label");
  for (const auto& r : shape_labels) label(r.anchor, r.text, r.colour, r.cls);
  if (!m.path.empty()) {
    const Pt s = P(m.path.front());
    o.add(
        "<path class=\"start-marker\" d=\"M{:.1f} {:.1f}l6 10h-12z\" stroke=\"{}\" fill=\"{}\" "
        "stroke-width=\"1.5\"><title>start</title></path>\n",
        s.x, s.y - 6, ink(Ink::kStart).stroke, ink(Ink::kStart).fill);
  }
  for (const auto& s : m.skips) {
    const Pt r = P(s.rest);
    o.add(
        "<rect class=\"rest-marker\" data-skip=\"{}\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"8\" "
        "height=\"8\" stroke=\"{}\" fill=\"{}\" stroke-width=\"{}\"><title>{}</title></rect>\n",
        s.index, r.x - 4, r.y - 4, ink(Ink::kRest).stroke, ink(Ink::kRest).fill,
        ink(Ink::kRest).width, esc(s.rest_label));
  }
  if (m.alarm_at) {
    const Pt a = P(*m.alarm_at);
    o.add("{}", alarm_marker(a.x, a.y, alarm_marker_legend(m.alarm_key) + ": " + m.alarm));
  }
  for (const auto& s : m.skips) {
    const Pt p = P(s.latch);
    const Ink ik = s.triggered ? Ink::kLatch : Ink::kMiss;
    o.add(
        "<circle class=\"skip-marker {}\" data-skip=\"{}\" data-line=\"{}\" cx=\"{:.2f}\" "
        "cy=\"{:.2f}\" r=\"5\" stroke=\"{}\" fill=\"{}\" stroke-width=\"{}\"><title>{}</title>"
        "</circle>\n",
        ink(ik).name, s.index, s.line, p.x, p.y, ink(ik).stroke, ink(ik).fill, ink(ik).width,
        esc(s.label));
  }
}

void draw_view(Svg& o, const PlotModel& m, const ViewDef& v, double x, double y) {
  const bool iso = v.look_axis < 0;
  const double left = iso ? 8 : 52, right = 10, top = 26, bottom = iso ? 8 : 30;
  const Frame f =
      fit_view(v, m.extent, x + left, y + top, kCellW - left - right, kCellH - top - bottom, 22);
  o.add("<g class=\"view\" id=\"view-{}\" data-frame=\"{} {} {} {} {} {} {} {}\">\n", v.id, f.u0,
        f.u1, f.v0, f.v1, f.x, f.y, f.w, f.h);
  o.add("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#fff\" stroke=\"#c8c8c8\"/>\n",
        x, y, kCellW, kCellH);
  o.add("<text x=\"{}\" y=\"{}\" font-size=\"13\" font-weight=\"bold\" fill=\"#222\">{}</text>\n",
        x + 8, y + 17, esc(v.title));
  o.add(
      "<clipPath id=\"clip-{}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n",
      v.id, f.x, f.y, f.w, f.h);
  draw_ticks(o, v, f);
  o.add("<g clip-path=\"url(#clip-{})\">\n", v.id);
  std::vector<std::string> notes;
  LabelPlacer labels(Box2{f.x, f.y, f.w, f.h});
  for (const auto& s : m.skips) {
    // Labels keep clear of every marker.
    for (const Vec3& p : {s.latch, s.rest}) {
      labels.block(Box2{f.px(dot(p, v.u)) - 6, f.py(dot(p, v.v)) - 6, 12, 12});
    }
  }
  if (m.alarm_at) {
    labels.block(Box2{f.px(dot(*m.alarm_at, v.u)) - 8, f.py(dot(*m.alarm_at, v.v)) - 8, 16, 16});
  }
  std::vector<LabelRequest> shape_labels;
  draw_shapes(o, m, v, f, notes, labels, shape_labels);
  draw_path(o, m, v, f, labels);
  draw_markers(o, m, v, f, labels, shape_labels);
  o.add("</g>\n");
  if (!notes.empty()) {
    // One line in the title row: planes this view looks straight at.
    std::string text = "face-on: ";
    for (std::size_t i = 0; i < notes.size(); ++i) text += (i > 0 ? ", " : "") + notes[i];
    const auto room =
        static_cast<std::size_t>((kCellW - text_width(v.title, 13) - 30) / (0.6 * 11));
    if (text.size() > room) text = text.substr(0, room > 3 ? room - 3 : 0) + "...";
    o.add(
        "<text class=\"note\" x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#2e7d46\" "
        "text-anchor=\"end\">{}</text>\n",
        x + kCellW - 8, y + 17, esc(text));
  }
  o.add("</g>\n");
}

}  // namespace

std::string esc(std::string_view text) {
  const std::string clean = clean_utf8(text);
  std::string out;
  out.reserve(clean.size());
  for (const char c : clean) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // Control characters are not allowed in XML 1.0.
        out += static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' ? ' ' : c;
    }
  }
  return out;
}

void append_path(std::string& d, const std::vector<Pt>& pts) {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    fmt::format_to(std::back_inserter(d), "{}{:.1f} {:.1f}", i == 0 ? 'M' : 'L', pts[i].x,
                   pts[i].y);
  }
}

std::string stroke_attrs(Ink i) {
  const InkStyle& st = ink(i);
  std::string a =
      fmt::format("stroke=\"{}\" stroke-width=\"{}\" fill=\"none\" stroke-linejoin=\"round\"",
                  st.stroke, st.width);
  if (st.dash[0] != '\0') a += fmt::format(" stroke-dasharray=\"{}\"", st.dash);
  return a;
}

std::string alarm_marker(double x, double y, const std::string& title) {
  return fmt::format(
      "<g class=\"alarm-marker\"><circle cx=\"{0:.1f}\" cy=\"{1:.1f}\" r=\"7\" stroke=\"#c00000\" "
      "fill=\"#ffffff\" stroke-width=\"2\"/><path d=\"M{2:.1f} {3:.1f}l8 8m0 -8l-8 8\" "
      "stroke=\"#c00000\" stroke-width=\"2\"/>{4}</g>\n",
      x, y, x - 4, y - 4, title.empty() ? std::string() : "<title>" + esc(title) + "</title>");
}

std::string alarm_marker_legend(const std::string& key) {
  const std::string what = key == "probe_crash" ? "probe crash"
                           : key == "collision" ? "collision"
                                                : "probe protection";
  return what + ": where the alarm came";
}

std::string to_svg(const PlotModel& m) {
  Svg body;
  // Header.
  body.add(
      "<text x=\"{}\" y=\"28\" font-size=\"20\" font-weight=\"bold\" fill=\"#111\">skipnc plot: "
      "{}</text>\n",
      kMargin, esc(m.program));
  std::string sub = fmt::format(
      "machine {} \u00b7 dialect {} \u00b7 {} after {} s of machine time \u00b7 {} skip{}",
      m.machine, m.dialect, m.status, num(m.time_s, 3), m.skips.size(),
      m.skips.size() == 1 ? "" : "s");
  if (!m.tip_note.empty()) sub += " \u00b7 " + m.tip_note;
  body.add("<text x=\"{}\" y=\"50\" font-size=\"13\" fill=\"#444\">{}</text>\n", kMargin, esc(sub));
  // The alarm on lines of its own below, wrapped to the picture's width.
  double header_h = kHeaderH;
  for (const std::string& line : wrap_words("ALARM " + m.alarm, kAlarmChars)) {
    if (m.alarm.empty()) break;
    body.add(
        "<text class=\"alarm\" x=\"{}\" y=\"{}\" font-size=\"13\" font-weight=\"bold\" "
        "fill=\"#c00000\">{}</text>\n",
        kMargin, header_h + 6, esc(line));
    header_h += 18;
  }
  double views_bottom = header_h;
  for (std::size_t i = 0; i < m.views.size(); ++i) {
    const double x = kMargin + static_cast<double>(i % 2) * (kCellW + kGap);
    const double y = header_h + static_cast<double>(i / 2) * (kCellH + kGap);
    draw_view(body, m, m.views[i], x, y);
    views_bottom = std::max(views_bottom, y + kCellH);
  }
  const double px = kMargin + 2 * kCellW + kGap + 20;
  const double panel_bottom = draw_panel(body, m, px, header_h, kWidth - kMargin - px);
  const double ty = std::max(views_bottom, panel_bottom) + 24;
  const double bottom = draw_more_zooms(
      body, m, kMargin, draw_timeline(body, m, kMargin, ty, kWidth - 2 * kMargin) + 24,
      kWidth - 2 * kMargin);
  const double height = std::ceil(bottom + kMargin);
  std::string out = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\" "
      "font-family=\"DejaVu Sans, Verdana, Arial, sans-serif\" data-generator=\"skipnc\">\n"
      "<title>skipnc plot: {2}</title>\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"#f7f7f5\"/>\n",
      kWidth, height, esc(m.program));
  out += body.s;
  out += "</svg>\n";
  return out;
}

}  // namespace skipnc::plot
