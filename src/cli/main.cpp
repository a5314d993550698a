// skipnc: command line (spec/cli.md).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>

#include "cli/commands.hpp"
#include "cli/guard.hpp"
#include "cli/outputs.hpp"
#include "cli/repeat.hpp"
#include "cli/show.hpp"
#include "run/plot.hpp"
#include "run/sweep.hpp"

namespace {

// The parsed commands' arguments. They live in main()'s frame, not in
// run_main()'s: the last-resort handler reads them after an exception has
// unwound run_main.
struct Parsed {
  skipnc::cli::RunArgs run, canon, demo, plot;
  skipnc::cli::SweepArgs sweep;
  skipnc::cli::ShowArgs show;
  // The arguments of the command that runs (null before one runs).
  const skipnc::cli::RunArgs* active = nullptr;
};

// A way for the tests to make an exception leave run_main (docs/testing.md):
// SKIPNC_TEST_THROW=bad_alloc|runtime_error|int, thrown once the command's
// arguments are parsed.
void test_throw() {
  const char* what = std::getenv("SKIPNC_TEST_THROW");
  if (what == nullptr) return;
  const std::string_view w(what);
  if (w == "bad_alloc") throw std::bad_alloc();
  if (w == "runtime_error") throw std::runtime_error("test exception");
  if (w == "int") throw 42;
}

// skipnc run PROGRAM ... (spec/cli.md).
CLI::App* add_run(CLI::App& app, skipnc::cli::RunArgs& run_args) {
  auto* run = app.add_subcommand("run", "run a part program on a simulated machine");
  run->add_option("program", run_args.program, "part program file (-: standard input)")->required();
  run->add_option("-m,--machine", run_args.machine, "machine file or built-in machine (mill3)");
  run->add_option("-s,--scene", run_args.scene, "scene file (TOML)");
  run->add_option("-d,--dialect", run_args.dialect,
                  "fanuc, nct, mitsubishi, compass, linuxcnc, grblhal, haas");
  run->add_option("-p,--param", run_args.params, "parameter N=V or N#B=V (repeatable)");
  run->add_option("--var", run_args.vars, "report variable V (5061, #5061, #<name>)");
  run->add_option("--report", run_args.report, "write the JSON report here (- for stdout)");
  run->add_option("--trace", run_args.trace, "write the per-cycle CSV trace here");
  run->add_option("--trace-every", run_args.trace_every,
                  "one trace row every N servo periods (default 1: every period)")
      ->check(CLI::Range(1LL, 1000000000LL));
  run->add_option("--plot", run_args.plot, "write pictures of the run: FILE.svg and/or FILE.html");
  run->add_option("-I,--include", run_args.include, "subprogram folder (repeatable)");
  run->add_option("--dprnt", run_args.dprnt, "file for DPRNT output (POPEN/PCLOS)");
  run->add_option("--log-dir", run_args.log_dir,
                  "folder for the files of LinuxCNC's (LOGOPEN,name) and (PROBEOPEN name)");
  run->add_flag("-q,--quiet", run_args.quiet, "no summary on standard output");
  run->add_flag("--progress", run_args.progress,
                "a progress line on standard error every 2 s (also without a terminal)");
  run->add_flag("--strict", run_args.strict,
                "a warning is an alarm (SN9076 strict_warning) at the block that raised it");
  run->add_option("--allow", run_args.allow,
                  "under --strict, warning CODE stays a warning (repeatable: --allow no_effect)");
  run->add_option("--junit", run_args.junit,
                  "write the checks (each --expect; with --repeat each run) as JUnit XML here");
  run->add_option("--expect", run_args.expect,
                  "CI check: #140=-0.05+-0.001, #140=vacant, status=completed, alarm=9061 "
                  "(repeatable; exit status 3 when one fails)");
  run->add_option("--repeat", run_args.repeat,
                  "run N times with the probe's scatter; report mean, std dev, worst case")
      ->check(CLI::Range(1, 1000000));
  run->add_option("--seed", run_args.seed, "first seed of the --repeat runs (default: the scene's)")
      ->check(CLI::Range(0LL, 9000000000000000000LL));
  return run;
}

// skipnc canon PROGRAM ...
CLI::App* add_canon(CLI::App& app, skipnc::cli::RunArgs& canon_args) {
  auto* canon = app.add_subcommand("canon", "print the canonical command stream, without motion");
  canon->add_option("program", canon_args.program, "part program file (-: standard input)")
      ->required();
  canon->add_option("-m,--machine", canon_args.machine, "machine file or built-in machine");
  canon->add_option("-d,--dialect", canon_args.dialect, "dialect");
  canon->add_option("-p,--param", canon_args.params, "parameter N=V or N#B=V (repeatable)");
  canon->add_option("-I,--include", canon_args.include, "subprogram folder (repeatable)");
  canon->add_flag("--strict", canon_args.strict, "a warning is an alarm (SN9076 strict_warning)");
  canon->add_option("--allow", canon_args.allow, "under --strict, warning CODE stays a warning");
  return canon;
}

// skipnc demo ...
CLI::App* add_demo(CLI::App& app, skipnc::cli::RunArgs& demo_args) {
  auto* demo = app.add_subcommand("demo", "run the built-in probing demo and explain it");
  demo->add_option("--report", demo_args.report, "also write the JSON report here");
  demo->add_option("--trace", demo_args.trace, "also write the per-cycle CSV trace here");
  demo->add_option("--plot", demo_args.plot, "also write pictures: FILE.svg and/or FILE.html");
  demo->add_flag("-q,--quiet", demo_args.quiet, "no explanation on standard output");
  return demo;
}

// skipnc plot PROGRAM ...
CLI::App* add_plot(CLI::App& app, skipnc::cli::RunArgs& plot_args) {
  auto* plot =
      app.add_subcommand("plot", "run a program and draw it: SVG and an offline HTML page");
  plot->add_option("program", plot_args.program, "part program file")->required();
  plot->add_option(
      "-o,--output", plot_args.plot,
      "FILE.svg or FILE.html, repeatable (default: PROGRAM.html and PROGRAM.svg here)");
  plot->add_option("-m,--machine", plot_args.machine, "machine file or built-in machine (mill3)");
  plot->add_option("-s,--scene", plot_args.scene, "scene file (TOML)");
  plot->add_option("-d,--dialect", plot_args.dialect,
                   "fanuc, nct, mitsubishi, compass, linuxcnc, grblhal, haas");
  plot->add_option("-p,--param", plot_args.params, "parameter N=V or N#B=V (repeatable)");
  plot->add_option("--var", plot_args.vars, "show variable V (5061, #5061, #<name>)");
  plot->add_option("--report", plot_args.report, "also write the JSON report here");
  plot->add_option("-I,--include", plot_args.include, "subprogram folder (repeatable)");
  plot->add_flag("-q,--quiet", plot_args.quiet, "no summary on standard output");
  plot->add_flag("--progress", plot_args.progress,
                 "a progress line on standard error every 2 s (also without a terminal)");
  plot->add_flag("--strict", plot_args.strict, "a warning is an alarm (SN9076 strict_warning)");
  plot->add_option("--allow", plot_args.allow, "under --strict, warning CODE stays a warning");
  return plot;
}

// skipnc sweep SPEC ...
CLI::App* add_sweep(CLI::App& app, skipnc::cli::SweepArgs& sweep_args) {
  auto* sweep = app.add_subcommand("sweep", "run a program in N scenarios on all cores");
  sweep->add_option("spec", sweep_args.spec, "sweep spec (TOML)")->required();
  sweep->add_option("--csv", sweep_args.csv,
                    "the table as CSV (default: SPEC.sweep.csv beside the spec)");
  sweep->add_option("--json", sweep_args.json,
                    "table and summary as JSON (SPEC.sweep.json beside the spec)");
  sweep->add_option("--junit", sweep_args.junit,
                    "JUnit XML: one test case per scenario, its failed checks as failures");
  sweep->add_option("-j,--workers", sweep_args.workers, "threads (0: every core; default: spec's)")
      ->check(CLI::Range(0, skipnc::run::kMaxWorkers));
  sweep->add_option("-n,--scenarios", sweep_args.scenarios, "scenarios (default: the spec's)")
      ->check(CLI::Range(std::int64_t{1}, skipnc::run::kMaxScenarios));
  sweep->add_option("--seed", sweep_args.seed, "seed of the draws (default: the spec's)")
      ->check(CLI::Range(0LL, static_cast<long long>(skipnc::run::kMaxSeed)));
  sweep->add_flag("-q,--quiet", sweep_args.quiet, "no summary on standard output");
  return sweep;
}

// skipnc show WHAT [NAME]
CLI::App* add_show(CLI::App& app, skipnc::cli::ShowArgs& show_args) {
  auto* show = app.add_subcommand("show", "print a built-in file: machine NAME, machines, demo");
  show->add_option("what", show_args.what, "machine, machines or demo")->required();
  show->add_option("name", show_args.name, "the built-in machine's name (mill3, lathe2, ...)");
  return show;
}

int run_main(int argc, char** argv, Parsed& p) {
  CLI::App app{"skipnc: a CNC kernel and simulated machine built around the G31 skip function"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "skipnc 0.1.0");
  CLI::App* run = add_run(app, p.run);
  CLI::App* canon = add_canon(app, p.canon);
  CLI::App* demo = add_demo(app, p.demo);
  CLI::App* plot = add_plot(app, p.plot);
  auto* dialects = app.add_subcommand("dialects", "list the dialects and what differs");
  CLI::App* sweep = add_sweep(app, p.sweep);
  CLI::App* show = add_show(app, p.show);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  for (auto [cmd, args] : {std::pair{run, &p.run}, std::pair{canon, &p.canon},
                           std::pair{demo, &p.demo}, std::pair{plot, &p.plot}}) {
    if (cmd->parsed()) p.active = args;
  }
  test_throw();
  if (run->parsed()) {
    if (auto r = skipnc::cli::read_stdin_program(p.run); !r) {
      return skipnc::cli::start_failure(p.run, r.error(), nullptr);
    }
    return p.run.repeat > 0 ? skipnc::cli::repeat_command(p.run) : skipnc::cli::run_command(p.run);
  }
  if (canon->parsed()) {
    if (auto r = skipnc::cli::read_stdin_program(p.canon); !r) {
      return skipnc::cli::start_failure(p.canon, r.error(), nullptr);
    }
    return skipnc::cli::canon_command(p.canon);
  }
  if (demo->parsed()) {
    return skipnc::cli::demo_command(p.demo);
  }
  if (plot->parsed()) {
    return skipnc::cli::plot_command(p.plot);
  }
  if (dialects->parsed()) return skipnc::cli::dialects_command();
  if (sweep->parsed()) return skipnc::cli::sweep_command(p.sweep);
  if (show->parsed()) return skipnc::cli::show_command(p.show);
  return 2;
}

}  // namespace

// No exception leaves skipnc: the last resort writes the report with the
// internal-error alarm. Text that standard output refused (a full disk, a
// closed pipe) makes the exit status non-zero.
int main(int argc, char** argv) {
  skipnc::cli::install_signal_handlers();
  skipnc::cli::reserve_emergency_memory();
  int rc = 0;
  Parsed parsed;
  try {
    rc = run_main(argc, argv, parsed);
  } catch (const std::system_error& e) {
    if (std::ferror(stdout)) {
      std::fprintf(stderr, "skipnc: cannot write standard output: %s\n", e.what());
      rc = rc == 0 ? 1 : rc;
    } else {
      rc = skipnc::cli::internal_failure(parsed.active, e.what());
    }
  } catch (const std::exception& e) {
    rc = skipnc::cli::internal_failure(parsed.active, e.what());
  } catch (...) {
    rc = skipnc::cli::internal_failure(parsed.active, "an exception of unknown type");
  }
  if (auto f = skipnc::cli::finish_stdout(); !f) {
    std::fprintf(stderr, "skipnc: %s\n", f.error().detail.c_str());
    if (rc == 0) rc = 1;
  }
  return rc;
}
