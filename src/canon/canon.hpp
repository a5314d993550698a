// The canonical command vocabulary: what the interpreter tells the motion
// side. Commands are small values; positions are machine coordinates in mm,
// feeds in mm/min, times in seconds. Each command carries its source line.
#pragma once

#include <cstdint>
#include <string>
#include <variant>

#include "core/axes.hpp"

namespace skipnc::canon {

// The plane of an arc: first and second axis of the plane, and the normal
// axis (helical motion). G17: X Y (Z), G18: Z X (Y), G19: Y Z (X).
struct Plane {
  int a0 = 0;
  int a1 = 1;
  int normal = 2;
  friend bool operator==(const Plane&, const Plane&) = default;
};

struct Rapid {
  AxisVec target;
  bool linear = true;  // false: each axis at its own rapid rate (non-linear positioning)
};

struct Feed {
  AxisVec target;
  double feed_mm_per_min = 0.0;
  bool exact_stop = false;  // come to rest at the end (G09, G61)
};

struct Arc {
  AxisVec target;
  double center0 = 0.0;  // centre on plane.a0, machine coordinates
  double center1 = 0.0;  // centre on plane.a1
  Plane plane;
  bool ccw = false;     // G03
  int extra_turns = 0;  // full turns before the end point (0 for ordinary arcs)
  double feed_mm_per_min = 0.0;
  bool exact_stop = false;
};

struct Dwell {
  double seconds = 0.0;
};

// A PMC signal address: X0.4, G12.3, ...
struct SignalAddr {
  char area = 'X';
  std::uint16_t byte = 0;
  std::uint8_t bit = 0;
  friend bool operator==(const SignalAddr&, const SignalAddr&) = default;
};

// kProbe: G38.2-G38.5 (LinuxCNC, grbl), a skip in the other controls' terms.
enum class SkipKind : std::uint8_t { kSkip, kMultiStep, kTorque, kProbe };
enum class SkipStop : std::uint8_t { kImmediate, kDecelerate };
enum class SkipLatch : std::uint8_t {
  kExact,    // the instant of the edge, inside the servo cycle (high-speed skip)
  kSampled,  // the first servo sample at which the input is seen, plus a delay
};

// Everything the motion side needs to monitor a skip block; the dialect and
// the parameters have been applied by the interpreter.
struct SkipSpec {
  SkipKind kind = SkipKind::kSkip;
  int p = -1;  // the P word as written, -1 when absent
  static constexpr int kMaxInputs = 12;
  int input_count = 0;  // inputs that end the block
  SignalAddr inputs[kMaxInputs];
  bool active_low = false;           // SK0: input active at 0
  bool edge = false;                 // TSG: a new active edge is required
  bool active_at_start_ends = true;  // level input already active at block start ends it
  // An input already active when the block starts is an error: the block
  // ends at once, no motion, no latch (LinuxCNC and grbl G38: the probe must
  // not be in the target state already). Before active_at_start_ends.
  bool active_at_start_fails = false;
  bool ignore_inputs = false;  // machine lock / Z-axis cancel: run to the end point
  bool torque_ends = false;    // P98 / P99
  int torque_axis = -1;
  double torque_limit_pct = 0.0;
  double torque_delay_s = 0.0;
  SkipStop stop = SkipStop::kImmediate;
  bool accel = false;                // SKF = 1: automatic acceleration/deceleration applies
  bool feed_fixed = true;            // feed override and dry run do not act (SKF = 0, Mitsubishi)
  bool override_zero_stops = false;  // with feed_fixed: override 0 % still stops (Mitsubishi)
  SkipLatch latch = SkipLatch::kExact;
  double latch_delay_s = 0.0;         // kSampled only
  bool servo_delay_comp = true;       // latch the actual (not the commanded) position
  bool locked_stores_command = true;  // a locked axis (machine lock) stores its command
  bool alarm_on_miss = false;         // K1
};

struct Skip {
  AxisVec target;
  double feed_mm_per_min = 0.0;
  SkipSpec spec;
};

// Non-motion commands: recorded, printed, and (where they affect the run)
// acted on by the machine.
struct Spindle {
  double rpm = 0.0;
  int direction = 0;  // 1 = M03, -1 = M04, 0 = stopped
  // Constant surface speed (G96): the programmed speed (m/min or ft/min) and
  // the G50 clamp (0: none); rpm is then the speed at the present diameter.
  double surface_speed = 0.0;
  double max_rpm = 0.0;
};
struct ToolSelect {
  int tool = 0;
};
struct MCode {
  int code = 0;
};
enum class StopKind : std::uint8_t { kProgramStop, kOptionalStop, kProgramEnd, kRewindEnd };
struct Stop {
  StopKind kind = StopKind::kProgramEnd;
};
struct Message {
  std::string text;
};
// A change of one axis's rate and acceleration from the next move on (grbl's
// $110-$112, $120-$122); 0 leaves that value as it is. Sent at rest.
struct AxisRate {
  int axis = 0;
  double rate_mm_per_min = 0.0;  // rapid and highest feed of the axis
  double accel_mm_s2 = 0.0;
};

// A limit on how many motion commands the planner may know beyond the one
// in motion, from the next motion command on (Haas G103 Pn: n blocks of
// look-ahead); 0: no limit (the planner's whole queue).
struct LookAhead {
  int blocks = 0;
};

using Command = std::variant<Rapid, Feed, Arc, Dwell, Skip, Spindle, ToolSelect, MCode, Stop,
                             Message, AxisRate, LookAhead>;

struct Stamped {
  Command cmd;
  std::uint32_t line = 0;
  // Where the block is: the interpreter's call context (its file, O number
  // and call stack; interp::CallContext), 0 for the main program.
  std::uint32_t source = 0;
  std::int32_t n = -1;  // the block's N number, -1 when it has none
};

// Whether a command moves the axes (and so goes to the motion kernel): the
// moves, dwells (timed in the kernel) and skip blocks.
constexpr bool is_motion(const Command& c) noexcept {
  return std::holds_alternative<Rapid>(c) || std::holds_alternative<Feed>(c) ||
         std::holds_alternative<Arc>(c) || std::holds_alternative<Dwell>(c) ||
         std::holds_alternative<Skip>(c);
}

// Where canonical commands go: the motion kernel's feeder, a printer, a
// plot recorder, a safety check in front of another sink.
class CommandSink {
 public:
  virtual ~CommandSink() = default;
  virtual void emit(const Stamped& cmd) = 0;
};

}  // namespace skipnc::canon
