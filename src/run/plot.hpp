// `skipnc plot` and `--plot FILE` on run and demo: watches a run and writes
// its pictures (SVG and/or an offline HTML page, by the file's extension).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "plot/recorder.hpp"
#include "run/session.hpp"
#include "sim/simulator.hpp"

namespace skipnc::run {

// Every FILE must end in .svg, .html or .htm.
[[nodiscard]] Result<void> check_plot_files(const std::vector<std::string>& files);

// Hooks a plot recorder into a run's options (beside a CSV trace, if any),
// and writes the pictures after the run.
class PlotCapture {
 public:
  PlotCapture(const config::MachineConfig& m, sim::RunOptions& opts);
  PlotCapture(const PlotCapture&) = delete;
  PlotCapture& operator=(const PlotCapture&) = delete;

  struct Output {
    std::string program;      // shown in the title
    std::string_view source;  // program text for the page ("" when unknown)
    std::vector<std::pair<std::string, std::optional<double>>> variables;
  };
  [[nodiscard]] Result<void> write(const std::vector<std::string>& files, const run::Session& s,
                                   const sim::RunResult& r, const Output& out);

 private:
  plot::Recorder rec_;
  plot::TeeTrace tee_;
};

// The program's text (for the page's block list); "" when it cannot be read.
std::string read_program_text(const std::string& path);

}  // namespace skipnc::run
