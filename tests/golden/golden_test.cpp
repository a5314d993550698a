// Golden tests: every tests/golden/<feature>/<case>.nc is run as a user
// would run it, and compared with what is stored beside it:
//   <case>.canon        expected `skipnc canon` output, exactly (with the
//                       dialect of the .json's "args", if any);
//   <case>.json         expected report fields (a subset of the report; numbers
//                       within "tolerance", default 1e-6), plus "exit" (the
//                       exit status) and "args" (extra command-line words, in
//                       which ${SOURCE_DIR} and ${TMP} name the source tree and
//                       the run's temporary folder);
//   <case>.scene.toml   the scene for the run (optional);
//   <case>.machine.toml the machine for the run and for canon (optional);
//   "memory" in the .json: {"machine": M, "vars": V}: the run's machine is M
//                       (extended) with V, a #500-#999 file beside the case,
//                       copied to the run's temporary folder as the control's
//                       kept commons (a probe calibrated before the program);
//                       "memory_after" checks that file's lines after the run;
//   <case>.dprnt        the file DPRNT writes between POPEN and PCLOS
//                       (--dprnt), byte for byte (optional).
// Programs in a folder named "macros" are called by the cases (-I), not cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/run_cli.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using skipnc::test::read_file;
using skipnc::test::run_cli;

namespace {

// tests/golden, the compatibility suite tests/compat (issue 29: programs
// in the style of public ones, run the same way) and tests/posts (issue 33:
// probing programs in the output format of public CAM posts).
std::vector<fs::path> golden_cases() {
  std::vector<fs::path> cases;
  for (const char* folder : {"golden", "compat", "posts"}) {
    const fs::path root = fs::path(SKIPNC_SOURCE_DIR) / "tests" / folder;
    if (!fs::exists(root)) continue;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      if (e.is_regular_file() && e.path().extension() == ".nc" &&
          e.path().parent_path().filename() != "macros") {
        cases.push_back(e.path());
      }
    }
  }
  std::sort(cases.begin(), cases.end());
  return cases;
}

std::string case_name(const fs::path& p) {
  const fs::path tests = fs::path(SKIPNC_SOURCE_DIR) / "tests";
  // Lexical: a case may be a symbolic link to an example's program.
  std::string n = p.lexically_relative(tests).replace_extension().string();
  if (n.starts_with("golden/")) n = n.substr(7);
  for (char& c : n) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return n;
}

// Every key of `want` must be in `got` with an equal value.
void expect_subset(const json& want, const json& got, const std::string& path, double tol) {
  if (want.is_object()) {
    ASSERT_TRUE(got.is_object()) << path << ": expected an object, got " << got.dump();
    for (auto it = want.begin(); it != want.end(); ++it) {
      ASSERT_TRUE(got.contains(it.key()))
          << path << "." << it.key() << " missing in " << got.dump();
      expect_subset(it.value(), got[it.key()], path + "." + it.key(), tol);
    }
  } else if (want.is_array()) {
    ASSERT_TRUE(got.is_array()) << path << ": expected an array, got " << got.dump();
    ASSERT_EQ(want.size(), got.size()) << path << ": " << got.dump();
    for (std::size_t i = 0; i < want.size(); ++i) {
      expect_subset(want[i], got[i], path + "[" + std::to_string(i) + "]", tol);
    }
  } else if (want.is_number() && got.is_number()) {
    EXPECT_NEAR(want.get<double>(), got.get<double>(), tol) << path;
  } else {
    EXPECT_EQ(want, got) << path;
  }
}

// The machine file of a case with "memory": extends the named machine and keeps
// #500-#999 in a copy of the case's vars file, in the run's temporary folder.
std::string memory_machine(const json& memory, const fs::path& nc, const fs::path& tmp) {
  std::string m = memory.at("machine").get<std::string>();
  const std::string key = "${SOURCE_DIR}";
  if (m.starts_with(key)) m = SKIPNC_SOURCE_DIR + m.substr(key.size());
  fs::copy_file(nc.parent_path() / memory.at("vars").get<std::string>(), tmp / "memory.vars");
  const fs::path machine = tmp / "memory.machine.toml";
  std::ofstream(machine) << "extends = " << json(m).dump()
                         << "\npersistent_variables = \"memory.vars\"\n";
  return machine.string();
}

