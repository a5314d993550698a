// A table of the interpreter that an NC block may write (work offsets, tool
// offsets, G54.4's setting error data), too large to copy for every block: each write made while a
// block runs records the entry's old value first. A block that succeeds
// drops the records (commit); an alarmed block puts the old values back,
// latest first (roll_back). Outside a block (a macro statement is one
// write) nothing is recorded. docs/architecture.md "The block transaction".
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include "config/machine_config.hpp"
#include "core/axes.hpp"
#include "interpreter/variables.hpp"

namespace skipnc::interp {

template <class T>
class JournaledTable {
 public:
  void assign(std::size_t n, const T& v) {
    items_.assign(n, v);
    undo_.clear();
  }
  std::size_t size() const noexcept { return items_.size(); }
  const T& operator[](std::size_t i) const noexcept { return items_[i]; }
  typename std::vector<T>::const_iterator begin() const noexcept { return items_.begin(); }
  typename std::vector<T>::const_iterator end() const noexcept { return items_.end(); }

  // Entry i for writing; inside a block its value is recorded first.
  T& write(std::size_t i) {
    if (recording_) undo_.emplace_back(i, items_[i]);
    return items_[i];
  }
  // Every entry for writing, unrecorded: only before the run starts.
  std::vector<T>& setup() noexcept { return items_; }

  // The records are dropped when the block ends, so a block starts with none.
  void begin_block() noexcept { recording_ = true; }
  void commit() noexcept {
    recording_ = false;
    undo_.clear();
  }
  void roll_back() noexcept {
    for (auto it = undo_.rbegin(); it != undo_.rend(); ++it) items_[it->first] = it->second;
    commit();
  }

 private:
  std::vector<T> items_;
  std::vector<std::pair<std::size_t, T>> undo_;
  bool recording_ = false;
};

// The offset tables an NC block may write, begun, committed and rolled back
// together so that none is left out of the block transaction.
// `Interpreter::Impl` derives from it (the members keep their names).
struct OffsetTables {
  // G54.4's data sets 0-7, ten values each (#26000-#26079).
  static constexpr std::size_t kSettingErrorValues = 80;

  // EXT, G54..G59, then G54.1 P1..P300 (mm); modal.work indexes it.
  JournaledTable<AxisVec> work_offsets;
  JournaledTable<config::ToolOffset> tools;  // index = offset number
  // G54.4 workpiece setting error data, #26000-#26079 (conversion_3d.cpp).
  JournaledTable<Value> setting_error_data;

  OffsetTables() { setting_error_data.assign(kSettingErrorValues, Value{}); }
  void begin_offsets() noexcept {
    work_offsets.begin_block();
    tools.begin_block();
    setting_error_data.begin_block();
  }
  void commit_offsets() noexcept {
    work_offsets.commit();
    tools.commit();
    setting_error_data.commit();
  }
  void roll_back_offsets() noexcept {
    work_offsets.roll_back();
    tools.roll_back();
    setting_error_data.roll_back();
  }
};

// A value an NC block seldom writes, too large to copy at the start of every
// block: inside a block, the first write() copies it first; a block that
// succeeds drops the copy (commit), an alarmed block puts it back
// (roll_back). Outside a block nothing is copied.
template <class T>
class BlockSaved {
  static_assert(std::is_nothrow_copy_assignable_v<T>);

 public:
  const T& get() const noexcept { return value_; }
  T& write() noexcept {
    if (recording_ && !saved_) {
      before_ = value_;
      saved_ = true;
    }
    changed_ = true;
    return value_;
  }
  // Whether the value may have changed (a write, a roll back) since the
  // last call: what is derived from it is found again only then.
  bool take_changed() noexcept { return std::exchange(changed_, false); }

  void begin_block() noexcept {
    recording_ = true;
    saved_ = false;
  }
  void commit() noexcept { recording_ = false; }
  void roll_back() noexcept {
    if (saved_) {
      value_ = before_;
      changed_ = true;
    }
    recording_ = false;
    saved_ = false;
  }

 private:
  T value_{};
  T before_{};
  bool recording_ = false;
  bool saved_ = false;
  bool changed_ = true;
};

}  // namespace skipnc::interp
