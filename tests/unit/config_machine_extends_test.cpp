// Machine files that extend a built-in machine or another file: only the
// keys the file has change; errors keep their file, line and column.
#include <gtest/gtest.h>

#include <string>

#include "config/machine_config.hpp"
#include "core/embedded.hpp"
#include "support/run_cli.hpp"

namespace skipnc::config {
namespace {

using skipnc::test::TempDir;

TEST(MachineExtends, ABuiltInPlusAWorkOffsetAndAToolLength) {
  auto m = parse_machine(R"(extends = "mill3"
name = "shop-vmc"
[work_offsets]
G54 = { X = 100.0, Y = 50.0, Z = -200.0 }
[tool_offsets]
20 = { length = 150.0 }
)",
                         "shop.toml");
  ASSERT_TRUE(m) << m.error().detail;
  const auto base = builtin_machine("mill3");
  ASSERT_TRUE(base);
  EXPECT_EQ(m->name, "shop-vmc");
  EXPECT_EQ(m->extends, "built-in mill3");
  ASSERT_EQ(m->axis_count(), 3);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(m->axes[i].name, base->axes[i].name);
    EXPECT_EQ(m->axes[i].kp_per_s, base->axes[i].kp_per_s);
    EXPECT_EQ(m->axes[i].rapid_mm_min, base->axes[i].rapid_mm_min);
  }
  EXPECT_EQ(m->period_ns, base->period_ns);
  EXPECT_EQ(m->dialect, "fanuc");
  EXPECT_EQ(m->work_offsets[1][0], 100.0);
  EXPECT_EQ(m->work_offsets[1][1], 50.0);
  EXPECT_EQ(m->work_offsets[1][2], -200.0);
  ASSERT_TRUE(m->tool_offsets.contains(20));
  EXPECT_EQ(m->tool_offsets.at(20).length_geometry, 150.0);
}

TEST(MachineExtends, AnAxisTableChangesOnlyTheKeysItHas) {
  auto m = parse_machine(R"(extends = "mill3"
[[axis]]
name = "Z"
kp = 70.0
[[axis]]
name = "A"
min = -360.0
max = 360.0
)",
                         "shop.toml");
  ASSERT_TRUE(m) << m.error().detail;
  ASSERT_EQ(m->axis_count(), 4);
  EXPECT_EQ(m->axes[0].kp_per_s, 50.0);  // X as in mill3
  EXPECT_EQ(m->axes[2].name, 'Z');
  EXPECT_EQ(m->axes[2].kp_per_s, 70.0);
  EXPECT_EQ(m->axes[2].min_mm, -500.0);  // the rest of Z as in mill3
  EXPECT_EQ(m->axes[2].accel_mm_s2, 2000.0);
  EXPECT_EQ(m->axes[3].name, 'A');  // a new axis goes last
  EXPECT_EQ(m->axes[3].max_mm, 360.0);
}

TEST(MachineExtends, AFileExtendsAFileAndAnOffsetChangesOnlyTheAxesItNames) {
  TempDir dir;
  dir.write("base.toml", R"(extends = "mill3"
name = "cell-base"
[work_offsets]
G54 = { X = 100.0, Y = 50.0, Z = -200.0 }
)");
  const auto child = dir.write("child.toml", R"(extends = "base.toml"
[work_offsets]
G54 = { Z = -210.5 }
)");
  auto m = load_machine_file(child.string());
  ASSERT_TRUE(m) << m.error().detail;
  EXPECT_EQ(m->name, "cell-base");
  EXPECT_EQ(m->work_offsets[1][0], 100.0);
  EXPECT_EQ(m->work_offsets[1][1], 50.0);
  EXPECT_EQ(m->work_offsets[1][2], -210.5);
}

TEST(MachineExtends, AnUnknownKeyIsStillAnErrorWithItsPlace) {
  auto m = parse_machine("extends = \"mill3\"\n[work_offsets]\nG54 = { X = 1.0 }\nspindel = 3\n",
                         "shop.toml");
  // `spindel` after [work_offsets] is a key of that table: not an offset name.
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().id, AlarmId::kConfig);
  EXPECT_EQ(m.error().loc.line, 4u);
  auto top = parse_machine("extends = \"mill3\"\nspindel_max_rpm = 3\n", "shop.toml");
  ASSERT_FALSE(top);
  EXPECT_EQ(top.error().loc.line, 2u);
  EXPECT_EQ(top.error().loc.column, 19u);  // at the value, as every key error
}

TEST(MachineExtends, AnErrorInTheExtendedFileIsReportedAtTheExtendsKeyWithItsPlace) {
  TempDir dir;
  dir.write("base.toml", "extends = \"mill3\"\n\n[latch]\nmode = \"late\"\n");
  const auto child = dir.write("child.toml", "name = \"x\"\nextends = \"base.toml\"\n");
  auto m = load_machine_file(child.string());
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().id, AlarmId::kConfig);
  EXPECT_EQ(m.error().loc.line, 2u);
  EXPECT_EQ(m.error().loc.column, 11u);
  EXPECT_NE(m.error().detail.find("base.toml:4:8"), std::string::npos) << m.error().detail;
}

TEST(MachineExtends, ALoopOfFilesIsRefused) {
  TempDir dir;
  dir.write("a.toml", "extends = \"b.toml\"\n");
  const auto b = dir.write("b.toml", "extends = \"a.toml\"\n");
  auto m = load_machine_file(b.string());
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().id, AlarmId::kConfig);
  EXPECT_EQ(m.error().loc.line, 1u);
}

TEST(MachineExtends, AMissingMachineNamesTheBuiltIns) {
  auto m = parse_machine("extends = \"mill5\"\n", "shop.toml");
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().loc.line, 1u);
  EXPECT_NE(m.error().detail.find("mill3"), std::string::npos);
  auto t = parse_machine("extends = 3\n", "shop.toml");
  ASSERT_FALSE(t);
  EXPECT_EQ(t.error().loc.column, 11u);
}

TEST(MachineExtends, TheServoPeriodChangedKeepsTheTimeLimitInSeconds) {
  auto m = parse_machine("extends = \"mill3\"\nservo_period_ms = 0.5\n", "shop.toml");
  ASSERT_TRUE(m);
  const auto base = builtin_machine("mill3");
  EXPECT_EQ(m->period_ns, 500'000);
  EXPECT_EQ(m->limits.max_ticks, base->limits.max_ticks * 2);
}

TEST(ShowCommand, PrintsTheBuiltInMachineAndTheDemoAsTheyAreCompiledIn) {
  const auto r = skipnc::test::run_cli({"show", "machine", "mill3"});
  EXPECT_EQ(r.exit_code, 0);
  const EmbeddedFile* f = embedded_entry("machines/mill3.toml");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(r.out, std::string(f->content));
  // What it prints loads as a machine file.
  EXPECT_TRUE(parse_machine(r.out, "copied.toml"));
  const auto demo = skipnc::test::run_cli({"show", "demo"});
  EXPECT_EQ(demo.exit_code, 0);
  EXPECT_NE(demo.out.find(std::string(embedded_entry("demo/probe_demo.nc")->content)),
            std::string::npos);
  EXPECT_NE(demo.out.find(std::string(embedded_entry("demo/probe_demo.toml")->content)),
            std::string::npos);
  EXPECT_EQ(skipnc::test::run_cli({"show", "machine", "mill9"}).exit_code, 2);
  EXPECT_EQ(skipnc::test::run_cli({"show", "machines"}).out.find("mill3\n") != std::string::npos,
            true);
}

}  // namespace
}  // namespace skipnc::config
