#include "run/plot.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "plot/plot.hpp"
#include "report/report.hpp"

namespace skipnc::run {

namespace {

enum class PlotFormat : std::uint8_t { kSvg, kHtml, kUnknown };

PlotFormat format_of(const std::string& file) {
  std::string ext = std::filesystem::path(file).extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".svg") return PlotFormat::kSvg;
  if (ext == ".html" || ext == ".htm") return PlotFormat::kHtml;
  return PlotFormat::kUnknown;
}

}  // namespace

Result<void> check_plot_files(const std::vector<std::string>& files) {
  for (const auto& f : files) {
    if (format_of(f) == PlotFormat::kUnknown) {
      return fail(AlarmId::kUsage, "--plot " + f + ": the file name must end in .svg or .html");
    }
  }
  return {};
}

PlotCapture::PlotCapture(const config::MachineConfig& m, sim::RunOptions& opts)
    : rec_(m), tee_(opts.trace, &rec_) {
  opts.trace = &tee_;
  opts.commands = &rec_;
}

Result<void> PlotCapture::write(const std::vector<std::string>& files, const run::Session& s,
                                const sim::RunResult& r, const Output& out) {
  rec_.finish();
  plot::PlotInput in;
  in.program = out.program;
  in.source = out.source;
  in.read_file = read_program_text;
  in.x_in_diameter = s.machine.lathe() && s.params->bit(config::param::kDiameterX);
  in.machine = &s.machine;
  in.dialect = &s.dialect;
  in.scene = &s.scene;
  in.result = &r;
  in.recorder = &rec_;
  in.variables = out.variables;
  const plot::PlotModel model = plot::build_model(in);
  for (const auto& f : files) {
    const std::string text =
        format_of(f) == PlotFormat::kSvg ? plot::to_svg(model) : plot::to_html(model);
    auto w = report::write_atomic(f, text);
    if (!w) return w;
  }
  return {};
}

std::string read_program_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace skipnc::run
