#include "sim/simulator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <optional>
#include <type_traits>
#include <unordered_map>

#include "config/skip_inputs.hpp"
#include "interpreter/interpreter.hpp"
#include "kernel/kernel_config.hpp"
#include "sim/probe_safety.hpp"

namespace skipnc::sim {

using machine::OperatorAction;
using machine::Plant;
using machine::ProbeScene;
using machine::Scene;

namespace {

// Per-block timing (RunResult::block_times): one comparison per period; a
// place's entry is touched only when the running block changes. The period
// ending at tick `now` belongs to the block the kernel ran in it.
class BlockClock {
 public:
  void period(std::uint32_t context, std::uint32_t line, Tick now) {
    if (open_ && context == context_ && line == line_) {
      end_ = now;
      return;
    }
    close();
    if (line == 0) return;  // no block yet
    context_ = context;
    line_ = line;
    start_ = now - 1;
    end_ = now;
    open_ = true;
  }
  // A block met at the start of the period ending at `now` that ran no
  // period of its own (a dwell of no time, G04 X0): a place that ran, for
  // no time, at that instant.
  void passed(std::uint32_t context, std::uint32_t line, Tick now) {
    const std::uint64_t key = (static_cast<std::uint64_t>(context) << 32) | line;
    auto [it, added] = index_.try_emplace(key, places_.size());
    if (added) places_.push_back(BlockTime{context, line, 0, now - 1, now - 1, 0});
    BlockTime& b = places_[it->second];
    ++b.runs;
    b.last = std::max(b.last, now - 1);
  }
  std::vector<BlockTime> finish() {
    close();
    return std::move(places_);
  }

 private:
  void close() {
    if (!open_) return;
    open_ = false;
    const std::uint64_t key = (static_cast<std::uint64_t>(context_) << 32) | line_;
    auto [it, added] = index_.try_emplace(key, places_.size());
    if (added) places_.push_back(BlockTime{context_, line_, 0, start_, 0, 0});
    BlockTime& b = places_[it->second];
    ++b.runs;
    b.last = end_;
    b.ticks += end_ - start_;
  }

  std::uint32_t context_ = 0, line_ = 0;
  Tick start_ = 0, end_ = 0;
  bool open_ = false;
  std::unordered_map<std::uint64_t, std::size_t> index_;
  std::vector<BlockTime> places_;
};

// What goes with each command pushed to the kernel (its work frame, whether
// it cuts), kept only where it changes and dropped once the kernel has
// passed it: read back by the running command's tag (tags grow in push
// order).
template <class T>
class TagLog {
 public:
  void note(std::uint32_t tag, const T& v) {
    if (!log_.empty() && log_.back().second == v) return;
    log_.emplace_back(tag, v);
  }
  const T& at(std::uint32_t tag) {
    while (log_.size() > 1 && log_[1].first <= tag) log_.pop_front();
    return log_.front().second;
  }

