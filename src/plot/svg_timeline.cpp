// The SVG's scope: time runs left to right over the whole run; one strip
// per channel (positions, path speed, following error, torque, then one
// logic trace per input signal); every latch and rest instant is a vertical
// line through all strips.
#include <algorithm>
#include <cmath>

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

}  // namespace

double draw_timeline(Svg& o, const PlotModel& m, double x, double y, double w) {
  const double label_w = 74, px0 = x + label_w, pw = w - label_w - 8;
  const double t0 = 0.0, t1 = std::max(m.time_s, m.t.empty() ? 1e-3 : m.t.back());
  auto X = [&](double t) { return px0 + (t - t0) / (t1 - t0) * pw; };
  o.add("<g class=\"timeline\" data-frame=\"{} {} {} {}\">\n", t0, t1, px0, pw);
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
  for (const auto& c : m.channels) {
    const double h = strip_height(c);
    const auto [vlo, vhi] = c.digital ? std::pair{-0.15, 1.25} : value_range(c);
    auto Y = [&](double v) { return sy + (vhi - v) / (vhi - vlo) * h; };
    o.add("<g class=\"strip\" data-channel=\"{}\" data-frame=\"{} {} {} {}\">\n", esc(c.id), vlo,
          vhi, sy, h);
    o.add("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#fff\" stroke=\"#d0d0d0\"/>\n",
          px0, sy, pw, h);
    if (c.flat) {
      const double mid = 0.5 * (vlo + vhi);
      o.add(
          "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#666\" "
          "text-anchor=\"end\">{}</text>\n",
          px0 - 4, Y(mid) + 3, num(mid, c.unit == "mm" ? 4 : 1));
    } else if (!c.digital) {
      // Tick labels at least 20 px apart.
      double step = nice_step(vhi - vlo, 3);
      for (int g = 0; g < 40 && step / (vhi - vlo) * h < 20; ++g) step = next_nice_step(step);
      const int dec = step < 1 ? static_cast<int>(std::ceil(-std::log10(step))) : 0;
      std::string grid;
      for (double v = std::ceil(vlo / step) * step; v <= vhi; v += step) {
        grid += fmt::format("M{:.1f} {:.1f}h{:.1f}", px0, Y(v), pw);
        o.add(
            "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#666\" "
            "text-anchor=\"end\">{}</text>\n",
            px0 - 4, Y(v) + 3, num(std::fabs(v) < step * 1e-6 ? 0.0 : v, dec));
      }
      o.add("<path d=\"{}\" stroke=\"#f0f0f0\" fill=\"none\"/>\n", grid);
    }
    o.add(
        "<clipPath id=\"tclip-{}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" "
        "height=\"{}\"/></clipPath>\n",
        esc(c.id), px0, sy, pw, h);
    o.add("<g clip-path=\"url(#tclip-{})\">\n", esc(c.id));
    for (const auto& s : c.series) {
      std::string d;
      if (c.digital) {
        for (std::size_t i = 0; i < s.v.size(); ++i) {
          const double xx = X(m.t[i]), yy = Y(s.v[i] > 0.5 ? 1.0 : 0.0);
          d += i == 0 ? fmt::format("M{:.1f} {:.1f}", xx, yy)
                      : fmt::format("H{:.1f}V{:.1f}", xx, yy);
        }
        if (!s.v.empty()) {
          o.add(
              "<path d=\"{}V{:.1f}H{:.1f}Z\" fill=\"{}\" fill-opacity=\"0.15\" stroke=\"none\"/>\n",
              d, Y(0), X(m.t.front()), s.colour);
        }
        o.add("<path d=\"{}\" stroke=\"{}\" stroke-width=\"1.5\" fill=\"none\"/>\n", d, s.colour);
      } else {
        std::vector<Pt> pts;
        pts.reserve(s.v.size());
        for (std::size_t i = 0; i < s.v.size(); ++i) pts.push_back(Pt{X(m.t[i]), Y(s.v[i])});
        append_path(d, simplify(pts, 0.3));
        o.add(
            "<path class=\"series\" data-series=\"{}\" d=\"{}\" stroke=\"{}\" stroke-width=\"1.3\" "
            "fill=\"none\"/>\n",
            esc(s.name), d, s.colour);
      }
    }
    o.add("</g>\n");
    // Title and series names at the left, inside the strip.
    double tx = px0 + 6;
    o.add(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" font-weight=\"bold\" fill=\"#333\" "
        "{}>{}{}</text>\n",
        tx, sy + 12, kHalo, esc(c.title),
        esc((c.unit.empty() ? std::string() : " (" + c.unit + ")") + (c.flat ? ": constant" : "")));
    tx += text_width(c.title + " (" + c.unit + ")", 11) + 10;
    if (c.series.size() > 1) {
      for (const auto& s : c.series) {
        o.add(
            "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" font-weight=\"bold\" fill=\"{}\" "
            "{}>{}</text>\n",
            tx, sy + 12, s.colour, kHalo, esc(s.name));
        tx += text_width(s.name, 11) + 8;
      }
    }
    o.add("</g>\n");
    sy += h + 6;
  }
  const double strips_bottom = sy - 6;
  // Skip instants through every strip, labelled above.
  LabelPlacer labels(Box2{px0 - 20, band, pw + 40, 18});
  for (const auto& s : m.skips) {
    const double xl = X(s.latch_t), xr = X(s.stop_t);
    o.add(
        "<path class=\"event rest\" d=\"M{:.1f} {:.1f}V{:.1f}\" stroke=\"#111\" stroke-width=\"1\" "
        "stroke-dasharray=\"4 3\"/>\n",
        xr, strips_top, strips_bottom);
    o.add(
        "<path class=\"event latch\" data-skip=\"{}\" d=\"M{:.1f} {:.1f}V{:.1f}\" "
        "stroke=\"#e0007a\" "
        "stroke-width=\"1.5\"/>\n",
        s.index, xl, strips_top, strips_bottom);
    const std::string text = place_label(m, s.ctx, s.line);
    const double tw = text_width(text, 10);
    Box2 b{xl - tw / 2, band, tw, 12};
    bool leader = false;
    b = labels.place(xl, band + 6, tw, 12, leader);
    o.add("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" fill=\"#b0005f\">{}</text>\n", b.x,
          b.y + 10, esc(text));
  }
  // Time axis.
  const double step = nice_step(t1 - t0, 10);
  const int dec = step < 1 ? static_cast<int>(std::ceil(-std::log10(step))) : 0;
  for (double t = std::ceil(t0 / step) * step; t <= t1 + step * 1e-9; t += step) {
    o.add(
        "<path d=\"M{:.1f} {:.1f}v4\" stroke=\"#666\"/><text x=\"{:.1f}\" y=\"{:.1f}\" "
        "font-size=\"10\" "
        "fill=\"#666\" text-anchor=\"middle\">{}</text>\n",
        X(t), strips_bottom, X(t), strips_bottom + 15, num(t, dec));
  }
  o.add("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" fill=\"#444\">time (s)</text>\n",
        px0 - label_w, strips_bottom + 15);
  o.add("</g>\n");
  return strips_bottom + 24;
}

}  // namespace skipnc::plot
