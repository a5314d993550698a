// G38.2-G38.5, the straight probe of LinuxCNC and grbl (docs/skip-dialects.md):
//   G38.2  toward the part, stops on contact, an error without one
//   G38.3  toward the part, stops on contact, no error without one
//   G38.4  away from the part, stops when contact is lost, an error without
//   G38.5  away from the part, stops when contact is lost, no error
// In the other controls' terms a skip: one input (the probe), level
// detection, the axes decelerate to a stop, and the block is the interpreter's
// point of synchronisation. Two rules are G38's own: the probe already in the
// state the move waits for is an error before any motion (LinuxCNC "Probe is
// already tripped ...", grbl ALARM 4), and the move goes on with the modal
// feed, override and acceleration of a G01. What the control stores is the
// dialect's: LinuxCNC #5061-#5069 in the work coordinates of the block and
// #5070 = 1/0; grbl the "[PRB:x,y,z:1]" line in machine coordinates.
#include <cmath>
#include <cstdio>
#include <string>

#include "config/skip_inputs.hpp"
#include "interpreter/impl.hpp"

namespace skipnc::interp {

bool Interpreter::Impl::probe_inverted() const noexcept {
  const int n = dialect.sw.probe_invert_param;
  if (n == 0) return false;
  return lang->probe_inverted(*this, n);  // a parameter bit, or grbl's $6
}

Flow<Step> Interpreter::Impl::probe_block(const AxisVec& target, AxisMask moved, CommandSink& out) {
  const SourceLoc at = loc(cur_col);
  const config::Switches& sw = dialect.sw;
  const GCode code = modal.probe;
  const std::string name = code_name(code);
  const bool toward = code == GCode(38, 2) || code == GCode(38, 3);
  // The block's checks, in LinuxCNC's order (convert_straight_probe).
  if (moved.empty()) return fail(AlarmId::kProbeNoAxis, name + " without an axis word", at);
  if (modal.cutter != CutterComp::kOff) {
    return fail(AlarmId::kProbeInCutterComp, name + " with G41/G42 active", at);
  }
  if (modal.feed_mode == FeedMode::kPerRev) {
    return fail(AlarmId::kProbeFeedPerRev, name + " in feed per revolution (G95)", at);
  }
  if (feed_mm_per_min() <= 0.0) return fail(AlarmId::kProbeZeroFeed, name + " with F0", at);
  // The end point at the start point: LinuxCNC refuses it for G38.2 and
  // G38.4 only, grbl for every G38 (error 33): probe_same_point_all.
  bool same = true;
  for (int i = 0; i < axis_count; ++i) same = same && target[i] == pos[i];
  if (same && (sw.probe_same_point_all || code == GCode(38, 2) || code == GCode(38, 4))) {
    return fail(AlarmId::kProbeTooShort, name + ": the end point is the start point", at);
  }
  pending_skip = PendingSkip{};
  pending_skip.g38 = code;
  canon::Skip sk;
  sk.target = target;
  sk.feed_mm_per_min = feed_mm_per_min();
  canon::SkipSpec& spec = sk.spec;
  spec.kind = canon::SkipKind::kProbe;
  spec.p = -1;
  skip_rules::BlockWords b;
  b.moved = moved;
  b.at = at;
  auto in = skip_rules::inputs(b, skip_rules::Form{}, dialect, params);
  SKIPNC_TRY(in);
  spec.input_count = 1;  // the probe input: the dialect's first
  spec.inputs[0] = in->addr[0];
  pending_skip.input_names[0] = config::signal_name(in->addr[0]);
  const bool invert = probe_inverted();  // a parameter bit, or grbl's $6 as the program set it
  // Away from the part the move waits for the input to go inactive: the
  // input's active state is the other one.
  spec.active_low = toward == invert;
  spec.edge = false;
  spec.active_at_start_ends = false;
  spec.active_at_start_fails = true;
  spec.ignore_inputs = false;
  spec.accel = true;
  spec.stop = canon::SkipStop::kDecelerate;
  spec.feed_fixed = false;
  spec.override_zero_stops = false;
  spec.latch = sw.probe_latch_sampled ? canon::SkipLatch::kSampled : canon::SkipLatch::kExact;
  spec.latch_delay_s = 0.0;
  spec.servo_delay_comp = sw.probe_latch_actual;
  spec.locked_stores_command = sw.skip_locked_stores_command;
  spec.alarm_on_miss = code == GCode(38, 2) || code == GCode(38, 4);
  return queue_skip(sk, at, out);
}

Flow<void> Interpreter::Impl::finish_probe(const SyncState& s) {
  PendingSkip& ps = pending_skip;
  const GCode code = *ps.g38;
  const std::string name = code_name(code);
  const bool toward = code == GCode(38, 2) || code == GCode(38, 3);
  pos = s.machine_position;
  if (s.active_at_start) {
    return fail(toward ? AlarmId::kProbeTrippedAtStart : AlarmId::kProbeClearAtStart,
                toward ? name + ": the probe was already in contact when the move began"
                       : name + ": the probe was not in contact when the move began",
                ps.loc);
  }
  const AxisVec latch = record_skip(s);  // skip.cpp
  // #5061-#5070 (RS274NGC), a success flag, grbl's [PRB:] (language.cpp)
  lang->store_probe(*this, latch, s.triggered);
  if (!s.triggered && ps.alarm_on_miss) {
    return fail(toward ? AlarmId::kProbeNoContact : AlarmId::kProbeNoBreak,
                toward ? name + " reached its end point without contact"
                       : name + " reached its end point still in contact",
                ps.loc);
  }
  return {};
}

}  // namespace skipnc::interp
