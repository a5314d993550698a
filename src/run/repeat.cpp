#include "run/repeat.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/utf8.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/sysvar_table.hpp"
#include "run/program_run.hpp"
#include "sim/simulator.hpp"

namespace skipnc::run {
namespace {

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

// The offsets a program can write, as (variable, label): each work
// offset's variables in the dialect's numbering (offset_variables_by).
std::vector<std::pair<int, std::string>> offset_variables(const config::MachineConfig& m,
                                                          const config::Dialect& d) {
  std::vector<std::pair<int, std::string>> out;
  static const char* kSets[] = {"EXT", "G54", "G55", "G56", "G57", "G58", "G59"};
  std::string names;
  for (const auto& a : m.axes) names += a.name;
  const bool by_letter = d.sw.offset_variables_by == config::OffsetVariables::kLetter;
  for (int set = 0; set < 7; ++set) {
    for (int slot = 0; slot < 20; ++slot) {
      const int i = interp::sysvar::offset_slot_axis(
          by_letter, static_cast<int>(names.size()), slot, [&names](char letter) {
            const auto at = names.find(letter);
            return at == std::string::npos ? -1 : static_cast<int>(at);
          });
      if (i < 0) continue;
      out.emplace_back(5201 + 20 * set + slot,
                       fmt::format("{} {}", kSets[set], names[static_cast<std::size_t>(i)]));
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

// The series by name, in the order they first appear.
class Collector {
 public:
  void add(const std::string& name, const std::string& kind, std::uint32_t line, bool nominal,
           double v) {
    auto it = by_name_.find(name);
    if (it == by_name_.end()) {
      it = by_name_.emplace(name, series_.size()).first;
      series_.push_back(RepeatSeries{name, kind, line, std::nullopt, {}});
    }
    RepeatSeries& se = series_[it->second];
    if (nominal) {
      se.nominal = v;
    } else {
      se.samples.push_back(v);
    }
  }
  // The skips' positions and the reported variables of one run.
  void run(const Session& s, const RepeatRequest& rq, const sim::RunResult& r,
           const interp::Interpreter& in, bool nominal) {
    for (std::size_t j = 0; j < r.skips.size(); ++j) {
      const auto& sk = r.skips[j];
      for (int i = 0; i < s.machine.axis_count(); ++i) {
        add(fmt::format("skip {} (line {}) {}", j + 1, sk.line,
                        s.machine.axes[static_cast<std::size_t>(i)].name),
            "skip", sk.line, nominal, sk.position[i]);
      }
    }
    for (const auto& v : rq.program.vars) {
      auto val = v.name.empty() ? in.read_variable(v.number) : in.read_named(v.name);
      if (val && !val->vacant) add("#" + v.key, "variable", 0, nominal, val->v);
    }
  }
  std::vector<RepeatSeries> take() { return std::move(series_); }

 private:
  std::vector<RepeatSeries> series_;
  std::map<std::string, std::size_t> by_name_;
};

// The offsets a program wrote, followed over the runs.
class OffsetWatch {
 public:
  Result<void> start(const interp::Setup& setup) {
    offsets_ = offset_variables(*setup.machine, *setup.dialect);
    auto fresh = interp::Interpreter::create(setup, AxisVec{});
    SKIPNC_TRY(fresh);
    for (const auto& o : offsets_) initial_.push_back(read(**fresh, o.first));
    written_.assign(offsets_.size(), false);
    values_.resize(offsets_.size());
    return {};
  }
  void run(const interp::Interpreter& in) {
    for (std::size_t k = 0; k < offsets_.size(); ++k) {
      const auto v = read(in, offsets_[k].first);
      values_[k].push_back(v);
      if (v != initial_[k]) written_[k] = true;
    }
  }
  void add_to(Collector& c) const {
    for (std::size_t k = 0; k < offsets_.size(); ++k) {
      if (!written_[k]) continue;
      const std::string name = fmt::format("#{} {}", offsets_[k].first, offsets_[k].second);
      for (std::size_t run = 0; run < values_[k].size(); ++run) {
        if (values_[k][run]) c.add(name, "offset", 0, run == 0, *values_[k][run]);
      }
    }
  }

 private:
  std::vector<std::pair<int, std::string>> offsets_;
  std::vector<std::optional<double>> initial_;
  std::vector<bool> written_;
  std::vector<std::vector<std::optional<double>>> values_;
};

}  // namespace

RepeatStats stats_of(const RepeatSeries& s) {
  RepeatStats st;
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

Result<RepeatOutcome> repeat_runs(const Session& s, const RepeatRequest& rq,
                                  const std::atomic<bool>* interrupt) {
  config::MachineConfig m = s.machine;
  // Every repetition starts from the same #500-#999 (the file's) and none
  // writes them back: the scatter is the probe's alone.
  std::vector<std::pair<int, double>> variables;
  SKIPNC_TRY(take_persistent(m, variables));
  variables.insert(variables.end(), rq.variables.begin(), rq.variables.end());
  RunIO io;
  io.interrupt = interrupt;
  io.dprnt_path = rq.dprnt_path;
  const interp::Setup setup = make_setup(s, Rig{&m, &s.dialect, s.params.get(), &s.scene},
                                         rq.program, io, std::move(variables));
  OffsetWatch offsets;  // offsets as the machine starts, to tell which ones the program wrote
  SKIPNC_TRY(offsets.start(setup));

  const auto& probe = s.scene.probing.probe;
  RepeatOutcome out;
  out.seed = rq.seed ? *rq.seed : (probe ? probe->seed : 1);
  out.scatter = probe && probe->repeatability != 0.0;
  out.runs = rq.runs;
  Collector series;
  for (int run = 0; run <= rq.runs; ++run) {
    if (interrupt != nullptr && interrupt->load(std::memory_order_relaxed)) {
      out.interrupted = true;
      out.runs = run > 0 ? run - 1 : 0;  // the scattered runs that finished
      break;
    }
    const bool nominal = run == 0;
    machine::Scene scene = s.scene;
    if (scene.probing.probe) {
      if (nominal) {
        scene.probing.probe->repeatability = 0.0;
      } else {
        scene.probing.probe->seed = out.seed + static_cast<std::uint64_t>(run - 1);
      }
    }
    ProgramRun pr(Rig{&m, &s.dialect, s.params.get(), &scene}, setup, io, false);
    auto res = pr.run();
    SKIPNC_TRY(res);
    if (res->status == sim::RunStatus::kInterrupted) {
      out.interrupted = true;
      out.runs = run > 0 ? run - 1 : 0;  // this run is cut short: not counted
      break;
    }
    out.log.push_back(RepeatRun{run, nominal ? 0 : out.seed + static_cast<std::uint64_t>(run - 1),
                                res->time_s, res->status != sim::RunStatus::kCompleted,
                                res->alarm ? describe(*res->alarm, &s.dialect) : std::string()});
    if (res->status != sim::RunStatus::kCompleted) {
      if (!nominal) ++out.alarms;
      if (out.first_alarm.empty() && res->alarm) {
        out.first_alarm = fmt::format("run {}: {}", run, describe(*res->alarm, &s.dialect));
      }
    }
    series.run(s, rq, *res, pr.interpreter(), nominal);
    offsets.run(pr.interpreter());
  }
  offsets.add_to(series);
  out.series = series.take();
  return out;
}

std::string repeat_json(const RepeatOutcome& o, const std::string& program) {
  std::string j = "{\n  \"format\": \"skipnc-repeat/1\",\n";
  j += "  \"program\": " + json_string(program) + ",\n";
  j += fmt::format("  \"runs\": {},\n  \"seed\": {},\n  \"alarms\": {},\n", o.runs, o.seed,
                   o.alarms);
  j += fmt::format("  \"interrupted\": {},\n", o.interrupted ? "true" : "false");
  j += "  \"values\": [";
  for (std::size_t i = 0; i < o.series.size(); ++i) {
    const RepeatSeries& se = o.series[i];
    const RepeatStats st = stats_of(se);
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
  return j;
}

}  // namespace skipnc::run
