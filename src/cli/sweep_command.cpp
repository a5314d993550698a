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
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/guard.hpp"
#include "cli/junit.hpp"
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

// First thing in the command: a signal from then on is the sweep's; one
// that came before (main()'s handlers, set before anything else, kept it in
// run_stop()) counts as the first, so the sweep takes no scenario and still
// writes its table (before, a SIGTERM while the spec was loading was lost
// and the sweep ran to its end).
void install_sweep_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_sweep_signal;
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
  if (run_stop().signal.load() != 0 && g_signals.load() == 0) {
    g_signals.fetch_add(1);
    g_stop_taking.store(true);
  }
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

// --junit FILE: one test case per scenario. The cases go to an unnamed
// temporary file as the rows come (memory does not grow with the sweep);
// the file itself is written whole at the end, its head announcing the counts.
class JunitSweep {
 public:
  JunitSweep(const run::SweepPlan& plan, std::string name)
      : plan_(plan), name_(std::move(name)), body_(name_.empty() ? nullptr : std::tmpfile()) {}
  JunitSweep(const JunitSweep&) = delete;
  JunitSweep& operator=(const JunitSweep&) = delete;
  ~JunitSweep() {
    if (body_ != nullptr) std::fclose(body_);
  }
  bool wanted() const { return !name_.empty(); }
  bool ok() const { return !wanted() || (body_ != nullptr && !failed_); }

  void row(const run::ScenarioRow& r) {
    if (!wanted() || failed_) return;
    const JunitCase c = scenario_case(r);
    counts_.add(c);
    time_s_ += c.time_s;
    const std::string x = junit_case(c);
    failed_ = body_ == nullptr || std::fwrite(x.data(), 1, x.size(), body_) != x.size();
  }

  // Writes the file (whole or not at all), copying the cases in chunks;
  // false, with the reason on standard error, when it could not be.
  bool write() {
    if (!wanted()) return true;
    if (body_ == nullptr || failed_ || std::fflush(body_) != 0) {
      std::cerr << "skipnc: junit: the test cases could not be kept in a temporary file\n";
      return false;
    }
    auto f = OutputFile::open(name_);
    if (!f) {
      std::cerr << "skipnc: junit: " << f.error().detail << "\n";
      return false;
    }
    Result<void> w = f->write(junit_head(plan_.spec_path, time_s_, counts_));
    std::rewind(body_);
    char buf[65536];
    for (std::size_t n; w && (n = std::fread(buf, 1, sizeof buf, body_)) > 0;)
      w = f->write(std::string_view(buf, n));
    if (w) w = f->write(junit_tail());
    if (w && std::ferror(body_) != 0)
      w = fail(AlarmId::kFileAccess, "the test cases' temporary file could not be read");
    if (w) w = f->commit();
    if (!w) {
      f->discard();
      std::cerr << "skipnc: junit: " << w.error().detail << "\n";
      return false;
    }
    return true;
  }

 private:
  JunitCase scenario_case(const run::ScenarioRow& r) const {
    JunitCase c{fmt::format("scenario {}", r.index),
                "skipnc.sweep." + plan_.spec_path,
                r.time_s,
                !r.pass,
                {},
                {},
                {},
                JunitProblem::kFailure,
                {}};
    std::string out;
    for (std::size_t k = 0; k < plan_.vary.size() && k < r.chosen.size(); ++k)
      out += fmt::format("{} = {}\n", plan_.vary[k].name, r.chosen[k]);
    for (std::size_t k = 0; k < plan_.request.vars.size() && k < r.values.size(); ++k) {
      out += fmt::format("#{} = {}\n", plan_.request.vars[k].key,
                         r.values[k] ? fmt::format("{}", *r.values[k]) : std::string("vacant"));
    }
    c.output = fmt::format("status {}\n{}", r.status, out);
    if (!c.failed) return c;
    const std::vector<std::string> why = run::row_failures(plan_, r);
    c.problem = r.status == "error"     ? JunitProblem::kError
                : r.status == "not_run" ? JunitProblem::kSkipped
                                        : JunitProblem::kFailure;
    c.failure_type = r.status == "completed" ? "expectation" : r.status;
    for (const std::string& w : why) {
      c.failure_message += (c.failure_message.empty() ? "" : "; ") + w;
      c.failure_text += w + "\n";
    }
    return c;
  }

  const run::SweepPlan& plan_;
  std::string name_;
  std::FILE* body_;
  JunitCounts counts_;
  double time_s_ = 0.0;
  bool failed_ = false;
};

// Opens both table files after checking them against the inputs and each
// other: nothing runs when one cannot be written.
Result<void> open_tables(const run::SweepPlan& plan, TableFile& csv, TableFile& json,
                         const std::string& junit) {
  std::vector<NamedFile> outputs{{"--csv", csv.name}, {"--json", json.name}};
  if (!junit.empty()) outputs.push_back({"--junit", junit});
  if (auto r = refuse_collisions(outputs, sweep_inputs(plan)); !r) return r;
  for (TableFile* t : {&csv, &json}) {
    auto f = OutputFile::open(t->name, ".partial");
    SKIPNC_TRY(f);
    t->file = std::move(*f);
  }
  return {};
}

}  // namespace

int sweep_command(const SweepArgs& a) {
  install_sweep_signals();
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
  if (auto r = open_tables(plan, csv, json, a.junit); !r) {
    std::cerr << "skipnc: " << run::describe(r.error(), &plan.session.dialect) << "\n";
    return 2;
  }
  JunitSweep junit(plan, a.junit);
  if (!junit.ok()) {
    std::cerr << "skipnc: junit: no temporary file for the test cases\n";
    return 2;
  }
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
        junit.row(r);
        progress.row(table.rows());
      },
      run::SweepStop{&g_stop_taking, &g_interrupt});
  json.write(table.json_tail());
  int rc = table.exit_status();
  if (!junit.write()) rc = std::max(rc, 1);
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
