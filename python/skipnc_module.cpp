// The Python module's native part (skipnc._skipnc): one run through the same
// path as `skipnc sweep` (run/scenario.hpp), the report as the CLI writes it,
// the trace as columns; sweeps by scenario range. python/skipnc/__init__.py
// is the interface users see.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "config/skip_inputs.hpp"
#include "report/report.hpp"
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

// The trace as columns, named as the CSV trace's header.
class ColumnTrace final : public sim::TraceSink {
 public:
  explicit ColumnTrace(const config::MachineConfig& m) : m_(m) {}
  void row(const sim::TraceRow& r) override {
    const int n = m_.axis_count();
    if (cols_.empty()) {
      names_ = {"time_s", "line", "feed_mm_min"};
      for (const char* kind : {"cmd", "act", "ferr", "torque"}) {
        for (const auto& a : m_.axes) names_.push_back(std::string(1, a.name) + "_" + kind);
      }
      signals_ = r.plant != nullptr ? r.plant->signal_count() : 0;
      for (std::size_t i = 0; i < signals_; ++i) {
        names_.push_back(config::signal_name(r.plant->signal_addr(i)));
      }
      cols_.resize(names_.size());
    }
    std::size_t c = 0;
    cols_[c++].push_back(r.time_s);
    cols_[c++].push_back(static_cast<double>(r.line));
    cols_[c++].push_back(r.feed_mm_per_min);
    const AxisVec ferr = *r.commanded - *r.actual;
    for (const AxisVec* v : {r.commanded, r.actual, &ferr, r.torque}) {
      for (int i = 0; i < n; ++i) cols_[c++].push_back((*v)[i]);
    }
    for (std::size_t i = 0; i < signals_; ++i) {
      cols_[c++].push_back(r.plant->signal_level(i) ? 1.0 : 0.0);
    }
  }
  py::dict arrays() const {
    py::dict out;
    for (std::size_t i = 0; i < names_.size(); ++i) {
      const auto& col = cols_[i];
      py::array_t<double> a(static_cast<py::ssize_t>(col.size()));
      std::copy(col.begin(), col.end(), a.mutable_data());
      out[py::str(names_[i])] = std::move(a);
    }
    return out;
  }

 private:
  const config::MachineConfig& m_;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> cols_;
  std::size_t signals_ = 0;
};

