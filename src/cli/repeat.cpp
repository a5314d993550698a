#include "cli/repeat.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli/guard.hpp"
#include "cli/outputs.hpp"
#include "core/utf8.hpp"
#include "interpreter/variables.hpp"
#include "report/report.hpp"
#include "run/session.hpp"
#include "sim/simulator.hpp"

namespace skipnc::cli {
namespace {

// One summarised quantity: its samples over the scattered runs.
struct Series {
  std::string name;  // "skip 2 X", "#103", "#5221 G54 X", "#11001 H1 geometry"
  std::string kind;  // "skip", "variable", "offset"
  std::uint32_t line = 0;
  std::optional<double> nominal;
  std::vector<double> samples;
};

struct Stats {
  double mean = 0.0, sd = 0.0, min = 0.0, max = 0.0, worst = 0.0;
};

Stats stats_of(const Series& s) {
  Stats st;
  const auto& x = s.samples;
  if (x.empty()) return st;
  double sum = 0.0;
  for (double v : x) sum += v;
  st.mean = sum / static_cast<double>(x.size());
  double ss = 0.0;
  for (double v : x) ss += (v - st.mean) * (v - st.mean);
  st.sd = x.size() > 1 ? std::sqrt(ss / static_cast<double>(x.size() - 1)) : 0.0;
  st.min = *std::min_element(x.begin(), x.end());
  st.max = *std::max_element(x.begin(), x.end());
  const double ref = s.nominal ? *s.nominal : st.mean;
  for (double v : x) st.worst = std::max(st.worst, std::fabs(v - ref));
  return st;
}

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (char c : utf8::make_valid(text)) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned>(static_cast<unsigned char>(c)));
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string json_number(double v) {
  return std::isfinite(v) ? fmt::format("{}", v) : "null";
}

// The offsets a program can write, as (variable, label).
std::vector<std::pair<int, std::string>> offset_variables(const config::MachineConfig& m) {
  std::vector<std::pair<int, std::string>> out;
  static const char* kSets[] = {"EXT", "G54", "G55", "G56", "G57", "G58", "G59"};
  for (int set = 0; set < 7; ++set) {
    for (int i = 0; i < m.axis_count(); ++i) {
      out.emplace_back(5201 + 20 * set + i,
                       fmt::format("{} {}", kSets[set], m.axes[static_cast<std::size_t>(i)].name));
    }
  }
  const int count = std::min(m.tool_offset_count, 999);
  for (int k = 1; k <= count; ++k) {
    out.emplace_back(11000 + k, fmt::format("H{} geometry", k));
    out.emplace_back(10000 + k, fmt::format("H{} wear", k));
    out.emplace_back(13000 + k, fmt::format("D{} geometry", k));
    out.emplace_back(12000 + k, fmt::format("D{} wear", k));
  }
  return out;
}

std::optional<double> read(const interp::Interpreter& in, int number) {
  auto v = in.read_variable(number);
  if (!v || v->vacant) return std::nullopt;
  return v->v;
}

}  // namespace

