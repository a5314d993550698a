// Calls: program lookup, M98 subprogram calls, G65 / G66 macro calls with
// their arguments, and M99 returns.
//
// Program lookup (docs/macro.md): O<n> is looked for, as a number (O0010 is
// O10), in the running file, the main program file and every file already
// loaded; then on the include path (-I, else the main program's folder), in
// order, as the files O<n>.nc, O<n>.NC, o<n>.nc, <n>.nc, O<n>, and with the
// number padded to four digits (O0010.nc, O0010); then inside the folder's
// library files (*.nc, *.txt, *.prg, *.tap holding several programs, like a
// punched ALL-PROG file), in name order. An -I that names a file makes that
// file a library. A program can only name a
// number: the file name is built here from digits, so no path a program
// writes can reach outside the include folders, and a file found there
// through a link that leads outside them is refused.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <vector>

#include "interpreter/impl.hpp"

namespace skipnc::interp {

namespace fs = std::filesystem;

// True when `p` (after resolving links) lies inside folder `dir`.
bool path_inside(const fs::path& p, const fs::path& dir) {
  std::error_code ec;
  const fs::path rp = fs::weakly_canonical(p, ec);
  if (ec) return false;
  const fs::path rd = fs::weakly_canonical(dir, ec);
  if (ec) return false;
  auto r = std::mismatch(rd.begin(), rd.end(), rp.begin(), rp.end());
  return r.first == rd.end();
}

namespace {

// The file names that hold program O<n> alone, in the order they are tried.
std::vector<std::string> program_file_names(std::int64_t number) {
  const std::string n = std::to_string(number);
  std::vector<std::string> names = {"O" + n + ".nc", "O" + n + ".NC", "o" + n + ".nc", n + ".nc",
                                    "O" + n};
  if (number < 1000) {
    char padded[24];
    std::snprintf(padded, sizeof padded, "%04lld", static_cast<long long>(number));
    names.push_back("O" + std::string(padded) + ".nc");
    names.push_back("O" + std::string(padded));
  }
  return names;
}

// The endings of the files of an include folder that are searched as
// libraries (several programs in one file, like a punched ALL-PROG file).
constexpr std::string_view kLibraryEndings[] = {".nc",  ".NC",  ".txt", ".TXT",
                                                ".prg", ".PRG", ".tap", ".TAP"};

// The library files of `dir` in name order: files with a library ending,
// other than the ones named after the program (tried before), that stay
// inside the folder when links are followed.
std::vector<fs::path> library_files(const fs::path& dir, const std::vector<std::string>& skip) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path& p = it->path();
    const std::string name = p.filename().string();
    const bool library =
        std::ranges::any_of(kLibraryEndings, [&](std::string_view e) { return name.ends_with(e); });
    if (!library || std::ranges::find(skip, name) != skip.end()) continue;
    std::error_code fe;
    if (!fs::is_regular_file(p, fe) || !path_inside(p, dir)) continue;
    out.push_back(p);
  }
  std::ranges::sort(out);
  return out;
}

}  // namespace

