// skip-rules.md 5.3: signal configuration (rules 13-20).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/skip_inputs.hpp"
#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

// G31 Z-50. F600. from Z0 at t = 0: Z = -10 mm/s * t (no acceleration).
const char* kProbeZ = "G21 G90 G54 G31 Z-50. F600.\nM30\n";

TEST(Rules, rule_13_sk0_0_skip_is_active_when_the_input_is_1) {
  // X0.4 goes to 1 when Z passes -3.
  const Outcome o = Rig().param("6200#1=0").trigger("X0.4", 'Z', -3.0).run(kProbeZ);
  ASSERT_TRUE(o.completed());
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().position[2], -3.0, kUm);
}

TEST(Rules, rule_13_sk0_1_skip_is_active_when_the_input_is_0) {
  // X0.4 is 1 while Z > -3 and drops to 0 when Z passes -3.
  const Outcome o = Rig().param("6200#1=1").trigger("X0.4", 'Z', -3.0, false).run(kProbeZ);
  ASSERT_TRUE(o.completed());
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().position[2], -3.0, kUm);
  // The same wiring with SK0 = 0: the input is active (1) at block start.
  const Outcome high = Rig().param("6200#1=0").trigger("X0.4", 'Z', -3.0, false).run(kProbeZ);
  ASSERT_TRUE(high.skip().triggered);
  EXPECT_NEAR(high.skip().position[2], 0.0, 1e-3);
}

// X0.4 is on from 0 to 1.0 s (already active when the G31 starts), then
// again from 1.5 s.
Rig pulses(const char* dialect) {
  Rig r(dialect);
  r.pulse("X0.4", 0.0, 1.0).pulse("X0.4", 1.5, 0.1);
  return r;
}

TEST(Rules, rule_14_tsg_0_level_an_input_active_at_block_start_ends_the_block) {
  const Outcome o = pulses("fanuc").param("6200#0=0").run(kProbeZ);
  ASSERT_TRUE(o.completed());
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().position[2], 0.0, 0.02) << "latched where the block started";
}

// Level detection, input on when the G31 starts (issue 14): the block ends
// with no motion at all, the latch is the block's start point (Z0, on the
// machine too) and its time the block's start.
Rig pulses(const char* dialect);
TEST(Rules, rule_14_level_input_on_at_start_ends_the_block_without_any_motion) {
  for (const char* d : {"fanuc", "nct", "mitsubishi"}) {
    const Outcome o = pulses(d).run(kProbeZ);
    ASSERT_TRUE(o.completed()) << d << " " << o.alarm_code();
    ASSERT_TRUE(o.skip().triggered) << d;
    EXPECT_EQ(o.skip().position[2], 0.0) << d << ": the latch is the start point";
    EXPECT_EQ(o.skip().time_s, 0.0) << d << ": the latch time is the block start";
    EXPECT_EQ(o.r.final_machine[2], 0.0) << d << ": not one period of motion";
  }
}

TEST(Rules, rule_14_tsg_1_edge_an_input_active_at_block_start_waits_for_a_new_edge) {
  const Outcome o = pulses("fanuc").param("6200#0=1").machine(ideal_servo).run(kProbeZ);
  ASSERT_TRUE(o.completed());
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().time_s, 1.5, 1e-9) << "the rising edge at 1.5 s, not the level at 0 s";
  // The falling edge at 1.0 s is not an active edge either.
  EXPECT_NEAR(o.skip().position[2], -15.0, 0.011) << "10 mm/s for 1.5 s";
}

TEST(Rules, rule_14_tsg_1_sk0_1_the_falling_edge_is_the_active_edge) {
  const Outcome o = pulses("fanuc").param("6200#0=1").param("6200#1=1").run(kProbeZ);
  ASSERT_TRUE(o.completed());
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().time_s, 1.0, 1e-9);
}

