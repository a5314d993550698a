// The SVG's scope: time runs left to right over the whole run; one strip
// per channel (positions, path speed, following error, torque, then one
// logic trace per input signal); every latch and rest instant is a vertical
// line through all strips.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "plot/svg_util.hpp"

namespace skipnc::plot {
namespace {

double strip_height(const Channel& c) {
  if (c.digital) return 26;
  if (c.flat) return 30;
  if (c.id.starts_with("pos_")) return 70;
  if (c.id == "following_error") return 100;
  return 80;
}

std::pair<double, double> value_range(const Channel& c) {
  double lo = 1e300, hi = -1e300;
  for (const auto& s : c.series) {
    for (double v : s.v) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (lo > hi) return {-1, 1};
  // A channel that barely moves gets a fixed span, so that noise is not
  // blown up to full height.
  if (hi - lo < c.min_span) {
    const double pad = std::max(std::fabs(hi) * 0.1, c.min_span), mid = 0.5 * (hi + lo);
    return {mid - pad, mid + pad};
  }
  // Room at the top for the strip's title.
  const double pad = 0.08 * (hi - lo);
  return {lo - pad, hi + 2.5 * pad};
}

// The timeline's time axis: t0..t1 across px0..px0+pw.
struct TimeFrame {
  double t0 = 0, t1 = 0, px0 = 0, pw = 0;
  double X(double t) const { return px0 + (t - t0) / (t1 - t0) * pw; }
};

// One strip: values vlo..vhi up sy+h..sy.
struct StripFrame {
  double sy = 0, h = 0, vlo = 0, vhi = 0;
  double Y(double v) const { return sy + (vhi - v) / (vhi - vlo) * h; }
};

// A strip's value labels: the constant of a flat channel, else a grid with
// tick labels at least 20 px apart (none for a logic trace).
void draw_strip_scale(Svg& o, const Channel& c, const TimeFrame& tf, const StripFrame& sf) {
  const double px0 = tf.px0, pw = tf.pw, vlo = sf.vlo, vhi = sf.vhi;
  if (c.flat) {
    const double mid = 0.5 * (vlo + vhi);
    o.add(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#666\" "
        "text-anchor=\"end\">{}</text>\n",
        px0 - 4, sf.Y(mid) + 3, num(mid, c.unit == "mm" ? 4 : 1));
  } else if (!c.digital) {
    double step = nice_step(vhi - vlo, 3);
    for (int g = 0; g < 40 && step / (vhi - vlo) * sf.h < 20; ++g) step = next_nice_step(step);
    const int dec = step < 1 ? static_cast<int>(std::ceil(-std::log10(step))) : 0;
    std::string grid;
    for (double v = std::ceil(vlo / step) * step; v <= vhi; v += step) {
      grid += fmt::format("M{:.1f} {:.1f}h{:.1f}", px0, sf.Y(v), pw);
      o.add(
          "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#666\" "
          "text-anchor=\"end\">{}</text>\n",
          px0 - 4, sf.Y(v) + 3, num(std::fabs(v) < step * 1e-6 ? 0.0 : v, dec));
    }
    o.add("<path d=\"{}\" stroke=\"#f0f0f0\" fill=\"none\"/>\n", grid);
  }
}

// A strip's series: logic traces as filled steps, the others as lines.
void draw_strip_series(Svg& o, const PlotModel& m, const Channel& c, const TimeFrame& tf,
                       const StripFrame& sf) {
  for (const auto& s : c.series) {
    std::string d;
    if (c.digital) {
      for (std::size_t i = 0; i < s.v.size(); ++i) {
        const double xx = tf.X(m.t[i]), yy = sf.Y(s.v[i] > 0.5 ? 1.0 : 0.0);
        d += i == 0 ? fmt::format("M{:.1f} {:.1f}", xx, yy) : fmt::format("H{:.1f}V{:.1f}", xx, yy);
      }
      if (!s.v.empty()) {
        o.add("<path d=\"{}V{:.1f}H{:.1f}Z\" fill=\"{}\" fill-opacity=\"0.15\" stroke=\"none\"/>\n",
              d, sf.Y(0), tf.X(m.t.front()), s.colour);
      }
      o.add("<path d=\"{}\" stroke=\"{}\" stroke-width=\"1.5\" fill=\"none\"/>\n", d, s.colour);
    } else {
      std::vector<Pt> pts;
      pts.reserve(s.v.size());
      for (std::size_t i = 0; i < s.v.size(); ++i) pts.push_back(Pt{tf.X(m.t[i]), sf.Y(s.v[i])});
      append_path(d, simplify(pts, 0.3));
      o.add(
          "<path class=\"series\" data-series=\"{}\" d=\"{}\" stroke=\"{}\" stroke-width=\"1.3\" "
          "fill=\"none\"/>\n",
          esc(s.name), d, s.colour);
    }
  }
}

// Title and series names at the left, inside the strip.
void draw_strip_titles(Svg& o, const Channel& c, const TimeFrame& tf, const StripFrame& sf) {
  double tx = tf.px0 + 6;
  o.add(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" font-weight=\"bold\" fill=\"#333\" "
      "{}>{}{}</text>\n",
      tx, sf.sy + 12, kHalo, esc(c.title),
      esc((c.unit.empty() ? std::string() : " (" + c.unit + ")") + (c.flat ? ": constant" : "")));
  tx += text_width(c.title + " (" + c.unit + ")", 11) + 10;
  if (c.series.size() > 1) {
    for (const auto& s : c.series) {
      o.add(
          "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" font-weight=\"bold\" fill=\"{}\" "
          "{}>{}</text>\n",
          tx, sf.sy + 12, s.colour, kHalo, esc(s.name));
      tx += text_width(s.name, 11) + 8;
    }
  }
}

// One channel's strip from `sy` down; returns its height.
double draw_strip(Svg& o, const PlotModel& m, const Channel& c, const TimeFrame& tf, double sy) {
  StripFrame sf;
  sf.sy = sy;
  sf.h = strip_height(c);
  std::tie(sf.vlo, sf.vhi) = c.digital ? std::pair{-0.15, 1.25} : value_range(c);
  o.add("<g class=\"strip\" data-channel=\"{}\" data-frame=\"{} {} {} {}\">\n", esc(c.id), sf.vlo,
        sf.vhi, sy, sf.h);
  o.add("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#fff\" stroke=\"#d0d0d0\"/>\n",
        tf.px0, sy, tf.pw, sf.h);
  draw_strip_scale(o, c, tf, sf);
  o.add(
      "<clipPath id=\"tclip-{}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" "
      "height=\"{}\"/></clipPath>\n",
      esc(c.id), tf.px0, sy, tf.pw, sf.h);
  o.add("<g clip-path=\"url(#tclip-{})\">\n", esc(c.id));
  draw_strip_series(o, m, c, tf, sf);
  o.add("</g>\n");
  draw_strip_titles(o, c, tf, sf);
  o.add("</g>\n");
  return sf.h;
}

// Skip instants through every strip, labelled above them in the band at `band`.
void draw_skip_instants(Svg& o, const PlotModel& m, const TimeFrame& tf, double band, double top,
                        double bottom) {
  LabelPlacer labels(Box2{tf.px0 - 20, band, tf.pw + 40, 18});
  for (const auto& s : m.skips) {
    const double xl = tf.X(s.latch_t), xr = tf.X(s.stop_t);
    o.add(
        "<path class=\"event rest\" d=\"M{:.1f} {:.1f}V{:.1f}\" stroke=\"#111\" stroke-width=\"1\" "
        "stroke-dasharray=\"4 3\"/>\n",
        xr, top, bottom);
    o.add(
        "<path class=\"event latch\" data-skip=\"{}\" d=\"M{:.1f} {:.1f}V{:.1f}\" "
        "stroke=\"#e0007a\" "
        "stroke-width=\"1.5\"/>\n",
        s.index, xl, top, bottom);
    const std::string text = place_label(m, s.ctx, s.line);
    const double tw = text_width(text, 10);
    Box2 b{xl - tw / 2, band, tw, 12};
    bool leader = false;
    b = labels.place(xl, band + 6, tw, 12, leader);
    if (b.w <= 0) continue;
    o.add("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#b0005f\">{}</text>\n", b.x,
          b.y + 10, esc(text));
  }
}

// The time axis under the strips.
void draw_time_axis(Svg& o, const TimeFrame& tf, double bottom, double label_w) {
  const double step = nice_step(tf.t1 - tf.t0, 10);
  const int dec = step < 1 ? static_cast<int>(std::ceil(-std::log10(step))) : 0;
  for (double t = std::ceil(tf.t0 / step) * step; t <= tf.t1 + step * 1e-9; t += step) {
    o.add(
        "<path d=\"M{:.1f} {:.1f}v4\" stroke=\"#666\"/><text x=\"{:.1f}\" y=\"{:.1f}\" "
        "font-size=\"10\" "
        "fill=\"#666\" text-anchor=\"middle\">{}</text>\n",
        tf.X(t), bottom, tf.X(t), bottom + 15, num(t, dec));
  }
  o.add("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" fill=\"#444\">time (s)</text>\n",
        tf.px0 - label_w, bottom + 15);
}

}  // namespace

double draw_timeline(Svg& o, const PlotModel& m, double x, double y, double w) {
  const double label_w = 74;
  TimeFrame tf;
  tf.px0 = x + label_w;
  tf.pw = w - label_w - 8;
  tf.t0 = 0.0;
  tf.t1 = std::max(m.time_s, m.t.empty() ? 1e-3 : m.t.back());
  o.add("<g class=\"timeline\" data-frame=\"{} {} {} {}\">\n", tf.t0, tf.t1, tf.px0, tf.pw);
  o.add(
      "<text x=\"{}\" y=\"{}\" font-size=\"14\" font-weight=\"bold\" fill=\"#222\">Timeline "
      "(scope)</text>\n",
      x, y + 14);
  o.add(
      "<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#666\">latch instants in magenta, rest "
      "instants dashed; "
      "{} servo periods, {} drawn</text>\n",
      x + 150, y + 14, m.periods, m.t.size());
  const double band = y + 22;
  double sy = y + 42;
  const double strips_top = sy;
  for (const auto& c : m.channels) sy += draw_strip(o, m, c, tf, sy) + 6;
  const double strips_bottom = sy - 6;
  draw_skip_instants(o, m, tf, band, strips_top, strips_bottom);
  draw_time_axis(o, tf, strips_bottom, label_w);
  o.add("</g>\n");
  return strips_bottom + 24;
}

}  // namespace skipnc::plot
