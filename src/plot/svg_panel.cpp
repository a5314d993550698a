// The SVG's right-hand column: legend, one card per skip (what was stored,
// where the axes stopped) with a zoom on its latch, variables, messages.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "plot/svg_util.hpp"

namespace skipnc::plot {
namespace {

constexpr std::size_t kMaxCards = 4;        // skips drawn with a zoom
constexpr std::size_t kMaxListed = 24;      // further skips, one line each
constexpr std::size_t kMaxGridZooms = 300;  // zooms below the timeline
constexpr double kZoomH = 118;

const Channel* channel(const PlotModel& m, std::string_view id) {
  for (const auto& c : m.channels) {
    if (c.id == id) return &c;
  }
  return nullptr;
}

// Value of a sampled channel at time t: linear between samples.
double value_at(const std::vector<double>& t, const std::vector<double>& v, double at) {
  if (t.empty()) return 0.0;
  const auto i = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), at) - t.begin());
  if (i == 0) return v.front();
  if (i >= t.size()) return v.back();
  const double k = t[i] > t[i - 1] ? (at - t[i - 1]) / (t[i] - t[i - 1]) : 0.0;
  return v[i - 1] + (v[i] - v[i - 1]) * k;
}

// Level of a logic channel at time t: held from the last sample at or before t.
double value_at_step(const std::vector<double>& t, const std::vector<double>& v, double at) {
  if (t.empty()) return 0.0;
  const auto i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin());
  return i == 0 ? v.front() : v[i - 1];
}

std::string fit_text(const std::string& s, double w, double font_px) {
  const auto max = static_cast<std::size_t>(std::max(4.0, w / (0.6 * font_px)));
  return s.size() <= max ? s : s.substr(0, max - 3) + "...";
}

void legend_item(Svg& o, Ink i, double x, double y, const std::string& text) {
  const InkStyle& st = ink(i);
  switch (i) {
    case Ink::kLatch:
    case Ink::kMiss:
      o.add("<circle cx=\"{}\" cy=\"{}\" r=\"5\" stroke=\"{}\" fill=\"{}\" stroke-width=\"{}\"/>",
            x + 14, y - 4, st.stroke, st.fill, st.width);
      break;
    case Ink::kRest:
      o.add(
          "<rect x=\"{}\" y=\"{}\" width=\"8\" height=\"8\" stroke=\"{}\" fill=\"{}\" "
          "stroke-width=\"{}\"/>",
          x + 10, y - 8, st.stroke, st.fill, st.width);
      break;
    case Ink::kStart:
      o.add("<path d=\"M{} {}l6 10h-12z\" stroke=\"{}\" fill=\"{}\" stroke-width=\"1.5\"/>", x + 14,
            y - 10, st.stroke, st.fill);
      break;
    case Ink::kTrigger:
    case Ink::kStop:
    case Ink::kPart:
    case Ink::kHole:
    case Ink::kSetter:
    case Ink::kStock:
      o.add(
          "<rect x=\"{}\" y=\"{}\" width=\"28\" height=\"8\" stroke=\"{}\" fill=\"{}\" "
          "fill-opacity=\"0.15\"{}/>",
          x, y - 8, st.stroke, st.fill,
          st.dash[0] != '\0' ? fmt::format(" stroke-dasharray=\"{}\"", st.dash) : std::string());
      break;
    default:
      o.add("<path d=\"M{} {}h28\" {}/>", x, y - 4, stroke_attrs(i));
  }
  o.add("<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#333\">{}</text>\n", x + 36, y, esc(text));
}

