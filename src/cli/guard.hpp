// What keeps a run from ending badly: signals, the processor-time limit and
// the progress display.
//
// SIGINT and SIGTERM ask the run to stop (the simulator stops at the next
// servo period or between two blocks; the outputs are then written whole, as
// after an alarm); a second one ends skipnc at once (the handler is reset).
// SIGPIPE is ignored, so that writing to a closed pipe is an error (EPIPE)
// that the run reports, not a silent death; SIGXFSZ likewise (EFBIG).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

namespace skipnc::cli {

// Why a run was asked to stop before its end; the first reason wins.
enum class StopReason : int { kNone, kSignal, kCpuLimit, kOutput };

struct RunStop {
  std::atomic<bool> flag{false};
  std::atomic<int> reason{static_cast<int>(StopReason::kNone)};
  std::atomic<int> signal{0};

  void request(StopReason r) noexcept;
  StopReason why() const noexcept { return static_cast<StopReason>(reason.load()); }
  // Clears a reason that belongs to one run only (CPU, output): a signal stays.
  void reset_run() noexcept;
};

// The process's one RunStop (the signal handler sets it).
RunStop& run_stop() noexcept;

// SIGINT, SIGTERM -> run_stop(); SIGPIPE ignored. Call once, first thing.
void install_signal_handlers() noexcept;

// A thread beside the run: checks the processor time of the run against its
// limit (limits.max_cpu_s: run_stop().request(kCpuLimit)) and shows progress
// on standard error: with `lines`, one line every kLinePeriodS seconds (for a
// log, without a terminal); else, when standard error is a terminal, one line
// rewritten in place.
class Watchdog {
 public:
  struct Options {
    double max_cpu_s = 0.0;  // 0: no limit
    bool lines = false;      // --progress
    bool terminal = false;   // standard error is a terminal and not --quiet
  };
  static constexpr double kLinePeriodS = 2.0;
  static constexpr double kTerminalPeriodS = 0.5;
  static constexpr double kQuietStartS = 1.0;  // a short run shows nothing

  explicit Watchdog(Options o);
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  // Starts counting one run's processor time (--repeat: each repetition).
  void start_run() noexcept;
  // From the simulator's progress callback: where the run is.
  void update(double simulated_s, std::uint32_t line) noexcept;
  // Processor seconds of the running run.
  double run_cpu_s() const noexcept;

 private:
  void loop();
  void show(double wall_s, bool final_line);

  Options o_;
  std::atomic<double> cpu0_{0.0};
  std::atomic<double> sim_s_{0.0};
  std::atomic<std::uint32_t> line_{0};
  std::mutex m_;
  std::condition_variable cv_;
  bool done_ = false;
  bool shown_ = false;
  std::thread thread_;
};

// Processor time of the whole process, seconds.
double process_cpu_s() noexcept;

}  // namespace skipnc::cli
