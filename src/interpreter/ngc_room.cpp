// LinuxCNC's modal state save/restore, log files and INI/HAL values
// (ngc_room.hpp), after LinuxCNC's "M Codes" (M70-M73), "Comments" (LOG,
// LOGOPEN, LOGAPPEND, LOGCLOSE, PROBEOPEN, PROBECLOSE) and "Named
// Parameters" (#<_ini[section]name>, #<_hal[pin]>) documentation.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/file.hpp"
#include "interpreter/impl.hpp"

namespace skipnc::interp {
namespace {

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

std::string trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s);
}

// A key of `table` equal to `want` ignoring case (LinuxCNC's reader folds
// the name of a named parameter to lower case; INI keys are upper case).
template <class Map>
auto find_folded(Map& table, const std::string& want) {
  return std::find_if(table.begin(), table.end(),
                      [&](const auto& kv) { return lower(kv.first) == lower(want); });
}

}  // namespace

// M70 save, M71 invalidate, M72 restore, M73 save and restore on return.
// The state saved is the one before the block's own modes (LinuxCNC saves it
// early in a block's order of execution); the motion mode is not part of it.
Flow<void> LinuxcncFamily::state_codes(Impl& im, const Words& words, const ModalState& before,
                                       SourceLoc where) {
  for (int i = 0; i < words.m_count; ++i) {
    const int m = words.m[static_cast<std::size_t>(i)];
    if (m < 70 || m > 73) continue;
    const std::size_t level = im.programs.frames.size();
    auto& saved = state.room.saved;
    auto it = std::find_if(saved.begin(), saved.end(),
                           [&](const NgcSavedState& s) { return s.level == level; });
    if (m == 70 || m == 73) {
      if (m == 73 && level == 1) continue;  // the main program: nothing to return from
      NgcSavedState s{level, before, im.length_offset, m == 73};
      if (it != saved.end()) {
        *it = s;
      } else {
        saved.push_back(s);
      }
    } else if (m == 71) {
      if (it != saved.end()) saved.erase(it);
    } else {
      if (it == saved.end()) {
        return fail(AlarmId::kBadValue, "M72 without a state saved by M70 at this call level",
                    where);
      }
      restore_state(im, *it);
    }
  }
  return {};
}

// The states saved as the block began: kept when there are any, put back
// if the block is alarmed.
void LinuxcncFamily::begin_block() {
  had_saved_ = !state.room.saved.empty();
  if (had_saved_) saved_before_ = state.room.saved;
}

void LinuxcncFamily::roll_back_block() {
  if (had_saved_) {
    state.room.saved = saved_before_;
  } else {
    state.room.saved.clear();
  }
}

void LinuxcncFamily::restore_state(Impl& im, const NgcSavedState& s) {
  const ModalState& m = s.modal;
  im.modal.units = m.units;
  im.modal.plane = m.plane;
  im.modal.distance = m.distance;
  im.modal.feed_mode = m.feed_mode;
  im.modal.ret = m.ret;
  im.modal.path = m.path;
  im.modal.arc_ijk_absolute = m.arc_ijk_absolute;
  im.modal.spindle_mode = m.spindle_mode;
  im.modal.feed = m.feed;
  im.modal.spindle = m.spindle;
  im.modal.spindle_dir = m.spindle_dir;
  im.modal.length = m.length;
  im.modal.h = m.h;
  im.length_offset = s.length_offset;
  if (m.work != im.modal.work && m.work >= 1 && m.work <= 9) select_work(im, m.work);
  im.modal.work = m.work;
}

// A sub returns (endsub / return): the state its M73 saved comes back, and
// what the level saved goes away with it.
void LinuxcncFamily::state_on_return(Impl& im) {
  const std::size_t level = im.programs.frames.size();
  auto& saved = state.room.saved;
  for (const NgcSavedState& s : saved) {
    if (s.level == level && s.autorestore) restore_state(im, s);
  }
  std::erase_if(saved, [&](const NgcSavedState& s) { return s.level >= level; });
}

