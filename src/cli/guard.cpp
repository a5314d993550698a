#include "cli/guard.hpp"

#include <signal.h>
#include <time.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace skipnc::cli {

void RunStop::request(StopReason r) noexcept {
  int none = static_cast<int>(StopReason::kNone);
  reason.compare_exchange_strong(none, static_cast<int>(r));
  flag.store(true);
}

void RunStop::reset_run() noexcept {
  if (why() == StopReason::kSignal) return;
  reason.store(static_cast<int>(StopReason::kNone));
  flag.store(false);
}

RunStop& run_stop() noexcept {
  static RunStop stop;
  return stop;
}

namespace {

extern "C" void on_stop_signal(int sig) {
  // Only lock-free atomic stores: async-signal-safe.
  run_stop().signal.store(sig);
  run_stop().request(StopReason::kSignal);
}

}  // namespace

void install_signal_handlers() noexcept {
  (void)run_stop();  // constructed before any signal can come
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  // No SA_RESTART: a blocking call (opening a FIFO, waiting for the
  // persistent-variable lock) returns EINTR and the run stops. SA_RESETHAND:
  // a second signal ends skipnc at once.
  sa.sa_flags = SA_RESETHAND;
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
  struct sigaction ign {};
  ign.sa_handler = SIG_IGN;
  sigemptyset(&ign.sa_mask);
  ::sigaction(SIGPIPE, &ign, nullptr);
  // A file larger than `ulimit -f` allows: the write fails with EFBIG and the
  // run ends with the output's alarm and its report, not killed by SIGXFSZ.
  ::sigaction(SIGXFSZ, &ign, nullptr);
  // A caller that must be able to stop skipnc from its first instant (before
  // main() could set these handlers) starts it with SIGINT and SIGTERM
  // blocked: they are unblocked here, a signal that came meanwhile is heard now.
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  ::sigprocmask(SIG_UNBLOCK, &stop, nullptr);
}

double process_cpu_s() noexcept {
  timespec ts{};
  if (::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0) return 0.0;
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

Watchdog::Watchdog(Options o) : o_(o) {
  start_run();
  if (o_.max_cpu_s > 0.0 || o_.lines || o_.terminal) thread_ = std::thread([this] { loop(); });
}

Watchdog::~Watchdog() {
  {
    std::lock_guard<std::mutex> lock(m_);
    done_ = true;
  }
  cv_.notify_all();
  if (thread_.joinable()) thread_.join();
  if (shown_ && o_.terminal && !o_.lines) std::fprintf(stderr, "\r%70s\r", "");
}

void Watchdog::start_run() noexcept {
  cpu0_.store(process_cpu_s());
}

void Watchdog::update(double simulated_s, std::uint32_t line) noexcept {
  sim_s_.store(simulated_s, std::memory_order_relaxed);
  line_.store(line, std::memory_order_relaxed);
}

double Watchdog::run_cpu_s() const noexcept {
  return process_cpu_s() - cpu0_.load();
}

void Watchdog::show(double wall_s, bool final_line) {
  const double sim = sim_s_.load(std::memory_order_relaxed);
  const unsigned line = line_.load(std::memory_order_relaxed);
  if (o_.lines) {
    std::fprintf(stderr, "skipnc: %.1f s simulated, line %u, %.1f s of processor time, %.0f s\n",
                 sim, line, run_cpu_s(), wall_s);
  } else {
    std::fprintf(stderr, "\r  %.0f s simulated, line %u ...%s", sim, line, final_line ? "\n" : "");
  }
  shown_ = true;
}

void Watchdog::loop() {
  using clock = std::chrono::steady_clock;
  const auto wall0 = clock::now();
  // The processor time is looked at ten times a second: a run stops within
  // 0.1 s of its limit.
  constexpr auto kTick = std::chrono::milliseconds(100);
  const double period = o_.lines ? kLinePeriodS : kTerminalPeriodS;
  double next_show = o_.lines ? kLinePeriodS : kQuietStartS;
  std::unique_lock<std::mutex> lock(m_);
  while (!done_) {
    cv_.wait_for(lock, kTick, [this] { return done_; });
    if (done_) break;
    if (o_.max_cpu_s > 0.0 && run_cpu_s() > o_.max_cpu_s) {
      run_stop().request(StopReason::kCpuLimit);
    }
    const double wall = std::chrono::duration<double>(clock::now() - wall0).count();
    if ((o_.lines || o_.terminal) && wall >= next_show) {
      show(wall, false);
      next_show = wall + period;
    }
  }
}

}  // namespace skipnc::cli
