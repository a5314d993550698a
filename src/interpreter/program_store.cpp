// The program store (program_store.hpp): program files, their one scan, and
// the lookups of called programs, subroutines and sequence numbers.
//
// Program lookup (docs/macro.md): O<n> is looked for, as a number (O0010 is
// O10), in the running file, the main program file and every file already
// loaded; then on the include path (-I, else the main program's folder), in
// order, as the files O<n>.nc, O<n>.NC, o<n>.nc, <n>.nc, O<n>, and with the
// number padded to four digits (O0010.nc, O0010); then inside the folder's
// library files (*.nc, *.txt, *.prg, *.tap holding several programs, like a
// punched ALL-PROG file), in name order. An -I that names a file makes that
// file a library. A program can only name a number: the file name is built
// here from digits, so no path a program writes can reach outside the
// include folders, and a file found there through a link that leads outside
// them is refused.
//
// Subroutine lookup (LinuxCNC's "O Codes"): `o<label> sub` in the running
// file, in the main program's file, then in <label>.ngc on the include path
// (LinuxCNC's SUBROUTINE_PATH: a file named after the subroutine, holding it).
#include "interpreter/program_store.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string_view>

namespace skipnc::interp {

namespace fs = std::filesystem;

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

// The number of an O-number block (`O<n>`, `o<n>`, `:<n>` after spaces).
std::optional<std::int64_t> program_number(std::string_view t) noexcept {
  std::size_t i = 0;
  while (i < t.size() && (t[i] == ' ' || t[i] == '\t')) ++i;
  if (i >= t.size() || (t[i] != 'O' && t[i] != 'o' && t[i] != ':')) return std::nullopt;
  std::int64_t n = 0;
  std::size_t j = i + 1;
  int digits = 0;
  while (j < t.size() && t[j] >= '0' && t[j] <= '9' && digits < 12) {
    n = n * 10 + (t[j] - '0');
    ++j;
    ++digits;
  }
  if (digits == 0) return std::nullopt;
  return n;
}

}  // namespace

bool may_be_oword(std::string_view t) noexcept {
  std::size_t i = 0;
  auto spaces = [&] {
    while (i < t.size() && (t[i] == ' ' || t[i] == '\t')) ++i;
  };
  spaces();
  if (i < t.size() && t[i] == '/') {
    ++i;
    if (i < t.size() && t[i] >= '1' && t[i] <= '9') ++i;
    spaces();
  }
  if (i < t.size() && (t[i] == 'N' || t[i] == 'n')) {
    ++i;
    while (i < t.size() && ((t[i] >= '0' && t[i] <= '9') || t[i] == ' ' || t[i] == '\t')) ++i;
  }
  return i < t.size() && (t[i] == 'O' || t[i] == 'o');
}