class Golden : public ::testing::TestWithParam<fs::path> {};

TEST_P(Golden, MatchesStoredResult) {
  const fs::path nc = GetParam();
  const fs::path canon = fs::path(nc).replace_extension(".canon");
  const fs::path expect = fs::path(nc).replace_extension(".json");
  const fs::path scene = fs::path(nc).replace_extension(".scene.toml");
  const fs::path machine = fs::path(nc).replace_extension(".machine.toml");
  ASSERT_TRUE(fs::exists(canon) || fs::exists(expect)) << nc << " has no .canon or .json beside it";
  if (fs::exists(canon)) {
    std::vector<std::string> args = {"canon", nc.string()};
    if (fs::exists(machine)) args.insert(args.end(), {"-m", machine.string()});
    if (fs::exists(expect)) {
      // The run's dialect (-d in the case's "args") is canon's too.
      const json a = json::parse(read_file(expect)).value("args", json::array());
      for (std::size_t i = 0; i + 1 < a.size(); ++i) {
        if (a[i] == "-d" || a[i] == "--dialect") {
          args.insert(args.end(), {"-d", a[i + 1].get<std::string>()});
        }
      }
    }
    const auto r = run_cli(args);
    EXPECT_EQ(r.out, read_file(canon)) << "canon output of " << nc;
  }
  if (fs::exists(expect)) {
    const json want = json::parse(read_file(expect));
    skipnc::test::TempDir tmp;
    const fs::path report = tmp.path / "report.json";
    std::vector<std::string> args = {"run", nc.string(), "--report", report.string(), "-q"};
    if (fs::exists(scene)) args.insert(args.end(), {"--scene", scene.string()});
    if (fs::exists(machine)) args.insert(args.end(), {"-m", machine.string()});
    if (want.contains("memory")) {
      args.insert(args.end(), {"-m", memory_machine(want["memory"], nc, tmp.path)});
    }
    const fs::path dprnt = fs::path(nc).replace_extension(".dprnt");
    if (fs::exists(dprnt)) args.insert(args.end(), {"--dprnt", (tmp.path / "out.dprnt").string()});
    if (want.contains("args")) {
      for (const auto& a : want["args"]) {
        // ${SOURCE_DIR}: the source tree (examples/...); ${TMP}: the run's temp folder.
        std::string v = a.get<std::string>();
        for (const auto& [key, value] :
             {std::pair<std::string, std::string>{"${SOURCE_DIR}", SKIPNC_SOURCE_DIR},
              {"${TMP}", tmp.path.string()}}) {
          for (auto at = v.find(key); at != std::string::npos; at = v.find(key)) {
            v.replace(at, key.size(), value);
          }
        }
        args.push_back(v);
      }
    }
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, want.value("exit", 0)) << "exit status of " << nc;
    ASSERT_TRUE(fs::exists(report)) << "no report written for " << nc;
    const json got = json::parse(read_file(report));
    const double tol = want.value("tolerance", 1e-6);
    if (want.contains("report")) expect_subset(want["report"], got, "report", tol);
    if (fs::exists(dprnt)) {
      EXPECT_EQ(read_file(tmp.path / "out.dprnt"), read_file(dprnt)) << "DPRNT file of " << nc;
    }
    if (want.contains("memory_after")) {
      EXPECT_EQ(read_file(tmp.path / "memory.vars"), want["memory_after"].get<std::string>())
          << "kept commons after " << nc;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, Golden, ::testing::ValuesIn(golden_cases()),
                         [](const auto& param_info) { return case_name(param_info.param); });

}  // namespace
