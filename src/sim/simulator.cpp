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

}  // namespace

Simulator::Simulator(const config::MachineConfig& m, const config::Dialect& d,
                     const config::Parameters& p, const Scene& scene)
    : m_(m), d_(d), p_(p), scene_(scene) {}

Simulator::~Simulator() = default;

Result<RunResult> Simulator::run(const interp::Setup& setup, const RunOptions& opts) {
  RunResult res;
  const AxisVec home{};
  auto created = interp::Interpreter::create(setup, home);
  SKIPNC_TRY(created);
  interp_ = std::move(*created);
  interp::Interpreter& in = *interp_;

  kernel::KernelConfig kc = kernel::kernel_config(m_);
  // The in-position check at the end of a rapid, unless the dialect's bit
  // turns it off (Fanuc 1601#5 NCI).
  kc.rapid_in_position = d_.sw.rapid_no_in_position_param == 0 ||
                         !p_.bit(d_.sw.rapid_no_in_position_param, d_.sw.rapid_no_in_position_bit);
  kernel::Kernel k(kc);
  Plant plant(m_, scene_, k.clock());
  k.set_position(home);
  plant.reset(home);
  plant.for_each_signal([&](const canon::SignalAddr& a, bool on) { k.preset_signal(a, on); });
  ProbeSafety safety(m_, p_, plant, opts.commands);
  FrameLog frames;
  frames.note(0, in.work_frame());
  // Whether the running command cuts, for a scene with stock.
  const bool has_stock = !plant.probing().stock().empty();
  TagLog<CutNote> cuts;
  cuts.note(0, CutNote{});
  Router router(k, &safety, &in, opts.trace != nullptr ? &frames : nullptr,
                has_stock ? &cuts : nullptr);
  AxisVec work_now;
  // Machine lock and Z-axis cancel (operator switches kept as parameters):
  // the locked axes do not move, the command does.
  AxisMask locked;
  if (d_.sw.machine_lock_param != 0 && p_.get(d_.sw.machine_lock_param) != 0.0) {
    for (int i = 0; i < m_.axis_count(); ++i) locked.set(i);
  }
  if (d_.sw.z_cancel_param != 0 && p_.get(d_.sw.z_cancel_param) != 0.0 && m_.axis_index('Z') >= 0) {
    locked.set(m_.axis_index('Z'));
  }
  k.set_locked_axes(locked);
  plant.set_locked(locked);
  kernel::OperatorState op;
  op.dry_run_feed_mm_min = d_.sw.dry_run_feed_param != 0
                               ? p_.get(d_.sw.dry_run_feed_param) * (m_.inch_machine ? 25.4 : 1.0)
                               : 0.0;
  std::size_t next_action = 0;  // scene [[operator]] actions not yet applied
  std::int64_t held_ticks = 0;  // periods the motion has stood held for ever

  kernel::TickInput tin;
  kernel::TickOutput tout;
  tout.commanded = home;
  AxisVec cmd_prev = home;
  bool waiting = false;  // the interpreter waits for a sync
  bool ending = false;   // the program ended; the machine finishes its motion
  bool held = false;     // an axis held away from its command ended the run
  double next_progress = 1.0;
  // The file of a call context (interpreter storage; the table only grows
  // while blocks are read, and a motion alarm ends the reading).
  auto file_of = [&](std::uint32_t ctx) -> std::string_view {
    const auto& cs = in.contexts();
    return ctx < cs.size() ? std::string_view(cs[ctx].file) : std::string_view(setup.program_name);
  };

  auto alarm = [&](Error e, std::uint32_t ctx) {
    res.status = RunStatus::kAlarm;
    res.alarm = std::move(e);
    res.alarm_context = ctx;
  };
  // A program error stops the reading of blocks; the motion already queued
  // is finished first, as if the blocks ran one by one, so the stopping
  // point does not depend on how far the planner had read ahead.
  std::optional<Error> program_alarm;
  BlockClock times;
  std::uint32_t program_alarm_context = 0;
  // --strict: a warning of the set-up (the probe's length against its H,
  // grbl on a lagging servo) is an alarm before the first block unless
  // --allow or the scene's [strict] allow names it.
  // They are reported after the program's own (res.warnings, at the end).
  std::vector<interp::Warning> setup_warnings;
  if (auto w = probe_length_warning(plant.probing().spec())) setup_warnings.push_back(*w);
  if (auto w = grbl_servo_warning(m_, d_)) setup_warnings.push_back(*w);
  if (setup.strict) {
    if (const interp::Warning* w = first_refused(setup_warnings, setup.strict_allow)) {
      program_alarm =
          Error{AlarmId::kStrictWarning, w->code + ": " + w->text, SourceLoc{file_of(0), 0, 1}, -1};
      ending = true;
    }
  }

  // The trace's row of the period just run.
  auto trace_row = [&]() {
    TraceRow r;
    r.tick = k.now();
    r.time_s = k.clock().seconds(k.now());
    r.commanded = &cmd_prev;
    r.actual = &plant.actual();
    r.torque = &plant.torque();
    r.feed_mm_per_min = tout.path_speed * 60.0;
    r.line = tout.line;
    r.source = tout.source;
    work_now = frames.at(tout.tag).apply(plant.actual(), m_.axis_count());
    r.work = &work_now;
    r.file = file_of(tout.source);
    r.plant = &plant;
    r.handshake = tout.handshake;
    r.handshake_names = d_.handshake.empty() ? nullptr : &d_.handshake;
    return r;
  };

  // Periods that would each repeat the last one, the time aside (a dwell, a
  // feed hold): the kernel's command stands, the machine is still, the
  // interpreter waits for the machine, and nothing of the scene, the
  // operator, the trace's --trace-every or the time limit is due before
  // them. They are passed in one step: the run is the same, bit for bit,
  // as one period at a time (G04 X1e9 took minutes of processor time).
  auto quiet_periods = [&]() -> std::int64_t {
    if (!plant.still()) return 0;  // most periods: the axes move
    const bool reading = !waiting && !ending && router.drained() && k.can_accept();
    if (reading || tout.line == 0 || !safety.quiet(plant)) return 0;
    std::int64_t n = std::min(k.quiet_ticks(), plant.quiet_ticks(k.now()));
    if (n <= 0) return 0;
    const Tick now = k.now();
    n = std::min<std::int64_t>(n, m_.limits.max_ticks - now - 2);
    if (next_action < scene_.operator_actions.size()) {
      const double at = scene_.operator_actions[next_action].at_time_s;
      n = std::min<std::int64_t>(
          n, static_cast<std::int64_t>(std::floor(at / k.clock().period_s())) - now - 2);
    } else if (tout.time_scale < 1e-12) {
      return 0;  // held for ever: ends after a second (below), period by period
    }
    if (opts.trace != nullptr) {
      const std::int64_t s = std::max<std::int64_t>(1, opts.trace->stride());
      n = std::min<std::int64_t>(n, (now / s + 1) * s - now - 1);  // the next row is written
    }
    return n;
  };

  for (;;) {
    // Feed the kernel until it is full or the interpreter must wait: first
    // the motion of the last block that did not fit, then new blocks.
    // A signal is heard between blocks too: a macro loop without motion
    // runs many blocks within one period.
    router.drain();
    while (!waiting && !ending && router.drained() && k.can_accept() && !safety.holds_reading() &&
           !(opts.interrupt != nullptr && opts.interrupt->load(std::memory_order_relaxed))) {
      auto st = in.step(router);
      if (!st) {
        program_alarm = st.error();
        program_alarm_context = in.context();
        ending = true;
        break;
      }
      if (*st == interp::Step::kSync) waiting = true;
      if (*st == interp::Step::kEnd) ending = true;
      const interp::Warning* strict_w =
          setup.strict ? first_refused(safety.warnings(), setup.strict_allow) : nullptr;
      if (strict_w != nullptr) {
        // --strict: the machine's warning (a skip move that cannot stop in
        // the over-travel) is an alarm at its block unless --allow names
        // it; as for any program alarm, what is already queued (the skip
        // move too) runs first.
        const interp::Warning& w = *strict_w;
        program_alarm = Error{AlarmId::kStrictWarning, w.code + ": " + w.text,
                              SourceLoc{file_of(w.context), w.line, 1}, -1};
        program_alarm_context = w.context;
        ending = true;
        break;
      }
    }
    if (res.status != RunStatus::kCompleted) break;
    if (const auto& r = router.refused()) {
      alarm(Error{AlarmId::kInternal,
                  "the kernel's motion queue refused a command although it had room",
                  SourceLoc{file_of(r->source), r->line, 1}, -1},
            r->source);
      break;
    }

    // The operator's actions due by the start of this period.
    if (next_action < scene_.operator_actions.size()) {
      const double t0 = k.clock().seconds(k.now());
      bool changed = false;
      for (; next_action < scene_.operator_actions.size() &&
             scene_.operator_actions[next_action].at_time_s <= t0 + 1e-12;
           ++next_action) {
        const OperatorAction& a = scene_.operator_actions[next_action];
        if (a.feed_hold) op.feed_hold = *a.feed_hold;
        if (a.interlock) op.interlock = *a.interlock;
        if (a.override_pct) op.override_pct = *a.override_pct;
        if (a.dry_run) op.dry_run = *a.dry_run;
        changed = true;
      }
      if (changed) k.set_operator(op);
    }

    if (const std::int64_t quiet = quiet_periods(); quiet > 0) {
      k.pass_quiet(quiet);
      times.period(tout.source, tout.line, k.now());
    }

    // One servo period.
    const AxisVec& cmd = tout.commanded;
    if (tout.torque_limited || plant.torque_limited())
      plant.set_torque_limit(tout.torque_limit_pct);
    if (tout.followed_up) cmd_prev = cmd;  // a jump of the command, not motion
    // The period follows the command of the last tick: that command says
    // whether the tool cuts in it.
    if (has_stock) {
      const CutNote& cut = cuts.at(tout.tag);
      plant.probing().set_cutting(cut.cuts, cut.end);
    }
    plant.advance(k.now() + 1, cmd_prev, cmd, tin);
    cmd_prev = cmd;
    k.tick(tin, tout);
    times.period(tout.source, tout.line, k.now());
    if (tout.passed_dwell_line != 0) {
      times.passed(tout.passed_dwell_source, tout.passed_dwell_line, k.now());
    }
    if (opts.trace != nullptr) opts.trace->row(trace_row());
    // Tool changes, probe crash, collision, probe protection.
    if (auto s = safety.after_period(plant, k, tout.line, file_of(tout.source))) {
      alarm(std::move(s->error), tout.source);
      res.alarm_position = s->machine_position;
      break;
    }
    // The kernel's faults: an excess following error (an axis held by a
    // stop while the command runs on, as a torque limit skip with no torque
    // limit commanded), an axis that never reaches its command at rest (held
    // by a stop short of it: the control would wait for ever), a command
    // beyond a stroke end (not given to the servo).
    if (const kernel::Fault& f = tout.fault) {
      alarm(fault_alarm(m_, f, file_of(tout.source), tout.line), tout.source);
      held = f.kind != kernel::Fault::Kind::kStrokeLimit;
      break;
    }

    if (waiting && router.drained() && k.idle() && (!k.skip().active || k.skip().done)) {
      interp::SyncState s;
      s.machine_position = k.command();
      s.actual_position = plant.actual();
      s.time_s = k.clock().seconds(k.now());
      const kernel::SkipResult& sk = k.skip();
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
      k.clear_skip();
      waiting = false;
      auto r = in.sync(s);
      if (!r) {
        alarm(r.error(), in.context());
        break;
      }
    }
    if (ending && router.drained() && k.idle()) {
      if (program_alarm) alarm(*program_alarm, program_alarm_context);
      break;
    }
    // A feed held for ever: the motion stands (feed hold, interlock or
    // override 0 %: no profile time passes) with motion still to run, and
    // no later [[operator]] action of the scene can release it. It ends
    // after one second of it, not at limits.max_time_s.
    const bool hold_forever =
        tout.time_scale < 1e-12 && !k.idle() && next_action >= scene_.operator_actions.size();
    held_ticks = hold_forever ? held_ticks + 1 : 0;
    if (static_cast<double>(held_ticks) * k.clock().period_s() >= 1.0) {
      alarm(Error{AlarmId::kTimeLimit, held_reason(op) + held_never_released,
                  SourceLoc{file_of(tout.source), tout.line, 1}, -1},
            tout.source);
      break;
    }
    if (k.now() >= m_.limits.max_ticks) {
      alarm(Error{AlarmId::kTimeLimit, "the run passed limits.max_time_s of simulated time",
                  SourceLoc{file_of(tout.source), tout.line, 1}, -1},
            tout.source);
      break;
    }
    if (opts.interrupt != nullptr && opts.interrupt->load(std::memory_order_relaxed)) {
      // The block the stop cut: the one the machine runs, or while the
      // machine is idle the one the interpreter is at (a macro loop). Was
      // always the interpreter's, a block or more ahead of the machine.
      const bool moving = !k.idle() && tout.line != 0;
      const std::uint32_t ctx = moving ? tout.source : in.context();
      res.status = RunStatus::kInterrupted;
      res.alarm = Error{AlarmId::kInterrupted, "stopped by a signal",
                        SourceLoc{file_of(ctx), moving ? tout.line : in.line(), 1}, -1};
      res.alarm_context = ctx;
      break;
    }
    if (opts.progress) {
      const double t = k.clock().seconds(k.now());
      if (t >= next_progress) {
        opts.progress(t, in.line());
        next_progress = t + 1.0;
      }
    }
  }
  if (opts.trace != nullptr && k.now() > 0) opts.trace->last(trace_row());
  res.ticks = k.now();
  res.time_s = k.clock().seconds(k.now());
  res.block_times = times.finish();
  res.period_s = k.clock().period_s();
  // Where the axes are: the command, unless an axis was held away from it
  // (a fault) or held still (machine lock, Z-axis cancel: the machine
  // stays where it is while the work position follows the command).
  res.final_machine = held ? plant.actual() : k.command();
  res.final_work = in.work_from_machine(res.final_machine);
  for (int i = 0; i < m_.axis_count(); ++i) {
    if (locked.has(i)) res.final_machine[i] = plant.actual()[i];
  }
  res.skips = in.skips();
  if (const interp::SkipRecord* p = in.pending_skip(); p != nullptr && res.alarm) {
    res.skips.push_back(cut_short_skip(*p, k.skip(), res.alarm_position, in));
    res.skips.back().end_position = res.final_work;  // where the alarm stopped the axes
  }
  if (has_stock) res.stock = stock_result(plant.probing().stock());
  res.contexts = in.contexts();
  res.program_inch = in.modal().units == interp::Units::kInch;
  res.messages = in.messages();
  for (auto& msg : router.messages) res.messages.push_back(msg);
  for (const auto& msg : safety.messages()) res.messages.push_back(msg);
  res.warnings = in.warnings();
  for (const auto& w : safety.warnings()) res.warnings.push_back(w);
  for (auto& w : setup_warnings) res.warnings.push_back(std::move(w));
  // Every run that ended, by itself, by an alarm or by a signal (SIGTERM,
  // SIGINT: the run stops between periods) writes #500-#999 and the DPRNT
  // file (was: an interrupted run wrote neither).
  {
    const std::size_t said = in.messages().size();
    auto saved = in.save_persistent();
    // What saving said (the log files written: ngc_room.cpp).
    for (std::size_t i = said; i < in.messages().size(); ++i)
      res.messages.push_back(in.messages()[i]);
    if (!saved && res.status == RunStatus::kCompleted) alarm(saved.error(), 0);
    // After an alarm the run's alarm stays the first one; the failed save is
    // said in the messages (was: not said at all).
    if (!saved && res.status != RunStatus::kCompleted) {
      res.messages.push_back("persistent variables not saved: " + saved.error().detail);
    }
  }
  in.release_persistent();
  return res;
}

}  // namespace skipnc::sim