double draw_legend(Svg& o, const PlotModel& m, double x, double y) {
  std::vector<Ink> used{Ink::kRapid, Ink::kFeed, Ink::kSkip};
  bool target = false, miss = false;
  for (const auto& s : m.skips) {
    target = target || (s.has_target && s.triggered);
    miss = miss || !s.triggered;
  }
  if (target) used.push_back(Ink::kTarget);
  if (!m.skips.empty()) used.push_back(Ink::kLatch);
  if (miss) used.push_back(Ink::kMiss);
  if (!m.skips.empty()) used.push_back(Ink::kRest);
  used.push_back(Ink::kStart);
  for (const Ink i :
       {Ink::kTrigger, Ink::kStop, Ink::kPart, Ink::kHole, Ink::kSetter, Ink::kStock}) {
    if (std::any_of(m.shapes.begin(), m.shapes.end(), [&](const Shape& s) { return s.ink == i; })) {
      used.push_back(i);
    }
  }
  o.add(
      "<text x=\"{}\" y=\"{}\" font-size=\"13\" font-weight=\"bold\" fill=\"#222\">Legend</text>\n",
      x, y + 14);
  y += 34;
  for (std::size_t i = 0; i < used.size(); ++i) {
    const Ink k = used[i];
    legend_item(o, k, x, y,
                k == Ink::kSkip && !m.skip_legend.empty() ? m.skip_legend : ink(k).legend);
    y += 17;
  }
  if (m.alarm_at) {
    o.add("{}", alarm_marker(x + 14, y - 4, ""));
    o.add("<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#333\">{}</text>\n", x + 36, y,
          esc(alarm_marker_legend(m.alarm_key)));
    y += 17;
  }
  return y;
}

int zoom_axis(const SkipMark& s) {
  int best = s.moved_axes.empty() ? 0 : s.moved_axes.front();
  double travel = -1.0;
  for (int a : s.moved_axes) {
    const double d = std::fabs(s.rest_machine[a] - s.latch_machine[a]);
    if (d > travel) {
      travel = d;
      best = a;
    }
  }
  return best;
}

// The zoom's window and plot area: time [ta, tb] across px0..px0+pw, values
// [vmin, vmax] down py0..py0+ph, the signal's strip of sig_h under it, and
// the model's samples i0..i1 inside the window.
struct ZoomFrame {
  double ta = 0, tb = 0, vmin = 0, vmax = 0;
  double px0 = 0, pw = 0, py0 = 0, ph = 0, sig_h = 16;
  std::size_t i0 = 0, i1 = 0;
  double X(double t) const { return px0 + (t - ta) / (tb - ta) * pw; }
  double Y(double v) const { return py0 + (vmax - v) / (vmax - vmin) * ph; }
};

struct ZoomRow {
  double t, act, cmd;
};

// Samples inside the window, plus the values at its two ends (the samples
// just outside may be far away where the trace was thinned); the value range
// that holds them and the latch and rest values.
std::vector<ZoomRow> zoom_rows(const PlotModel& m, const SkipMark& s, int axis,
                               const std::vector<double>& act, const std::vector<double>& err,
                               ZoomFrame& f) {
  f.i0 = static_cast<std::size_t>(std::lower_bound(m.t.begin(), m.t.end(), f.ta) - m.t.begin());
  f.i1 = static_cast<std::size_t>(std::upper_bound(m.t.begin(), m.t.end(), f.tb) - m.t.begin());
  std::vector<ZoomRow> rows;
  auto at = [&](double t) {
    return ZoomRow{t, value_at(m.t, act, t), value_at(m.t, act, t) + value_at(m.t, err, t)};
  };
  rows.push_back(at(f.ta));
  for (std::size_t i = f.i0; i < f.i1; ++i)
    rows.push_back(ZoomRow{m.t[i], act[i], act[i] + err[i]});
  rows.push_back(at(f.tb));
  f.vmin = std::min(s.latch_machine[axis], s.rest_machine[axis]);
  f.vmax = std::max(s.latch_machine[axis], s.rest_machine[axis]);
  for (const auto& r : rows) {
    f.vmin = std::min({f.vmin, r.act, r.cmd});
    f.vmax = std::max({f.vmax, r.act, r.cmd});
  }
  const double span = std::max(f.vmax - f.vmin, 1e-3);
  f.vmin -= 0.08 * span;
  f.vmax += 0.08 * span;
  return rows;
}

