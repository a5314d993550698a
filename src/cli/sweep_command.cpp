// skipnc sweep SPEC.toml (run/sweep.hpp).
//
// The table is streamed: each row goes to the CSV and JSON files as soon as
// it and the rows before it are done (in index order), so memory does not
// grow with the number of scenarios, and a sweep that is stopped keeps every
// finished row. The files are written to "<name>.partial" and renamed into
// place at the end: a sweep killed outright leaves its finished rows there.
#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/outputs.hpp"
#include "core/file.hpp"
#include "run/sweep.hpp"

namespace skipnc::cli {
namespace {

namespace fs = std::filesystem;

// SIGINT or SIGTERM: no scenario is started any more (the rest are not_run);
// a second one also stops the running scenarios (interrupted); the table is
// written whole either way. A third ends skipnc at once.
std::atomic<int> g_signals{0};
std::atomic<bool> g_stop_taking{false};
std::atomic<bool> g_interrupt{false};
extern "C" void on_sweep_signal(int sig) {
  const int n = g_signals.fetch_add(1) + 1;
  g_stop_taking.store(true);
  if (n >= 2) {
    g_interrupt.store(true);
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    ::sigaction(sig, &dfl, nullptr);
  }
}

void install_sweep_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_sweep_signal;
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
}

// touch.sweep.toml -> touch.sweep.csv, beside the spec (never silently in
// the folder the command runs in).
std::string default_output(const std::string& spec, std::string_view ext) {
  const fs::path p(spec);
  std::string stem = p.stem().string();
  if (stem.ends_with(".sweep")) stem.resize(stem.size() - 6);
  return (p.parent_path() / (stem + ".sweep." + std::string(ext))).string();
}

// Every file a sweep reads: none may be an output.
std::vector<NamedFile> sweep_inputs(const run::SweepPlan& plan) {
  std::vector<NamedFile> in{{"the sweep spec", plan.spec_path},
                            {"the program", plan.request.program_path}};
  for (auto& f : session_inputs(plan.session)) in.push_back(std::move(f));
  if (!plan.session.machine.persistent_vars.empty())
    in.push_back({"the persistent-variable file", plan.session.machine.persistent_vars});
  for (auto& f : include_inputs(plan.request.include_dirs)) in.push_back(std::move(f));
  return in;
}

// One streamed table file: the text goes to "<name>.partial" as it comes,
// which is renamed to the name at the end.
struct TableFile {
  std::string name;
  OutputFile file;
  bool failed = false;

  void write(std::string_view text) {
    if (failed) return;
    if (auto w = file.write(text); !w) {
      std::cerr << "skipnc: " << w.error().detail << "\n";
      failed = true;
    }
  }
};

// A line on standard error, rewritten in place, when it is a terminal.
class Progress {
 public:
  Progress(std::int64_t total, bool on) : total_(total), on_(on) {}
  void row(std::int64_t done) {
    if (!on_) return;
    const auto now = clock::now();
    if (now < next_ && done < total_) return;
    next_ = now + std::chrono::milliseconds(500);
    const double s = std::chrono::duration<double>(now - start_).count();
    const double rate = s > 0.0 ? static_cast<double>(done) / s : 0.0;
    const double left = rate > 0.0 ? static_cast<double>(total_ - done) / rate : 0.0;
    std::fprintf(stderr, "\r  %lld/%lld scenarios, %.0f/s, %.0f s left   ",
                 static_cast<long long>(done), static_cast<long long>(total_), rate, left);
    shown_ = true;
  }
  ~Progress() {
    if (shown_) std::fprintf(stderr, "\r%70s\r", "");
  }

 private:
  using clock = std::chrono::steady_clock;
  std::int64_t total_;
  bool on_;
  bool shown_ = false;
  clock::time_point start_ = clock::now();
  clock::time_point next_ = start_ + std::chrono::seconds(1);
};

// Opens both table files after checking them against the inputs and each
// other: nothing runs when one cannot be written.
Result<void> open_tables(const run::SweepPlan& plan, TableFile& csv, TableFile& json) {
  if (auto r = refuse_collisions({{"--csv", csv.name}, {"--json", json.name}}, sweep_inputs(plan));
      !r) {
    return r;
  }
  for (TableFile* t : {&csv, &json}) {
    auto f = OutputFile::open(t->name, ".partial");
    if (!f) return std::unexpected(f.error());
    t->file = std::move(*f);
  }
  return {};
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
  TableFile csv{a.csv.empty() ? default_output(a.spec, "csv") : a.csv, {}};
  TableFile json{a.json.empty() ? default_output(a.spec, "json") : a.json, {}};
  if (auto r = open_tables(plan, csv, json); !r) {
    std::cerr << "skipnc: " << run::describe(r.error(), &plan.session.dialect) << "\n";
    return 2;
  }
  install_sweep_signals();
  run::SweepTable table(plan);
  csv.write(table.csv_header());
  json.write(table.json_head());
  Progress progress(plan.scenarios, !a.quiet && ::isatty(STDERR_FILENO) == 1);
  const int workers = a.workers >= 0 ? a.workers : plan.workers;
  run::run_scenarios(
      plan, 0, plan.scenarios, workers,
      [&](const run::ScenarioRow& r) {
        csv.write(table.csv_row(r));
        json.write(table.json_row(r, table.rows() == 0));
        table.add(r);
        progress.row(table.rows());
      },
      run::SweepStop{&g_stop_taking, &g_interrupt});
  json.write(table.json_tail());
  int rc = table.exit_status();
  for (TableFile* t : {&csv, &json}) {
    if (auto c = t->file.commit(); !c) {
      if (!t->failed) std::cerr << "skipnc: " << c.error().detail << "\n";
      rc = std::max(rc, 1);
    }
  }
  if (!a.quiet) {
    std::FILE* f = csv.name == "-" || json.name == "-" ? stderr : stdout;
    fmt::print(f, "{}", table.summary_text());
    fmt::print(f, "  table: {} and {}\n", csv.name, json.name);
  }
  if (rc == 2) {
    std::cerr << "skipnc: no scenario could start (every row is an error): "
              << "the sweep did not run\n";
  }
  return rc;
}

}  // namespace skipnc::cli
