// What each fuzz harness does with one input, and what it checks. Shared by
// the libFuzzer harnesses (tests/fuzz/fuzz_*.cpp, clang) and by the
// regression test (tests/regression/regression_test.cpp, the normal test
// run), so a kept input is replayed exactly as the fuzzer ran it.
//
// Each check returns "" when the input was handled as it must be (a result
// or a clear alarm with a location) and a description of the broken rule
// otherwise; a crash, a sanitizer report, a hang or a leak is found by the
// tools around it.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "config/skip_inputs.hpp"
#include "gcode/parser.hpp"
#include "gcode/source.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/variables.hpp"
#include "machine/mesh.hpp"
#include "machine/scene.hpp"
#include "report/report.hpp"
#include "sim/simulator.hpp"

namespace skipnc::fuzz {

// Budgets that keep one input short: a few milliseconds in the release
// build, tens of milliseconds under ASan + UBSan (a servo period of the
// whole machine costs about 100 us there).
inline constexpr std::int64_t kMaxStatements = 20'000;
inline constexpr std::int64_t kMaxTicks = 1'500;    // 1.5 s of machine time at 1 ms
inline constexpr std::int64_t kMaxFileTicks = 400;  // machine and scene files
inline constexpr std::size_t kMaxBlocks = 4096;

// Expression trees are never deeper than this: evaluation recurses over them.
inline constexpr int kDepthBound = gcode::kMaxExprDepth;

// One dialect with its default parameters, loaded once.
struct DialectEnv {
  config::Dialect dialect;
  std::unique_ptr<config::Parameters> params;
  machine::Scene scene;  // a probe trigger at Z-3 (machine) on the first skip input
};

struct Env {
  config::MachineConfig machine;  // mill3 with the budgets above
  std::vector<DialectEnv> dialects;
  std::string include_dir;  // an empty folder: subprogram lookup finds nothing outside

