// A block that raises an alarm emits no canonical command and changes no
// state: random good words, then one bad word placed among them.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "property/program_gen.hpp"

namespace skipnc::property {
namespace {

// Words that a block may hold without an alarm (mill3, fanuc, tools 1-3).
const std::vector<std::string> kGood = {
    "S1200", "T2",  "G43 H1",   "G49",    "G91", "G20",
    "M08",   "G55", "F500.",    "G17",    "G61", "M09 (MSG,SEEN)",
    "M03",   "D2",  "G54.1 P2", "G1 X1.", "E3.", "G0 Z-1.",
    "G98",   "G94", "N77"};

// One bad word each, with where it fails: in the plan (values, groups,
// addresses) or in the commit (arc geometry, dwell, G10, M98).
const std::vector<std::string> kBad = {
    "D999",          "H999",           "G1.7",         "F-1.",        "A1.",
    "G0 G1",         "G90 G91",        "G20 G21",      "G4 G31 Z-1.", "G31 G28 Z0",
    "G31 G92 X0",    "G54.1 P999",     "M98",          "G2 X1. R0",   "G4 P1.5",
    "G10 L2 P9 X1.", "G10 L77 P1 X1.", "G2 X5. I0 J0", "G17 G18"};

// The state a program can see: modal codes, offsets, positions, counters.
std::vector<double> visible_state(const interp::Interpreter& in) {
  std::vector<double> v;
  const int vars[] = {4001, 4002, 4003, 4005, 4006, 4007, 4008, 4009, 4010, 4012, 4014,
                      4015, 4107, 4109, 4111, 4114, 4119, 4120, 5001, 5002, 5003, 5021,
                      5023, 5041, 5043, 5083, 5201, 5221, 5223, 5241, 3901};
  for (int n : vars) {
    auto r = in.read_variable(n);
    v.push_back(r && !r->vacant ? r->v : -1e300);
  }
  for (int i = 0; i < 3; ++i) v.push_back(in.position()[i]);
  v.push_back(static_cast<double>(in.messages().size()));
  const interp::ModalState& m = in.modal();
  v.push_back(m.feed);
  v.push_back(m.spindle);
  v.push_back(m.spindle_dir);
  v.push_back(m.tool);
  v.push_back(m.h);
  v.push_back(m.d);
  v.push_back(m.work);
  v.push_back(m.seq);
  v.push_back(m.last_m);
  v.push_back(static_cast<double>(m.motion));
  v.push_back(static_cast<double>(m.length));
  v.push_back(static_cast<double>(m.path));
  return v;
}

RC_GTEST_PROP(BlockTransaction, AnAlarmedBlockEmitsNothingAndChangesNoState, ()) {
  const Machine m("fanuc");
  std::string prefix = "G21 G90 G17 G40 G49 G54 G94 F300.\n";
  const int n = *rc::gen::inRange(0, 4);
  for (int i = 0; i < n; ++i) prefix += *rc::gen::elementOf(kGood) + "\n";
  std::vector<std::string> words;
  const int k = *rc::gen::inRange(0, 4);
  for (int i = 0; i < k; ++i) words.push_back(*rc::gen::elementOf(kGood));
  const std::string bad = *rc::gen::elementOf(kBad);
  const auto at = static_cast<std::size_t>(*rc::gen::inRange(0, k + 1));
  words.insert(words.begin() + static_cast<std::ptrdiff_t>(at), bad);
  std::string block;
  for (const auto& w : words) block += (block.empty() ? "" : " ") + w;
  const std::string program = prefix + block + "\nM30\n";
  RC_TAG(bad);

  auto in = interp::Interpreter::create(m.setup(program), AxisVec{});
  RC_ASSERT(in.has_value());
  Collect sink;
  for (int guard = 0; guard < 100; ++guard) {
    const std::vector<double> before = visible_state(**in);
    const std::size_t emitted = sink.cmds.size();
    auto st = (*in)->step(sink);
    if (!st) {
      RC_ASSERT((*in)->line() == static_cast<std::uint32_t>(n + 2));  // the bad block
      RC_ASSERT(sink.cmds.size() == emitted);
      RC_ASSERT(visible_state(**in) == before);
      return;
    }
    RC_ASSERT(*st != interp::Step::kEnd);  // every bad word raises an alarm
    if (*st == interp::Step::kSync) {
      interp::SyncState s;
      s.machine_position = (*in)->position();
      s.actual_position = s.machine_position;
      s.skip_done = true;
      s.latch_machine = s.machine_position;
      RC_ASSERT((*in)->sync(s).has_value());
    }
  }
  RC_FAIL("no alarm: " + program);
}

}  // namespace
}  // namespace skipnc::property
