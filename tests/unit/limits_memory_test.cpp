// What one run keeps in memory is bounded by the machine file's [limits]
// (issue 21: `N1 DPRNT[...] / GOTO1` grew to 24 GB; 2M named variables used
// 186 MB with no limit).
#include <gtest/gtest.h>

#include <string>

#include "rules/rule_rig.hpp"
#include "support/report_run.hpp"

namespace skipnc::rules {
namespace {

TEST(LimitsMemory, NamedVariablesPastTheLimitAreAnAlarm) {
  const Outcome o =
      Rig()
          .machine([](config::MachineConfig& m) { m.limits.max_named_variables = 10; })
          .run(
              "#<A0>=0\n#<A1>=1\n#<A2>=2\n#<A3>=3\n#<A4>=4\n#<A5>=5\n#<A6>=6\n#<A7>=7\n#<A8>=8\n#<"
              "A9>=9\n#<A10>=10\nM30\n");
  EXPECT_EQ(o.alarm_id(), AlarmId::kNamedVariableLimit);
  EXPECT_EQ(o.alarm_code(), "SN9071");
  EXPECT_EQ(o.alarm_line(), 11u) << "the eleventh name";
}

TEST(LimitsMemory, RewritingANamedVariableDoesNotCountAgain) {
  const Outcome o = Rig()
                        .machine([](config::MachineConfig& m) { m.limits.max_named_variables = 2; })
                        .run("#<A>=1\n#<B>=2\n#<A>=3\n#<B>=4\nM30\n");
  EXPECT_TRUE(o.completed()) << o.alarm_code();
}

TEST(LimitsMemory, MessagesPastTheLimitAreDroppedAndSaidOnce) {
  const Outcome o =
      Rig()
          .machine([](config::MachineConfig& m) { m.limits.max_message_bytes = 1024; })
          .run(
              "#1=0\n"
              "WHILE [#1 LT 1000] DO1\n"
              "(MSG,0123456789)\n"
              "#1=#1+1\n"
              "END1\n"
              "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_EQ(o.r.messages.size(), 103u) << "102 of 10 bytes, then the note";
  EXPECT_NE(o.r.messages.back().find("max_message_bytes"), std::string::npos);
}

}  // namespace
}  // namespace skipnc::rules

namespace skipnc::test {
namespace {

// An endless DPRNT loop ends with dprnt_limit at the bound, and the DPRNT
// file is not written past it.
TEST(LimitsMemory, DprntPastTheLimitIsAnAlarm) {
  TempDir dir;
  const auto m = dir.write("m.toml", "extends = \"mill3\"\n[limits]\nmax_dprnt_bytes = 1000\n");
  const auto prog = dir.write("p.nc", "POPEN\nN1 DPRNT[0123456789]\nGOTO1\n");
  const auto out = dir.path / "out.txt";
  const auto r = run_with_report(dir, prog, {"-m", m.string(), "--dprnt", out.string()});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 1) << r.err;
  EXPECT_EQ(r.report["alarm"].value("code", ""), "SN9070");
  EXPECT_LE(read_file(out).size(), 1000u);
}

}  // namespace
}  // namespace skipnc::test