  Env() {
    auto m = config::builtin_machine("mill3");
    if (!m) std::abort();
    machine = std::move(*m);
    machine.limits.max_macro_statements = kMaxStatements;
    machine.limits.max_ticks = kMaxTicks;
    for (const char* name : {"fanuc", "nct", "mitsubishi", "compass"}) {
      auto d = config::builtin_dialect(name);
      if (!d) continue;  // a dialect not there yet is left out
      DialectEnv de;
      de.dialect = std::move(*d);
      dialects.push_back(std::move(de));
    }
    if (dialects.empty()) std::abort();
    // The parameters point at their dialect: made once the vector is final.
    for (auto& de : dialects) {
      de.params = std::make_unique<config::Parameters>(&de.dialect);
      const std::string scene =
          "[[trigger]]\nsignal = \"SKIP\"\naxis = \"Z\"\nat = -3.0\ndirection = \"decreasing\"\n";
      auto sc = machine::parse_scene(scene, "fuzz.scene.toml", machine, de.dialect, *de.params);
      if (sc) de.scene = std::move(*sc);
    }
    std::string tmpl =
        (std::filesystem::temp_directory_path() / "skipnc-fuzz-include-XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr) std::abort();
    include_dir = tmpl;
  }
  ~Env() {
    std::error_code ec;
    std::filesystem::remove(include_dir, ec);
  }
  Env(const Env&) = delete;
  Env& operator=(const Env&) = delete;
};

inline const Env& env() {
  static const Env e;
  return e;
}

// ---------------------------------------------------------------------------
// Helpers

inline std::string show_error(const Error& e) {
  return std::string(alarm_key(e.id)) + " at " + std::string(e.loc.file) + ":" +
         std::to_string(e.loc.line) + ":" + std::to_string(e.loc.column) + ": " + e.detail;
}

// A program error must say where it happened, and never be an internal one.
inline std::string check_program_error(const Error& e, std::uint32_t max_line) {
  if (e.id == AlarmId::kInternal) return "internal error: " + show_error(e);
  if (e.id == AlarmId::kCount) return "alarm without identity: " + show_error(e);
  if (e.loc.file.empty() || e.loc.line == 0 || e.loc.column == 0) {
    return "alarm without file:line:column: " + show_error(e);
  }
  if (e.loc.line > max_line + 1) return "alarm on a line past the end: " + show_error(e);
  return {};
}

inline std::uint32_t count_lines(std::string_view text) {
  std::uint32_t n = 1;
  for (char c : text) n += c == '\n' ? 1 : 0;
  return n;
}

// Depth of an expression tree, or -1 when an index is out of range or the
// tree is not a tree (a node reached twice).
inline int tree_depth(const gcode::Block& b, gcode::ExprId id, std::vector<char>& seen,
                      int depth = 1) {
  if (id == gcode::kNoExpr) return 0;
  if (id < 0 || static_cast<std::size_t>(id) >= b.nodes.size()) return -1;
  if (seen[static_cast<std::size_t>(id)] != 0) return -1;
  if (depth > kDepthBound + 8) return depth;  // deep enough to report; stop here
  seen[static_cast<std::size_t>(id)] = 1;
  const gcode::ExprNode& n = b.nodes[static_cast<std::size_t>(id)];
  const int a = tree_depth(b, n.a, seen, depth + 1);
  const int c = tree_depth(b, n.b, seen, depth + 1);
  if (a < 0 || c < 0) return -1;
  return std::max({depth, a, c});
}

inline std::string check_block(const gcode::Block& b) {
  std::vector<char> seen(b.nodes.size(), 0);
  auto root = [&](gcode::ExprId id, const char* what) -> std::string {
    const int d = tree_depth(b, id, seen);
    if (d < 0) return std::string("broken expression tree at ") + what;
    if (d > kDepthBound) {
      return std::string("expression deeper than ") + std::to_string(kDepthBound) + " at " + what +
             ": " + std::to_string(d);
    }
    return {};
  };
  for (const auto& w : b.words) {
    if (w.letter < 'A' || w.letter > 'Z') return "word letter out of range";
    if (w.is_expr) {
      if (auto s = root(w.expr, "a word"); !s.empty()) return s;
    } else if (!std::isfinite(w.value)) {
      return "word value not finite";
    }
  }
  for (gcode::ExprId id : {b.stmt.lhs, b.stmt.rhs, b.stmt.cond, b.stmt.target}) {
    if (auto s = root(id, "a statement"); !s.empty()) return s;
  }
  for (gcode::ExprId id : b.args) {
    if (auto s = root(id, "an O-word argument"); !s.empty()) return s;
  }
  for (const auto& a : b.assigns) {
    if (auto s = root(a.lhs, "a parameter setting"); !s.empty()) return s;
    if (auto s = root(a.rhs, "a parameter setting"); !s.empty()) return s;
  }
  if (b.stmt.kind == gcode::StmtKind::kOword &&
      (b.stmt.label < 0 || static_cast<std::size_t>(b.stmt.label) >= b.names.size())) {
    return "O-word label index out of range";
  }
  for (const auto& p : b.print_items) {
    if (p.is_text && (p.text < 0 || static_cast<std::size_t>(p.text) >= b.names.size())) {
      return "print text index out of range";
    }
    if (!p.is_text) {
      if (auto s = root(p.var, "a print item"); !s.empty()) return s;
    }
  }
  for (const auto& n : b.nodes) {
    if (n.op == gcode::Op::kNumber && !std::isfinite(n.value)) return "literal not finite";
    if (n.op == gcode::Op::kNamedVar &&
        (n.name < 0 || static_cast<std::size_t>(n.name) >= b.names.size())) {
      return "variable name index out of range";
    }
  }
  for (const auto& c : b.comments) {
    if (c.text < 0 || static_cast<std::size_t>(c.text) >= b.names.size()) {
      return "comment index out of range";
    }
  }
  return {};
}

// A file with the input's bytes that open_file_source can open by name.
class MemFile {
 public:
  explicit MemFile(std::string_view data) {
    fd_ = ::memfd_create("skipnc-fuzz", MFD_CLOEXEC);
    if (fd_ < 0) return;
    std::size_t done = 0;
    while (done < data.size()) {
      const ssize_t w = ::write(fd_, data.data() + done, data.size() - done);
      if (w <= 0) break;
      done += static_cast<std::size_t>(w);
    }
  }
  ~MemFile() {
    if (fd_ >= 0) ::close(fd_);
  }
  MemFile(const MemFile&) = delete;
  MemFile& operator=(const MemFile&) = delete;
  bool ok() const { return fd_ >= 0; }
  std::string path() const { return "/proc/self/fd/" + std::to_string(fd_); }

