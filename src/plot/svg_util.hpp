// Small helpers shared by the SVG writer's parts (svg.cpp: views,
// svg_panel.cpp: legend and skips, svg_timeline.cpp: the scope).
#pragma once

#include <fmt/format.h>

#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "plot/model.hpp"
#include "plot/view.hpp"

namespace skipnc::plot {

struct Svg {
  std::string s;
  template <class... A>
  void add(fmt::format_string<A...> f, A&&... a) {
    fmt::format_to(std::back_inserter(s), f, std::forward<A>(a)...);
  }
};

// Text for XML content and attribute values.
std::string esc(std::string_view text);

// Appends "M x y L x y ..." (one decimal) to an SVG path.
void append_path(std::string& d, const std::vector<Pt>& pts);

// stroke, stroke-width, dash and fill="none" for a line in the given ink.
std::string stroke_attrs(Ink i);

// A white outline under label text, so that it reads over lines.
inline constexpr const char* kHalo =
    "stroke=\"#ffffff\" stroke-width=\"3\" stroke-opacity=\"0.85\" paint-order=\"stroke\"";

// The marker of a crash, collision or protection alarm at (x, y): a red
// cross in a circle (class "alarm-marker"), with `title` as its tooltip.
std::string alarm_marker(double x, double y, const std::string& title);
// Its legend: "probe crash: where the alarm came" ...
std::string alarm_marker_legend(const std::string& key);

// Legend, skip cards with a zoom on each latch, variables and messages, from
// (x, y) in a column `w` wide. Returns the bottom.
double draw_panel(Svg& o, const PlotModel& m, double x, double y, double w);

// The scope: one strip per channel, skip instants marked. Returns the bottom.
double draw_timeline(Svg& o, const PlotModel& m, double x, double y, double w);
// The latch zooms of the skips the panel shows without one, in a grid
// (svg_panel.cpp); returns the y below them.
double draw_more_zooms(Svg& o, const PlotModel& m, double x, double y, double w);

// Time window [t0, t1] of the zoom on skip k's latch.
std::pair<double, double> latch_window(const SkipMark& s);

}  // namespace skipnc::plot
