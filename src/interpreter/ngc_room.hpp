// LinuxCNC's facilities beside the language proper (ngc_room.cpp): the
// modal state M70/M73 save and M72 restores, the files (LOGOPEN,...) and
// (PROBEOPEN ...) write, and the INI/HAL values a program reads. Kept in one
// object of the interpreter so that the rest of it does not carry them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "interpreter/modal.hpp"

namespace skipnc::interp {

// A modal state saved by M70 (or M73: restored on return) at a call level.
struct NgcSavedState {
  std::size_t level = 0;  // frames.size() when saved
  ModalState modal;
  double length_offset = 0.0;  // mm
  bool autorestore = false;    // M73
};

// A file the program writes: (LOGOPEN,name) / (LOGAPPEND,name) or
// (PROBEOPEN name). Its text is kept and written at the end of the run.
struct NgcLogFile {
  std::string name;
  std::string text;
  bool probe = false;
  std::size_t lines = 0;
};

struct NgcRoom {
  std::vector<NgcSavedState> saved;  // at most one per call level
  std::vector<NgcLogFile> files;     // every file opened, in order
  int log = -1;                      // the open log (index in files), -1: none
  int probe = -1;                    // the open probe log
};

}  // namespace skipnc::interp
