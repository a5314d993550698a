// Pictures of a run: a self-contained SVG and an offline HTML page drawn
// from one PlotModel (model.hpp), which is built from the run's result, the
// scene, the machine and a Recorder that watched the run (recorder.hpp).
//
//   plot::Recorder rec(machine);                // a sim::TraceSink and a command tap
//   opts.trace = &rec; opts.commands = &rec;    // sim::RunOptions
//   ... run ...; rec.finish();
//   auto model = plot::build_model({...});
//   std::string svg = plot::to_svg(model), html = plot::to_html(model);
#pragma once

#include <string>

#include "plot/model.hpp"

namespace skipnc::plot {

// Views XY/XZ/YZ/isometric, a panel with the legend and the skips (each with
// a zoom on its latch), and a scope-like timeline.
std::string to_svg(const PlotModel& m);

// The same content as an interactive page: zoom and pan, hover to read a
// point, step block by block. No network: script and styles are inside.
std::string to_html(const PlotModel& m);

// The model as JSON (what the page's script draws).
std::string to_json(const PlotModel& m);

}  // namespace skipnc::plot
