// Measurement uncertainty (`skipnc run --repeat N`, Python run(repeat=N)):
// the cycle runs once without the probe's scatter (the nominal run) and N
// times with it, each with its own seed (S, S+1, ...); the latch model is
// the machine's. Every latched value, every reported variable and every
// offset the program wrote is summarised: nominal, mean, standard
// deviation, minimum, maximum and the worst deviation from the nominal run
// (docs/scene.md).
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "run/scenario.hpp"
#include "run/session.hpp"

namespace skipnc::run {

// One summarised quantity: its samples over the scattered runs.
struct RepeatSeries {
  std::string name;  // "skip 2 (line 9) X", "#103", "#5221 G54 X", "#11001 H1 geometry"
  std::string kind;  // "skip", "variable", "offset"
  std::uint32_t line = 0;
  std::optional<double> nominal;
  std::vector<double> samples;
};

struct RepeatStats {
  double mean = 0.0, sd = 0.0, min = 0.0, max = 0.0;
  double worst = 0.0;  // the largest |sample - nominal| (the mean without a nominal)
};
RepeatStats stats_of(const RepeatSeries& s);

struct RepeatRequest {
  // The program, its include folders, strict and the reported variables
  // (its expect and plot_files are not used).
  RunRequest program;
  std::string dprnt_path;                         // DPRNT file; empty: none
  std::vector<std::pair<int, double>> variables;  // #1-#33, #100-#199, #500-#999 at the start
  int runs = 0;                                   // scattered runs
  std::optional<std::uint64_t> seed;  // first seed; none: the scene probe's (1 without a probe)
};

// One run of the repetitions (run 0 is the nominal one), for --junit.
struct RepeatRun {
  int run = 0;
  std::uint64_t seed = 0;  // the probe's scatter seed (0 for the nominal run)
  double time_s = 0.0;     // simulated
  bool alarm = false;
  std::string alarm_text;  // describe(): "file:line:column: alarm CODE (N): message"
};

struct RepeatOutcome {
  int runs = 0;  // scattered runs that finished
  std::uint64_t seed = 1;
  int alarms = 0;           // scattered runs that ended in an alarm
  std::string first_alarm;  // "run 3: file:line:column: alarm ..." ("" without)
  bool interrupted = false;
  bool scatter = false;  // the scene's probe scatters (else every run is the nominal one)
  std::vector<RepeatSeries> series;
  std::vector<RepeatRun> log;  // every run that finished, in order
  int exit_code() const { return alarms > 0 || interrupted ? 1 : 0; }
};

// The runs. A returned error is a run that could not start (exit status 2
// for the command line). Never writes #500-#999 back; `interrupt` ends the
// repetitions early (the runs that finished are kept, `interrupted` set).
[[nodiscard]] Result<RepeatOutcome> repeat_runs(const Session& s, const RepeatRequest& rq,
                                                const std::atomic<bool>* interrupt = nullptr);

// The JSON report of --repeat (format skipnc-repeat/1, docs/cli.md).
std::string repeat_json(const RepeatOutcome& o, const std::string& program);

}  // namespace skipnc::run