// The skip's signal as a logic trace under the plot.
void draw_zoom_signal(Svg& o, const PlotModel& m, const SkipMark& s, const ZoomFrame& f) {
  const auto& names = m.signal_names;
  auto sig = std::find(names.begin(), names.end(), s.signal);
  if (sig == names.end()) return;
  const auto* ch = channel(m, "signal_" + *sig);
  if (ch == nullptr) return;
  const auto& v = ch->series.front().v;
  const double ylo = f.py0 + f.ph + f.sig_h + 2, yhi = f.py0 + f.ph + 6;
  auto level_y = [&](double t) { return value_at_step(m.t, v, t) > 0.5 ? yhi : ylo; };
  std::string d = fmt::format("M{:.1f} {:.1f}", f.X(f.ta), level_y(f.ta));
  for (std::size_t i = f.i0; i < f.i1; ++i)
    d += fmt::format("H{:.1f}V{:.1f}", f.X(m.t[i]), v[i] > 0.5 ? yhi : ylo);
  d += fmt::format("H{:.1f}", f.X(f.tb));
  o.add("<path d=\"{}\" stroke=\"#2e9e4f\" stroke-width=\"1.5\" fill=\"none\"/>\n", d);
}

// The latch value and the instants of the latch and of rest.
void draw_zoom_marks(Svg& o, const SkipMark& s, int axis, const ZoomFrame& f) {
  const double px0 = f.px0, py0 = f.py0;
  const double lv = f.Y(s.latch_machine[axis]);
  o.add("<path d=\"M{:.1f} {:.1f}H{:.1f}\" stroke=\"#e0007a\" stroke-dasharray=\"2 3\"/>\n", px0,
        lv, px0 + f.pw);
  o.add(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#b0005f\" "
      "text-anchor=\"end\">{}</text>\n",
      px0 - 4, lv + 3, num(s.latch_machine[axis]));
  const double rv = f.Y(s.rest_machine[axis]);
  if (std::fabs(rv - lv) > 10) {
    o.add(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#111\" "
        "text-anchor=\"end\">{}</text>\n",
        px0 - 4, rv + 3, num(s.rest_machine[axis]));
  }
  const double xl = f.X(s.latch_t), xr = f.X(s.stop_t);
  o.add(
      "<path class=\"zoom-latch\" d=\"M{:.1f} {:.1f}V{:.1f}\" stroke=\"#e0007a\" "
      "stroke-width=\"1.5\"/>\n",
      xl, py0, py0 + f.ph + f.sig_h + 4);
  o.add("<path d=\"M{:.1f} {:.1f}V{:.1f}\" stroke=\"#111\" stroke-dasharray=\"4 3\"/>\n", xr, py0,
        py0 + f.ph + f.sig_h + 4);
  o.add("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\" fill=\"#e0007a\" stroke=\"#fff\"/>\n", xl, lv);
  o.add(
      "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"7\" height=\"7\" fill=\"#fff\" stroke=\"#111\" "
      "stroke-width=\"1.5\"/>\n",
      xr - 3.5, rv - 3.5);
}

// Time ticks in ms from the latch, along the zoom's bottom edge at `y_text`.
void draw_zoom_ticks(Svg& o, const SkipMark& s, const ZoomFrame& f, double x, double y_text) {
  const double ta = f.ta, tb = f.tb;
  const double step = nice_step((tb - ta) * 1000.0, 5);
  const int dec = step < 1 ? static_cast<int>(std::ceil(-std::log10(step))) : 0;
  for (double ms = std::ceil((ta - s.latch_t) * 1000.0 / step) * step;
       ms <= (tb - s.latch_t) * 1000.0; ms += step) {
    const double tx = f.X(s.latch_t + ms / 1000.0);
    o.add(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"9\" fill=\"#666\" "
        "text-anchor=\"middle\">{}{}</text>\n",
        tx, y_text, ms > 0 ? "+" : "", num(ms, dec));
  }
  o.add("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"9\" fill=\"#666\">ms</text>\n", x + 6, y_text);
}

