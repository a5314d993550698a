// The Python module's native part (skipnc._skipnc): one run through the run
// library (run/scenario.hpp, run/repeat.hpp), the report as the command line
// writes it, the trace as columns named as the CSV trace's; sweeps by
// scenario range, as tables of named columns. python/skipnc/__init__.py is
// the interface users see.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/report.hpp"
#include "run/expect.hpp"
#include "run/repeat.hpp"
#include "run/scenario.hpp"
#include "run/session.hpp"
#include "run/sweep.hpp"

namespace py = pybind11;
using namespace skipnc;

namespace {

// A start error (configuration, usage, unreadable program): the CLI's text,
// file:line:column first.
class StartError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void raise(const Error& e, const config::Dialect* d) {
  throw StartError(run::describe(e, d));
}

template <typename T>
py::array_t<T> to_array(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// The trace as columns, those of the CSV trace (report::TraceColumns): the
// numbers as float64 arrays; `file` as indexes into the distinct file names.
class ColumnTrace final : public sim::TraceSink {
 public:
  explicit ColumnTrace(const config::MachineConfig& m) : m_(m) {}
  void row(const sim::TraceRow& r) override {
    if (cols_.empty()) {
      layout_ = report::TraceColumns::of(m_, r);
      cols_.resize(layout_.names.size() - 1);
    }
    layout_.numbers(r, values_);
    for (std::size_t i = 0; i < values_.size(); ++i) cols_[i].push_back(values_[i]);
    if (files_.empty() || r.file != files_[last_file_]) {
      auto it = std::find(files_.begin(), files_.end(), r.file);
      if (it == files_.end()) it = files_.insert(files_.end(), std::string(r.file));
      last_file_ = static_cast<std::size_t>(it - files_.begin());
    }
    file_.push_back(static_cast<std::int32_t>(last_file_));
  }
  // (names, {name: array}, file names); the `file` entry is the indexes.
  py::tuple columns() const {
    py::dict out;
    std::size_t c = 0;
    for (std::size_t i = 0; i < layout_.names.size(); ++i) {
      if (i == report::TraceColumns::kFile) {
        out[py::str(layout_.names[i])] = to_array(file_);
      } else {
        out[py::str(layout_.names[i])] = to_array(cols_[c++]);
      }
    }
    return py::make_tuple(layout_.names, out, files_);
  }

 private:
  const config::MachineConfig& m_;
  report::TraceColumns layout_;
  std::vector<std::vector<double>> cols_;
  std::vector<double> values_;
  std::vector<std::int32_t> file_;
  std::vector<std::string> files_;
  std::size_t last_file_ = 0;
};

// What run() and repeat() share: the session and the program.
struct RunSpec {
  std::string program, program_text, machine, machine_text, scene, scene_text, dialect;
  std::vector<std::string> params, include, vars;
};

void open(const RunSpec& spec, run::Session& s) {
  const run::SessionOptions o{spec.machine, spec.dialect, spec.scene, spec.params};
  if (auto r = run::open_session(o, {spec.machine_text, spec.scene_text}, s); !r) {
    raise(r.error(), s.dialect.name.empty() ? nullptr : &s.dialect);
  }
}

std::vector<run::VarRef> var_refs(const std::vector<std::string>& vars, const run::Session& s) {
  std::vector<run::VarRef> out;
  for (const auto& v : vars) {
    auto r = run::parse_var_ref(v);
    if (!r) raise(r.error(), &s.dialect);
    out.push_back(*r);
  }
  return out;
}

run::RunRequest request_of(const RunSpec& spec, const run::Session& s, bool strict) {
  run::RunRequest rq;
  rq.program_path = spec.program;
  rq.program_text = spec.program_text;
  rq.program_name = spec.program.empty() ? std::string("program") : spec.program;
  rq.include_dirs = spec.include;
  rq.vars = var_refs(spec.vars, s);
  rq.strict = strict;
  return rq;
}

py::dict run_program(const RunSpec& spec, const std::vector<std::pair<int, double>>& variables,
                     bool trace, bool strict, const std::vector<std::string>& expect,
                     const std::vector<std::string>& plot) {
  run::Session s;
  open(spec, s);
  run::RunRequest rq = request_of(spec, s, strict);
  rq.plot_files = plot;
  for (const auto& text : expect) {
    auto e = run::parse_expectation(text);
    if (!e) raise(e.error(), &s.dialect);
    rq.expect.push_back(*e);
  }
  run::Variation var;
  var.variables = variables;
  std::unique_ptr<ColumnTrace> columns;
  if (trace) columns = std::make_unique<ColumnTrace>(s.machine);
  Result<run::RunOutcome> res;
  {
    py::gil_scoped_release unlocked;
    res = run::run_variation(s, rq, var, columns.get());
  }
  if (!res) raise(res.error(), &s.dialect);
  py::dict out;
  out["report"] = res->report_json;
  out["trace"] = columns ? py::object(columns->columns()) : py::object(py::none());
  out["exit_code"] = res->exit_code;
  out["failed"] = res->failed_expectations;
  return out;
}

py::dict repeat_program(const RunSpec& spec, const std::vector<std::pair<int, double>>& variables,
                        bool strict, int runs, std::optional<std::uint64_t> seed) {
  run::Session s;
  open(spec, s);
  run::RepeatRequest rq;
  rq.program = request_of(spec, s, strict);
  rq.runs = runs;
  rq.seed = seed;
  rq.variables = variables;
  Result<run::RepeatOutcome> res;
  {
    py::gil_scoped_release unlocked;
    res = run::repeat_runs(s, rq);
  }
  if (!res) raise(res.error(), &s.dialect);
  py::dict out;
  out["report"] = run::repeat_json(*res, rq.program.program_name);
  out["exit_code"] = res->exit_code();
  return out;
}

// A loaded sweep spec; scenarios can be run by range, anywhere. Rows travel
// as a table: a dict of NumPy arrays keyed by column name (sweep_columns).
class Sweep {
 public:
  Sweep(const std::string& spec, std::optional<std::int64_t> scenarios,
        std::optional<std::uint64_t> seed) {
    run::SweepOverrides o;
    o.scenarios = scenarios;
    o.seed = seed;
    if (auto r = run::load_sweep(spec, o, plan_); !r) {
      raise(r.error(), plan_.session.dialect.name.empty() ? nullptr : &plan_.session.dialect);
    }
    columns_ = {"scenario", "probe_seed", "status", "alarm", "alarm_text"};
    for (const auto& r : plan_.vary) columns_.push_back(r.name);
    for (const auto& v : plan_.request.vars) {
      // A variable both varied and reported: its value after the run.
      const std::string name = "#" + v.key;
      columns_.push_back(std::find(columns_.begin(), columns_.end(), name) == columns_.end()
                             ? name
                             : name + " (end)");
    }
    for (const auto& c : plan_.checks) columns_.push_back(c.e.text);
    columns_.insert(columns_.end(), {"pass", "time_s"});
  }
  std::int64_t count() const { return plan_.scenarios; }
  std::uint64_t seed() const { return plan_.seed; }
  int workers() const { return plan_.workers; }
  const std::vector<std::string>& columns() const { return columns_; }
  py::dict run(std::int64_t begin, std::int64_t end, int workers) const {
    if (begin < 0 || end > plan_.scenarios || begin > end) {
      throw std::out_of_range("scenarios are 0.." + std::to_string(plan_.scenarios));
    }
    std::vector<run::ScenarioRow> rows;
    {
      py::gil_scoped_release unlocked;
      rows = run::run_scenarios(plan_, begin, end, workers);
    }
    return table_of(rows);
  }
  std::string csv(const py::dict& t) const { return run::sweep_csv(plan_, rows_of(t)); }
  std::string json(const py::dict& t) const { return run::sweep_json(plan_, rows_of(t)); }
  std::string summary(const py::dict& t) const {
    return run::sweep_summary_text(plan_, rows_of(t));
  }
  std::vector<std::string> vary() const {
    std::vector<std::string> out;
    for (const auto& r : plan_.vary) out.push_back(r.name);
    return out;
  }
  std::vector<std::string> variables() const {
    std::vector<std::string> out;
    for (const auto& v : plan_.request.vars) out.push_back(v.key);
    return out;
  }
  std::vector<std::string> expect() const {
    std::vector<std::string> out;
    for (const auto& c : plan_.checks) out.push_back(c.e.text);
    return out;
  }

 private:
  py::dict table_of(const std::vector<run::ScenarioRow>& rows) const;
  std::vector<run::ScenarioRow> rows_of(const py::dict& t) const;
  run::SweepPlan plan_;
  std::vector<std::string> columns_;
};

py::dict Sweep::table_of(const std::vector<run::ScenarioRow>& rows) const {
  const std::size_t nv = plan_.vary.size(), nr = plan_.request.vars.size();
  std::vector<std::int64_t> index, alarm;
  std::vector<std::uint64_t> seeds;
  std::vector<double> time;
  std::vector<std::string> status, alarm_text;
  std::vector<std::vector<double>> num(nv + nr);
  std::vector<std::vector<bool>> checks(plan_.checks.size() + 1);  // the last: pass
  for (const auto& r : rows) {
    index.push_back(r.index);
    seeds.push_back(r.probe_seed);
    status.push_back(r.status);
    alarm.push_back(r.alarm);
    alarm_text.push_back(r.alarm_text);
    for (std::size_t k = 0; k < nv; ++k) num[k].push_back(r.chosen[k]);
    for (std::size_t k = 0; k < nr; ++k) {
      num[nv + k].push_back(r.values[k] ? *r.values[k] : std::nan(""));
    }
    for (std::size_t k = 0; k < plan_.checks.size(); ++k) checks[k].push_back(r.checks[k]);
    checks.back().push_back(r.pass);
    time.push_back(r.time_s);
  }
  auto np = py::module_::import("numpy");
  auto strings = [&](const std::vector<std::string>& v) {
    return np.attr("array")(v, py::arg("dtype") = "str");
  };
  auto bools = [&](const std::vector<bool>& v) {
    py::array_t<bool> a(static_cast<py::ssize_t>(v.size()));
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
  };
  py::dict t;
  std::size_t c = 0;
  t[py::str(columns_[c++])] = to_array(index);
  t[py::str(columns_[c++])] = to_array(seeds);
  t[py::str(columns_[c++])] = strings(status);
  t[py::str(columns_[c++])] = to_array(alarm);
  t[py::str(columns_[c++])] = strings(alarm_text);
  for (const auto& col : num) t[py::str(columns_[c++])] = to_array(col);
  for (const auto& col : checks) t[py::str(columns_[c++])] = bools(col);
  t[py::str(columns_[c++])] = to_array(time);
  return t;
}

std::vector<run::ScenarioRow> Sweep::rows_of(const py::dict& t) const {
  for (const auto& name : columns_) {
    if (!t.contains(name)) {
      throw std::invalid_argument("a table of another sweep (no column '" + name + "')");
    }
  }
  auto np = py::module_::import("numpy");
  auto col = [&](const std::string& name) {
    return py::list(np.attr("asarray")(t[py::str(name)]).attr("tolist")());
  };
  const std::size_t n = py::len(t[py::str("scenario")]);
  std::vector<run::ScenarioRow> rows(n);
  std::vector<py::list> cols;
  for (const auto& name : columns_) {
    cols.push_back(col(name));
    if (cols.back().size() != n)
      throw std::invalid_argument("column '" + name + "' is not " + std::to_string(n) + " long");
  }
  const std::size_t nv = plan_.vary.size(), nr = plan_.request.vars.size();
  for (std::size_t i = 0; i < n; ++i) {
    run::ScenarioRow& r = rows[i];
    std::size_t c = 0;
    r.index = cols[c++][i].cast<std::int64_t>();
    r.probe_seed = cols[c++][i].cast<std::uint64_t>();
    r.status = cols[c++][i].cast<std::string>();
    r.alarm = cols[c++][i].cast<int>();
    r.alarm_text = cols[c++][i].cast<std::string>();
    for (std::size_t k = 0; k < nv; ++k) r.chosen.push_back(cols[c++][i].cast<double>());
    for (std::size_t k = 0; k < nr; ++k) {
      const double x = cols[c++][i].cast<double>();
      r.values.push_back(std::isnan(x) ? std::nullopt : std::optional<double>(x));
    }
    for (std::size_t k = 0; k < plan_.checks.size(); ++k)
      r.checks.push_back(cols[c++][i].cast<bool>());
    r.pass = cols[c++][i].cast<bool>();
    r.time_s = cols[c++][i].cast<double>();
  }
  return rows;
}

constexpr const char* kRunDoc = R"(run(spec, variables, trace, strict, expect, plot) -> dict

One run of a program (the native half of skipnc.run; use that). spec is
(program, program_text, machine, machine_text, scene, scene_text, dialect,
params, include, vars). Returns {"report": JSON text, "trace": (names,
columns, file names) or None, "exit_code": int, "failed": [str]}. Raises
StartError when the run cannot start.)";

constexpr const char* kRepeatDoc = R"(repeat(spec, variables, strict, runs, seed) -> dict

The runs of `skipnc run --repeat` (the native half of skipnc.run(repeat=N)):
{"report": the skipnc-repeat/1 JSON text, "exit_code": int}.)";

