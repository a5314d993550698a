// The decisions of a skip block (G31, G31.n, G31 P98/P99) as pure rule
// functions: each reads the block's words, the dialect's switches, the
// parameters and the little modal state it names, and returns one piece of
// the canon::SkipSpec or the alarm. None touches the interpreter, so each is
// tested on its own (tests/unit/interpreter_skip_rules_test.cpp);
// Interpreter::Impl::skip_block (skip.cpp) gathers the words, calls them in
// the order below and emits the command.
//
// The order is the order of the alarms: a block with two faults reports the
// first rule's.
//   form           addresses the control's G31 has (K, P, G53), P a whole
//                  number, Q only with P98/P99, no cutter compensation
//                  (rules 6, 36, 41)
//   torque         P98/P99: one axis, not synchronous, Q or 6280, 6281
//                  (37-46)
//   inputs         the inputs that end the block, their addresses (16-20,
//                  38-39)
//   feed           the feed the move runs at (7-10)
//   detection      polarity and edge, acc/dec, override, how the axes stop,
//                  how the position is latched, inputs ignored (11-15, 27, 35)
//   alarm_on_miss  whether a block without a signal alarms (33-34, 45)
// Rule numbers are those of skip-rules.md, as in tests/rules/.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "canon/canon.hpp"
#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "core/axes.hpp"
#include "core/diag.hpp"

namespace skipnc::interp::skip_rules {

// Mitsubishi multi-step skip function 1: G31.n reads its skip condition from
// parameter 1175 + 2(n-1) and its feed from the parameter after it.
inline constexpr int kStepParam = 1175;

// One word of the block as written.
struct Word {
  double value = 0.0;
  bool has_point = false;  // written with a decimal point
  bool is_expr = false;    // the value of an expression or a variable
  SourceLoc at;            // where the word is (alarms point at it)
};

// What the rules read of the block.
struct BlockWords {
  std::optional<Word> p, q, k;
  // The F word as a path feed (mm/min; in feed per revolution already
  // multiplied by the spindle speed); nullopt without F.
  std::optional<double> f_mm_per_min;
  bool g53 = false;  // G53 in the block
  AxisMask moved;    // the axes with a word
  int step = 0;      // n of G31.n, 0 for G31
  SourceLoc at;      // the block, for alarms that belong to no one word
};

// The command form: the P value and whether the block is a torque limit skip.
struct Form {
  int p = -1;  // -1 without P
  bool torque = false;
};
// `cutter_comp`: G41/G42 is active.
[[nodiscard]] Result<Form> form(const BlockWords& b, const config::Switches& sw, bool cutter_comp);

// The torque limit skip of a P98/P99 block.
struct Torque {
  int axis = -1;           // the one axis that moves
  bool ends = false;       // a torque limit was commanded: reaching it ends the block
  double limit_pct = 0.0;  // Q, else the parameter (6280), else 100
  double delay_s = 0.0;    // detection delay (6281)
};
// `axis_names`: the machine's axis letters in order (for the alarm's text).
[[nodiscard]] Result<Torque> torque(const BlockWords& b, const Form& f, std::string_view axis_names,
                                    const config::Switches& sw, const config::Parameters& params);

// The inputs that end the block.
struct Inputs {
  canon::SkipKind kind = canon::SkipKind::kSkip;
  int count = 0;
  std::array<canon::SignalAddr, canon::SkipSpec::kMaxInputs> addr{};
  int highest = -1;  // the highest input index (0 = SKIP / the first P), -1: none
};
[[nodiscard]] Result<Inputs> inputs(const BlockWords& b, const Form& f, const config::Dialect& d,
                                    const config::Parameters& params);

// Whether the F of a skip block becomes the modal F (Mitsubishi: no, rule 7).
bool block_f_is_modal(const config::Switches& sw) noexcept;

// The feeds the feed rule may choose from, as path feeds (mm/min).
struct FeedState {
  double modal_mm_per_min = 0.0;         // the modal F (with the block's F when that is modal)
  double last_cutting_mm_per_min = 0.0;  // F of the last non-rapid move
  bool inch_machine = false;             // parameter feeds are in inch/min
};
[[nodiscard]] Result<double> feed(const BlockWords& b, const FeedState& s,
                                  const config::Switches& sw, const config::Parameters& params);

// How the inputs are detected, how the move runs and how it stops.
struct Detection {
  bool active_low = false;
  bool edge = false;
  bool active_at_start_ends = true;
  bool ignore_inputs = false;
  bool accel = false;
  canon::SkipStop stop = canon::SkipStop::kImmediate;
  bool feed_fixed = true;
  bool override_zero_stops = false;
  canon::SkipLatch latch = canon::SkipLatch::kExact;
  double latch_delay_s = 0.0;
  bool servo_delay_comp = true;
  bool locked_stores_command = true;
};
// `length_axis`: the tool length axis (Z), -1 when the machine has none.
Detection detection(const BlockWords& b, const Inputs& in, int length_axis,
                    const config::Switches& sw, const config::Parameters& params,
                    const config::MachineConfig& mc);

// Whether a block that ends without a signal alarms (K, else the parameter).
[[nodiscard]] Result<bool> alarm_on_miss(const BlockWords& b, const config::Switches& sw,
                                         const config::Parameters& params);

}  // namespace skipnc::interp::skip_rules