// A small scope around one latch: the moving axis (actual and commanded),
// the skip signal, the latch instant and the instant the axes came to rest.
void draw_zoom(Svg& o, const PlotModel& m, const SkipMark& s, double x, double y, double w,
               double h) {
  ZoomFrame f;
  std::tie(f.ta, f.tb) = latch_window(s);
  const int axis = zoom_axis(s);
  const Channel* pos =
      channel(m, fmt::format("pos_{}", m.axis_names[static_cast<std::size_t>(axis)]));
  const Channel* fe = channel(m, "following_error");
  if (pos == nullptr || fe == nullptr || m.t.empty()) return;
  const auto& act = pos->series.front().v;
  const auto& err = fe->series[static_cast<std::size_t>(axis)].v;
  const std::vector<ZoomRow> rows = zoom_rows(m, s, axis, act, err, f);
  const double left = 62;
  f.px0 = x + left;
  f.pw = w - left - 6;
  f.py0 = y + 16;
  f.ph = h - 16 - f.sig_h - 20;
  const char axis_name = m.axis_names[static_cast<std::size_t>(axis)];
  o.add("<g class=\"latch-zoom\" data-skip=\"{}\" data-window=\"{} {}\">\n", s.index, f.ta, f.tb);
  o.add("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#fff\" stroke=\"#d0d0d0\"/>\n",
        x, y, w, h);
  o.add(
      "<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#444\">Zoom on the latch: {} actual (solid) "
      "and "
      "commanded (thin), {}</text>\n",
      x + 6, y + 12, axis_name, esc(s.signal.empty() ? std::string("no signal") : s.signal));
  o.add(
      "<clipPath id=\"zclip-{}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n",
      s.index, f.px0, f.py0 - 2, f.pw, f.ph + f.sig_h + 6);
  o.add("<g clip-path=\"url(#zclip-{})\">\n", s.index);
  std::vector<Pt> a, c;
  for (const auto& r : rows) {
    a.push_back(Pt{f.X(r.t), f.Y(r.act)});
    c.push_back(Pt{f.X(r.t), f.Y(r.cmd)});
  }
  std::string da, dc;
  append_path(da, a);
  append_path(dc, c);
  o.add("<path d=\"{}\" stroke=\"#999\" stroke-width=\"1\" fill=\"none\"/>\n", dc);
  o.add("<path d=\"{}\" stroke=\"{}\" stroke-width=\"1.8\" fill=\"none\"/>\n", da,
        axis_colour(axis));
  draw_zoom_signal(o, m, s, f);
  o.add("</g>\n");
  draw_zoom_marks(o, s, axis, f);
  draw_zoom_ticks(o, s, f, x, y + h - 4);
  o.add("</g>\n");
}

}  // namespace

std::pair<double, double> latch_window(const SkipMark& s) {
  // From a little before the signal to just after the axes came to rest.
  const double d = std::max(s.stop_t - s.latch_t, 0.004);
  return {s.latch_t - std::max(0.25 * d, 0.004), s.stop_t + 0.1 * d};
}

// One skip's card: its place and block, what it stored, where it came to
// rest and, with `zoom`, the zoom on its latch. Returns the y below it.
double draw_skip_card(Svg& o, const PlotModel& m, const SkipMark& s, double x, double y, double w,
                      bool zoom) {
  std::string vars;
  for (const auto& v : s.vars)
    vars += fmt::format("{}{} = {}", vars.empty() ? "" : ", ", v.name, num(v.value));
  std::string rest;
  for (int a : s.moved_axes) {
    rest += fmt::format("{}{}{}", rest.empty() ? "" : " ",
                        m.axis_names[static_cast<std::size_t>(a)], num(s.end_position[a]));
  }
  const std::string head =
      fmt::format("{}. {}: {}", s.index + 1, place_text(m, s.ctx, s.line), s.block);
  const std::string what =
      s.triggered ? fmt::format("{} at {} s: stored {}", s.signal, num(s.latch_t, 6), vars)
                  : fmt::format("no signal: ran to its end point, stored {}", vars);
  const std::string stop =
      s.ended_by_alarm
          ? fmt::format(
                "cut short by the alarm: stopped at {} (work) at {} s, {} mm past the latch", rest,
                num(s.stop_t, 4), num(s.overtravel_mm))
          : fmt::format("rest {} (work) at {} s, {} mm past the latch", rest, num(s.stop_t, 4),
                        num(s.overtravel_mm));
  o.add("<g class=\"skip-card\" data-skip=\"{}\">\n", s.index);
  o.add("<text x=\"{}\" y=\"{}\" font-size=\"12\" font-weight=\"bold\" fill=\"#222\">{}</text>\n",
        x, y + 12, esc(fit_text(head, w, 12)));
  if (!zoom) {
    o.add("<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#b0005f\">{}</text>\n</g>\n", x + 12,
          y + 26, esc(fit_text(what, w - 12, 11)));
    return y + 32;
  }
  o.add("<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#b0005f\">{}</text>\n", x + 12, y + 27,
        esc(fit_text(what, w - 12, 11)));
  o.add("<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#333\">{}</text>\n", x + 12, y + 41,
        esc(fit_text(stop, w - 12, 11)));
  draw_zoom(o, m, s, x, y + 48, w, kZoomH);
  o.add("</g>\n");
  return y + 48 + kZoomH + 12;
}