int repeat_command(const RunArgs& a) {
  run::Session s;
  auto o = run::open_session(run::SessionOptions{a.machine, a.dialect, a.scene, a.params}, s);
  // A run that cannot start writes the report with its alarm too (was:
  // none), as `run` without --repeat does.
  if (!o) return start_failure(a, o.error(), &s);
  std::vector<run::VarRef> vars;
  for (const auto& v : a.vars) {
    auto r = run::parse_var_ref(v);
    if (!r) return start_failure(a, r.error(), &s);
    vars.push_back(*r);
  }
  interp::Setup setup;
  // Every repetition starts from the same #500-#999 (the file's) and none
  // writes them back: the scatter is the probe's alone, and the file is
  // not changed N+1 times (was: each run saved, the next one read that).
  if (!s.machine.persistent_vars.empty()) {
    std::array<interp::Value, 500> kept{};
    if (auto r = interp::load_persistent(s.machine.persistent_vars, kept); !r) {
      return start_failure(a, r.error(), &s);
    }
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if (!kept[i].vacant) setup.variables.emplace_back(static_cast<int>(i) + 500, kept[i].v);
    }
    s.machine.persistent_vars.clear();
  }
  setup.machine = &s.machine;
  setup.dialect = &s.dialect;
  setup.params = s.params.get();
  setup.program_path = a.program;
  setup.program_name = a.program;
  setup.include_dirs = a.include;
  setup.dprnt_path = a.dprnt;
  setup.log_dir = a.log_dir;
  setup.strict = a.strict;

  // Offsets as the machine starts, to tell which ones the program wrote.
  const auto offsets = offset_variables(s.machine);
  std::vector<std::optional<double>> initial;
  {
    auto fresh = interp::Interpreter::create(setup, AxisVec{});
    if (!fresh) return start_failure(a, fresh.error(), &s);
    for (const auto& [number, label] : offsets) initial.push_back(read(**fresh, number));
  }

  const auto& probe = s.scene.probing.probe;
  const std::uint64_t seed0 =
      a.seed >= 0 ? static_cast<std::uint64_t>(a.seed) : (probe ? probe->seed : 1);
  std::vector<Series> series;
  std::map<std::string, std::size_t> by_name;
  auto add = [&](const std::string& name, const std::string& kind, std::uint32_t line, bool nominal,
                 double v) {
    auto it = by_name.find(name);
    if (it == by_name.end()) {
      it = by_name.emplace(name, series.size()).first;
      series.push_back(Series{name, kind, line, std::nullopt, {}});
    }
    Series& se = series[it->second];
    if (nominal) {
      se.nominal = v;
    } else {
      se.samples.push_back(v);
    }
  };
  std::vector<bool> written(offsets.size(), false);
  std::vector<std::vector<std::optional<double>>> offset_values(offsets.size());
  int alarms = 0;
  std::string first_alarm;
  int runs = a.repeat;
  // SIGTERM / SIGINT end the repetitions: the report keeps the runs that
  // finished, says "interrupted", and the exit status is 1 (was: the signal
  // was not heard until every run had ended).
  bool interrupted = false;
  sim::RunOptions opts;
  opts.interrupt = &run_stop().flag;
  for (int run = 0; run <= runs; ++run) {
    if (run_stop().flag.load(std::memory_order_relaxed)) {
      interrupted = true;
      runs = run > 0 ? run - 1 : 0;  // the scattered runs that finished
      break;
    }
    const bool nominal = run == 0;
    machine::Scene scene = s.scene;
    if (scene.probing.probe) {
      if (nominal) {
        scene.probing.probe->repeatability = 0.0;
      } else {
        scene.probing.probe->seed = seed0 + static_cast<std::uint64_t>(run - 1);
      }
    }
    sim::Simulator sim(s.machine, s.dialect, *s.params, scene);
    auto res = sim.run(setup, opts);
    if (!res) return start_failure(a, res.error(), &s);
    if (res->status == sim::RunStatus::kInterrupted) {
      interrupted = true;
      runs = run > 0 ? run - 1 : 0;  // this run is cut short: not counted
      break;
    }
    if (res->status != sim::RunStatus::kCompleted) {
      if (!nominal) ++alarms;
      if (first_alarm.empty() && res->alarm) {
        first_alarm = fmt::format("run {}: {}", run, run::describe(*res->alarm, &s.dialect));
      }
    }
    const interp::Interpreter& in = *sim.interpreter();
    for (std::size_t j = 0; j < res->skips.size(); ++j) {
      const auto& sk = res->skips[j];
      for (int i = 0; i < s.machine.axis_count(); ++i) {
        add(fmt::format("skip {} (line {}) {}", j + 1, sk.line,
                        s.machine.axes[static_cast<std::size_t>(i)].name),
            "skip", sk.line, nominal, sk.position[i]);
      }
    }
    for (const auto& v : vars) {
      auto val = v.name.empty() ? in.read_variable(v.number) : in.read_named(v.name);
      if (val && !val->vacant) add("#" + v.key, "variable", 0, nominal, val->v);
    }
    for (std::size_t k = 0; k < offsets.size(); ++k) {
      const auto v = read(in, offsets[k].first);
      offset_values[k].push_back(v);
      if (v != initial[k]) written[k] = true;
    }
  }
  for (std::size_t k = 0; k < offsets.size(); ++k) {
    if (!written[k]) continue;
    const std::string name = fmt::format("#{} {}", offsets[k].first, offsets[k].second);
    for (std::size_t run = 0; run < offset_values[k].size(); ++run) {
      if (offset_values[k][run]) add(name, "offset", 0, run == 0, *offset_values[k][run]);
    }
  }

  if (!a.quiet) {
    std::FILE* f = a.report == "-" ? stderr : stdout;
    fmt::print(f,
               "{}: {} runs with the probe's scatter (seeds {}..{}) and one without it (nominal)\n",
               a.program, runs, seed0, seed0 + static_cast<std::uint64_t>(runs) - 1);
    if (!probe || probe->repeatability == 0.0) {
      fmt::print(
          f, "  (the scene's probe has no repeatability scatter: every run is the nominal one)\n");
    }
    fmt::print(f, "  {:<32} {:>13} {:>13} {:>11} {:>13} {:>13} {:>11}\n", "value", "nominal",
               "mean", "std dev", "min", "max", "worst");
    for (const auto& se : series) {
      const Stats st = stats_of(se);
      fmt::print(f, "  {:<32} {:>13} {:>13.6f} {:>11.6f} {:>13.6f} {:>13.6f} {:>11.6f}\n", se.name,
                 se.nominal ? fmt::format("{:.6f}", *se.nominal) : std::string("-"), st.mean, st.sd,
                 st.min, st.max, st.worst);
    }
    fmt::print(f, "  worst: the largest |value - nominal| over the scattered runs\n");
    if (alarms > 0)
      fmt::print(f, "  {} of {} runs ended in an alarm; {}\n", alarms, runs, first_alarm);
  }
  if (!a.report.empty()) {
    std::string j = "{\n  \"format\": \"skipnc-repeat/1\",\n";
    j += "  \"program\": " + json_string(a.program) + ",\n";
    j += fmt::format("  \"runs\": {},\n  \"seed\": {},\n  \"alarms\": {},\n", runs, seed0, alarms);
    j += fmt::format("  \"interrupted\": {},\n", interrupted ? "true" : "false");
    j += "  \"values\": [";
    for (std::size_t i = 0; i < series.size(); ++i) {
      const Series& se = series[i];
      const Stats st = stats_of(se);
      j += i == 0 ? "\n" : ",\n";
      j += fmt::format(
          "    {{\"name\": {}, \"kind\": {}, \"line\": {}, \"count\": {}, \"nominal\": {}, "
          "\"mean\": {}, "
          "\"std\": {}, \"min\": {}, \"max\": {}, \"worst\": {}}}",
          json_string(se.name), json_string(se.kind), se.line, se.samples.size(),
          se.nominal ? json_number(*se.nominal) : "null", json_number(st.mean), json_number(st.sd),
          json_number(st.min), json_number(st.max), json_number(st.worst));
    }
    j += "\n  ]\n}\n";
    auto w = report::write_atomic(a.report, j);
    if (!w) {
      std::cerr << "skipnc: " << w.error().detail << "\n";
      return 1;
    }
  }
  return alarms > 0 || interrupted ? 1 : 0;
}

}  // namespace skipnc::cli
