// The output channel of DPRNT/BPRNT between POPEN and PCLOS (Custom Macro
// B): the lines kept for the --dprnt file, written whole at the end of the
// run (macro_flow.cpp). Held by the interpreter as one member.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "core/diag.hpp"
#include "interpreter/flow.hpp"

namespace skipnc::interp {

class PrintChannel {
 public:
  // `path`: the --dprnt file (empty: the lines go to the messages only);
  // `limit`: limits.max_dprnt_bytes.
  PrintChannel(std::string path, std::int64_t limit) : path_(std::move(path)), limit_(limit) {}

  void open() noexcept {  // POPEN
    open_ = true;
    used_ = true;
  }
  void close() noexcept { open_ = false; }  // PCLOS
  // Keeps one printed line for the file while the channel is open and a
  // file was named; past the limit, alarm kDprntLimit at `where`.
  Flow<void> keep(const std::string& line, SourceLoc where);
  // The file, written whole (temporary file, then rename) when POPEN ran.
  Result<void> write() const;

 private:
  std::string path_;
  std::int64_t limit_ = 0;
  std::string text_;
  bool open_ = false;
  bool used_ = false;
};

}  // namespace skipnc::interp