 private:
  std::deque<std::pair<std::uint32_t, T>> log_;
};
using FrameLog = TagLog<interp::WorkFrame>;

// Whether a motion command cuts the stock, and where a cutting one ends.
struct CutNote {
  bool cuts = false;
  AxisVec end;
  friend bool operator==(const CutNote&, const CutNote&) = default;
};

// Routes the interpreter's commands: motion to the kernel, the rest recorded.
// With a frame log, each motion command's work frame is noted (the trace's
// work columns). With a cut log, whether each motion command cuts: the
// spindle turns (as the commands before it left it) and it is a feed, an
// arc or a dwell (a spinning tool at rest in the stock cuts where it
// settles); a rapid or a skip move never cuts. A cutting command's end
// point goes with it (ProbeScene::set_cutting).
//
// The simulator reads a block only while Kernel::can_accept() says there is
// room for a few moves, but one block may queue more than the whole queue
// holds (a G83 with a small Q makes three moves a peck; K repeats the hole).
// The motion that does not fit waits here, in order, with the frame and the
// cut note it had when it was emitted, and goes to the kernel as the ticks
// make room (drain()); no block is read meanwhile. So a push is offered only
// when the kernel has room, and a refusal cannot happen: if it does, it is
// kept (refused()) and the run ends in an internal alarm, never in a move
// lost without a word.
class Router final : public canon::CommandSink {
 public:
  Router(kernel::Kernel& k, canon::CommandSink* tap, const interp::Interpreter* in = nullptr,
         FrameLog* frames = nullptr, TagLog<CutNote>* cuts = nullptr)
      : k_(k), tap_(tap), in_(in), frames_(frames), cuts_(cuts) {}
  void emit(const canon::Stamped& c) override {
    if (tap_ != nullptr) tap_->emit(c);
    std::visit(
        [&](const auto& cmd) {
          using T = std::decay_t<decltype(cmd)>;
          if constexpr (std::is_same_v<T, canon::Rapid> || std::is_same_v<T, canon::Feed> ||
                        std::is_same_v<T, canon::Arc> || std::is_same_v<T, canon::Dwell> ||
                        std::is_same_v<T, canon::Skip>) {
            Pending p{c, {}, {}, 0};
            if (frames_ != nullptr) p.frame = in_->work_frame();
            if constexpr (!std::is_same_v<T, canon::Dwell>) target_ = cmd.target;
            if (cuts_ != nullptr) {
              constexpr bool kCutting = std::is_same_v<T, canon::Feed> ||
                                        std::is_same_v<T, canon::Arc> ||
                                        std::is_same_v<T, canon::Dwell>;
              const bool cuts = kCutting && spindle_dir_ != 0;
              p.cut = CutNote{cuts, cuts ? target_ : AxisVec{}};
            }
            p.window = window_;
            if (backlog_.empty() && k_.can_push(window_)) {
              push(p);
            } else {
              backlog_.push_back(std::move(p));
            }
          } else if constexpr (std::is_same_v<T, canon::Spindle>) {
            spindle_dir_ = cmd.direction;
          } else if constexpr (std::is_same_v<T, canon::Message>) {
            messages.push_back(cmd.text);
          } else if constexpr (std::is_same_v<T, canon::AxisRate>) {
            k_.set_axis_rate(cmd);  // sent at rest (a grbl '$' line waits for the motion)
          } else if constexpr (std::is_same_v<T, canon::LookAhead>) {
            window_ = cmd.blocks;  // for the motion emitted from now on
          }
        },
        c.cmd);
  }
  // Moves the waiting motion to the kernel while it has room.
  void drain() {
    while (!backlog_.empty() && k_.can_push(backlog_.front().window) && !refused_) {
      push(backlog_.front());
      backlog_.pop_front();
    }
  }
  // Every motion command emitted so far is in the kernel.
  bool drained() const noexcept { return backlog_.empty(); }
  // The command the kernel refused, if one was.
  const std::optional<canon::Stamped>& refused() const noexcept { return refused_; }
  std::vector<std::string> messages;

 private:
  struct Pending {
    canon::Stamped cmd;
    interp::WorkFrame frame;  // with a frame log
    CutNote cut;              // with a cut log
    int window = 0;           // the look-ahead limit it was emitted under (G103)
  };
  void push(const Pending& p) {
    if (frames_ != nullptr) frames_->note(k_.next_tag(), p.frame);
    if (cuts_ != nullptr) cuts_->note(k_.next_tag(), p.cut);
    if (!k_.push(p.cmd)) refused_ = p.cmd;
  }