// (LOGOPEN,name) (LOGAPPEND,name) (LOGCLOSE) (LOG,text) (PROBEOPEN name)
// (PROBECLOSE); any other comment is a comment.
Flow<void> LinuxcncFamily::log_comment(Impl& im, std::string_view text, SourceLoc where) {
  const std::string head = lower(text.substr(0, std::min<std::size_t>(text.size(), 10)));
  auto open = [&](std::string_view name, bool probe) -> Flow<void> {
    const std::string n = trimmed(name);
    if (n.empty() || n.find_first_of("/\\") != std::string::npos || n == "." || n == "..") {
      return fail(AlarmId::kFileAccess,
                  "'" + n + "': a log file is a plain file name, written in --log-dir", where);
    }
    state.room.files.push_back(NgcLogFile{n, {}, probe, 0});
    (probe ? state.room.probe : state.room.log) = static_cast<int>(state.room.files.size()) - 1;
    return {};
  };
  if (head.starts_with("logopen,")) return open(text.substr(8), false);
  if (head.starts_with("logappend,")) return open(text.substr(10), false);
  if (head.starts_with("probeopen")) return open(text.substr(9), true);
  if (head.starts_with("logclose")) {
    state.room.log = -1;
  } else if (head.starts_with("probeclose")) {
    state.room.probe = -1;
  } else if (head.starts_with("log,") && state.room.log >= 0) {
    auto m = message_text(im, text.substr(4), where);
    SKIPNC_TRY(m);
    NgcLogFile& f = state.room.files[static_cast<std::size_t>(state.room.log)];
    f.text += *m + "\n";
    ++f.lines;
  }
  return {};
}

// After each G38: the nine coordinates X Y Z A B C U V W (#5061-#5069) on a
// line of the open probe log, as LinuxCNC's "%f" prints them.
void LinuxcncFamily::probe_log(Impl& im) {
  if (state.room.probe < 0) return;
  NgcLogFile& f = state.room.files[static_cast<std::size_t>(state.room.probe)];
  char buf[48];
  for (int n = 5061; n <= 5069; ++n) {
    std::snprintf(buf, sizeof buf, "%s%f", n == 5061 ? "" : " ", im.vars.ngc_param(n) + 0.0);
    f.text += buf;
  }
  f.text += "\n";
  ++f.lines;
}

// The files at the end of the run: written whole in setup.log_dir, or, with
// none, their lines given as messages; either way one message names each.
Result<void> LinuxcncFamily::write_logs(Impl& im) {
  for (const NgcLogFile& f : state.room.files) {
    const char* kind = f.probe ? "probe log '" : "log '";
    if (im.setup.log_dir.empty()) {
      im.add_message(kind + f.name + "': " + std::to_string(f.lines) +
                     " lines, not written (no --log-dir)");
      continue;
    }
    const std::filesystem::path p = std::filesystem::path(im.setup.log_dir) / f.name;
    auto r = write_file_atomic(p.string(), f.text);
    if (!r) return r;
    im.add_message(kind + f.name + "': " + std::to_string(f.lines) + " lines written");
  }
  return {};
}

// #<_ini[SECTION]NAME> and #<_hal[pin]> from the machine file's [ini] and
// [hal] tables; nullopt when `n` (lower case) is neither form.
std::optional<Flow<Value>> LinuxcncFamily::ini_hal(Impl& im, const std::string& n,
                                                   SourceLoc where) {
  const bool ini = n.starts_with("_ini[");
  if (!ini && !n.starts_with("_hal[")) return std::nullopt;
  const std::size_t close = n.find(']');
  if (close == std::string::npos) return std::nullopt;
  const std::string first = n.substr(5, close - 5);
  if (!ini) {
    auto it = find_folded(im.mc.hal, first);
    if (it != im.mc.hal.end()) return Flow<Value>(Value::of(it->second));
    return Flow<Value>(fail(AlarmId::kNamedUndefined,
                            "#<_hal[" + first + "]>: the machine file has no such pin; add it " +
                                "to its [hal] table: \"" + first + "\" = value",
                            where));
  }
  const std::string key = n.substr(close + 1);
  auto sec = find_folded(im.mc.ini, first);
  if (sec != im.mc.ini.end()) {
    auto it = find_folded(sec->second, key);
    if (it != sec->second.end()) return Flow<Value>(Value::of(it->second));
  }
  std::string s = first, k = key;
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (char& c : k) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return Flow<Value>(fail(AlarmId::kNamedUndefined,
                          "#<_ini[" + first + "]" + key + ">: the machine file has no such " +
                              "INI value; add it: [ini." + s + "] " + k + " = value",
                          where));
}

}  // namespace skipnc::interp
