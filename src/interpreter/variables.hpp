// Custom macro variables: local (#1-#33, one set per macro call level),
// common (#100-#199, #500-#999) and the vacant value. System variables are
// answered by the interpreter, which knows the state they describe.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/diag.hpp"

namespace skipnc::interp {

// A macro value: a number, or vacant (#0, never assigned).
struct Value {
  double v = 0.0;
  bool vacant = true;
  static constexpr Value of(double x) noexcept { return Value{x, false}; }
  static constexpr Value null() noexcept { return Value{0.0, true}; }
  // In arithmetic a vacant value counts as 0.
  constexpr double num() const noexcept { return vacant ? 0.0 : v; }
  friend constexpr bool operator==(const Value&, const Value&) = default;
};

inline constexpr int kLocalCount = 33;

class VariableStore {
 public:
  VariableStore();

  // Call levels: 0 is the main program; each G65/G66 call opens one.
  void push_level();
  void pop_level();
  int level() const noexcept { return static_cast<int>(locals_.size()) - 1; }
  std::array<Value, kLocalCount + 1>& locals() noexcept { return locals_.back(); }

  // Ordinary variables (not system): #1-#33, #100-#199, #500-#999.
  static bool is_local(int n) noexcept { return n >= 1 && n <= kLocalCount; }
  static bool is_common(int n) noexcept { return n >= 100 && n <= 199; }
  static bool is_persistent(int n) noexcept { return n >= 500 && n <= 999; }
  // An ordinary variable's value: false, `out` untouched, when n is not
  // one. Inline: each variable read of an expression's fast path comes here.
  [[gnu::always_inline]] bool find(int n, Value& out) const noexcept {
    if (is_local(n)) {
      out = locals_.back()[static_cast<std::size_t>(n)];
    } else if (is_common(n)) {
      out = common_[static_cast<std::size_t>(n - 100)];
    } else if (is_persistent(n)) {
      out = persistent_[static_cast<std::size_t>(n - 500)];
    } else {
      return false;
    }
    return true;
  }
  // An ordinary variable's value, vacant for any other n.
  [[gnu::always_inline]] Value get(int n) const noexcept {
    Value v = Value::null();
    find(n, v);
    return v;
  }
  void set(int n, Value v);

  // Named variables (#<name>), created on first write.
  Value get_named(const std::string& name) const noexcept;
  void set_named(const std::string& name, Value v);
  bool has_named(const std::string& name) const noexcept { return named_.contains(name); }
  std::size_t named_count() const noexcept { return named_.size(); }

  // RS274NGC (LinuxCNC): numbered parameters #31-#5602 are one global
  // store, 0 until set (no vacant value); #1-#30 are local to a call level;
  // named parameters without a leading '_' are local to a call level too.
  static constexpr int kNgcParams = 5603;  // #0-#5602 (RS274NGC_MAX_PARAMETERS)
  void enable_ngc_params();
  double ngc_param(int n) const noexcept { return ngc_params_[static_cast<std::size_t>(n)]; }
  void set_ngc_param(int n, double v) {
    if (recording_) [[unlikely]] {
      record(Undo::kNgcParam, n);
    }
    ngc_params_[static_cast<std::size_t>(n)] = v;
    ngc_touched_[static_cast<std::size_t>(n)] = true;
  }
  bool ngc_touched(int n) const noexcept { return ngc_touched_[static_cast<std::size_t>(n)]; }
  const std::unordered_map<std::string, Value>* find_local_named(const std::string& name) const;
  Value* local_named(const std::string& name);
  void set_local_named(const std::string& name, Value v);
  std::size_t local_named_count() const noexcept { return named_local_.back().size(); }

  // Reset clears #100-#199 (Fanuc: vacant at reset); #500-#999 are kept.
  void clear_common() noexcept;
  const std::array<Value, 500>& persistent() const noexcept { return persistent_; }
  std::array<Value, 500>& persistent() noexcept { return persistent_; }
  bool persistent_dirty() const noexcept { return persistent_dirty_; }

  // The journal of an NC block (docs/architecture.md "The block
  // transaction"): between begin_block() and commit() or roll_back(), each
  // write and each call level opened or closed is recorded, so that
  // roll_back() leaves every variable and level as before the block.
  void begin_block() noexcept {
    dirty_before_ = persistent_dirty_;
    recording_ = true;
  }
  void commit() noexcept {
    recording_ = false;
    if (!undo_.empty()) drop_records();
  }
  void roll_back();

 private:
  struct Undo {
    enum Kind : std::uint8_t { kNumbered, kNgcParam, kNamed, kLocalNamed, kPush, kPop };
    Kind kind = kNumbered;
    bool existed = false;  // kNamed, kLocalNamed: the name had a value; kNgcParam: touched
    int n = 0;
    Value old;
    std::string name;
  };
  // A call level closed inside the block, kept for roll_back().
  struct Level {
    std::array<Value, kLocalCount + 1> locals;
    std::unordered_map<std::string, Value> named;
  };
  [[gnu::noinline]] void record(Undo::Kind kind, int n);
  void record_named(Undo::Kind kind, const std::string& name);
  void undo(Undo& u);
  void drop_records() noexcept;
  bool recording_ = false;
  bool dirty_before_ = false;
  std::vector<Undo> undo_;
  std::vector<Level> popped_;

  std::vector<std::array<Value, kLocalCount + 1>> locals_;
  std::array<Value, 100> common_{};      // #100-#199
  std::array<Value, 500> persistent_{};  // #500-#999
  bool persistent_dirty_ = false;
  std::unordered_map<std::string, Value> named_;
  std::vector<double> ngc_params_;
  std::vector<bool> ngc_touched_;
  std::vector<std::unordered_map<std::string, Value>> named_local_{1};
};

// LinuxCNC's parameter file (the INI's PARAMETER_FILE, "*.var"): one line
// per parameter, "NUMBER VALUE". The parameters it lists are read at the
// start and written back at the end (atomically: a temporary file in the
// same folder, renamed), with #5161-#5390 always among them, as LinuxCNC
// does. `numbers` gets the parameters listed.
[[nodiscard]] Result<void> load_var_file(const std::string& path, std::vector<int>& numbers,
                                         std::vector<double>& values);
[[nodiscard]] Result<void> save_var_file(const std::string& path, const std::vector<int>& numbers,
                                         const std::vector<double>& values);

// Reads and writes the persistent-variable file (#500-#999). Writing is
// atomic: a temporary file in the same folder, flushed and renamed.
[[nodiscard]] Result<void> load_persistent(const std::string& path, std::array<Value, 500>& out);
[[nodiscard]] Result<void> save_persistent(const std::string& path,
                                           const std::array<Value, 500>& values);

// The lock of a persistent-variable file: `<path>.lock` beside it, held
// (flock, exclusive) from the read of one run to its write, so that runs
// sharing the file wait for each other instead of losing updates. A file
// whose folder cannot hold the lock (read-only) is used without one.
class PersistentLock {
 public:
  PersistentLock() = default;
  PersistentLock(const PersistentLock&) = delete;
  PersistentLock& operator=(const PersistentLock&) = delete;
  PersistentLock(PersistentLock&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
  PersistentLock& operator=(PersistentLock&& o) noexcept;
  ~PersistentLock() { release(); }

  // Waits up to `wait_s` for the lock; then file_access "in use".
  [[nodiscard]] static Result<PersistentLock> acquire(const std::string& path, double wait_s);
  void release() noexcept;
  bool held() const noexcept { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace skipnc::interp
