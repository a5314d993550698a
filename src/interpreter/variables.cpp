#include "interpreter/variables.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/file.hpp"

namespace skipnc::interp {

VariableStore::VariableStore() {
  locals_.emplace_back();
}

void VariableStore::push_level() {
  locals_.emplace_back();
  named_local_.emplace_back();
}

void VariableStore::pop_level() {
  if (locals_.size() > 1) locals_.pop_back();
  if (named_local_.size() > 1) named_local_.pop_back();
}

void VariableStore::enable_ngc() {
  ngc_params_.assign(kNgcParams, 0.0);
  ngc_touched_.assign(kNgcParams, false);
}

Value* VariableStore::local_named(const std::string& name) {
  auto& m = named_local_.back();
  auto it = m.find(name);
  return it == m.end() ? nullptr : &it->second;
}

void VariableStore::set_local_named(const std::string& name, Value v) {
  named_local_.back()[name] = v;
}

Value VariableStore::get(int n) const noexcept {
  if (is_local(n)) return locals_.back()[static_cast<std::size_t>(n)];
  if (is_common(n)) return common_[static_cast<std::size_t>(n - 100)];
  if (is_persistent(n)) return persistent_[static_cast<std::size_t>(n - 500)];
  return Value::null();
}

void VariableStore::set(int n, Value v) noexcept {
  if (is_local(n)) {
    locals_.back()[static_cast<std::size_t>(n)] = v;
  } else if (is_common(n)) {
    common_[static_cast<std::size_t>(n - 100)] = v;
  } else if (is_persistent(n)) {
    persistent_[static_cast<std::size_t>(n - 500)] = v;
    persistent_dirty_ = true;
  }
}

Value VariableStore::get_named(const std::string& name) const noexcept {
  if (auto it = named_.find(name); it != named_.end()) return it->second;
  return Value::null();
}

void VariableStore::set_named(const std::string& name, Value v) {
  named_[name] = v;
}

void VariableStore::clear_common() noexcept {
  common_.fill(Value::null());
}

Result<void> load_var_file(const std::string& path, std::vector<int>& numbers,
                           std::vector<double>& values) {
  numbers.clear();
  values.clear();
  std::ifstream in(path);
  if (!in) {
    if (errno == ENOENT) return {};  // a new file: written at the end
    return fail(AlarmId::kConfig, "cannot read the parameter file '" + path + "'");
  }
  std::string line;
  std::uint32_t lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::size_t i = line.find_first_not_of(" \t\r");
    if (i == std::string::npos) continue;
    int n = 0;
    double v = 0.0;
    char tail = 0;
    if (std::sscanf(line.c_str() + i, "%d %lf %c", &n, &v, &tail) != 2 || n < 1 ||
        n >= VariableStore::kNgcParams || !std::isfinite(v)) {
      return std::unexpected(Error{AlarmId::kConfig,
                                   "a parameter file line is \"NUMBER VALUE\" with NUMBER 1-" +
                                       std::to_string(VariableStore::kNgcParams - 1),
                                   SourceLoc{path, lineno, static_cast<std::uint32_t>(i + 1)}, -1});
    }
    numbers.push_back(n);
    values.push_back(v);
  }
  return {};
}

Result<void> save_var_file(const std::string& path, const std::vector<int>& numbers,
                           const std::vector<double>& values) {
  std::string text;
  char buf[64];
  for (std::size_t i = 0; i < numbers.size() && i < values.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%d\t%.6f\n", numbers[i], values[i]);
    text += buf;
  }
  return write_file_atomic(path, text);
}

// File format: one line per non-vacant variable, "#<n> = <value>" with 17
// significant digits; comment lines start with ';'. Unknown content is an
// error with its line, so a damaged file is never half-used.
Result<void> load_persistent(const std::string& path, std::array<Value, 500>& out) {
  std::ifstream in(path);
  if (!in) {
    if (errno == ENOENT) return {};  // first run: nothing kept yet
    return fail(AlarmId::kConfig, "cannot read persistent variables '" + path + "'");
  }
  std::array<Value, 500> vals{};
  std::string line;
  std::uint32_t lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == ';') continue;
    int n = 0;
    double v = 0.0;
    char tail = 0;
    if (std::sscanf(line.c_str(), "#%d = %lf %c", &n, &v, &tail) != 2 || n < 500 || n > 999) {
      return fail(AlarmId::kConfig,
                  "persistent variable file '" + path + "': line " + std::to_string(lineno) +
                      " is not '#<500-999> = <number>'",
                  SourceLoc{{}, lineno, 1});
    }
    if (!std::isfinite(v)) {
      // NaN or a number beyond the double range: never a value a run wrote.
      return fail(AlarmId::kConfig,
                  "persistent variable file '" + path + "': line " + std::to_string(lineno) +
                      ": #" + std::to_string(n) + " is not a finite number",
                  SourceLoc{{}, lineno, 1});
    }
    vals[static_cast<std::size_t>(n - 500)] = Value::of(v);
  }
  out = vals;
  return {};
}

Result<void> save_persistent(const std::string& path, const std::array<Value, 500>& values) {
  std::string text = "; skipnc persistent macro variables #500-#999\n";
  char buf[64];
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i].vacant) continue;
    std::snprintf(buf, sizeof buf, "#%zu = %.17g\n", i + 500, values[i].v);
    text += buf;
  }
  return write_file_atomic(path, text);
}

PersistentLock& PersistentLock::operator=(PersistentLock&& o) noexcept {
  if (this != &o) {
    release();
    fd_ = o.fd_;
    o.fd_ = -1;
  }
  return *this;
}

void PersistentLock::release() noexcept {
  if (fd_ >= 0) {
    ::flock(fd_, LOCK_UN);
    ::close(fd_);
    fd_ = -1;
  }
}

Result<PersistentLock> PersistentLock::acquire(const std::string& path, double wait_s) {
  PersistentLock lock;
  const std::string name = path + ".lock";
  const int fd = ::open(name.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd < 0) {
    if (errno == EACCES || errno == EROFS || errno == EPERM) return lock;  // read-only: no lock
    return fail(AlarmId::kFileAccess,
                "cannot open the lock '" + name + "': " + std::strerror(errno));
  }
  lock.fd_ = fd;
  // Poll rather than block: a run that holds the file for ever (a bug, a
  // stopped process) ends in an alarm, not a hang.
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
  while (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    if (errno != EWOULDBLOCK && errno != EINTR) {
      return fail(AlarmId::kFileAccess, "cannot lock '" + name + "': " + std::strerror(errno));
    }
    if (std::chrono::steady_clock::now() >= until) {
      return fail(AlarmId::kFileAccess,
                  "persistent variables '" + path + "' are in use by another run (lock '" + name +
                      "' held for more than " + std::to_string(static_cast<int>(wait_s)) + " s)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return lock;
}

}  // namespace skipnc::interp
