// The sweep spec's check (run/sweep.hpp), apart from targets.hpp because it
// needs the run library: fuzz_sweep and tests/regression use it.
#pragma once

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run/sweep.hpp"
#include "targets.hpp"

namespace skipnc::fuzz {

// A sweep spec (beside a short probing program p.nc): a refusal is a config
// or usage error; a spec that loads runs up to three scenarios, each row has
// a known status, and the tables are whole (the CSV one line per row, the
// JSON valid with as many rows and the summary's counts adding up).
inline std::string check_sweep(std::string_view data) {
  static const std::string dir = [] {
    std::string tmpl =
        (std::filesystem::temp_directory_path() / "skipnc-fuzz-sweep-XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr) std::abort();
    std::ofstream(std::filesystem::path(tmpl) / "p.nc") << kProbeProgram;
    return tmpl;
  }();
  const std::string spec = (std::filesystem::path(dir) / "s.sweep.toml").string();
  std::ofstream(spec, std::ios::binary | std::ios::trunc) << data;
  run::SweepPlan plan;
  if (auto r = run::load_sweep(spec, {}, plan); !r) {
    const AlarmId id = r.error().id;
    if (id != AlarmId::kConfig && id != AlarmId::kUsage && id != AlarmId::kFileAccess)
      return "sweep spec error of kind " + std::string(alarm_key(id));
    return {};
  }
  plan.scenarios = std::min<std::int64_t>(plan.scenarios, 3);
  plan.session.machine.limits.max_ticks = kMaxFileTicks;
  plan.session.machine.limits.max_macro_statements = kMaxStatements;
  const auto rows = run::run_scenarios(plan, 0, plan.scenarios, 1);
  if (static_cast<std::int64_t>(rows.size()) != plan.scenarios) return "rows missing";
  for (const auto& r : rows) {
    if (r.status != "completed" && r.status != "alarm" && r.status != "interrupted" &&
        r.status != "error")
      return "row status '" + r.status + "'";
    if (r.pass && r.status == "error") return "an error row passed";
  }
  const std::string csv = run::sweep_csv(plan, rows);
  if (std::count(csv.begin(), csv.end(), '\n') != static_cast<std::ptrdiff_t>(rows.size()) + 1 &&
      csv.find('"') == std::string::npos) {
    return "CSV lines != rows + 1";
  }
  const auto j = nlohmann::json::parse(run::sweep_json(plan, rows), nullptr, false);
  if (j.is_discarded()) return "sweep JSON not valid";
  const auto& sum = j["summary"];
  if (j["rows"].size() != rows.size()) return "JSON rows != rows";
  if (sum["passed"].get<std::int64_t>() + sum["failed"].get<std::int64_t>() +
          sum["errors"].get<std::int64_t>() + sum["not_run"].get<std::int64_t>() !=
      static_cast<std::int64_t>(rows.size())) {
    return "summary counts do not add up";
  }
  return {};
}

}  // namespace skipnc::fuzz
