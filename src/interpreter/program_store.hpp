// The program store: the files of programs a run reads (the main program's
// and the ones called programs are found in), their indexes (O numbers,
// `o<name> sub` definitions, GOTO labels, WHILE exits, O-word jumps), the
// include folders, and the call frames. Lookups of a called program by
// number (M98, G65, G66), of a subroutine by name (o<name> call) and of a
// sequence number (GOTO, M99 P, M97) are its methods; the interpreter runs
// what they find (macro_call.cpp, oword.cpp, macro_flow.cpp).
//
// Each file is indexed by one scan (index()), the first time a lookup needs
// it: the O numbers (O<n>, :<n>) and the RS274NGC `o<label> sub` and
// `o<label> endsub` lines together. A file is scanned with a reader of its
// own, so the running read position is not disturbed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/diag.hpp"
#include "gcode/ast.hpp"
#include "gcode/parser.hpp"
#include "gcode/source.hpp"

namespace skipnc::interp {

// True when `p` (after resolving links) lies inside folder `dir`: called
// programs stay inside the include folders.
bool path_inside(const std::filesystem::path& p, const std::filesystem::path& dir);

// Whether a raw line can be an RS274NGC O-word: after spaces, an optional
// '/n' and an optional N number, an 'o'.
bool may_be_oword(std::string_view t) noexcept;

// An O-word label as LinuxCNC writes it: "o" and the label in lower case
// (the parser keeps names upper case).
std::string shown_oword(const std::string& label);

// A file of programs: the main program file or one found on the include path.
struct ProgramFile {
  std::string path;     // empty: the main program given as text
  std::string display;  // shown in errors (file name as given)
  std::unique_ptr<gcode::Source> src;
  // The one scan (ProgramStore::index): O numbers at the block after them,
  // `o<label> sub` definitions by label at the block after the sub, the
  // labels that have an `o<label> endsub`.
  bool indexed = false;
  std::unordered_map<std::int64_t, gcode::SourcePos> programs;
  std::unordered_map<std::string, gcode::SourcePos> subs;
  std::unordered_set<std::string> endsubs;
  // The GOTO / M99 P targets of each program of the file, keyed by the
  // offset of the program's first block (ProgramStore::find_label).
  struct LabelIndex {
    // Every N of the program sorted by (number, offset), found by one scan,
    // when there are at most limits.max_label_index of them.
    bool complete = false;
    std::vector<std::pair<std::int64_t, gcode::SourcePos>> all;
    // Otherwise the positions of each number asked for, one scan per number
    // (a cache of at most kLabelCache numbers).
    std::unordered_map<std::int64_t, std::vector<gcode::SourcePos>> asked;
  };
  static constexpr std::size_t kLabelCache = 4096;
  std::unordered_map<std::uint64_t, LabelIndex> labels;
  // A false WHILE: the position after its END, keyed by the WHILE block's
  // offset, found by the first scan; later passes jump there at once.
  std::unordered_map<std::uint64_t, gcode::SourcePos> while_exits;
  // The O-word a skip forward from an O-word block found (oword.cpp), keyed
  // by that block's offset and what was looked for: later passes seek there.
  struct OJump {
    gcode::SourcePos at;     // the O-word block found
    gcode::SourcePos after;  // the block after it
  };
  std::unordered_map<std::uint64_t, OJump> ojumps;
};

// An RS274NGC loop being run (o-word while, do, repeat).
struct OLoop {
  std::string label;
  gcode::OKind kind = gcode::OKind::kNone;  // kWhile, kDo or kRepeat
  gcode::SourcePos start;                   // the opening block
  gcode::SourcePos body;                    // the block after it
  double left = 0.0;                        // repeat: passes still to run
};

struct Loop {
  int id = 0;
  gcode::SourcePos pos;   // the WHILE (or DO) block
  std::uint64_t end = 0;  // offset of its END block, once known
  bool end_known = false;
};

// One level of the call stack.
struct Frame {
  ProgramFile* file = nullptr;
  gcode::SourcePos start;     // first block of the program
  gcode::SourcePos resume;    // next block to read when this frame runs again
  std::int64_t program = 0;   // O number (0: main program without one)
  std::uint32_t context = 0;  // CallContext index
  int repeats_left = 0;       // M98 L / G65 L
  bool macro = false;         // G65/G66 call: owns a local-variable level
  bool modal_call = false;    // a G66 call (no re-entry of the modal macro inside)
  std::vector<Loop> loops;
  // RS274NGC: a frame opened by `o<label> call` (its label), and its loops.
  std::string sub_label;
  std::vector<OLoop> oloops;
  // M97 (Haas): a local subprogram of the caller's program. `start` is its
  // first block (where L repeats begin); its GOTO and M99 P labels are those
  // of the whole program, which begins at `program_start`.
  bool local = false;
  gcode::SourcePos program_start;
  const gcode::SourcePos& label_origin() const noexcept { return local ? program_start : start; }
};

// A program found: its file and the block it begins at.
struct ProgramAt {
  ProgramFile* file = nullptr;
  gcode::SourcePos at;
};

class ProgramStore {
 public:
  struct Options {
    std::string main_name;  // the main program as errors name it
    std::string main_path;  // its file; empty: `main_text`
    // The main program's text when it has no file; must outlive the store.
    const std::string* main_text = nullptr;
    std::vector<std::string> include_dirs;  // -I, in order
    gcode::SourceLimits source;             // how text is cut into blocks
    gcode::ParseLimits parse;               // how an indexed block is parsed
    std::int64_t max_label_index = 0;       // limits.max_label_index
  };