Flow<void> Interpreter::Impl::find_program(std::int64_t number, ProgramFile*& file,
                                           gcode::SourcePos& at, SourceLoc where) {
  auto scan = [&](ProgramFile& pf) -> Result<bool> {
    if (auto it = pf.programs.find(number); it != pf.programs.end()) {
      file = &pf;
      at = it->second;
      return true;
    }
    if (pf.scanned) return false;
    // Scan the file once for program numbers with a source of its own, so
    // the running read position is not disturbed.
    auto opened = scanner_for(pf);
    SKIPNC_TRY(opened);
    const std::unique_ptr<gcode::Source> scanner = std::move(*opened);
    gcode::RawBlock rb;
    for (;;) {
      auto more = scanner->next(rb);
      SKIPNC_TRY(more);
      if (!*more) break;
      std::size_t i = 0;
      while (i < rb.text.size() && (rb.text[i] == ' ' || rb.text[i] == '\t')) ++i;
      if (i < rb.text.size() && (rb.text[i] == 'O' || rb.text[i] == 'o' || rb.text[i] == ':')) {
        std::int64_t n = 0;
        std::size_t j = i + 1;
        int digits = 0;
        while (j < rb.text.size() && rb.text[j] >= '0' && rb.text[j] <= '9' && digits < 12) {
          n = n * 10 + (rb.text[j] - '0');
          ++j;
          ++digits;
        }
        if (digits > 0) pf.programs.emplace(n, scanner->tell());
      }
    }
    pf.scanned = true;
    if (auto it = pf.programs.find(number); it != pf.programs.end()) {
      file = &pf;
      at = it->second;
      return true;
    }
    return false;
  };
  for (ProgramFile* pf : {frames.back().file, files.front().get()}) {
    auto r = scan(*pf);
    SKIPNC_TRY(r);
    if (*r) return {};
  }
  for (auto& pf : files) {
    auto r = scan(*pf);
    SKIPNC_TRY(r);
    if (*r) return {};
  }
  const std::vector<std::string> dirs = include_dirs();
  const std::string n = std::to_string(number);
  const std::vector<std::string> names = program_file_names(number);
  // A file not loaded yet: opened, scanned, kept in `files`. Null when it is
  // already loaded (its programs were searched above).
  auto load = [&](const fs::path& p) -> Result<ProgramFile*> {
    bool added = false;
    auto pf = program_file(p, added);
    SKIPNC_TRY(pf);
    return added ? *pf : nullptr;
  };
  std::vector<std::string> libraries_tried;
  // A library: a file holding several programs (%, O9810 ... M99, O9811 ...
  // M99, %), searched for the O number only.
  auto search_library = [&](const fs::path& p) -> Result<bool> {
    libraries_tried.push_back(p.filename().string());
    auto pf = load(p);
    SKIPNC_TRY(pf);
    if (*pf == nullptr) return false;
    return scan(**pf);
  };
  for (const auto& d : dirs) {
    std::error_code ec;
    if (fs::is_regular_file(d, ec)) {  // -I ALL-PROG.TXT: a library file
      auto r = search_library(fs::path(d));
      SKIPNC_TRY(r);
      if (*r) return {};
      continue;
    }
    const fs::path dir(d.empty() ? "." : d);
    for (const auto& name : names) {
      const fs::path p = dir / name;
      if (!fs::is_regular_file(p, ec)) continue;
      if (!path_inside(p, dir)) {
        return fail(AlarmId::kProgramNotFound,
                    "program O" + n + ": '" + p.string() + "' leads outside the include folder",
                    where);
      }
      auto pf = load(p);
      SKIPNC_TRY(pf);
      if (*pf == nullptr) continue;
      auto r = scan(**pf);
      SKIPNC_TRY(r);
      if (*r) return {};
      // A file named after the program without an O block: run it from the top.
      file = *pf;
      at = gcode::SourcePos{};
      (*pf)->programs.emplace(number, at);
      return {};
    }
    for (const fs::path& p : library_files(dir, names)) {
      auto r = search_library(p);
      SKIPNC_TRY(r);
      if (*r) return {};
    }
  }
  std::string detail = "program O" + n + " not found: looked in the programs loaded, then in";
  for (const auto& d : dirs) detail += " '" + (d.empty() ? std::string(".") : d) + "'";
  detail += " for";
  for (const auto& name : names) detail += " " + name;
  if (!libraries_tried.empty()) {
    detail += ", and for O" + n + " inside";
    constexpr std::size_t kShown = 8;  // library names listed; the rest are counted
    for (std::size_t i = 0; i < libraries_tried.size() && i < kShown; ++i) {
      detail += " " + libraries_tried[i];
    }
    if (libraries_tried.size() > kShown) {
      detail += " and " + std::to_string(libraries_tried.size() - kShown) + " more files";
    }
  }
  return fail(AlarmId::kProgramNotFound, detail, where);
}

// Nesting (Fanuc): G65/G66 macro calls up to 4 levels, M98 subprogram calls
// up to 10 levels, each counted on its own (limits.max_macro_levels,
// limits.max_subprogram_levels of the machine file).
// The context of a call: one per distinct call path (file, program, caller,
// calling line and code), so that a block's context names its call stack.
std::uint32_t Interpreter::Impl::context_of(CallContext c) {
  for (std::size_t i = 0; i < contexts.size(); ++i) {
    if (contexts[i] == c) return static_cast<std::uint32_t>(i);
  }
  contexts.push_back(std::move(c));
  return static_cast<std::uint32_t>(contexts.size() - 1);
}

