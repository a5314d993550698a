// A false WHILE inside a loop: its END is found once and remembered, so
// later passes jump there (issue 21: a false WHILE used to re-read every
// block to its END on each pass). The results must be the same as a scan's.
#include <gtest/gtest.h>

#include <string>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

TEST(WhileExits, AFalseWhileInsideALoopIsSkippedOnEveryPass) {
  std::string body;
  for (int i = 0; i < 200; ++i) body += "#2=#2+1000\n";
  const Outcome o = Rig().run(
      "#1=0\n#2=0\n"
      "WHILE [#1 LT 100] DO1\n"
      "WHILE [#1 LT 0] DO2\n" +
      body +
      "END2\n"
      "#2=#2+1\n"
      "#1=#1+1\n"
      "END1\n"
      "#100=#2\n"
      "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_EQ(o.var(100), 100.0);
}

// The same WHILE, false on some passes and true on others: the remembered
// exit is used only when the condition is false.
TEST(WhileExits, AWhileThatTurnsTrueStillRunsItsBody) {
  const Outcome o = Rig().run(
      "#1=0\n#2=0\n"
      "WHILE [#1 LT 10] DO1\n"
      "#3=0\n"
      "WHILE [[#1 GE 5] AND [#3 LT 1]] DO2\n"
      "#2=#2+100\n"
      "#3=1\n"
      "END2\n"
      "#2=#2+1\n"
      "#1=#1+1\n"
      "END1\n"
      "#100=#2\n"
      "M30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_EQ(o.var(100), 510.0);
}

// A missing END is still an alarm, on the first pass and not cached away.
TEST(WhileExits, AMissingEndIsStillAnAlarm) {
  const Outcome o = Rig().run("#1=0\nWHILE [#1 LT 0] DO2\n#2=1\nM30\n");
  EXPECT_EQ(o.alarm_id(), AlarmId::kMissingEnd);
}

}  // namespace
}  // namespace skipnc::rules
