// Every input that ever crashed, hung or leaked a harness (or broke one of
// its checks) is kept under tests/regression/<harness>/ and replayed here
// through the very check the fuzzer ran (tests/fuzz/targets.hpp), in the
// normal test run. To add one: copy the file libFuzzer wrote (crash-...,
// timeout-..., leak-...) to tests/regression/<harness>/ with a name that
// says what it is, fix the bug, and add a test below when the input deserves
// a statement of what the user must see.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz/targets.hpp"
#include "support/run_cli.hpp"

namespace fs = std::filesystem;

namespace skipnc::fuzz {
namespace {

struct Case {
  std::string harness;
  fs::path file;
};

std::vector<Case> kept_inputs() {
  std::vector<Case> out;
  const fs::path root = fs::path(SKIPNC_SOURCE_DIR) / "tests" / "regression";
  for (const char* h : {"parser", "expr", "interp", "machine", "scene", "stl", "ngc_params"}) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(root / h, ec)) {
      if (e.is_regular_file()) out.push_back({h, e.path()});
    }
  }
  std::sort(out.begin(), out.end(), [](const Case& a, const Case& b) { return a.file < b.file; });
  return out;
}

std::string replay(const Case& c) {
  const std::string data = test::read_file(c.file);
  if (c.harness == "parser") return check_parser(data);
  if (c.harness == "expr") return check_expr(data);
  if (c.harness == "interp") return check_interp(data);
  if (c.harness == "machine") return check_machine(data);
  if (c.harness == "stl") return check_stl(data);
  if (c.harness == "ngc_params") return check_ngc_params(data);
  return check_scene(data);
}

class KeptInput : public ::testing::TestWithParam<Case> {};
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(KeptInput);

TEST_P(KeptInput, HandledWithoutBreakingARule) {
  EXPECT_EQ(replay(GetParam()), "") << GetParam().file.filename();
}

INSTANTIATE_TEST_SUITE_P(Regression, KeptInput, ::testing::ValuesIn(kept_inputs()),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           std::string n = i.param.harness + "_" + i.param.file.filename().string();
                           for (char& ch : n) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return n;
                         });

// What a user sees for the inputs that once crashed.

// 30000 operators in one expression overflowed the stack of the recursive
// evaluator (expr/operator-chain-stack-overflow): now the parser refuses a
// tree deeper than gcode::kMaxExprDepth, at the expression's start.
TEST(Regression, LongOperatorChainIsAnAlarmWithItsPlace) {
  test::TempDir dir;
  const auto p = dir.write(
      "chain.nc", "G0 X0\n#1=1" + [] {
        std::string s;
        for (int i = 0; i < 30000; ++i) s += "+1";
        return s;
      }() + "\n");
  const auto r = test::run_cli({"canon", p.string()}, (dir.path / "err.txt").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(test::read_file(dir.path / "err.txt").find(p.string() + ":2:4: alarm"),
            std::string::npos);
}

// toml++ 3.3 asserted (or, with NDEBUG, ran into undefined behaviour) on a
// table header such as "[+[axis]]" and on a non-ASCII character outside a
// string value (machine/, scene/ table-header-*, non-ascii-*), and on a '}'
// where an array expects a value (close-brace-*): now the run
// cannot start (exit 2) and the error names file:line:column. Writing this
// test showed the file name of every machine or scene file error printed
// from freed memory (the options holding it ended before the message was
// written); the session keeps the names now (src/cli/session).
TEST(Regression, MalformedTomlIsAConfigErrorWithItsPlace) {
  test::TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1.\nM30\n");
  struct Bad {
    const char* option;
    std::string text;
    const char* where;
  };
  const Bad cases[] = {
      {"-s", "[[trigger]]\nsignal = \"SKIP\"\n[+[axis]]\n", ":3:2: error:"},
      {"-s", "[[o\xc4\xa0rator]]\n", ":1:4: error:"},
      {"-m", "name = \"m\"\n\"\xc3\xa9\" = 1\n", ":2:2: error:"},
      {"-m", "name = \"m\" \xc3\xa9\n", ":1:12: error:"},
      {"-m", "name = \"m\"\nlimits = [1, }]\n", ":2:14: error:"},
      {"-s", "[[trigger]]\nsignal = [ }\n", ":2:12: error:"},
      {"-m", "name = \"m\"\nwhen = 1979-05-27 0\n", ":2:19: error:"},
      {"-s", "[[trigger]]\nat = 0x1['X\xef\xb9\xbf'\n", ":2:12: error:"},
      {"-m", "name = \"m\"\ns = \"\"\"\\\xef\xb9\xbf\"\"\"\n", ":2:9: error:"},
  };
  for (const auto& c : cases) {
    const auto file = dir.write("bad.toml", c.text);
    const auto r = test::run_cli({"run", prog.string(), c.option, file.string(), "-q"},
                                 (dir.path / "err.txt").string());
    EXPECT_EQ(r.exit_code, 2) << c.text;
    const std::string err = test::read_file(dir.path / "err.txt");
    EXPECT_NE(err.find(file.string() + c.where), std::string::npos) << c.text << "\n" << err;
  }
}

}  // namespace
}  // namespace skipnc::fuzz
