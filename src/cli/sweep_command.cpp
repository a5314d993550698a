// skipnc sweep SPEC.toml (run/sweep.hpp).
#include <fmt/format.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <iostream>

#include "cli/commands.hpp"
#include "run/sweep.hpp"

namespace skipnc::cli {
namespace {

std::atomic<bool> g_sweep_interrupt{false};
extern "C" void on_sweep_signal(int) {
  g_sweep_interrupt.store(true);
}

}  // namespace

int sweep_command(const SweepArgs& a) {
  run::SweepPlan plan;
  run::SweepOverrides o;
  if (a.scenarios > 0) o.scenarios = a.scenarios;
  if (a.seed >= 0) o.seed = static_cast<std::uint64_t>(a.seed);
  if (auto r = run::load_sweep(a.spec, o, plan); !r) {
    std::cerr << "skipnc: " << run::describe(r.error(), &plan.session.dialect) << "\n";
    return 2;
  }
  // touch.sweep.toml -> touch.sweep.csv; touch.toml -> touch.sweep.csv
  std::string stem = std::filesystem::path(a.spec).stem().string();
  if (stem.ends_with(".sweep")) stem.resize(stem.size() - 6);
  const std::string csv = a.csv.empty() ? stem + ".sweep.csv" : a.csv;
  const std::string json = a.json.empty() ? stem + ".sweep.json" : a.json;
  std::signal(SIGINT, on_sweep_signal);
  std::signal(SIGTERM, on_sweep_signal);
  const int workers = a.workers >= 0 ? a.workers : plan.workers;
  const auto rows = run::run_scenarios(plan, 0, plan.scenarios, workers, &g_sweep_interrupt);
  int rc = 0;
  for (const auto& [path, text] :
       {std::pair{csv, run::sweep_csv(plan, rows)}, std::pair{json, run::sweep_json(plan, rows)}}) {
    if (auto w = report::write_atomic(path, text); !w) {
      std::cerr << "skipnc: " << w.error().detail << "\n";
      rc = 1;
    }
  }
  if (!a.quiet) {
    std::FILE* f = csv == "-" || json == "-" ? stderr : stdout;
    fmt::print(f, "{}", run::sweep_summary_text(plan, rows));
    fmt::print(f, "  table: {} and {}\n", csv, json);
  }
  for (const auto& r : rows) {
    if (!r.pass) rc = 1;
  }
  return rc;
}

}  // namespace skipnc::cli
