// Starts the skipnc binary as a child process that a test can signal, time
// and measure (exit status or signal, peak memory, wall time). For tests of
// what the process does as a whole: interruption, kills, memory bounds.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace skipnc::test {

struct ChildExit {
  bool started = false;
  bool exited = false;     // ended by exit(); else by a signal (or still running)
  int code = -1;           // exit status
  int signal = 0;          // the signal that ended it
  bool timed_out = false;  // killed by wait_child after its time limit
  long max_rss_kb = 0;     // peak resident memory
  double wall_s = 0.0;
};

class Child {
 public:
  // Runs `skipnc args...` with standard output and error sent to the files.
  // With `stop_signals_blocked`, SIGINT and SIGTERM are blocked from the
  // start (posix_spawn's signal mask), as a caller does that must be able to
  // stop skipnc before its main() runs: skipnc unblocks them once its
  // handlers are set.
  Child(const std::vector<std::string>& args, const std::string& out_file = "/dev/null",
        const std::string& err_file = "/dev/null", bool stop_signals_blocked = false) {
    std::vector<std::string> argv_s;
    argv_s.emplace_back(SKIPNC_BINARY);
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    if (stop_signals_blocked) {
      sigset_t stop;
      sigemptyset(&stop);
      sigaddset(&stop, SIGINT);
      sigaddset(&stop, SIGTERM);
      posix_spawnattr_setsigmask(&attr, &stop);
      posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK);
    }
    start_ = std::chrono::steady_clock::now();
    started_ = ::posix_spawn(&pid_, argv[0], &fa, &attr, argv.data(), environ) == 0;
    posix_spawnattr_destroy(&attr);
    posix_spawn_file_actions_destroy(&fa);
  }
  ~Child() {
    if (started_ && !reaped_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  pid_t pid() const { return pid_; }
  bool started() const { return started_; }
  void signal(int sig) const {
    if (started_ && !reaped_) ::kill(pid_, sig);
  }
  double elapsed_s() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  // Waits for the child to end; after `timeout_s` it is killed and reported
  // as timed out (a hang).
  ChildExit wait(double timeout_s) {
    ChildExit r;
    r.started = started_;
    if (!started_ || reaped_) return r;
    int status = 0;
    struct rusage ru {};
    for (;;) {
      const pid_t w = ::wait4(pid_, &status, WNOHANG, &ru);
      if (w == pid_) break;
      if (w < 0) return r;
      if (elapsed_s() > timeout_s) {
        r.timed_out = true;
        ::kill(pid_, SIGKILL);
        ::wait4(pid_, &status, 0, &ru);
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    reaped_ = true;
    r.wall_s = elapsed_s();
    r.exited = WIFEXITED(status);
    r.code = r.exited ? WEXITSTATUS(status) : -1;
    r.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    r.max_rss_kb = ru.ru_maxrss;
    return r;
  }

 private:
  pid_t pid_ = -1;
  bool started_ = false;
  bool reaped_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace skipnc::test