Flow<void> Interpreter::Impl::call(std::int64_t program, int repeats, bool macro, SourceLoc where,
                                   bool modal_call) {
  int subs = 0, macros = 0;
  for (std::size_t i = 1; i < frames.size(); ++i) (frames[i].macro ? macros : subs)++;
  if (macro && macros >= mc.limits.max_macro_levels) {
    return fail(
        AlarmId::kMacroNesting,
        "macro call nesting deeper than " + std::to_string(mc.limits.max_macro_levels) + " levels",
        where);
  }
  if (!macro && subs >= mc.limits.max_subprogram_levels) {
    return fail(AlarmId::kSubprogramNesting,
                "subprogram nesting deeper than " +
                    std::to_string(mc.limits.max_subprogram_levels) + " levels",
                where);
  }
  ProgramFile* file = nullptr;
  gcode::SourcePos at;
  auto found = find_program(program, file, at, where);
  if (!found) return found;
  Frame f;
  f.file = file;
  f.start = at;
  f.program = program;
  f.repeats_left = repeats - 1;
  f.macro = macro;
  return push_frame(
      f, (macro ? (modal_call ? "G66 P" : "G65 P") : "M98 P") + std::to_string(program), where);
}

// M97 Pn Ll (Haas "M97 Local Sub-Program Call"): the block at Nn of the
// running program, as a subprogram level of its own (counted with M98's),
// run l times; M99 returns to the block after the M97.
Flow<void> Interpreter::Impl::local_call(std::int64_t label, int repeats, SourceLoc where) {
  int subs = 0;
  for (std::size_t i = 1; i < frames.size(); ++i) subs += frames[i].macro ? 0 : 1;
  if (subs >= mc.limits.max_subprogram_levels) {
    return fail(AlarmId::kSubprogramNesting,
                "subprogram nesting deeper than " +
                    std::to_string(mc.limits.max_subprogram_levels) + " levels",
                where);
  }
  const gcode::SourcePos resume = frames.back().file->src->tell();
  auto at = find_label(label, block_pos.offset, where);
  SKIPNC_TRY(at);
  const Frame& caller = frames.back();
  Frame f;
  f.file = caller.file;
  f.start = *at;
  f.program = caller.program;
  f.repeats_left = repeats - 1;
  f.local = true;
  f.program_start = caller.label_origin();
  // find_label read the file: the caller resumes after the M97 block.
  auto s = caller.file->src->seek(resume);
  SKIPNC_TRY(s);
  return push_frame(std::move(f), "M97 P" + std::to_string(label), where);
}

// The called program's frame on top of the caller's: the caller resumes
// after the calling block, the call path gets its context, reading goes on
// at the frame's start.
Flow<void> Interpreter::Impl::push_frame(Frame f, std::string call, SourceLoc where) {
  frames.back().resume = frames.back().file->src->tell();
  f.resume = f.start;
  f.context = context_of(CallContext{f.file->display, f.program, frames.back().context, where.line,
                                     std::move(call), f.file->path});
  frames.push_back(std::move(f));
  const Frame& top = frames.back();
  return top.file->src->seek(top.start);
}

// A second reader of a program file, for a scan that must not move the
// running read position.
Result<std::unique_ptr<gcode::Source>> Interpreter::Impl::scanner_for(const ProgramFile& pf) const {
  if (pf.path.empty()) {
    return gcode::make_string_source(pf.display, setup.program_text, source_limits());
  }
  return gcode::open_file_source(pf.path, pf.display, source_limits());
}

// Where called programs are looked for: the -I folders, else the folder of
// the main program.
std::vector<std::string> Interpreter::Impl::include_dirs() const {
  std::vector<std::string> dirs = setup.include_dirs;
  if (dirs.empty()) {
    const fs::path parent = fs::path(setup.program_path).parent_path();
    dirs.push_back(setup.program_path.empty() || parent.empty() ? std::string(".")
                                                                : parent.string());
  }
  return dirs;
}

// The program file at `p`: the one already loaded, or opened now and kept in
// `files` (`added` says which).
Result<ProgramFile*> Interpreter::Impl::program_file(const fs::path& p, bool& added) {
  added = false;
  for (const auto& f : files) {
    std::error_code ec;
    if (!f->path.empty() && fs::equivalent(f->path, p, ec)) return f.get();
  }
  auto pf = std::make_unique<ProgramFile>();
  pf->path = p.string();
  pf->display = p.filename().string();
  auto src = gcode::open_file_source(pf->path, pf->display, source_limits());
  SKIPNC_TRY(src);
  pf->src = std::move(*src);
  files.push_back(std::move(pf));
  added = true;
  return files.back().get();
}