  // Opens the main program and puts its frame at the bottom of the stack.
  Result<void> open(Options o);

  // The call stack: [0] the main program, back() the one being run. The
  // interpreter pushes and pops frames as it calls and returns.
  std::vector<Frame> frames;

  ProgramFile& main_file() noexcept { return *files_.front(); }
  ProgramFile& running_file() noexcept { return *frames.back().file; }

  // Where called programs are looked for: the -I folders, else the folder
  // of the main program.
  std::vector<std::string> include_dirs() const;

  // The one scan of a file: every O number and `o<label> sub` / `endsub`.
  // Once per file; later calls return at once.
  Result<void> index(ProgramFile& pf);

  // M98 / G65 / G66 P<number>: the running file, the main file, every file
  // loaded, then the include folders (macro_call.cpp's rules). Alarm
  // program_not_found, saying where it looked, when there is none.
  Result<ProgramAt> find_program(std::int64_t number, SourceLoc where);

  // o<label> call: the running file, the main file, then <name>.ngc in the
  // include folders. Nothing when there is none (sub_not_found says so).
  Result<std::optional<ProgramAt>> find_sub(const std::string& label, SourceLoc where);
  std::string sub_not_found(const std::string& label) const;

  // GOTO n / M99 Pn / M97 Pn in the program of frame `f`: the first N n
  // after the block at offset `from`, else the first one. Reads f's source
  // (the caller seeks where it goes next).
  Result<gcode::SourcePos> find_label(const Frame& f, std::int64_t n, std::uint64_t from,
                                      SourceLoc where);

 private:
  Result<std::optional<ProgramAt>> in_file(ProgramFile& pf, std::int64_t number);
  Result<std::optional<ProgramAt>> sub_in_file(ProgramFile& pf, const std::string& label,
                                               SourceLoc where);
  Result<std::optional<ProgramAt>> program_in_folder(const std::string& dir, std::int64_t number,
                                                     std::vector<std::string>& libraries,
                                                     SourceLoc where);
  Result<std::optional<ProgramAt>> program_in_library(const std::filesystem::path& p,
                                                      std::int64_t number,
                                                      std::vector<std::string>& libraries);
  Result<ProgramFile*> program_file(const std::filesystem::path& p, bool& added);
  Result<std::unique_ptr<gcode::Source>> scanner_for(const ProgramFile& pf) const;

  Options opt_;
  std::vector<std::unique_ptr<ProgramFile>> files_;
  // The subs found in <name>.ngc on the include path, by label: a later call
  // not answered by the running or the main file goes there at once (the
  // folders are not searched again; the file is open already).
  std::unordered_map<std::string, ProgramAt> subs_on_path_;
};

}  // namespace skipnc::interp