  kernel::Kernel& k_;
  canon::CommandSink* tap_;
  const interp::Interpreter* in_;
  FrameLog* frames_;
  TagLog<CutNote>* cuts_;
  int spindle_dir_ = 0;
  int window_ = 0;  // canon::LookAhead in force
  AxisVec target_;  // where the motion emitted so far ends
  std::deque<Pending> backlog_;
  std::optional<canon::Stamped> refused_;
};

Error fault_alarm(const config::MachineConfig& m, const kernel::Fault& f, std::string_view file,
                  std::uint32_t line) {
  const auto& a = m.axes[static_cast<std::size_t>(f.axis)];
  Error e;
  e.loc = SourceLoc{file, line, 1};
  switch (f.kind) {
    case kernel::Fault::Kind::kStrokeLimit: {
      const bool plus = f.value > a.max_mm;
      e.id = AlarmId::kStrokeLimit;
      e.detail = fmt::format("{}{} at {:.4f} mm, beyond the stroke limit {:g} mm", plus ? "+" : "-",
                             a.name, f.value, plus ? a.max_mm : a.min_mm);
      break;
    }
    case kernel::Fault::Kind::kExcessError:
      e.id = AlarmId::kServoExcessError;
      // The limit as docs/skip-dialects.md gives it (1.5 x rapid / kp + 1
      // mm: 16 mm on mill3), a whole number without decimals.
      e.detail = fmt::format("axis {}: following error {:.4f} mm exceeds {:g} mm", a.name, f.value,
                             f.limit);
      break;
    case kernel::Fault::Kind::kInPositionTimeout:
    case kernel::Fault::Kind::kNone:
      e.id = AlarmId::kInPositionTimeout;
      e.detail = fmt::format(
          "axis {}: {:.4f} mm from its command after {:g} s at rest (in-position width {:g} mm); "
          "a stop holds it",
          a.name, f.value, m.in_position_timeout_s, m.in_position_mm);
      break;
  }
  return e;
}

// The skip block an alarm cut short, as far as it ran: its latch when the
// input came, the instant, where the axes are now and the alarm's point.
interp::SkipRecord cut_short_skip(const interp::SkipRecord& pending, const kernel::SkipResult& sk,
                                  const std::optional<AxisVec>& alarm_position,
                                  const interp::Interpreter& in) {
  interp::SkipRecord rec = pending;
  rec.ended_by_alarm = true;
  rec.triggered = sk.triggered;
  rec.time_s = sk.triggered ? sk.time_s : 0.0;
  if (sk.triggered) {
    rec.machine_position = sk.latch_machine;
    rec.position = in.work_from_machine(sk.latch_machine);
    if (sk.input_index >= 0 && sk.input_index < sk.spec.input_count) {
      rec.signal = config::signal_name(sk.spec.inputs[sk.input_index]);
    } else if (sk.torque_reached) {
      rec.signal = "TORQUE";
    }
  }
  rec.crash_machine = alarm_position;
  return rec;
}

StockResult stock_result(const machine::geo::Stock& st) {
  StockResult r;
  r.removed_mm3 = st.removed_volume();
  for (int i = 0; i <= st.nx(); ++i) r.x_edges.push_back(i < st.nx() ? st.x0(i) : st.hi().x);
  for (int j = 0; j <= st.ny(); ++j) r.y_edges.push_back(j < st.ny() ? st.y0(j) : st.hi().y);
  r.lowest_along_x.assign(static_cast<std::size_t>(st.nx()), st.hi().z);
  r.lowest_along_y.assign(static_cast<std::size_t>(st.ny()), st.hi().z);
  for (int j = 0; j < st.ny(); ++j) {
    for (int i = 0; i < st.nx(); ++i) {
      double& x = r.lowest_along_x[static_cast<std::size_t>(i)];
      double& y = r.lowest_along_y[static_cast<std::size_t>(j)];
      x = std::min(x, st.top(i, j));
      y = std::min(y, st.top(i, j));
    }
  }
  return r;
}

// Why the motion stands still: the operator's switch that holds it.
std::string held_reason(const kernel::OperatorState& op) {
  if (op.feed_hold) return "the motion is in feed hold";
  if (op.interlock) return "the axes are interlocked";
  return "the feed override is 0 %";
}
constexpr const char* held_never_released =
    " and no later [[operator]] action of the scene releases it: the run would never end";

// --strict: the first warning that --allow does not name, or null.
const interp::Warning* first_refused(const std::vector<interp::Warning>& ws,
                                     const std::vector<std::string>& allow) {
  for (const interp::Warning& w : ws) {
    if (std::find(allow.begin(), allow.end(), w.code) == allow.end()) return &w;
  }
  return nullptr;
}

// The scene's probe is longer or shorter than the H the control believes
// (an uncalibrated H, or Renishaw's H to the ball's lowest point): never an
// error, said once with both numbers (docs/scene.md "The probe's length").
std::optional<interp::Warning> probe_length_warning(const machine::Probing& spec) {
  if (!spec.probe || spec.probe->h_number == 0) return std::nullopt;
  const auto& p = *spec.probe;
  std::string text = fmt::format(
      "the probe's length (gauge line to ball centre) is {:.4f} mm in the scene, but H{} of the "
      "machine file holds {:.4f} mm ({:+.4f}): the stored values follow from both",
      p.length, p.h_number, p.h_length, p.h_length - p.length);
  if (std::fabs(p.h_length - p.length - p.ball_radius) < 1e-6) {
    text += "; H is to the ball's lowest point (centre length + ball radius, Renishaw's rule)";
  }
  return interp::Warning{"probe_length_differs", 0, 0, std::move(text)};
}

// grbl drives steppers: its position is the step count and its [PRB:] the
// commanded position at the switch. On a machine whose axes lag (kp > 0)
// that is ahead of the tool: said once (the built-in grbl3 has kp = 0).
std::optional<interp::Warning> grbl_servo_warning(const config::MachineConfig& m,
                                                  const config::Dialect& d) {
  if (d.sw.language != config::Language::kGrbl) return std::nullopt;
  for (const auto& a : m.axes) {
    if (a.kp_per_s > 0.0) {
      return interp::Warning{
          "grbl_servo_lag", 0, 0,
          fmt::format("the grbl dialect runs on a machine whose {} axis lags its command "
                      "(kp = {}/s): grbl's position and [PRB:] are its step count, the command, "
                      "ahead of the tool; grbl machines are steppers (-m grbl3: kp = 0)",
                      a.name, a.kp_per_s)};
    }
  }
  return std::nullopt;
}

// The kernel's settings for this machine and dialect: the in-position check
// at the end of a rapid, unless the dialect's bit turns it off (Fanuc 1601#5
// NCI).
kernel::KernelConfig run_kernel_config(const config::MachineConfig& m, const config::Dialect& d,
                                       const config::Parameters& p) {
  kernel::KernelConfig kc = kernel::kernel_config(m);
  kc.rapid_in_position = d.sw.rapid_no_in_position_param == 0 ||
                         !p.bit(d.sw.rapid_no_in_position_param, d.sw.rapid_no_in_position_bit);
  return kc;
}

// One run of a program: the interpreter, the kernel and the plant, servo
// period by servo period (Simulator::run). Each step of a period is a
// function of its own; their order in run() is the period's.
class RunLoop {
 public:
  RunLoop(const config::MachineConfig& m, const config::Dialect& d, const config::Parameters& p,
          const Scene& scene, interp::Interpreter& in, const interp::Setup& setup,
          const RunOptions& opts)
      : m_(m),
        d_(d),
        p_(p),
        scene_(scene),
        in_(in),
        setup_(setup),
        opts_(opts),
        k_(run_kernel_config(m, d, p)),
        plant_(m, scene, k_.clock()),
        safety_(m, p, plant_, opts.commands),
        has_stock_(!plant_.probing().stock().empty()),
        router_(k_, &safety_, &in, opts.trace != nullptr ? &frames_ : nullptr,
                has_stock_ ? &cuts_ : nullptr) {
    set_up();
  }
  RunResult run();

