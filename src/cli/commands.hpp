#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace skipnc::cli {

struct RunArgs {
  std::string program;       // a file, or "-": standard input
  std::string program_text;  // the text read from standard input (program "-", main.cpp)
  std::string machine = "mill3";
  std::string scene;
  std::string dialect;
  std::vector<std::string> params;
  std::vector<std::string> vars;
  std::vector<std::string> expect;  // --expect (run/expect.hpp)
  std::string report;
  std::string junit;  // --junit FILE: the checks as JUnit XML (cli/junit.hpp)
  std::string trace;
  std::vector<std::string> plot;  // --plot FILE: .svg or .html pictures of the run
  std::vector<std::string> include;
  std::string dprnt;
  std::string log_dir;  // --log-dir
  bool quiet = false;
  int repeat = 0;                  // --repeat N: N runs with the probe's scatter (cli/repeat.hpp)
  long long seed = -1;             // --seed S: first seed of those runs (-1: the scene's)
  bool progress = false;           // --progress: a line on standard error every few seconds
  bool strict = false;             // --strict: a warning is an alarm (strict_warning)
  std::vector<std::string> allow;  // --allow CODE: this warning stays a warning under --strict
  long long trace_every = 1;       // --trace-every N: a trace row every N servo periods
};

int run_command(const RunArgs& a);
int canon_command(const RunArgs& a);
int demo_command(const RunArgs& a);
int dialects_command();
// `skipnc plot`: a run whose pictures go to the -o files (default
// <program>.html and <program>.svg in the current folder).
int plot_command(RunArgs a);

// `skipnc sweep SPEC`: the scenarios of run/sweep.hpp, a table and a summary.
struct SweepArgs {
  std::string spec;
  std::string csv;    // default: <spec stem>.sweep.csv here
  std::string json;   // default: <spec stem>.sweep.json here
  std::string junit;  // JUnit XML, one test case per scenario; empty: none
  int workers = -1;   // -1: the spec's
  std::int64_t scenarios = -1;
  long long seed = -1;
  bool quiet = false;
};
int sweep_command(const SweepArgs& a);

}  // namespace skipnc::cli