TEST(Rules, rule_15_mitsubishi_input_active_when_g31_starts_completes_it_at_once) {
  const Outcome o =
      pulses("mitsubishi").run("G21 G90 G54 G31 Z-50. F600.\nG91 G1 X2. F600.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_NEAR(o.skip().position[2], 0.0, 0.02);
  EXPECT_NEAR(o.skip().end_position[2], 0.0, 0.02);
  EXPECT_NEAR(o.r.final_work[0], 2.0, kUm) << "the next block runs";
}

TEST(Rules, rule_15_compass_rising_edge_input_active_at_start_does_not_end_the_block) {
  const Outcome o = pulses("compass").run("G21 G90 G54 G31 Z-50. F600.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_GT(o.skip().time_s, 1.49);
}

class FixedAddress : public ::testing::TestWithParam<std::pair<int, const char*>> {};

TEST_P(FixedAddress, rule_16_3008_2_0_fixed_addresses_p1_to_p4) {
  const auto [p, addr] = GetParam();
  // Every fixed address pulses at its own time; only the selected one ends the block.
  Rig r("fanuc");
  r.param("3008#2=0")
      .pulse("X0.4", 0.2, 0.05)
      .pulse("X0.1", 0.4, 0.05)
      .pulse("X0.2", 0.6, 0.05)
      .pulse("X0.3", 0.8, 0.05);
  const Outcome o = r.run("G21 G90 G54 G31 Z-50. F600. P" + std::to_string(p) + "\nM30\n");
  ASSERT_TRUE(o.completed());
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_EQ(o.skip().signal, addr);
  EXPECT_NEAR(o.skip().time_s, 0.2 * p, 1e-9);
  EXPECT_EQ(o.skip().kind, canon::SkipKind::kMultiStep);
}

INSTANTIATE_TEST_SUITE_P(P1toP4, FixedAddress,
                         ::testing::Values(std::pair{1, "X0.4"}, std::pair{2, "X0.1"},
                                           std::pair{3, "X0.2"}, std::pair{4, "X0.3"}));

TEST(Rules, rule_16_plain_g31_uses_skip_x0_4) {
  const Outcome o = Rig().pulse("X0.1", 0.2, 0.05).pulse("X0.4", 0.3, 0.05).run(kProbeZ);
  ASSERT_TRUE(o.skip().triggered);
  EXPECT_EQ(o.skip().signal, "X0.4");
  EXPECT_NEAR(o.skip().time_s, 0.3, 1e-9);
}

TEST(Rules, rule_17_3008_2_1_x_area_the_seed_example_p1_x14_2_p2_x14_3) {
  Rig r("fanuc");
  r.param("3008#2=1").param("3008#1=0").param("3012=14").param("3020=2").param("3021=3");
  r.pulse("X14.2", 0.2, 0.05).pulse("X14.3", 0.4, 0.05).pulse("X0.4", 0.1, 0.05);
  const Outcome p1 = r.run("G21 G90 G54 G31 Z-50. F600. P1\nM30\n");
  ASSERT_TRUE(p1.skip().triggered);
  EXPECT_EQ(p1.skip().signal, "X14.2");
  EXPECT_NEAR(p1.skip().time_s, 0.2, 1e-9);
  const Outcome p2 = r.run("G21 G90 G54 G31 Z-50. F600. P2\nM30\n");
  EXPECT_EQ(p2.skip().signal, "X14.3");
  EXPECT_NEAR(p2.skip().time_s, 0.4, 1e-9);
}

TEST(Rules, rule_17_3008_1_1_g_area_and_3025_for_p5_to_p12) {
  Rig r("fanuc");
  r.param("3008#2=1").param("3008#1=1").param("3012=300").param("3022=6").param("3025=20");
  r.pulse("G300.6", 0.2, 0.05).pulse("X20.1", 0.3, 0.05);
  const Outcome p3 = r.run("G21 G90 G54 G31 Z-50. F600. P3\nM30\n");
  EXPECT_EQ(p3.skip().signal, "G300.6");
  const Outcome p6 = r.run("G21 G90 G54 G31 Z-50. F600. P6\nM30\n");
  EXPECT_EQ(p6.skip().signal, "X20.1") << "P6 = bit 1 of the X byte in 3025";
}

TEST(Rules, rule_17_out_of_range_address_parameters_are_refused_at_load) {
  auto d = config::builtin_dialect("fanuc");
  ASSERT_TRUE(d);
  auto apply = [&](config::Parameters& p, const char* text) {
    auto s = config::Parameters::parse_setting(text);
    EXPECT_TRUE(s);
    return p.apply(*s);
  };
  {
    config::Parameters p(&*d);
    EXPECT_FALSE(apply(p, "3020=8")) << "a bit is 0-7";
    EXPECT_FALSE(apply(p, "3012=512")) << "a G byte is 0-511";
    EXPECT_FALSE(apply(p, "3025=128")) << "an X byte is 0-127";
  }
  {
    // 3012 = 300 is a G byte; with area X (3008#1 = 0) it is out of range.
    config::Parameters p(&*d);
    ASSERT_TRUE(apply(p, "3008#2=1"));
    ASSERT_TRUE(apply(p, "3012=300"));
    auto r = config::check_skip_addresses(*d, p);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().id, AlarmId::kConfig);
    EXPECT_NE(r.error().detail.find("3012"), std::string::npos) << r.error().detail;
    ASSERT_TRUE(apply(p, "3008#1=1"));
    EXPECT_TRUE(config::check_skip_addresses(*d, p)) << "in area G it is valid";
  }
}

TEST(Rules, rule_18_compass_stops_on_the_rising_edge_and_resets_skip_at_each_g31) {
  // Skip rises at 0.2 s (first G31) and stays on until 0.5 s; the second G31
  // starts at about 0.24 s with the input on and waits for the edge at 0.7 s.
  const Outcome o = Rig("compass")
                        .pulse("X0.4", 0.2, 0.3)
                        .pulse("X0.4", 0.7, 0.05)
                        .traced()
                        .run("G21 G90 G54 G31 Z-50. F600.\nG31 Z-20.\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  ASSERT_EQ(o.skip_count(), 2U);
  EXPECT_NEAR(o.skip(0).time_s, 0.2, 1e-9);
  EXPECT_NEAR(o.skip(1).time_s, 0.7, 1e-9);
  // The handshake's Skip flag is 0 again when the second G31 starts.
  bool seen_first = false, reset = false;
  for (const auto& s : o.trace) {
    if (s.line == 1 && s.hs.skip) seen_first = true;
    if (seen_first && s.line == 2 && s.hs.active && !s.hs.skip && s.t < 0.7) reset = true;
  }
  EXPECT_TRUE(seen_first);
  EXPECT_TRUE(reset) << "Skip is reset to 0 at the start of the next G31";
}

TEST(Rules, rule_19_nct_p0_to_p3_select_skip_inputs_1_to_4) {
  Rig r("nct");
  r.pulse("X0.4", 0.2, 0.05)
      .pulse("X0.1", 0.4, 0.05)
      .pulse("X0.2", 0.6, 0.05)
      .pulse("X0.3", 0.8, 0.05);
  const char* addr[] = {"X0.4", "X0.1", "X0.2", "X0.3"};
  for (int p = 0; p <= 3; ++p) {
    const Outcome o = r.run("G21 G90 G54 G31 Z-50. F600. P" + std::to_string(p) + "\nM30\n");
    ASSERT_TRUE(o.completed()) << "P" << p;
    EXPECT_EQ(o.skip().signal, addr[p]) << "P" << p;
    EXPECT_EQ(o.skip().kind, canon::SkipKind::kSkip);
  }
  const Outcome none = r.run(kProbeZ);
  EXPECT_EQ(none.skip().signal, "X0.4") << "no P: skip signal 1";
  const Outcome bad = r.run("G21 G90 G54 G31 Z-50. F600. P4\nM30\n");
  EXPECT_EQ(bad.alarm_number(), 3051);
  EXPECT_EQ(bad.alarm_code(), "3051");
}

TEST(Rules, rule_20_multi_step_p1_to_p12_only_the_selected_input_ends_the_block) {
  // P5..P12 are bits 0..7 of the X byte in 3025 (1 by default).
  Rig r("fanuc");
  for (int bit = 0; bit < 8; ++bit) {
    r.pulse("X1." + std::to_string(bit), 0.1 + 0.05 * bit, 0.01);
  }
  r.pulse("X0.4", 0.05, 0.01);
  for (int p = 5; p <= 12; ++p) {
    const Outcome o = r.run("G21 G90 G54 G31 Z-50. F600. P" + std::to_string(p) + "\nM30\n");
    ASSERT_TRUE(o.completed()) << "P" << p;
    ASSERT_TRUE(o.skip().triggered);
    EXPECT_EQ(o.skip().signal, "X1." + std::to_string(p - 5));
    EXPECT_NEAR(o.skip().time_s, 0.1 + 0.05 * (p - 5), 1e-9) << "P" << p;
  }
  const Outcome bad = r.run("G21 G90 G54 G31 Z-50. F600. P13\nM30\n");
  EXPECT_EQ(bad.alarm_id(), AlarmId::kSkipBadP);
}

TEST(Rules, rule_20_mitsubishi_p_is_a_bit_mask_of_skip_signals) {
  // G31 P5: skip signal 1 or 3 (the manual's example).
  Rig r("mitsubishi");
  r.pulse("X0.1", 0.1, 0.01).pulse("X0.2", 0.2, 0.01).pulse("X0.4", 0.3, 0.01);
  const Outcome o = r.run("G21 G90 G54 G31 Z-50. F600. P5\nM30\n");
  ASSERT_TRUE(o.completed()) << o.alarm_code();
  EXPECT_EQ(o.skip().signal, "X0.2") << "signal 3 at 0.2 s; signal 2 at 0.1 s is not selected";
  EXPECT_EQ(o.skip().kind, canon::SkipKind::kMultiStep);
  const Outcome bad = r.run("G21 G90 G54 G31 Z-50. F600. P256\nM30\n");
  EXPECT_EQ(bad.alarm_code(), "P35");
}

// Seed 000: 6200#0 TSG and #1 SK0 set "SKIP, SKIP2-SKIP4" only. With SK0 = 1
// (active at 0) a G31 P1 whose input is 0 at the start ends at once; a G31
// P5 (SKIP5, X1.0) is still a level input active at 1 and latches where its
// input turns on.
TEST(Rules, rule_20_tsg_and_sk0_apply_to_skip1_to_skip4_only) {
  const Outcome p1 = Rig()
                         .param("6200#1=1")
                         .trigger("X0.4", 'Z', -3.0)
                         .run("G21 G90 G54 G31 P1 Z-10. F100.\nM30\n");
  ASSERT_TRUE(p1.completed()) << p1.alarm_code();
  ASSERT_TRUE(p1.skip().triggered);
  EXPECT_NEAR(p1.var(5063), 0.0, kUm) << "active at 0: already on at the start";
  const Outcome p5 = Rig()
                         .param("6200#1=1")
                         .trigger("X1.0", 'Z', -3.0)
                         .run("G21 G90 G54 G31 P5 Z-10. F100.\nM30\n");
  ASSERT_TRUE(p5.completed()) << p5.alarm_code();
  ASSERT_TRUE(p5.skip().triggered);
  EXPECT_NEAR(p5.var(5063), -3.0, kUm) << "SKIP5: active at 1 whatever SK0 says";
}

}  // namespace
}  // namespace skipnc::rules