constexpr const char* kSweepDoc = R"(A sweep spec (docs/cli.md, `skipnc sweep`), loaded and checked.

Sweep(spec, scenarios=None, seed=None): scenarios and seed override the
spec's. Its scenarios can be run by range, anywhere (a scenario's values
depend only on the seed and its index); run() gives a table, a dict of NumPy
arrays keyed by the names in `columns` (those of the CSV table, plus
alarm_text); csv(), json() and summary() write a table exactly as the
command does.)";

}  // namespace

PYBIND11_MODULE(_skipnc, m) {
  m.doc() = "skipnc's native module (use the skipnc package: help(skipnc)).";
  m.attr("__version__") = SKIPNC_VERSION;
  py::register_exception<StartError>(m, "StartError", PyExc_ValueError).doc() =
      "The run cannot start (exit status 2 on the command line): a bad machine, scene, "
      "parameter, expectation or program. The text is the command line's message, with file, "
      "line and column. A ValueError.";
  py::class_<RunSpec>(m, "RunSpec", "What a run loads (internal to skipnc.run).")
      .def(py::init<>())
      .def_readwrite("program", &RunSpec::program)
      .def_readwrite("program_text", &RunSpec::program_text)
      .def_readwrite("machine", &RunSpec::machine)
      .def_readwrite("machine_text", &RunSpec::machine_text)
      .def_readwrite("scene", &RunSpec::scene)
      .def_readwrite("scene_text", &RunSpec::scene_text)
      .def_readwrite("dialect", &RunSpec::dialect)
      .def_readwrite("params", &RunSpec::params)
      .def_readwrite("include", &RunSpec::include)
      .def_readwrite("vars", &RunSpec::vars);
  m.def("run", &run_program, kRunDoc, py::arg("spec"), py::arg("variables"), py::arg("trace"),
        py::arg("strict"), py::arg("expect"), py::arg("plot"));
  m.def("repeat", &repeat_program, kRepeatDoc, py::arg("spec"), py::arg("variables"),
        py::arg("strict"), py::arg("runs"), py::arg("seed"));
  py::class_<Sweep>(m, "Sweep", kSweepDoc)
      .def(
          py::init<const std::string&, std::optional<std::int64_t>, std::optional<std::uint64_t>>(),
          py::arg("spec"), py::arg("scenarios") = py::none(), py::arg("seed") = py::none())
      .def_property_readonly("count", &Sweep::count, "Number of scenarios.")
      .def_property_readonly("seed", &Sweep::seed, "Seed of the draws.")
      .def_property_readonly("workers", &Sweep::workers, "The spec's workers (0: every core).")
      .def_property_readonly("vary", &Sweep::vary, "Names of the varied quantities, in order.")
      .def_property_readonly("variables", &Sweep::variables, "The reported variables' keys.")
      .def_property_readonly("expect", &Sweep::expect, "The spec's checks, as written.")
      .def_property_readonly("columns", &Sweep::columns,
                             "The table's column names, in order: scenario, probe_seed, status, "
                             "alarm (0: none), alarm_text, each varied quantity, each reported "
                             "variable as '#<key>' (NaN: vacant; '#<key> (end)' when that name "
                             "is also varied), each check (bool), pass, time_s.")
      .def("run", &Sweep::run,
           "run(begin, end, workers=1) -> dict: scenarios begin..end-1 on `workers` threads "
           "(0: every core), as a table (a dict of NumPy arrays keyed by `columns`).",
           py::arg("begin"), py::arg("end"), py::arg("workers") = 1)
      .def("csv", &Sweep::csv, "csv(table) -> str: the CSV table `skipnc sweep` writes.",
           py::arg("table"))
      .def("json", &Sweep::json, "json(table) -> str: the JSON table `skipnc sweep` writes.",
           py::arg("table"))
      .def("summary", &Sweep::summary, "summary(table) -> str: the summary `skipnc sweep` prints.",
           py::arg("table"));
}