// The zooms of the skips after the first kMaxCards, in a grid of three
// across, below the timeline: every latch has its zoom in the SVG (at most
// kMaxGridZooms of them; the page has all).
double draw_more_zooms(Svg& o, const PlotModel& m, double x, double y, double w) {
  if (m.skips.size() <= kMaxCards) return y;
  o.add(
      "<text x=\"{}\" y=\"{}\" font-size=\"14\" font-weight=\"bold\" fill=\"#222\">Latch zooms "
      "of skips {} to {}</text>\n",
      x, y + 14, kMaxCards + 1, std::min(m.skips.size(), kMaxCards + kMaxGridZooms));
  y += 26;
  constexpr int kAcross = 3;
  constexpr double kGapX = 24;
  const double cw = (w - (kAcross - 1) * kGapX) / kAcross;
  double row_bottom = y;
  for (std::size_t k = kMaxCards; k < m.skips.size(); ++k) {
    const std::size_t i = k - kMaxCards;
    if (i >= kMaxGridZooms) {
      o.add(
          "<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#666\">{} more in the HTML "
          "page</text>\n",
          x, row_bottom + 12, m.skips.size() - k);
      return row_bottom + 18;
    }
    const double cx = x + static_cast<double>(i % kAcross) * (cw + kGapX);
    if (i % kAcross == 0) y = row_bottom;
    row_bottom = std::max(row_bottom, draw_skip_card(o, m, m.skips[k], cx, y, cw, true));
  }
  return row_bottom;
}

double draw_panel(Svg& o, const PlotModel& m, double x, double y, double w) {
  y = draw_legend(o, m, x, y) + 10;
  o.add(
      "<text x=\"{}\" y=\"{}\" font-size=\"13\" font-weight=\"bold\" fill=\"#222\">Skips "
      "({})</text>\n",
      x, y + 14, m.skips.size());
  y += 22;
  if (m.skips.empty()) {
    o.add("<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#666\">No skip block ran.</text>\n", x,
          y + 12);
    y += 20;
  }
  for (const auto& s : m.skips) {
    if (s.index >= kMaxCards + kMaxListed) {
      o.add(
          "<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#666\">{} more in the HTML "
          "page</text>\n",
          x, y + 12, m.skips.size() - s.index);
      y += 18;
      break;
    }
    if (s.index >= kMaxCards) {
      y = draw_skip_card(o, m, s, x, y, w, false);
      continue;
    }
    y = draw_skip_card(o, m, s, x, y, w, true);
  }
  if (!m.variables.empty()) {
    o.add(
        "<text x=\"{}\" y=\"{}\" font-size=\"13\" font-weight=\"bold\" "
        "fill=\"#222\">Variables</text>\n",
        x, y + 14);
    y += 20;
    std::string row;
    for (std::size_t i = 0; i < m.variables.size(); ++i) {
      const auto& [k, v] = m.variables[i];
      row += fmt::format("{}#{} = {}", row.empty() ? "" : "    ", k,
                         v ? num(*v) : std::string("<vacant>"));
      if (i % 3 == 2 || i + 1 == m.variables.size()) {
        o.add("<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#333\">{}</text>\n", x, y + 12,
              esc(row));
        row.clear();
        y += 16;
      }
    }
  }
  if (!m.messages.empty()) {
    o.add(
        "<text x=\"{}\" y=\"{}\" font-size=\"13\" font-weight=\"bold\" "
        "fill=\"#222\">Messages</text>\n",
        x, y + 14);
    y += 20;
    for (std::size_t i = 0; i < m.messages.size() && i < 12; ++i) {
      o.add("<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#333\">{}</text>\n", x, y + 12,
            esc(fit_text(m.messages[i], w, 11)));
      y += 16;
    }
  }
  return y;
}

}  // namespace skipnc::plot
