#include "interpreter/variables.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <thread>
#include <vector>

#include "core/file.hpp"

namespace skipnc::interp {

VariableStore::VariableStore() {
  locals_.emplace_back();
}

void VariableStore::push_level() {
  if (recording_) record(Undo::kPush, 0);
  locals_.emplace_back();
  named_local_.emplace_back();
}

void VariableStore::pop_level() {
  if (recording_ && locals_.size() > 1) {
    record(Undo::kPop, 0);
    popped_.push_back(Level{locals_.back(), std::move(named_local_.back())});
  }
  if (locals_.size() > 1) locals_.pop_back();
  if (named_local_.size() > 1) named_local_.pop_back();
}

void VariableStore::enable_ngc_params() {
  ngc_params_.assign(kNgcParams, 0.0);
  ngc_touched_.assign(kNgcParams, false);
}

Value* VariableStore::local_named(const std::string& name) {
  auto& m = named_local_.back();
  auto it = m.find(name);
  return it == m.end() ? nullptr : &it->second;
}

void VariableStore::set_local_named(const std::string& name, Value v) {
  if (recording_) record_named(Undo::kLocalNamed, name);
  named_local_.back()[name] = v;
}

void VariableStore::set(int n, Value v) {
  if (recording_) [[unlikely]] {
    record(Undo::kNumbered, n);
  }
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
  if (recording_) record_named(Undo::kNamed, name);
  named_[name] = v;
}

void VariableStore::clear_common() noexcept {
  common_.fill(Value::null());
}

// ---------------------------------------------------------------------------
// The block's journal.

void VariableStore::drop_records() noexcept {
  undo_.clear();
  popped_.clear();
}

void VariableStore::record(Undo::Kind kind, int n) {
  Undo u;
  u.kind = kind;
  u.n = n;
  if (kind == Undo::kNumbered) u.old = get(n);
  if (kind == Undo::kNgcParam) {
    u.old = Value::of(ngc_params_[static_cast<std::size_t>(n)]);
    u.existed = ngc_touched_[static_cast<std::size_t>(n)];
  }
  undo_.push_back(std::move(u));
}

void VariableStore::record_named(Undo::Kind kind, const std::string& name) {
  const auto& m = kind == Undo::kNamed ? named_ : named_local_.back();
  Undo u;
  u.kind = kind;
  u.name = name;
  if (auto it = m.find(name); it != m.end()) {
    u.existed = true;
    u.old = it->second;
  }
  undo_.push_back(std::move(u));
}

void VariableStore::undo(Undo& u) {
  switch (u.kind) {
    case Undo::kNumbered:
      set(u.n, u.old);
      break;
    case Undo::kNgcParam:
      ngc_params_[static_cast<std::size_t>(u.n)] = u.old.v;
      ngc_touched_[static_cast<std::size_t>(u.n)] = u.existed;
      break;
    case Undo::kNamed:
    case Undo::kLocalNamed: {
      auto& m = u.kind == Undo::kNamed ? named_ : named_local_.back();
      if (u.existed) {
        m[u.name] = u.old;
      } else {
        m.erase(u.name);
      }
      break;
    }
    case Undo::kPush:
      pop_level();
      break;
    case Undo::kPop:
      locals_.push_back(popped_.back().locals);
      named_local_.push_back(std::move(popped_.back().named));
      popped_.pop_back();
      break;
  }
}

void VariableStore::roll_back() {
  recording_ = false;
  for (auto it = undo_.rbegin(); it != undo_.rend(); ++it) undo(*it);
  persistent_dirty_ = dirty_before_;
  drop_records();
}

namespace {

// A whole decimal number, nothing else (no sign, no hex, no overflow).
bool whole_number(std::string_view t, int& out) {
  const auto r = std::from_chars(t.data(), t.data() + t.size(), out);
  return !t.empty() && t.front() != '-' && r.ec == std::errc{} && r.ptr == t.data() + t.size();
}

// A finite decimal number ("1.5", "-2e3"; no hex, no inf or nan).
bool finite_number(std::string_view t, double& out) {
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  const auto r = std::from_chars(t.data(), t.data() + t.size(), out, std::chars_format::general);
  return !t.empty() && r.ec == std::errc{} && r.ptr == t.data() + t.size() && std::isfinite(out);
}

// "A B" or "A = B" split at blanks (and '=' when `equals`): the two words.
bool two_words(std::string_view line, bool equals, std::string_view& a, std::string_view& b) {
  auto blank = [&](char c) { return c == ' ' || c == '\t' || c == '\r' || (equals && c == '='); };
  std::vector<std::string_view> words;
  std::size_t i = 0;
  int eqs = 0;
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) eqs += line[i++] == '=' ? 1 : 0;
    const std::size_t start = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  if (words.size() != 2 || (equals && eqs != 1)) return false;
  a = words[0];
  b = words[1];
  return true;
}

// The file's text; "" for a file that does not exist yet (nothing kept yet).
Result<std::string> read_kept_file(const std::string& path, InputKind kind) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 && errno == ENOENT) return std::string();
  auto text = read_input_file(path, kind);
  if (!text) return fail(AlarmId::kConfig, text.error().detail);
  return text;
}

}  // namespace