// run_program() (_skipnc.run): the JSON report text and the trace columns (None without trace).
py::tuple run_program(const std::string& program, const std::string& program_text,
                      const std::string& machine, const std::string& scene,
                      const std::string& dialect, const std::vector<std::string>& params,
                      const std::vector<std::pair<int, double>>& variables,
                      const std::vector<std::string>& include, const std::vector<std::string>& vars,
                      bool trace) {
  run::Session s;
  if (auto o = run::open_session(run::SessionOptions{machine, dialect, scene, params}, s); !o) {
    raise(o.error(), s.dialect.name.empty() ? nullptr : &s.dialect);
  }
  run::RunRequest rq;
  rq.program_path = program;
  rq.program_text = program_text;
  rq.program_name = program.empty() ? std::string("program") : program;
  rq.include_dirs = include;
  for (const auto& v : vars) {
    auto r = run::parse_var_ref(v);
    if (!r) raise(r.error(), &s.dialect);
    rq.vars.push_back(*r);
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
  return py::make_tuple(res->report_json,
                        columns ? py::object(columns->arrays()) : py::object(py::none()),
                        res->exit_code);
}

py::dict row_to_dict(const run::ScenarioRow& r) {
  py::dict d;
  d["scenario"] = r.index;
  d["probe_seed"] = r.probe_seed;
  d["status"] = r.status;
  d["alarm"] = r.alarm;
  d["alarm_text"] = r.alarm_text;
  d["chosen"] = r.chosen;
  d["values"] = r.values;
  d["checks"] = r.checks;
  d["pass"] = r.pass;
  d["time"] = r.time_s;
  return d;
}

run::ScenarioRow row_from_dict(const py::dict& d) {
  run::ScenarioRow r;
  r.index = d["scenario"].cast<std::int64_t>();
  r.probe_seed = d["probe_seed"].cast<std::uint64_t>();
  r.status = d["status"].cast<std::string>();
  r.alarm = d["alarm"].cast<int>();
  r.alarm_text = d["alarm_text"].cast<std::string>();
  r.chosen = d["chosen"].cast<std::vector<double>>();
  r.values = d["values"].cast<std::vector<std::optional<double>>>();
  r.checks = d["checks"].cast<std::vector<bool>>();
  r.pass = d["pass"].cast<bool>();
  r.time_s = d["time"].cast<double>();
  return r;
}

std::vector<run::ScenarioRow> rows_from(const py::list& rows, const run::SweepPlan& plan) {
  std::vector<run::ScenarioRow> out;
  for (const auto& item : rows) {
    out.push_back(row_from_dict(item.cast<py::dict>()));
    const auto& r = out.back();
    if (r.chosen.size() != plan.vary.size() || r.values.size() != plan.request.vars.size() ||
        r.checks.size() != plan.checks.size()) {
      throw std::invalid_argument("a row of another sweep (its columns differ)");
    }
  }
  return out;
}

// A loaded sweep spec; scenarios can be run by range, anywhere.
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
  }
  std::int64_t count() const { return plan_.scenarios; }
  std::uint64_t seed() const { return plan_.seed; }
  int workers() const { return plan_.workers; }
  py::list run(std::int64_t begin, std::int64_t end, int workers) const {
    if (begin < 0 || end > plan_.scenarios || begin > end) {
      throw std::out_of_range("scenarios are 0.." + std::to_string(plan_.scenarios));
    }
    std::vector<run::ScenarioRow> rows;
    {
      py::gil_scoped_release unlocked;
      rows = run::run_scenarios(plan_, begin, end, workers);
    }
    py::list out;
    for (const auto& r : rows) out.append(row_to_dict(r));
    return out;
  }
  std::string csv(const py::list& rows) const {
    return run::sweep_csv(plan_, rows_from(rows, plan_));
  }
  std::string json(const py::list& rows) const {
    return run::sweep_json(plan_, rows_from(rows, plan_));
  }
  std::string summary(const py::list& rows) const {
    return run::sweep_summary_text(plan_, rows_from(rows, plan_));
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
    for (const auto& c : plan_.checks) out.push_back(c.text);
    return out;
  }

 private:
  run::SweepPlan plan_;
};

}  // namespace

PYBIND11_MODULE(_skipnc, m) {
  m.doc() = "skipnc native module (use the skipnc package)";
  py::register_exception<StartError>(m, "StartError", PyExc_ValueError);
  m.def("run", &run_program, py::arg("program"), py::arg("program_text"), py::arg("machine"),
        py::arg("scene"), py::arg("dialect"), py::arg("params"), py::arg("variables"),
        py::arg("include"), py::arg("vars"), py::arg("trace"));
  py::class_<Sweep>(m, "Sweep")
      .def(
          py::init<const std::string&, std::optional<std::int64_t>, std::optional<std::uint64_t>>(),
          py::arg("spec"), py::arg("scenarios") = py::none(), py::arg("seed") = py::none())
      .def_property_readonly("count", &Sweep::count)
      .def_property_readonly("seed", &Sweep::seed)
      .def_property_readonly("workers", &Sweep::workers)
      .def_property_readonly("vary", &Sweep::vary)
      .def_property_readonly("variables", &Sweep::variables)
      .def_property_readonly("expect", &Sweep::expect)
      .def("run", &Sweep::run, py::arg("begin"), py::arg("end"), py::arg("workers") = 1)
      .def("csv", &Sweep::csv)
      .def("json", &Sweep::json)
      .def("summary", &Sweep::summary);
}