// M99 (or the end of a called program): runs the program again while
// repetitions are left, else returns to the block after the call, or with
// M99 Pn to sequence number n of the calling program.
Flow<Step> Interpreter::Impl::return_from_sub(std::optional<std::int64_t> label, SourceLoc where) {
  Frame& f = frames.back();
  if (frames.size() == 1) {
    // M99 in the main program: back to its start (or to the label), as the
    // control does; the statement limit ends an endless repetition.
    if (label) {
      auto j = jump_to_label(*label, block_pos.offset, where);
      SKIPNC_TRY(j);
      return Step::kContinue;
    }
    auto s = f.file->src->seek(f.start);
    SKIPNC_TRY(s);
    f.loops.clear();
    return Step::kContinue;
  }
  if (label && dialect.sw.m99_p_jumps_in_subprogram) {
    // Haas: M99 Pn in a subprogram branches to Nn of that subprogram; it
    // does not return to the caller.
    auto j = jump_to_label(*label, block_pos.offset, where);
    SKIPNC_TRY(j);
    return Step::kContinue;
  }
  if (f.repeats_left > 0) {
    --f.repeats_left;
    f.loops.clear();
    auto s = f.file->src->seek(f.start);
    SKIPNC_TRY(s);
    return Step::kContinue;
  }
  const bool macro = f.macro;
  frames.pop_back();
  if (macro) vars.pop_level();
  Frame& caller = frames.back();
  auto s = caller.file->src->seek(caller.resume);
  SKIPNC_TRY(s);
  if (label) {
    const std::uint64_t from = caller.resume.offset > 0 ? caller.resume.offset - 1 : 0;
    auto j = jump_to_label(*label, from, where);
    SKIPNC_TRY(j);
  }
  return Step::kContinue;
}

bool Interpreter::Impl::in_modal_call() const noexcept {
  for (const Frame& f : frames) {
    if (f.modal_call) return true;
  }
  return false;
}

// One argument word of a G65/G66 block, in block order.
// Specification I: A B C D E F H I J K M Q R S T U V W X Y Z -> #1..#26
// (A1 B2 C3 I4 J5 K6 D7 E8 F9 H11 M13 Q17 R18 S19 T20 U21 V22 W23 X24 Y25
// Z26). Specification II: I J K repeated up to ten times -> #4..#33, a new
// set starting when a letter does not follow the previous one in I J K
// order. Where both name one variable (D and I2 -> #7), the later word wins
// (Fanuc 16i operator's manual B-63684EN, custom macro, "mixture of argument
// specifications I and II").
// Decimal point (same manual, "position of the decimal point"): a value
// written without a decimal point is in the least input increment of its
// address: lengths (X Y Z U V W I J K Q R and axis letters) become
// 0.001 mm / 0.0001 inch per unit (unless parameter 3401#0 DPI = 1); the
// other addresses (D E F H M S T, and A B C when they are not axes) are
// taken as written. Expressions (X#1, X[...]) are taken as computed.
Flow<void> Interpreter::Impl::collect_argument(const gcode::Word& w, const WordVal& v, int& ijk_set,
                                               int& ijk_last) {
  static constexpr std::array<std::int8_t, 26> kSpecI = {
      1,  2,  3,  7,  8,  9,  -1, 11, 4,  5,  6,  -1, 13,  // A..M
      -1, -1, -1, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26,  // N..Z
  };
  const char c = w.letter;
  int var = 0;
  if (c == 'I' || c == 'J' || c == 'K') {
    const int k = c - 'I';
    if (ijk_set < 0 || k <= ijk_last) ++ijk_set;
    ijk_last = k;
    if (ijk_set >= 10) {
      return fail(AlarmId::kIllegalArgumentAddress,
                  std::string("more than ten sets of I J K arguments (") + c + ")", loc(w.column));
    }
    var = 4 + ijk_set * 3 + k;
  } else {
    var = kSpecI[static_cast<std::size_t>(c - 'A')];
    if (var < 0) {
      return fail(AlarmId::kIllegalArgumentAddress,
                  std::string(1, c) + " cannot be a macro argument", loc(w.column));
    }
  }
  const bool length = axis_of_letter[static_cast<std::size_t>(c - 'A')] >= 0 ||
                      std::strchr("IJKQRUVWXYZ", c) != nullptr;
  const double x = length ? word_length(v, false) : v.value;
  call_args[static_cast<std::size_t>(var)] = Value::of(x);
  return {};
}

Flow<void> Interpreter::Impl::macro_call(std::int64_t program, int repeats, bool modal_call,
                                         SourceLoc where) {
  const std::array<Value, kLocalCount + 1> args = modal_call ? modal_macro_args : call_args;
  auto c = call(program, repeats, true, where, modal_call);
  if (!c) return c;
  frames.back().modal_call = modal_call;
  vars.push_level();
  vars.locals() = args;
  return {};
}

}  // namespace skipnc::interp