 private:
  void set_up();
  void strict_setup_warnings();
  [[gnu::always_inline]] inline std::string_view file_of(std::uint32_t ctx) const;
  void alarm(Error e, std::uint32_t ctx);
  TraceRow trace_row();
  [[gnu::always_inline]] inline void read_blocks();
  [[gnu::always_inline]] inline void apply_operator_actions();
  [[gnu::always_inline]] inline std::int64_t quiet_periods() const;
  [[gnu::always_inline]] inline bool machine_alone() const;
  [[gnu::always_inline]] inline std::int64_t before_next_event(std::int64_t n) const;
  std::int64_t cruise_periods();
  bool servo_settled() const;
  void pass_cruise(std::int64_t n);
  [[gnu::always_inline]] inline void servo_period();
  [[gnu::always_inline]] inline bool period_alarm();
  [[gnu::always_inline]] inline bool sync_interpreter();
  [[gnu::always_inline]] inline bool run_stops();
  void finish();
  void save_persistent();

  const config::MachineConfig& m_;
  const config::Dialect& d_;
  const config::Parameters& p_;
  const Scene& scene_;
  interp::Interpreter& in_;
  const interp::Setup& setup_;
  const RunOptions& opts_;
  RunResult res_;
  kernel::Kernel k_;
  Plant plant_;
  ProbeSafety safety_;
  FrameLog frames_;
  // Whether the running command cuts, for a scene with stock.
  bool has_stock_;
  TagLog<CutNote> cuts_;
  Router router_;
  AxisVec work_now_;
  // Machine lock and Z-axis cancel (operator switches kept as parameters):
  // the locked axes do not move, the command does.
  AxisMask locked_;
  kernel::OperatorState op_;
  std::size_t next_action_ = 0;  // scene [[operator]] actions not yet applied
  std::int64_t held_ticks_ = 0;  // periods the motion has stood held for ever
  kernel::TickInput tin_;
  kernel::TickOutput tout_;
  AxisVec cmd_prev_;
  bool waiting_ = false;  // the interpreter waits for a sync
  bool ending_ = false;   // the program ended; the machine finishes its motion
  bool held_ = false;     // an axis held away from its command ended the run
  double next_progress_ = 1.0;
  Tick next_cruise_try_ = 0;  // cruise_periods looks again from this period on
  // A program error stops the reading of blocks; the motion already queued
  // is finished first, as if the blocks ran one by one, so the stopping
  // point does not depend on how far the planner had read ahead.
  std::optional<Error> program_alarm_;
  std::uint32_t program_alarm_context_ = 0;
  BlockClock times_;
  // The set-up's warnings (the probe's length against its H, grbl on a
  // lagging servo), reported after the program's own.
  std::vector<interp::Warning> setup_warnings_;
};

void RunLoop::set_up() {
  const AxisVec home{};
  k_.set_position(home);
  plant_.reset(home);
  plant_.for_each_signal([&](const canon::SignalAddr& a, bool on) { k_.preset_signal(a, on); });
  frames_.note(0, in_.work_frame());
  cuts_.note(0, CutNote{});
  if (d_.sw.machine_lock_param != 0 && p_.get(d_.sw.machine_lock_param) != 0.0) {
    for (int i = 0; i < m_.axis_count(); ++i) locked_.set(i);
  }
  if (d_.sw.z_cancel_param != 0 && p_.get(d_.sw.z_cancel_param) != 0.0 && m_.axis_index('Z') >= 0) {
    locked_.set(m_.axis_index('Z'));
  }
  k_.set_locked_axes(locked_);
  plant_.set_locked(locked_);
  op_.dry_run_feed_mm_min = d_.sw.dry_run_feed_param != 0
                                ? p_.get(d_.sw.dry_run_feed_param) * (m_.inch_machine ? 25.4 : 1.0)
                                : 0.0;
  tout_.commanded = home;
  cmd_prev_ = home;
  strict_setup_warnings();
}

// --strict: a warning of the set-up is an alarm before the first block
// unless --allow or the scene's [strict] allow names it.
void RunLoop::strict_setup_warnings() {
  if (auto w = probe_length_warning(plant_.probing().spec())) setup_warnings_.push_back(*w);
  if (auto w = grbl_servo_warning(m_, d_)) setup_warnings_.push_back(*w);
  if (!setup_.strict) return;
  if (const interp::Warning* w = first_refused(setup_warnings_, setup_.strict_allow)) {
    program_alarm_ =
        Error{AlarmId::kStrictWarning, w->code + ": " + w->text, SourceLoc{file_of(0), 0, 1}, -1};
    ending_ = true;
  }
}

// The file of a call context (interpreter storage; the table only grows
// while blocks are read, and a motion alarm ends the reading).
std::string_view RunLoop::file_of(std::uint32_t ctx) const {
  const auto& cs = in_.contexts();
  return ctx < cs.size() ? std::string_view(cs[ctx].file) : std::string_view(setup_.program_name);
}

void RunLoop::alarm(Error e, std::uint32_t ctx) {
  res_.status = RunStatus::kAlarm;
  res_.alarm = std::move(e);
  res_.alarm_context = ctx;
}

// The trace's row of the period just run.
TraceRow RunLoop::trace_row() {
  TraceRow r;
  r.tick = k_.now();
  r.time_s = k_.clock().seconds(k_.now());
  r.commanded = &cmd_prev_;
  r.actual = &plant_.actual();
  r.torque = &plant_.torque();
  r.feed_mm_per_min = tout_.path_speed * 60.0;
  r.line = tout_.line;
  r.source = tout_.source;
  work_now_ = frames_.at(tout_.tag).apply(plant_.actual(), m_.axis_count());
  r.work = &work_now_;
  r.file = file_of(tout_.source);
  r.plant = &plant_;
  r.handshake = tout_.handshake;
  r.handshake_names = d_.handshake.empty() ? nullptr : &d_.handshake;
  return r;
}

// Feeds the kernel until it is full or the interpreter must wait: first the
// motion of the last block that did not fit, then new blocks. A signal is
// heard between blocks too: a macro loop without motion runs many blocks
// within one period.
void RunLoop::read_blocks() {
  router_.drain();
  while (!waiting_ && !ending_ && router_.drained() && k_.can_accept() &&
         !safety_.holds_reading() &&
         !(opts_.interrupt != nullptr && opts_.interrupt->load(std::memory_order_relaxed))) {
    auto st = in_.step(router_);
    if (!st) {
      program_alarm_ = st.error();
      program_alarm_context_ = in_.context();
      ending_ = true;
      return;
    }
    if (*st == interp::Step::kSync) waiting_ = true;
    if (*st == interp::Step::kEnd) ending_ = true;
    const interp::Warning* strict_w =
        setup_.strict ? first_refused(safety_.warnings(), setup_.strict_allow) : nullptr;
    if (strict_w != nullptr) {
      // --strict: the machine's warning (a skip move that cannot stop in
      // the over-travel) is an alarm at its block unless --allow names
      // it; as for any program alarm, what is already queued (the skip
      // move too) runs first.
      const interp::Warning& w = *strict_w;
      program_alarm_ = Error{AlarmId::kStrictWarning, w.code + ": " + w.text,
                             SourceLoc{file_of(w.context), w.line, 1}, -1};
      program_alarm_context_ = w.context;
      ending_ = true;
      return;
    }
  }
}

// The operator's actions due by the start of this period.
void RunLoop::apply_operator_actions() {
  if (next_action_ >= scene_.operator_actions.size()) return;
  const double t0 = k_.clock().seconds(k_.now());
  bool changed = false;
  for (; next_action_ < scene_.operator_actions.size() &&
         scene_.operator_actions[next_action_].at_time_s <= t0 + 1e-12;
       ++next_action_) {
    const OperatorAction& a = scene_.operator_actions[next_action_];
    if (a.feed_hold) op_.feed_hold = *a.feed_hold;
    if (a.interlock) op_.interlock = *a.interlock;
    if (a.override_pct) op_.override_pct = *a.override_pct;
    if (a.dry_run) op_.dry_run = *a.dry_run;
    changed = true;
  }
  if (changed) k_.set_operator(op_);
}

// Periods that would each repeat the last one, the time aside (a dwell, a
// feed hold): the kernel's command stands, the machine is still, the
// interpreter waits for the machine, and nothing of the scene, the
// operator, the trace's --trace-every or the time limit is due before
// them. They are passed in one step: the run is the same, bit for bit,
// as one period at a time (G04 X1e9 took minutes of processor time).
// The machine runs a block with nothing to read meanwhile (the interpreter
// waits for it, or the queue is full) and the safety checks have nothing to
// do: the periods ahead depend on the machine alone (quiet_periods,
// cruise_periods).
bool RunLoop::machine_alone() const {
  const bool reading = !waiting_ && !ending_ && router_.drained() && k_.can_accept();
  return !reading && tout_.line != 0 && safety_.quiet(plant_);
}

// n periods cut short before the time limit and the next operator action.
std::int64_t RunLoop::before_next_event(std::int64_t n) const {
  const Tick now = k_.now();
  n = std::min<std::int64_t>(n, m_.limits.max_ticks - now - 2);
  if (next_action_ < scene_.operator_actions.size()) {
    const double at = scene_.operator_actions[next_action_].at_time_s;
    n = std::min<std::int64_t>(
        n, static_cast<std::int64_t>(std::floor(at / k_.clock().period_s())) - now - 2);
  }
  return n;
}

std::int64_t RunLoop::quiet_periods() const {
  if (!plant_.still()) return 0;  // most periods: the axes move
  if (!machine_alone()) return 0;
  std::int64_t n = std::min(k_.quiet_ticks(), plant_.quiet_ticks(k_.now()));
  if (n <= 0) return 0;
  if (next_action_ >= scene_.operator_actions.size() && tout_.time_scale < 1e-12) {
    return 0;  // held for ever: ends after a second (run_stops), period by period
  }
  const Tick now = k_.now();
  n = before_next_event(n);
  if (opts_.trace != nullptr) {
    const std::int64_t s = std::max<std::int64_t>(1, opts_.trace->stride());
    n = std::min<std::int64_t>(n, (now / s + 1) * s - now - 1);  // the next row is written
  }
  return n;
}

// A servo whose following error is within this of where it settles under
// the cruise's constant velocity may be passed over (cruise_periods): its
// transient has decayed.
constexpr double kCruiseSettledMm = 1e-9;
// Fewer periods than this are run one by one (the checks cost more).
constexpr std::int64_t kCruiseMinPeriods = 16;
// After a look that found no cruise to pass, the periods before the next
// look: most periods are in short moves or a servo's transient, and a look
// every period cost a quarter of the run (short moves).
constexpr std::int64_t kCruiseLookAgain = 64;
constexpr std::int64_t kCruiseSettleAgain = 128;

// Periods of a feed's cruise that can be passed at once: the command moves
// along a straight line at constant speed (no skip block, full rate, its end
// within the stroke), nothing of the scene can sense, stop or load the axes,
// every servo has settled (kCruiseSettledMm) at a following error within its
// limit, and no operator action or the time limit is due before them (the
// progress display is then told the time after them). The command is a closed form of the count of
// periods (the same bits as period by period); the servo's recurrence is applied in closed form
// (Plant::pass_cruise), within 1e-9 mm of the period-by-period run (in practice a few units in the
// last place of the positions: 1e-14 mm at 100 mm). A trace (--trace, --plot) asks for the rows of
// those periods, digit for digit: with one, every period is run (a following error of exactly half
// a printed digit, common with round feeds and gains, would print one way or the other). G1 X1.
// F0.001 took 1.9 s of processor time for its 60 million periods, now 0.004 s.
std::int64_t RunLoop::cruise_periods() {
  const Tick now = k_.now();
  next_cruise_try_ = now + kCruiseLookAgain;
  if (opts_.trace != nullptr || !plant_.can_cruise() || !machine_alone()) return 0;
  const std::int64_t n = k_.cruise_ticks();
  if (n < kCruiseMinPeriods) return 0;
  if (!servo_settled()) {
    next_cruise_try_ = now + kCruiseSettleAgain;
    return 0;
  }
  return before_next_event(n);
}

// Every axis's following error within kCruiseSettledMm of where the cruise
// settles it, and that within the excess-error limit: along the passed
// periods the error goes from the one to the other monotonically.
bool RunLoop::servo_settled() const {
  const AxisVec step = k_.cruise_step();
  for (int i = 0; i < m_.axis_count(); ++i) {
    const double ess = plant_.steady_error(i, step[i]);
    const double e = cmd_prev_[i] - plant_.actual()[i];
    if (!(std::fabs(e - ess) <= kCruiseSettledMm) || !(std::fabs(ess) < k_.excess_error_mm(i)))
      return false;
  }
  return true;
}

// Passes n periods of the cruise: the kernel's command and time, then the
// servo in closed form from the command before to the command after.
void RunLoop::pass_cruise(std::int64_t n) {
  const AxisVec from = cmd_prev_;
  const AxisVec step = k_.cruise_step();
  k_.pass_cruise(n, tout_);
  cmd_prev_ = k_.previous_command();
  plant_.pass_cruise(n, from, cmd_prev_, step, tin_);
  k_.cruised(plant_.actual());
  times_.period(tout_.source, tout_.line, k_.now());
}

// One servo period: the plant follows the kernel's last command, the kernel
// ticks, the block's time and the trace's row are kept.
void RunLoop::servo_period() {
  const AxisVec& cmd = tout_.commanded;
  if (tout_.torque_limited || plant_.torque_limited())
    plant_.set_torque_limit(tout_.torque_limit_pct);
  if (tout_.followed_up) cmd_prev_ = cmd;  // a jump of the command, not motion
  // The period follows the command of the last tick: that command says
  // whether the tool cuts in it.
  if (has_stock_) {
    const CutNote& cut = cuts_.at(tout_.tag);
    plant_.probing().set_cutting(cut.cuts, cut.end);
  }
  plant_.advance(k_.now() + 1, cmd_prev_, cmd, tin_);
  cmd_prev_ = cmd;
  k_.tick(tin_, tout_);
  times_.period(tout_.source, tout_.line, k_.now());
  if (tout_.passed_dwell_line != 0) {
    times_.passed(tout_.passed_dwell_source, tout_.passed_dwell_line, k_.now());
  }
  if (opts_.trace != nullptr) opts_.trace->row(trace_row());
}

// The alarms of the period just run: tool changes, probe crash, collision,
// probe protection; then the kernel's faults: an excess following error (an
// axis held by a stop while the command runs on, as a torque limit skip with
// no torque limit commanded), an axis that never reaches its command at rest
// (held by a stop short of it: the control would wait for ever), a command
// beyond a stroke end (not given to the servo). True when one ends the run.
bool RunLoop::period_alarm() {
  // The file is named only when the check has something to look at (most
  // periods have nothing: safety_.quiet).
  const std::string_view file = safety_.quiet(plant_) ? std::string_view{} : file_of(tout_.source);
  if (auto s = safety_.after_period(plant_, k_, tout_.line, file)) {
    alarm(std::move(s->error), tout_.source);
    res_.alarm_position = s->machine_position;
    return true;
  }
  if (const kernel::Fault& f = tout_.fault) {
    alarm(fault_alarm(m_, f, file_of(tout_.source), tout_.line), tout_.source);
    held_ = f.kind != kernel::Fault::Kind::kStrokeLimit;
    return true;
  }
  return false;
}

// The interpreter waiting for the machine (a skip block, a read of the
// position) goes on once the motion has ended. True when that is an alarm.
bool RunLoop::sync_interpreter() {
  if (!(waiting_ && router_.drained() && k_.idle() && (!k_.skip().active || k_.skip().done)))
    return false;
  interp::SyncState s;
  s.machine_position = k_.command();
  s.actual_position = plant_.actual();
  s.time_s = k_.clock().seconds(k_.now());
  const kernel::SkipResult& sk = k_.skip();
  if (sk.active) {
    s.skip_done = true;
    s.triggered = sk.triggered;
    s.torque_reached = sk.torque_reached;
    s.active_at_start = sk.active_at_start;
    s.latch_machine = sk.latch_machine;
    s.input_index = sk.input_index;
    if (sk.triggered) s.time_s = sk.time_s;
    s.machine_position = sk.stop_position;
  }
  k_.clear_skip();
  waiting_ = false;
  auto r = in_.sync(s);
  if (!r) {
    alarm(r.error(), in_.context());
    return true;
  }
  return false;
}

// Whether the run ends after this period: the program ended and the motion
// with it, a feed held for ever, the time limit, a signal. Else the progress
// is said about every simulated second.
bool RunLoop::run_stops() {
  if (ending_ && router_.drained() && k_.idle()) {
    if (program_alarm_) alarm(*program_alarm_, program_alarm_context_);
    return true;
  }
  // A feed held for ever: the motion stands (feed hold, interlock or
  // override 0 %: no profile time passes) with motion still to run, and
  // no later [[operator]] action of the scene can release it. It ends
  // after one second of it, not at limits.max_time_s.
  const bool hold_forever =
      tout_.time_scale < 1e-12 && !k_.idle() && next_action_ >= scene_.operator_actions.size();
  held_ticks_ = hold_forever ? held_ticks_ + 1 : 0;
  if (static_cast<double>(held_ticks_) * k_.clock().period_s() >= 1.0) {
    alarm(Error{AlarmId::kTimeLimit, held_reason(op_) + held_never_released,
                SourceLoc{file_of(tout_.source), tout_.line, 1}, -1},
          tout_.source);
    return true;
  }
  if (k_.now() >= m_.limits.max_ticks) {
    alarm(Error{AlarmId::kTimeLimit, "the run passed limits.max_time_s of simulated time",
                SourceLoc{file_of(tout_.source), tout_.line, 1}, -1},
          tout_.source);
    return true;
  }
  if (opts_.interrupt != nullptr && opts_.interrupt->load(std::memory_order_relaxed)) {
    // The block the stop cut: the one the machine runs, or while the
    // machine is idle the one the interpreter is at (a macro loop). Was
    // always the interpreter's, a block or more ahead of the machine.
    const bool moving = !k_.idle() && tout_.line != 0;
    const std::uint32_t ctx = moving ? tout_.source : in_.context();
    res_.status = RunStatus::kInterrupted;
    res_.alarm = Error{AlarmId::kInterrupted, "stopped by a signal",
                       SourceLoc{file_of(ctx), moving ? tout_.line : in_.line(), 1}, -1};
    res_.alarm_context = ctx;
    return true;
  }
  if (opts_.progress) {
    const double t = k_.clock().seconds(k_.now());
    if (t >= next_progress_) {
      opts_.progress(t, in_.line());
      next_progress_ = t + 1.0;
    }
  }
  return false;
}

RunResult RunLoop::run() {
  for (;;) {
    read_blocks();
    if (res_.status != RunStatus::kCompleted) break;
    if (const auto& r = router_.refused()) {
      alarm(Error{AlarmId::kInternal,
                  "the kernel's motion queue refused a command although it had room",
                  SourceLoc{file_of(r->source), r->line, 1}, -1},
            r->source);
      break;
    }
    apply_operator_actions();
    if (const std::int64_t quiet = quiet_periods(); quiet > 0) {
      k_.pass_quiet(quiet);
      times_.period(tout_.source, tout_.line, k_.now());
    } else if (k_.now() >= next_cruise_try_) {  // looked at every kCruiseLookAgain periods
      if (const std::int64_t cruise = cruise_periods(); cruise > 0) pass_cruise(cruise);
    }
    servo_period();
    if (period_alarm() || sync_interpreter() || run_stops()) break;
  }
  finish();
  save_persistent();
  return std::move(res_);
}

// What the run leaves: the last trace row, its time, where the axes are, the
// skips, the stock, the messages and warnings.
void RunLoop::finish() {
  if (opts_.trace != nullptr && k_.now() > 0) opts_.trace->last(trace_row());
  res_.ticks = k_.now();
  res_.time_s = k_.clock().seconds(k_.now());
  res_.block_times = times_.finish();
  res_.period_s = k_.clock().period_s();
  // Where the axes are: the command, unless an axis was held away from it
  // (a fault) or held still (machine lock, Z-axis cancel: the machine
  // stays where it is while the work position follows the command).
  res_.final_machine = held_ ? plant_.actual() : k_.command();
  res_.final_work = in_.work_from_machine(res_.final_machine);
  for (int i = 0; i < m_.axis_count(); ++i) {
    if (locked_.has(i)) res_.final_machine[i] = plant_.actual()[i];
  }
  res_.skips = in_.skips();
  if (const interp::SkipRecord* p = in_.pending_skip(); p != nullptr && res_.alarm) {
    res_.skips.push_back(cut_short_skip(*p, k_.skip(), res_.alarm_position, in_));
    res_.skips.back().end_position = res_.final_work;  // where the alarm stopped the axes
  }
  if (has_stock_) res_.stock = stock_result(plant_.probing().stock());
  res_.contexts = in_.contexts();
  res_.program_inch = in_.modal().units == interp::Units::kInch;
  res_.messages = in_.messages();
  for (auto& msg : router_.messages) res_.messages.push_back(msg);
  for (const auto& msg : safety_.messages()) res_.messages.push_back(msg);
  res_.warnings = in_.warnings();
  for (const auto& w : safety_.warnings()) res_.warnings.push_back(w);
  for (auto& w : setup_warnings_) res_.warnings.push_back(std::move(w));
}

// Every run that ended, by itself, by an alarm or by a signal (SIGTERM,
// SIGINT: the run stops between periods) writes #500-#999 and the DPRNT
// file (was: an interrupted run wrote neither).
void RunLoop::save_persistent() {
  const std::size_t said = in_.messages().size();
  auto saved = in_.save_persistent();
  // What saving said (the log files written: ngc_room.cpp).
  for (std::size_t i = said; i < in_.messages().size(); ++i)
    res_.messages.push_back(in_.messages()[i]);
  if (!saved && res_.status == RunStatus::kCompleted) alarm(saved.error(), 0);
  // After an alarm the run's alarm stays the first one; the failed save is
  // said in the messages (was: not said at all).
  if (!saved && res_.status != RunStatus::kCompleted) {
    res_.messages.push_back("persistent variables not saved: " + saved.error().detail);
  }
  in_.release_persistent();
}

}  // namespace

Simulator::Simulator(const config::MachineConfig& m, const config::Dialect& d,
                     const config::Parameters& p, const Scene& scene)
    : m_(m), d_(d), p_(p), scene_(scene) {}

Simulator::~Simulator() = default;

Result<RunResult> Simulator::run(const interp::Setup& setup, const RunOptions& opts) {
  auto created = interp::Interpreter::create(setup, AxisVec{});
  SKIPNC_TRY(created);
  interp_ = std::move(*created);
  // A loop of some kilobytes (the kernel's queue): on the heap.
  auto loop = std::make_unique<RunLoop>(m_, d_, p_, scene_, *interp_, setup, opts);
  return loop->run();
}

}  // namespace skipnc::sim
