// Property (one value, one number): for random runs with skips, the
// report's skips[].position is the very number the program reads from
// #5061-#5063 (on CompassNC #<NC.SysVars.G31.LCS.X/Y/Z>), bit for bit, in
// the run's record and in the JSON report alike; on the dialects whose
// control counts positions in least input increments
// (skip_position_increment: fanuc, nct, mitsubishi) that number is a whole
// number of increments (0.001 mm, 0.0001 inch), elsewhere the latch as it
// came (docs/position-variables.md).
//
// A random dialect, G20 or G21, a random G54 offset, a tool length offset
// (G43 H1-H3) or none, a G31 in a random direction at a random feed to a
// trigger plane on the way; the program copies the skip position into
// #101-#103 right after the G31 (as a macro does).
//
// Seed and count: RC_PARAMS="seed=7 max_success=10000".
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "config/skip_inputs.hpp"
#include "machine/scene.hpp"
#include "property/program_gen.hpp"
#include "report/report.hpp"
#include "sim/simulator.hpp"

namespace skipnc::property {
namespace {

std::string skip_var(const std::string& dialect, int axis) {
  if (dialect == "compass") return std::string("#<NC.SysVars.G31.LCS.") + "XYZ"[axis] + ">";
  return "#" + std::to_string(5061 + axis);
}

struct SkipRun {
  std::string program;
  std::string scene_text;
};

SkipRun random_skip_run(const std::string& dialect, Machine& m, bool inch) {
  const double unit = inch ? 25.4 : 1.0;
  AxisVec target;
  double len = 0.0;
  do {
    // 4-25 mm long in either unit (in inch: -0.98 to 0.98).
    for (int i = 0; i < 3; ++i) target[i] = gen_real(-25, 25, 5000) / unit;
    len = std::sqrt(target[0] * target[0] + target[1] * target[1] + target[2] * target[2]);
  } while (len * unit < 4.0);
  int axis = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::fabs(target[i]) > std::fabs(target[axis])) axis = i;
  }
  // Machine coordinates of the plane: the G54 shift plus a random point
  // of the way, to 1e-7 mm (between increments). The Fanuc family keeps
  // the offsets' numbers in the input unit in force (docs/time-and-units.md):
  // under G20 the machine file's G54 and H numbers are inches.
  AxisVec shift;
  for (int i = 0; i < 3; ++i) shift[i] = gen_real(-50, 50, 1000) / unit;
  m.machine.work_offsets[1] = shift;  // G54
  const int h = *rc::gen::inRange(0, inch ? 2 : 4);
  // G43 Hh moves Z by its length (Machine: the number 10 h).
  const double length = axis == 2 && h > 0 ? 10.0 * h : 0.0;
  const double at = (shift[axis] + length) * unit + target[axis] * gen_real(0.1, 0.8, 70) * unit;
  SkipRun r;
  r.scene_text = std::string("[[trigger]]\nsignal = \"SKIP\"\naxis = \"") + "XYZ"[axis] +
                 "\"\nat = " + num(at, 7) + "\ndirection = \"" +
                 (target[axis] < 0 ? "decreasing" : "increasing") + "\"\n";
  const double feed = gen_real(30, 3000, 297);
  r.program = std::string(inch ? "G20" : "G21") + " G90 G54\n" +
              (h > 0 ? "G43 H" + std::to_string(h) + " " : std::string()) + "G0 X0 Y0 Z0\n" +
              "G31 X" + num(target[0], 4) + " Y" + num(target[1], 4) + " Z" + num(target[2], 4) +
              " F" + num(feed, 1) + "\n";
  for (int i = 0; i < 3; ++i) {
    r.program += "#" + std::to_string(101 + i) + " = " + skip_var(dialect, i) + "\n";
  }
  r.program += "M30\n";
  return r;
}

RC_GTEST_PROP(SkipReportEqualsVariable, ReportPositionIsTheNumberTheProgramReads, ()) {
  const std::string dialect =
      *rc::gen::elementOf(std::vector<std::string>{"fanuc", "nct", "mitsubishi", "compass"});
  Machine m(dialect);
  const bool inch = *rc::gen::arbitrary<bool>();
  RC_ASSERT(config::check_skip_addresses(m.dialect, *m.params).has_value());
  const SkipRun sr = random_skip_run(dialect, m, inch);
  auto scene =
      machine::parse_scene(sr.scene_text, "prop.scene.toml", m.machine, m.dialect, *m.params);
  RC_ASSERT(scene.has_value());
  sim::Simulator sim(m.machine, m.dialect, *m.params, *scene);
  auto run = sim.run(m.setup(sr.program), {});
  RC_ASSERT(run.has_value());
  if (run->status != sim::RunStatus::kCompleted || run->skips.size() != 1u ||
      !run->skips.front().triggered) {
    RC_FAIL("the run did not end with one touch: " +
            (run->alarm ? run->alarm->detail : std::string("no alarm")) + "\n" + sr.program +
            sr.scene_text);
  }
  const interp::SkipRecord& sk = run->skips.front();

  report::ReportInput in;
  in.program = "gen.nc";
  in.dialect = dialect;
  in.machine = &m.machine;
  in.dialect_table = &m.dialect;
  in.result = *run;
  const double inc = inch ? 0.0001 : 0.001;
  for (int i = 0; i < 3; ++i) {
    auto v = sim.interpreter()->read_variable(101 + i);
    RC_ASSERT(v.has_value());
    RC_ASSERT(!v->vacant);
    // The record and the variable: the same double.
    if (v->v != sk.position[i]) {
      RC_FAIL("axis " + std::to_string(i) + ": record " + num(sk.position[i], 12) + ", " +
              skip_var(dialect, i) + " " + num(v->v, 12) + "\n" + sr.program + sr.scene_text);
    }
    if (m.dialect.sw.skip_position_increment) {
      const double steps = v->v / inc;
      RC_ASSERT(std::fabs(steps - std::round(steps)) < 1e-6);
    }
    in.variables.emplace_back(std::to_string(101 + i), v->v);
  }
  // The JSON report: skips[0].position and the variables, the same numbers.
  const auto j = nlohmann::json::parse(report::to_json(in));
  for (int i = 0; i < 3; ++i) {
    const double rep = j["skips"][0]["position"][std::string(1, "XYZ"[i])].get<double>();
    const double var = j["variables"][std::to_string(101 + i)].get<double>();
    RC_ASSERT(rep == var);
  }
  RC_TAG(dialect);
}

}  // namespace
}  // namespace skipnc::property