std::string shown_oword(const std::string& label) {
  std::string s = "o" + label;
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

namespace {

// The file a named subroutine is looked for in: o<probe_x> -> probe_x
// (lower case, as LinuxCNC looks for it); empty for a numbered one.
std::string sub_file_stem(const std::string& label) {
  if (label.size() < 3 || label.front() != '<') return {};
  std::string name = label.substr(1, label.size() - 2);
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

}  // namespace

Result<void> ProgramStore::open(Options o) {
  opt_ = std::move(o);
  auto file = std::make_unique<ProgramFile>();
  file->display = opt_.main_name;
  if (opt_.main_path.empty()) {
    file->src = gcode::make_string_source(
        opt_.main_name, opt_.main_text != nullptr ? *opt_.main_text : std::string(), opt_.source);
  } else {
    file->path = opt_.main_path;
    auto src = gcode::open_file_source(opt_.main_path, opt_.main_name, opt_.source);
    SKIPNC_TRY(src);
    file->src = std::move(*src);
  }
  Frame main;
  main.file = file.get();
  main.start = file->src->tell();
  main.resume = main.start;
  files_.push_back(std::move(file));
  frames.push_back(std::move(main));
  return {};
}

std::vector<std::string> ProgramStore::include_dirs() const {
  std::vector<std::string> dirs = opt_.include_dirs;
  if (dirs.empty()) {
    const fs::path parent = fs::path(opt_.main_path).parent_path();
    dirs.push_back(opt_.main_path.empty() || parent.empty() ? std::string(".") : parent.string());
  }
  return dirs;
}

// A second reader of a program file, for a scan that must not move the
// running read position.
Result<std::unique_ptr<gcode::Source>> ProgramStore::scanner_for(const ProgramFile& pf) const {
  if (pf.path.empty()) {
    return gcode::make_string_source(
        pf.display, opt_.main_text != nullptr ? *opt_.main_text : std::string(), opt_.source);
  }
  return gcode::open_file_source(pf.path, pf.display, opt_.source);
}

// The program file at `p`: the one already loaded, or opened now and kept
// (`added` says which).
Result<ProgramFile*> ProgramStore::program_file(const fs::path& p, bool& added) {
  added = false;
  for (const auto& f : files_) {
    std::error_code ec;
    if (!f->path.empty() && fs::equivalent(f->path, p, ec)) return f.get();
  }
  auto pf = std::make_unique<ProgramFile>();
  pf->path = p.string();
  pf->display = p.filename().string();
  auto src = gcode::open_file_source(pf->path, pf->display, opt_.source);
  SKIPNC_TRY(src);
  pf->src = std::move(*src);
  files_.push_back(std::move(pf));
  added = true;
  return files_.back().get();
}

// One pass over the file: O numbers by their text alone; O-word blocks
// (RS274NGC only: no other syntax has them) parsed for sub and endsub. A
// block that does not parse is reported when (and if) it runs.
Result<void> ProgramStore::index(ProgramFile& pf) {
  if (pf.indexed) return {};
  auto opened = scanner_for(pf);
  SKIPNC_TRY(opened);
  const std::unique_ptr<gcode::Source> scanner = std::move(*opened);
  const bool owords = opt_.parse.syntax == gcode::Syntax::kRs274ngc;
  gcode::RawBlock rb;
  gcode::Block b;
  for (;;) {
    auto more = scanner->next(rb);
    SKIPNC_TRY(more);
    if (!*more) break;
    if (auto n = program_number(rb.text)) pf.programs.emplace(*n, scanner->tell());
    if (!owords || !may_be_oword(rb.text)) continue;
    auto parsed = gcode::parse_block(rb.text, SourceLoc{pf.display, rb.line, rb.column}, rb.offset,
                                     b, opt_.parse);
    if (!parsed || b.stmt.kind != gcode::StmtKind::kOword) continue;
    const std::string& label = b.names[static_cast<std::size_t>(b.stmt.label)];
    if (b.stmt.okind == gcode::OKind::kSub) pf.subs.emplace(label, scanner->tell());
    if (b.stmt.okind == gcode::OKind::kEndsub) pf.endsubs.insert(label);
  }
  pf.indexed = true;
  return {};
}

inline Result<std::optional<ProgramAt>> ProgramStore::in_file(ProgramFile& pf,
                                                              std::int64_t number) {
  if (!pf.indexed) SKIPNC_TRY(index(pf));
  if (auto it = pf.programs.find(number); it != pf.programs.end()) {
    return ProgramAt{&pf, it->second};
  }
  return std::nullopt;
}

// A library: a file holding several programs (%, O9810 ... M99, O9811 ...
// M99, %), searched for the O number only; one already loaded was searched
// with the loaded files.
Result<std::optional<ProgramAt>> ProgramStore::program_in_library(
    const fs::path& p, std::int64_t number, std::vector<std::string>& libraries) {
  libraries.push_back(p.filename().string());
  bool added = false;
  auto pf = program_file(p, added);
  SKIPNC_TRY(pf);
  if (!added) return std::nullopt;
  return in_file(**pf, number);
}

// O<number> in one include folder (or library file): the files named after
// the program, then the folder's library files.
Result<std::optional<ProgramAt>> ProgramStore::program_in_folder(
    const std::string& d, std::int64_t number, std::vector<std::string>& libraries,
    SourceLoc where) {
  std::error_code ec;
  if (fs::is_regular_file(d, ec)) return program_in_library(fs::path(d), number, libraries);
  const fs::path dir(d.empty() ? "." : d);
  const std::vector<std::string> names = program_file_names(number);
  for (const auto& name : names) {
    const fs::path p = dir / name;
    if (!fs::is_regular_file(p, ec)) continue;
    if (!path_inside(p, dir)) {
      return fail(AlarmId::kProgramNotFound,
                  "program O" + std::to_string(number) + ": '" + p.string() +
                      "' leads outside the include folder",
                  where);
    }
    bool added = false;
    auto pf = program_file(p, added);
    SKIPNC_TRY(pf);
    if (!added) continue;  // searched with the loaded files
    auto r = in_file(**pf, number);
    SKIPNC_TRY(r);
    if (*r) return r;
    // A file named after the program without an O block: run it from the top.
    (*pf)->programs.emplace(number, gcode::SourcePos{});
    return ProgramAt{*pf, gcode::SourcePos{}};
  }
  for (const fs::path& p : library_files(dir, names)) {
    auto r = program_in_library(p, number, libraries);
    SKIPNC_TRY(r);
    if (*r) return r;
  }
  return std::nullopt;
}

Result<ProgramAt> ProgramStore::find_program(std::int64_t number, SourceLoc where) {
  for (ProgramFile* pf : {frames.back().file, files_.front().get()}) {
    auto r = in_file(*pf, number);
    SKIPNC_TRY(r);
    if (*r) return **r;
  }
  // By index: a library searched below adds to files_.
  for (std::size_t i = 0; i < files_.size(); ++i) {
    auto r = in_file(*files_[i], number);
    SKIPNC_TRY(r);
    if (*r) return **r;
  }
  const std::vector<std::string> dirs = include_dirs();
  std::vector<std::string> libraries;
  for (const auto& d : dirs) {
    auto r = program_in_folder(d, number, libraries, where);
    SKIPNC_TRY(r);
    if (*r) return **r;
  }
  const std::string n = std::to_string(number);
  std::string detail = "program O" + n + " not found: looked in the programs loaded, then in";
  for (const auto& d : dirs) detail += " '" + (d.empty() ? std::string(".") : d) + "'";
  detail += " for";
  for (const auto& name : program_file_names(number)) detail += " " + name;
  if (!libraries.empty()) {
    detail += ", and for O" + n + " inside";
    constexpr std::size_t kShown = 8;  // library names listed; the rest are counted
    for (std::size_t i = 0; i < libraries.size() && i < kShown; ++i) {
      detail += " " + libraries[i];
    }
    if (libraries.size() > kShown) {
      detail += " and " + std::to_string(libraries.size() - kShown) + " more files";
    }
  }
  return fail(AlarmId::kProgramNotFound, detail, where);
}

inline Result<std::optional<ProgramAt>> ProgramStore::sub_in_file(ProgramFile& pf,
                                                                  const std::string& label,
                                                                  SourceLoc where) {
  if (!pf.indexed) SKIPNC_TRY(index(pf));
  auto it = pf.subs.find(label);
  if (it == pf.subs.end()) return std::nullopt;
  // A sub without its endsub would run to the end of the file and end the
  // program there: an alarm, as LinuxCNC's rs274 stops ("File ended with no
  // percent sign or program end").
  if (!pf.endsubs.contains(label)) {
    return fail(
        AlarmId::kOwordFlow,
        shown_oword(label) + " sub in " + pf.display + " has no " + shown_oword(label) + " endsub",
        where);
  }
  return ProgramAt{&pf, it->second};
}

Result<std::optional<ProgramAt>> ProgramStore::find_sub(const std::string& label, SourceLoc where) {
  for (ProgramFile* pf : {frames.back().file, files_.front().get()}) {
    auto r = sub_in_file(*pf, label, where);
    SKIPNC_TRY(r);
    if (*r) return r;
  }
  const std::string name = sub_file_stem(label);
  if (name.empty()) return std::nullopt;
  if (auto known = subs_on_path_.find(label); known != subs_on_path_.end()) return known->second;
  for (const auto& d : include_dirs()) {
    const fs::path p = fs::path(d) / (name + ".ngc");
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) continue;
    if (!path_inside(p, fs::path(d))) {  // o</..>: as M98's files, inside the folder
      return fail(AlarmId::kProgramNotFound,
                  shown_oword(label) + ": '" + p.string() + "' leads outside the include folder",
                  where);
    }
    bool added = false;
    auto have = program_file(p, added);
    SKIPNC_TRY(have);
    auto r = sub_in_file(**have, label, where);
    SKIPNC_TRY(r);
    if (*r) {
      subs_on_path_.emplace(label, **r);
      return r;
    }
    return fail(AlarmId::kProgramNotFound,
                p.filename().string() + " has no " + shown_oword(label) + " sub", where);
  }
  return std::nullopt;
}

// What a call without its sub says: where it looked. LinuxCNC looks in the
// running file, then <name>.ngc in the SUBROUTINE_PATH folders (here -I).
std::string ProgramStore::sub_not_found(const std::string& label) const {
  const ProgramFile* running = frames.back().file;
  std::string text = "no " + shown_oword(label) + " sub: not in " + running->display;
  if (running != files_.front().get()) text += " nor " + files_.front()->display;
  const std::string name = sub_file_stem(label);
  if (name.empty()) return text;
  text += ", and no " + name + ".ngc in the folders searched:";
  for (const auto& d : include_dirs()) text += " '" + d + "'";
  return text + " (a folder is added with -I)";
}

namespace {

// One pass over the program of frame `f`: `each(number, position)` for every
// block with an N, in file order, until it returns false.
template <class Each>
Result<void> scan_program_labels(const Frame& f, const gcode::ParseLimits& limits, Each each) {
  gcode::Source& src = *f.file->src;
  const gcode::SourcePos& origin = f.label_origin();
  auto s = src.seek(origin);
  if (!s) return s;
  gcode::RawBlock rb;
  gcode::Block b;
  // A main program read from the top begins with its own '%' and O block:
  // they open the program; a '%' or O block after its first other block
  // ends it.
  bool body = false;
  for (;;) {
    const gcode::SourcePos at = src.tell();
    auto more = src.next(rb);
    SKIPNC_TRY(more);
    if (!*more) break;
    // Cheap test before parsing: only blocks with an N, or an O or '%'
    // that ends the program, matter.
    if (rb.text.find_first_of("NnOo:%") == std::string_view::npos) {
      body = body || rb.text.find_first_not_of(" \t") != std::string_view::npos;
      continue;
    }
    auto p = gcode::parse_block(rb.text, SourceLoc{f.file->display, rb.line, rb.column}, rb.offset,
                                b, limits);
    if (!p) continue;  // reported if the block is ever executed
    const bool opens = b.percent || b.has_o;
    if (opens && (body || (at.offset != origin.offset && origin.offset != 0))) break;
    body = body || !opens;
    if (b.has_n && !each(b.n, at)) break;
  }
  return {};
}

// Of positions in file order (`pos` of each element): the first after the
// offset `from`, else the first; null when there is none.
template <class It, class Pos>
const gcode::SourcePos* first_after(It first, It last, std::uint64_t from, Pos pos) {
  const gcode::SourcePos* any = nullptr;
  for (; first != last; ++first) {
    const gcode::SourcePos& p = pos(*first);
    if (p.offset > from) return &p;
    if (any == nullptr) any = &p;
  }
  return any;
}

// Every label of the program, sorted by number then file order, when there
// are at most `cap`; otherwise none and `complete` stays false.
Result<void> index_labels(const Frame& f, const gcode::ParseLimits& limits, std::size_t cap,
                          ProgramFile::LabelIndex& idx) {
  bool over = false;
  auto s = scan_program_labels(f, limits, [&](std::int64_t num, gcode::SourcePos at) {
    if (idx.all.size() == cap) {
      over = true;
      return false;
    }
    idx.all.emplace_back(num, at);
    return true;
  });
  SKIPNC_TRY(s);
  if (over) {
    idx.all.clear();
    idx.all.shrink_to_fit();
    return {};
  }
  // By number, then file order (the scan's order is the offsets').
  std::stable_sort(idx.all.begin(), idx.all.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  idx.complete = true;
  return {};
}

}  // namespace

// The index holds every label of a program up to limits.max_label_index (one
// scan, then a binary search per jump); a larger program keeps only the
// numbers asked for, each found by its own scan, so memory stays bounded
// whatever the file's size (issue 21: a 1 GB program with a GOTO held every
// label). Fanuc searches forward, then from the top.
Result<gcode::SourcePos> ProgramStore::find_label(const Frame& f, std::int64_t n,
                                                  std::uint64_t from, SourceLoc where) {
  auto [it, fresh] = f.file->labels.try_emplace(f.label_origin().offset);
  ProgramFile::LabelIndex& idx = it->second;
  if (fresh) {
    SKIPNC_TRY(index_labels(f, opt_.parse, static_cast<std::size_t>(opt_.max_label_index), idx));
  }
  const gcode::SourcePos* found = nullptr;
  if (idx.complete) {
    auto [lo, hi] = std::equal_range(
        idx.all.begin(), idx.all.end(), std::pair<std::int64_t, gcode::SourcePos>{n, {}},
        [](const auto& x, const auto& y) { return x.first < y.first; });
    found = first_after(
        lo, hi, from, [](const auto& e) -> const auto& { return e.second; });
  } else {
    auto a = idx.asked.find(n);
    if (a == idx.asked.end()) {
      if (idx.asked.size() >= ProgramFile::kLabelCache) idx.asked.clear();
      std::vector<gcode::SourcePos> at_n;
      auto s = scan_program_labels(f, opt_.parse, [&](std::int64_t num, gcode::SourcePos p) {
        if (num == n) at_n.push_back(p);
        return true;
      });
      SKIPNC_TRY(s);
      a = idx.asked.emplace(n, std::move(at_n)).first;
    }
    found = first_after(
        a->second.begin(), a->second.end(), from,
        [](const gcode::SourcePos& p) -> const auto& { return p; });
  }
  if (found == nullptr) {
    return fail(AlarmId::kSequenceNotFound,
                "sequence number N" + std::to_string(n) + " not found in this program", where);
  }
  return *found;
}

}  // namespace skipnc::interp