// LinuxCNC's parameter file: "NUMBER VALUE" per line. A line that is not
// (a sign, hex, a number that overflows, a number given twice) is an error
// with its place: a damaged file is never half-used.
Result<void> load_var_file(const std::string& path, std::vector<int>& numbers,
                           std::vector<double>& values) {
  numbers.clear();
  values.clear();
  auto text = read_kept_file(path, kParameterFileInput);
  SKIPNC_TRY(text);
  std::vector<bool> seen(static_cast<std::size_t>(VariableStore::kNgcParams), false);
  std::istringstream in(*text);
  std::string line;
  std::uint32_t lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::size_t i = line.find_first_not_of(" \t\r");
    if (i == std::string::npos) continue;
    std::string_view a, b;
    int n = 0;
    double v = 0.0;
    const bool ok = two_words(line, false, a, b) && whole_number(a, n) && finite_number(b, v) &&
                    n >= 1 && n < VariableStore::kNgcParams;
    if (!ok || seen[static_cast<std::size_t>(n)]) {
      return std::unexpected(Error{AlarmId::kConfig,
                                   ok ? "parameter " + std::to_string(n) + " is given twice"
                                      : "a parameter file line is \"NUMBER VALUE\" with NUMBER 1-" +
                                            std::to_string(VariableStore::kNgcParams - 1) +
                                            " and a finite decimal VALUE",
                                   SourceLoc{path, lineno, static_cast<std::uint32_t>(i + 1)}, -1});
    }
    seen[static_cast<std::size_t>(n)] = true;
    numbers.push_back(n);
    values.push_back(v);
  }
  return {};
}

// Every value is written whole, whatever its size (%.6f as LinuxCNC writes
// it: 1e60 takes 68 characters).
Result<void> save_var_file(const std::string& path, const std::vector<int>& numbers,
                           const std::vector<double>& values) {
  std::string text;
  for (std::size_t i = 0; i < numbers.size() && i < values.size(); ++i) {
    text += fmt::format("{}\t{:.6f}\n", numbers[i], values[i]);
  }
  return write_file_atomic(path, text);
}

// File format: one line per non-vacant variable, "#<n> = <value>" with 17
// significant digits; comment lines start with ';'. Unknown content (hex, an
// overflowing number, a variable given twice) is an error with its line, so
// a damaged file is never half-used.
Result<void> load_persistent(const std::string& path, std::array<Value, 500>& out) {
  auto text = read_kept_file(path, kVariableFileInput);
  SKIPNC_TRY(text);
  std::array<Value, 500> vals{};
  std::istringstream in(*text);
  std::string line;
  std::uint32_t lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == ';') continue;
    std::string_view a, b;
    int n = 0;
    double v = 0.0;
    const bool ok = two_words(line, true, a, b) && a.starts_with('#') &&
                    whole_number(a.substr(1), n) && n >= 500 && n <= 999;
    if (!ok) {
      return fail(AlarmId::kConfig,
                  "persistent variable file '" + path + "': line " + std::to_string(lineno) +
                      " is not '#<500-999> = <number>'",
                  SourceLoc{{}, lineno, 1});
    }
    if (!finite_number(b, v) || !vals[static_cast<std::size_t>(n - 500)].vacant) {
      // NaN, hex or a number beyond the double range: never a value a run wrote.
      return fail(AlarmId::kConfig,
                  "persistent variable file '" + path + "': line " + std::to_string(lineno) +
                      ": #" + std::to_string(n) +
                      (finite_number(b, v) ? " is given twice" : " is not a finite decimal number"),
                  SourceLoc{{}, lineno, 1});
    }
    vals[static_cast<std::size_t>(n - 500)] = Value::of(v);
  }
  out = vals;
  return {};
}

Result<void> save_persistent(const std::string& path, const std::array<Value, 500>& values) {
  std::string text = "; skipnc persistent macro variables #500-#999\n";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i].vacant) continue;
    text += fmt::format("#{} = {:.17g}\n", i + 500, values[i].v);
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
  // A device or a FIFO is never a persistent file (nor is "<it>.lock" made).
  if (struct stat st{}; ::stat(path.c_str(), &st) == 0) {
    SKIPNC_TRY(check_input_file(path, kVariableFileInput));
  }
  int fd = ::open(name.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  // A lock file this user may not write (made by another user in a shared
  // folder): flock() holds on a descriptor open for reading too.
  if (fd < 0 && (errno == EACCES || errno == EROFS || errno == EPERM))
    fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) {
    // No lock can be held: two runs at once could lose an update. Refused.
    return fail(AlarmId::kFileAccess, "cannot hold the lock '" + name +
                                          "' of the persistent file (" + std::strerror(errno) +
                                          "): two runs at once could lose updates");
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
