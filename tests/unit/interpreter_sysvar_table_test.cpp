// The system-variable table (interpreter/sysvar_table.hpp) is the one place
// the numbers live: it must be ordered for its search, each of its ranges
// must be in docs/macro.md, each must read as a variable of the control on
// a run, and exactly its live ranges must wait for motion.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "interpreter/sysvar_table.hpp"
#include "rules/rule_rig.hpp"

namespace skipnc::interp::sysvar {
namespace {

TEST(SysvarTable, OrderedWithoutOverlapsAndFoundByEveryNumber) {
  for (std::size_t i = 0; i < std::size(kRanges); ++i) {
    const Range& r = kRanges[i];
    EXPECT_LE(r.first, r.last) << r.first;
    if (i > 0) {
      EXPECT_GT(r.first, kRanges[i - 1].last) << r.first;
    }
    for (int n : {r.first, r.last}) {
      int k = 0;
      EXPECT_EQ(find(n, k), &r) << n;
      EXPECT_EQ(k, n);
      if (r.alias != 0) {
        EXPECT_EQ(find(n + r.alias, k), &r) << n + r.alias;
        EXPECT_EQ(k, n);
      }
    }
  }
  int k = 0;
  EXPECT_EQ(find(3008, k), nullptr);
  EXPECT_EQ(find(4023, k), nullptr);
  EXPECT_EQ(find(4223, k), nullptr);
  EXPECT_EQ(find(5009, k), nullptr);
  EXPECT_EQ(find(2507, k), nullptr);
}

TEST(SysvarTable, EveryRangeIsInTheMacroPage) {
  std::ifstream in(std::filesystem::path(SKIPNC_SOURCE_DIR) / "docs" / "macro.md");
  std::stringstream page;
  page << in.rdbuf();
  for (const Range& r : kRanges) {
    // The old work-offset rows are written #2600.. in the page.
    const std::string first = "#" + std::to_string(r.first);
    EXPECT_NE(page.str().find(first), std::string::npos) << first << " is not in docs/macro.md";
  }
}

// Every readable range reads on a run (an axis the machine lacks reads
// vacant, not an alarm), and every range the table does not allow to be
// written raises write_protected.
TEST(SysvarTable, EveryRangeReadsAndTheReadOnlyOnesAreProtected) {
  for (const Range& r : kRanges) {
    const std::string n = std::to_string(r.first);
    const rules::Outcome o = rules::Rig().run("#100=#" + n + "\nM30\n");
    EXPECT_TRUE(o.completed()) << "#" << n << ": " << o.alarm_code();
    if (!(r.access & kWrite)) {
      const rules::Outcome w = rules::Rig().run("#" + n + "=1\nM30\n");
      EXPECT_EQ(w.alarm_id(), AlarmId::kWriteProtected) << "#" << n;
    }
  }
}

// The live ranges, and only they, wait for the queued motion: read right
// after a move, a live value is the one at its end; a value that does not
// change with motion is read at once (the move is still ahead).
TEST(SysvarTable, OnlyTheLiveRangesWaitForMotion) {
  const rules::Outcome o = rules::Rig().run(
      "G21 G90 G54 G1 X10. F6000.\n#100=#5021\nG1 X20.\n#101=#5001\n#102=#3001\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_NEAR(o.var(100), 10.0, 0.001) << "#5021 waited for the move";
  EXPECT_NEAR(o.var(101), 20.0, 1e-9) << "#5001: the block end point, at once";
  EXPECT_GT(o.var(102), 150.0) << "#3001 waited: both moves took their time (ms)";
  for (const Range& r : kRanges) {
    const bool expected = r.id == Id::kMachinePos || r.id == Id::kWorkPos ||
                          r.id == Id::kServoError || r.id == Id::kClockMs ||
                          r.id == Id::kClockHours;
    EXPECT_EQ(r.live, expected) << r.first;
  }
}

}  // namespace
}  // namespace skipnc::interp::sysvar