 private:
  int fd_ = -1;
};

// One block as a source returns it, or its error.
struct SeenBlock {
  bool ok = false;
  AlarmId error = AlarmId::kCount;
  std::string text;
  gcode::SourcePos at;  // tell() before next()
  std::uint64_t offset = 0;
  std::uint32_t line = 0, column = 0;
  friend bool operator==(const SeenBlock&, const SeenBlock&) = default;
};

inline std::vector<SeenBlock> read_all(gcode::Source& src) {
  std::vector<SeenBlock> out;
  gcode::RawBlock rb;
  while (out.size() < kMaxBlocks) {
    SeenBlock s;
    s.at = src.tell();
    auto r = src.next(rb);
    if (!r) {
      s.error = r.error().id;
      s.line = r.error().loc.line;
      s.column = r.error().loc.column;
      out.push_back(s);
      if (src.tell().offset == s.at.offset) break;  // no progress: stop
      continue;
    }
    if (!*r) break;
    s.ok = true;
    s.text = std::string(rb.text);
    s.offset = rb.offset;
    s.line = rb.line;
    s.column = rb.column;
    out.push_back(std::move(s));
  }
  return out;
}

// ---------------------------------------------------------------------------
// Lexer, parser and sources

inline std::string check_parser(std::string_view data) {
  // A small block limit and window, so that long blocks and the sliding
  // window are reached with short inputs.
  gcode::SourceLimits limits;
  limits.max_block_bytes = 200;
  limits.window_bytes = 0;
  auto mem = gcode::make_string_source("fuzz.nc", std::string(data), limits);
  const std::vector<SeenBlock> blocks = read_all(*mem);

  // The file source must see exactly the same blocks.
  MemFile file(data);
  if (file.ok()) {
    auto fs = gcode::open_file_source(file.path(), "fuzz.nc", limits);
    if (!fs) return "cannot open the in-memory file: " + fs.error().detail;
    const std::vector<SeenBlock> again = read_all(**fs);
    if (again != blocks) return "file source and memory source disagree";
    // Seeking back to a block gives that block again.
    std::size_t seeks = 0;
    for (std::size_t i = blocks.size(); i-- > 0 && seeks<32; i = i> 3 ? i - 3 : 0) {
      const SeenBlock& b = blocks[i];
      ++seeks;
      if (!(*fs)->seek(b.at)) return "seek to a block's position failed";
      gcode::RawBlock rb;
      auto r = (*fs)->next(rb);
      if (b.ok != r.has_value()) return "seek: a different outcome the second time";
      if (b.ok && (!*r || rb.text != b.text || rb.line != b.line || rb.column != b.column)) {
        return "seek: a different block the second time";
      }
      if (i == 0) break;
    }
  }

  gcode::Block blk;
  gcode::ParseLimits pl;
  pl.max_bracket_depth = 5;  // Fanuc's five levels
  // Macro B twice (the second time at the hard nesting bound), then the
  // RS274NGC and grbl syntaxes on the same blocks.
  for (int round = 0; round < 4; ++round) {
    if (round == 2) pl.syntax = gcode::Syntax::kRs274ngc;
    if (round == 3) pl.syntax = gcode::Syntax::kGrbl;
    for (const auto& b : blocks) {
      if (!b.ok) {
        if (b.error != AlarmId::kBlockTooLong) return "source error other than a long block";
        continue;
      }
      if (b.text.size() > limits.max_block_bytes) return "block longer than the limit";
      const SourceLoc loc{"fuzz.nc", b.line, b.column};
      auto r = gcode::parse_block(b.text, loc, b.offset, blk, pl);
      if (!r) {
        const Error& e = r.error();
        if (e.id == AlarmId::kInternal) return "internal error: " + show_error(e);
        if (e.loc.line != b.line || e.loc.column < b.column ||
            e.loc.column > b.column + b.text.size()) {
          return "parse error outside its block: " + show_error(e);
        }
        continue;
      }
      if (blk.loc.line != b.line) return "block line not kept";
      if (auto s = check_block(blk); !s.empty()) return s;
    }
    pl.max_bracket_depth = 512;  // the hard bound
  }
  // The whole input as one block (end-of-block characters inside).
  auto r = gcode::parse_block(data, SourceLoc{"fuzz.nc", 1, 1}, 0, blk, pl);
  if (r) {
    if (auto s = check_block(blk); !s.empty()) return s;
  }
  return {};
}

// ---------------------------------------------------------------------------
// The interpreter alone (as `skipnc canon`), with the statement budget

class NullSink final : public canon::CommandSink {
 public:
  void emit(const canon::Stamped& c) override {
    ++count;
    (void)c;
  }
  std::size_t count = 0;
};

inline interp::Setup make_setup(const Env& e, const DialectEnv& d, std::string program) {
  interp::Setup s;
  s.machine = &e.machine;
  s.dialect = &d.dialect;
  s.params = d.params.get();
  s.program_text = std::move(program);
  s.program_name = "fuzz.nc";
  s.include_dirs = {e.include_dir};
  return s;
}

// Runs the program without motion; skip blocks reach their end point.
inline std::string run_canon(const Env& e, const DialectEnv& d, const std::string& program,
                             std::unique_ptr<interp::Interpreter>* keep = nullptr) {
  auto in = interp::Interpreter::create(make_setup(e, d, program), AxisVec{});
  if (!in) return "could not start: " + show_error(in.error());
  NullSink sink;
  const std::uint32_t lines = count_lines(program);
  // Every step executes one block or ends: the statement budget bounds it.
  for (std::int64_t i = 0; i <= 4 * kMaxStatements + 16; ++i) {
    auto st = (*in)->step(sink);
    if (!st) {
      auto s = check_program_error(st.error(), lines);
      if (keep != nullptr) *keep = std::move(*in);
      return s;
    }
    if (*st == interp::Step::kEnd) {
      if (keep != nullptr) *keep = std::move(*in);
      return {};
    }
    if (*st == interp::Step::kSync) {
      interp::SyncState sync;
      sync.machine_position = (*in)->position();
      sync.actual_position = sync.machine_position;
      sync.skip_done = true;
      sync.latch_machine = sync.machine_position;
      auto r = (*in)->sync(sync);
      if (!r) {
        auto s = check_program_error(r.error(), lines);
        if (keep != nullptr) *keep = std::move(*in);
        return s;
      }
    }
  }
  return "the interpreter ran past its statement budget";
}

// `#1 = <expression>`: one block, the expression taken as written.
inline std::string check_expr(std::string_view data) {
  const Env& e = env();
  std::string program = "#1=";
  for (char c : data) program += (c == '\n' || c == ';') ? ' ' : c;
  program += '\n';
  std::unique_ptr<interp::Interpreter> in;
  auto s = run_canon(e, e.dialects.front(), program, &in);
  if (!s.empty()) return s;
  if (in) {
    auto v = in->read_variable(1);
    if (v && !v->vacant && !std::isfinite(v->v)) return "#1 holds a value that is not finite";
  }
  return {};
}

// ---------------------------------------------------------------------------
// The whole machine: interpreter, kernel and plant, with a tick budget

// "!n" at the start selects dialect n (0 fanuc, 1 nct, 2 mitsubishi, 3 compass).
inline std::pair<const DialectEnv*, std::string_view> pick_dialect(std::string_view data) {
  const Env& e = env();
  std::size_t d = 0;
  if (data.size() >= 2 && data[0] == '!' && data[1] >= '0' && data[1] <= '9') {
    d = static_cast<std::size_t>(data[1] - '0') % e.dialects.size();
    data.remove_prefix(2);
  }
  return {&e.dialects[d], data};
}

inline std::string check_run(const config::MachineConfig& m, const config::Dialect& d,
                             const config::Parameters& p, const machine::Scene& scene,
                             const interp::Setup& setup) {
  sim::Simulator sim(m, d, p, scene);
  auto r = sim.run(setup, {});
  if (!r) return {};  // could not start: an error value, nothing ran
  const sim::RunResult& res = *r;
  // The report, as `skipnc run --report` writes it (issue 21: the JSON path
  // is fuzzed too): whatever the program held, valid JSON.
  {
    report::ReportInput in;
    in.program = setup.program_name;
    in.dialect = d.name;
    in.machine = &m;
    in.dialect_table = &d;
    in.result = res;
    for (int n : {100, 5061, 5063}) {
      auto v = sim.interpreter()->read_variable(n);
      in.variables.emplace_back(std::to_string(n),
                                v && !v->vacant ? std::optional<double>(v->v) : std::nullopt);
    }
    if (!nlohmann::json::accept(report::to_json(in))) return "the report is not valid JSON";
  }
  if (res.ticks > m.limits.max_ticks + 1) return "the run passed its tick budget";
  if (res.status == sim::RunStatus::kAlarm) {
    if (!res.alarm) return "alarm status without an alarm";
    if (res.alarm->id == AlarmId::kInternal) return "internal error: " + show_error(*res.alarm);
  }
  for (int i = 0; i < m.axis_count(); ++i) {
    if (!std::isfinite(res.final_machine[i])) return "final position not finite";
  }
  for (const auto& sk : res.skips) {
    for (int i = 0; i < m.axis_count(); ++i) {
      if (!std::isfinite(sk.position[i]) || !std::isfinite(sk.end_position[i])) {
        return "skip position not finite";
      }
    }
  }
  return {};
}

inline std::string check_interp(std::string_view data) {
  const Env& e = env();
  auto [d, text] = pick_dialect(data);
  const std::string program(text);
  if (auto s = run_canon(e, *d, program); !s.empty()) return "canon: " + s;
  return check_run(e.machine, d->dialect, *d->params, d->scene, make_setup(e, *d, program));
}

// ---------------------------------------------------------------------------
// Machine and scene files: a file that loads must also run a short program.

inline constexpr std::string_view kProbeProgram =
    "G91 G31 Z-2. F1000\nG90 G0 Z0\nG1 X1. F2000\nM30\n";

inline std::string check_machine(std::string_view data) {
  auto m = config::parse_machine(data, "fuzz.machine.toml");
  if (!m) {
    if (m.error().id != AlarmId::kConfig) return "machine file error that is not a config error";
    return {};
  }
  if (m->axes.empty() || m->period_ns <= 0) return "a machine without axes or servo period";
  for (const auto& a : m->axes) {
    if (!(a.min_mm < a.max_mm) || !(a.accel_mm_s2 > 0) || !(a.rapid_mm_min > 0)) {
      return "an axis with limits out of range was accepted";
    }
  }
  if (m->limits.max_macro_statements < 1 || m->limits.max_ticks < 0) {
    return "limits out of range were accepted";
  }
  // The dialects are loaded once (env()); an unknown name cannot start a run.
  const config::Dialect* d = nullptr;
  for (const auto& de : env().dialects) {
    if (de.dialect.name == m->dialect) d = &de.dialect;
  }
  if (d == nullptr) return {};
  config::Parameters p(d);
  for (const auto& s : m->params) {
    if (!p.apply(s)) return {};
  }
  if (!config::check_skip_addresses(*d, p)) return {};
  m->persistent_vars.clear();  // the fuzzer writes no files
  m->limits.max_ticks = std::min<std::int64_t>(m->limits.max_ticks, kMaxFileTicks);
  m->limits.max_macro_statements = std::min<std::int64_t>(m->limits.max_macro_statements, 1000);
  machine::Scene scene;
  interp::Setup setup;
  setup.machine = &*m;
  setup.dialect = d;
  setup.params = &p;
  setup.program_text = std::string(kProbeProgram);
  setup.program_name = "probe.nc";
  setup.include_dirs = {env().include_dir};
  return check_run(*m, *d, p, scene, setup);
}

inline std::string check_scene(std::string_view data) {
  const Env& e = env();
  const DialectEnv& d = e.dialects.front();
  auto sc = machine::parse_scene(data, "fuzz.scene.toml", e.machine, d.dialect, *d.params);
  if (!sc) {
    if (sc.error().id != AlarmId::kConfig) return "scene file error that is not a config error";
    return {};
  }
  config::MachineConfig m = e.machine;
  m.limits.max_ticks = kMaxFileTicks;
  interp::Setup setup = make_setup(e, d, std::string(kProbeProgram));
  setup.machine = &m;
  return check_run(m, d.dialect, *d.params, *sc, setup);
}

// An STL file, binary or ASCII: a refusal names the file; a mesh that loads
// has finite vertices, and its hierarchy answers a distance and a contact
// query with finite numbers.
inline std::string check_stl(std::string_view data) {
  auto tris = machine::geo::parse_stl(data, "fuzz.stl", 1.0);
  if (!tris) {
    if (tris.error().detail.find("fuzz.stl") == std::string::npos)
      return "STL error that does not name the file: " + tris.error().detail;
    return {};
  }
  for (const auto& t : *tris) {
    for (const auto& v : {t.a, t.b, t.c}) {
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        return "STL vertex not finite";
    }
  }
  const machine::geo::TriMesh mesh(std::move(*tris));
  if (mesh.size() == 0) return {};
  const double d = mesh.surface_distance({0.0, 0.0, 0.0});
  if (std::isnan(d)) return "surface distance is NaN";
  double t = 0.0;
  machine::geo::Vec3 point, normal;
  if (mesh.first_contact({-1e3, -1e3, -1e3}, {1e3, 1e3, 1e3}, 1.0, t, point, normal) &&
      !(t >= 0.0 && t <= 1.0)) {
    return "contact outside [0, 1]";
  }
  return {};
}

// LinuxCNC's parameter file: a refusal has its line; a file that loads has
// each number once, in 1-5601, with finite values, and what is saved reads
// back the same numbers with values within the %.6f rounding.
inline std::string check_ngc_params(std::string_view data) {
  MemFile in(data);
  if (!in.ok()) return {};
  std::vector<int> numbers;
  std::vector<double> values;
  auto r = interp::load_var_file(in.path(), numbers, values);
  if (!r) {
    if (r.error().loc.line == 0 && r.error().detail.find("parameter file") == std::string::npos)
      return "parameter file error without a line: " + r.error().detail;
    return {};
  }
  std::vector<bool> seen(interp::VariableStore::kNgcParams, false);
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    if (numbers[i] < 1 || numbers[i] >= interp::VariableStore::kNgcParams)
      return "number out of range";
    if (seen[static_cast<std::size_t>(numbers[i])]) return "a number loaded twice";
    seen[static_cast<std::size_t>(numbers[i])] = true;
    if (!std::isfinite(values[i])) return "a value not finite";
  }
  static const std::string dir = [] {
    std::string tmpl =
        (std::filesystem::temp_directory_path() / "skipnc-fuzz-params-XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr) std::abort();
    return tmpl;
  }();
  const std::string saved = (std::filesystem::path(dir) / "params.var").string();
  if (!interp::save_var_file(saved, numbers, values)) return "the parameter file was not saved";
  std::vector<int> n2;
  std::vector<double> v2;
  auto back = interp::load_var_file(saved, n2, v2);
  if (!back) return "a saved parameter file does not load: " + back.error().detail;
  if (n2 != numbers) return "a saved parameter file reads back other numbers";
  for (std::size_t i = 0; i < v2.size(); ++i) {
    if (!(std::fabs(v2[i] - values[i]) <= 5e-7 + std::fabs(values[i]) * 1e-15))
      return "a saved value reads back as another";
  }
  return {};
}

}  // namespace skipnc::fuzz
