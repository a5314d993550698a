// The skip block's rule functions (interpreter/skip_rules.hpp) on their own:
// a built-in dialect, its parameters as a user sets them (--param), and the
// words of one block. Each test names the rule of skip-rules.md it checks;
// the expected addresses, feeds and alarms come from the rule, the dialect's
// manual numbers where the rule gives them (P608, P603, P/S 015), else the
// alarm's identity. tests/rules/ checks the same rules through a whole run.
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "interpreter/skip_rules.hpp"

namespace skipnc::interp::skip_rules {
namespace {

// A built-in dialect with its parameters. Not copyable: the parameters keep
// a pointer to the dialect.
struct Control {
  config::Dialect d;
  config::Parameters p;

  explicit Control(std::string_view name, std::initializer_list<std::string_view> settings = {})
      : d(load(name)), p(&d) {
    for (std::string_view s : settings) {
      auto setting = config::Parameters::parse_setting(s);
      EXPECT_TRUE(setting.has_value()) << s;
      if (!setting) continue;
      auto applied = p.apply(*setting);
      EXPECT_TRUE(applied.has_value()) << s << ": " << (applied ? "" : applied.error().detail);
    }
  }
  Control(const Control&) = delete;
  Control& operator=(const Control&) = delete;

  const config::Switches& sw() const { return d.sw; }
  int number(const Error& e) const { return d.alarm(e.id).number; }
  std::string code(const Error& e) const { return d.alarm(e.id).code; }

  static config::Dialect load(std::string_view name) {
    auto d = config::builtin_dialect(name);
    EXPECT_TRUE(d.has_value()) << name;
    return d ? *d : config::Dialect{};
  }
};

constexpr int kX = 0;
constexpr int kY = 1;
constexpr int kZ = 2;
constexpr std::string_view kAxes = "XYZ";

Word word(double value, bool has_point = false) {
  Word w;
  w.value = value;
  w.has_point = has_point;
  return w;
}

// G31 X..: one axis moved.
BlockWords block(std::initializer_list<int> axes = {kX}) {
  BlockWords b;
  for (int a : axes) b.moved.set(a);
  return b;
}

BlockWords with_p(int p, std::initializer_list<int> axes = {kX}) {
  BlockWords b = block(axes);
  b.p = word(p);
  return b;
}

canon::SignalAddr addr(char area, int byte, int bit) {
  return canon::SignalAddr{area, static_cast<std::uint16_t>(byte), static_cast<std::uint8_t>(bit)};
}

// The inputs of a block that the rules accept (the test fails otherwise).
Inputs inputs_of(const BlockWords& b, const Control& c, bool cutter_comp = false) {
  auto f = form(b, c.sw(), cutter_comp);
  EXPECT_TRUE(f.has_value()) << (f ? "" : f.error().detail);
  if (!f) return {};
  auto in = inputs(b, *f, c.d, c.p);
  EXPECT_TRUE(in.has_value()) << (in ? "" : in.error().detail);
  return in ? *in : Inputs{};
}

// The alarm the form and input rules give a block (kCount: none).
AlarmId input_alarm(const BlockWords& b, const Control& c) {
  auto f = form(b, c.sw(), false);
  if (!f) return f.error().id;
  auto in = inputs(b, *f, c.d, c.p);
  return in ? AlarmId::kCount : in.error().id;
}

Detection detection_of(const BlockWords& b, const Control& c,
                       const config::MachineConfig& mc = config::MachineConfig{}) {
  return detection(b, inputs_of(b, c), kZ, c.sw(), c.p, mc);
}

// ---------------------------------------------------------------- form

TEST(SkipRulesForm, rule_06_fanuc_g31_in_cutter_comp_is_ps0035) {
  const Control c("fanuc");
  auto f = form(block(), c.sw(), true);
  ASSERT_FALSE(f.has_value());
  EXPECT_EQ(f.error().id, AlarmId::kSkipInCutterComp);
  EXPECT_EQ(c.number(f.error()), 35);
}

TEST(SkipRulesForm, rule_06_mitsubishi_g31_in_cutter_comp_is_p608) {
  const Control c("mitsubishi");
  auto f = form(block(), c.sw(), true);
  ASSERT_FALSE(f.has_value());
  EXPECT_EQ(c.code(f.error()), "P608");
}

TEST(SkipRulesForm, rule_06_without_cutter_comp_the_block_is_accepted) {
  for (const char* name : {"fanuc", "nct", "mitsubishi", "compass"}) {
    const Control c(name);
    EXPECT_TRUE(form(block(), c.sw(), false).has_value()) << name;
  }
}

TEST(SkipRulesForm, rule_41_p98_p99_in_cutter_comp_is_the_torque_skip_alarm) {
  const Control c("fanuc");
  for (int p : {98, 99}) {
    auto f = form(with_p(p), c.sw(), true);
    ASSERT_FALSE(f.has_value()) << p;
    EXPECT_EQ(f.error().id, AlarmId::kTorqueSkipCutterComp) << p;
  }
}

TEST(SkipRulesForm, rule_20_p_must_be_a_whole_number) {
  const Control c("fanuc");
  BlockWords b = block();
  b.p = word(1.5, true);
  auto f = form(b, c.sw(), false);
  ASSERT_FALSE(f.has_value());
  EXPECT_EQ(f.error().id, AlarmId::kSkipBadP);
  b.p = word(1.0, true);  // P1. written with a point
  EXPECT_FALSE(form(b, c.sw(), false).has_value());
  b.p->is_expr = true;  // P#1 with #1 = 1: the value of an expression is a number
  auto from_expr = form(b, c.sw(), false);
  ASSERT_TRUE(from_expr.has_value());
  EXPECT_EQ(from_expr->p, 1);
}

TEST(SkipRulesForm, rule_37_q_needs_p98_or_p99) {
  const Control c("fanuc");
  BlockWords b = with_p(1);
  b.q = word(50);
  auto f = form(b, c.sw(), false);
  ASSERT_FALSE(f.has_value());
  EXPECT_EQ(f.error().id, AlarmId::kSkipSyntax);
  b.p = word(99);
  auto torque_form = form(b, c.sw(), false);
  ASSERT_TRUE(torque_form.has_value());
  EXPECT_TRUE(torque_form->torque);
}

TEST(SkipRulesForm, rules_37_to_46_p98_p99_are_torque_skip_only_where_the_dialect_has_it) {
  // Fanuc (seed 000): P99 is the torque limit skip. Mitsubishi's P is a
  // mask of skip signals (multi-step skip function 2): P99 is signals 1, 2,
  // 6 and 7, not a torque skip.
  auto fanuc = form(with_p(99), Control("fanuc").sw(), false);
  auto mitsubishi = form(with_p(99), Control("mitsubishi").sw(), false);
  ASSERT_TRUE(fanuc.has_value() && mitsubishi.has_value());
  EXPECT_TRUE(fanuc->torque);
  EXPECT_FALSE(mitsubishi->torque);
}

TEST(SkipRulesForm, rule_33_34_k_is_an_address_of_fanuc_g31_only) {
  BlockWords b = block();
  b.k = word(1);
  EXPECT_TRUE(form(b, Control("fanuc").sw(), false).has_value());
  for (const char* name : {"nct", "mitsubishi", "compass"}) {
    const Control c(name);
    auto f = form(b, c.sw(), false);
    ASSERT_FALSE(f.has_value()) << name;
    EXPECT_EQ(f.error().id, AlarmId::kSkipSyntax) << name;
  }
}

TEST(SkipRulesForm, rule_36_g31_g53_only_on_compass) {
  BlockWords b = block();
  b.g53 = true;
  EXPECT_TRUE(form(b, Control("compass").sw(), false).has_value());
  for (const char* name : {"fanuc", "nct", "mitsubishi"}) {
    const Control c(name);
    auto f = form(b, c.sw(), false);
    ASSERT_FALSE(f.has_value()) << name;
    EXPECT_EQ(f.error().id, AlarmId::kSkipSyntax) << name;
  }
}

// Seed 001 (NCT 18.1, no rule number): a G31 without a target is a format
// error, 3051; the Fanuc manual has no such error.
TEST(SkipRulesForm, nct_g31_without_an_axis_word_is_3051) {
  const Control c("nct");
  auto f = form(block({}), c.sw(), false);
  ASSERT_FALSE(f.has_value());
  EXPECT_EQ(c.number(f.error()), 3051);
  EXPECT_TRUE(form(block({}), Control("fanuc").sw(), false).has_value());
}

TEST(SkipRulesForm, rule_18_compass_g31_has_no_p) {
  const Control c("compass");
  auto f = form(with_p(1), c.sw(), false);
  ASSERT_FALSE(f.has_value());
  EXPECT_EQ(f.error().id, AlarmId::kSkipSyntax);
}

// -------------------------------------------------------------- torque

Result<Torque> torque_of(const BlockWords& b, const Control& c) {
  auto f = form(b, c.sw(), false);
  EXPECT_TRUE(f.has_value() && f->torque);
  if (!f) return std::unexpected(f.error());
  return torque(b, *f, kAxes, c.sw(), c.p);
}

TEST(SkipRulesTorque, rule_37_q_is_the_torque_limit_override) {
  const Control c("fanuc");
  BlockWords b = with_p(99, {kZ});
  b.q = word(150);
  auto t = torque_of(b, c);
  ASSERT_TRUE(t.has_value());
  EXPECT_DOUBLE_EQ(t->limit_pct, 150.0);
  EXPECT_TRUE(t->ends);
  EXPECT_EQ(t->axis, kZ);
}

TEST(SkipRulesTorque, rule_37_q_omitted_uses_parameter_6280) {
  const Control c("fanuc", {"6280=40"});
  auto t = torque_of(with_p(98, {kY}), c);
  ASSERT_TRUE(t.has_value());
  EXPECT_DOUBLE_EQ(t->limit_pct, 40.0);
  EXPECT_EQ(t->axis, kY);
}

TEST(SkipRulesTorque, rule_37_q_outside_1_to_300_is_refused) {
  const Control c("fanuc");
  for (double q : {0.0, 0.5, 301.0}) {
    BlockWords b = with_p(99, {kZ});
    b.q = word(q);
    auto t = torque_of(b, c);
    ASSERT_FALSE(t.has_value()) << q;
    EXPECT_EQ(t.error().id, AlarmId::kTorqueSkipBadQ) << q;
  }
  for (double q : {1.0, 300.0}) {
    BlockWords b = with_p(99, {kZ});
    b.q = word(q);
    EXPECT_TRUE(torque_of(b, c).has_value()) << q;
  }
}

TEST(SkipRulesTorque, rule_40_p98_p99_with_two_axes_or_none_is_ps0015) {
  const Control c("fanuc");
  for (int p : {98, 99}) {
    auto two = torque_of(with_p(p, {kX, kZ}), c);
    ASSERT_FALSE(two.has_value()) << p;
    EXPECT_EQ(two.error().id, AlarmId::kTorqueSkipAxes);
    EXPECT_EQ(c.number(two.error()), 15) << "old numbering P/S 015";
    auto none = torque_of(with_p(p, {}), c);
    ASSERT_FALSE(none.has_value()) << p;
    EXPECT_EQ(c.number(none.error()), 15);
  }
}

TEST(SkipRulesTorque, rule_42_an_axis_under_synchronous_control_is_refused) {
  // 90012: bit n = axis n+1 under synchronous control; Y (bit 1) here.
  const Control c("fanuc", {"90012=2"});
  auto on_y = torque_of(with_p(99, {kY}), c);
  ASSERT_FALSE(on_y.has_value());
  EXPECT_EQ(on_y.error().id, AlarmId::kTorqueSkipSyncAxis);
  EXPECT_TRUE(torque_of(with_p(99, {kZ}), c).has_value()) << "Z is not synchronous";
}

TEST(SkipRulesTorque, rule_44_parameter_6281_is_the_detection_delay_in_ms) {
  const Control c("fanuc", {"6281=250"});
  auto t = torque_of(with_p(98, {kZ}), c);
  ASSERT_TRUE(t.has_value());
  EXPECT_DOUBLE_EQ(t->delay_s, 0.25);
}

TEST(SkipRulesTorque, rule_46_no_torque_limit_commanded_the_limit_does_not_end_the_block) {
  const Control c("fanuc", {"6280=0"});
  auto t = torque_of(with_p(99, {kZ}), c);
  ASSERT_TRUE(t.has_value());
  EXPECT_FALSE(t->ends);
}

// -------------------------------------------------------------- inputs

TEST(SkipRulesInputs, rule_16_fanuc_plain_g31_watches_skip_x0_4) {
  const Control c("fanuc");
  const Inputs in = inputs_of(block(), c);
  ASSERT_EQ(in.count, 1);
  EXPECT_EQ(in.addr[0], addr('X', 0, 4));
  EXPECT_EQ(in.kind, canon::SkipKind::kSkip);
}

TEST(SkipRulesInputs, rule_16_3008_2_0_fixed_addresses_p1_to_p4) {
  const Control c("fanuc");
  const canon::SignalAddr expected[] = {addr('X', 0, 4), addr('X', 0, 1), addr('X', 0, 2),
                                        addr('X', 0, 3)};
  for (int p = 1; p <= 4; ++p) {
    const Inputs in = inputs_of(with_p(p), c);
    ASSERT_EQ(in.count, 1) << p;
    EXPECT_EQ(in.addr[0], expected[p - 1]) << "P" << p;
  }
}

TEST(SkipRulesInputs, rule_17_3008_2_1_the_seed_example_p1_x14_2_p2_x14_3) {
  const Control c("fanuc", {"3008#2=1", "3008#1=0", "3012=14", "3020=2", "3021=3"});
  EXPECT_EQ(inputs_of(with_p(1), c).addr[0], addr('X', 14, 2));
  EXPECT_EQ(inputs_of(with_p(2), c).addr[0], addr('X', 14, 3));
}

TEST(SkipRulesInputs, rule_17_3008_1_1_g_area_and_3025_for_p5_to_p12) {
  const Control c("fanuc", {"3008#2=1", "3008#1=1", "3012=300", "3022=6", "3025=9"});
  EXPECT_EQ(inputs_of(with_p(3), c).addr[0], addr('G', 300, 6));
  // P5..P12: bits 0..7 of the X byte in 3025.
  EXPECT_EQ(inputs_of(with_p(5), c).addr[0], addr('X', 9, 0));
  EXPECT_EQ(inputs_of(with_p(12), c).addr[0], addr('X', 9, 7));
}

TEST(SkipRulesInputs, rule_19_nct_p0_to_p3_are_inputs_1_to_4_no_p_is_input_1) {
  // NCT wires its skip inputs 1-4 where Fanuc's SKIP1-SKIP4 are: P0 is
  // Fanuc's P1, one lower (the off-by-one of rule 19).
  const Control nct("nct");
  const Control fanuc("fanuc");
  for (int p = 0; p <= 3; ++p) {
    const Inputs in = inputs_of(with_p(p), nct);
    ASSERT_EQ(in.count, 1) << p;
    EXPECT_EQ(in.addr[0], inputs_of(with_p(p + 1), fanuc).addr[0]) << "P" << p;
    EXPECT_EQ(in.kind, canon::SkipKind::kSkip) << "a selection, not multi-step skip";
  }
  EXPECT_EQ(inputs_of(block(), nct).addr[0], inputs_of(with_p(0), nct).addr[0]);
}

TEST(SkipRulesInputs, rule_19_nct_p4_is_alarm_3051) {
  const Control c("nct");
  auto f = form(with_p(4), c.sw(), false);
  ASSERT_TRUE(f.has_value());
  auto in = inputs(with_p(4), *f, c.d, c.p);
  ASSERT_FALSE(in.has_value());
  EXPECT_EQ(in.error().id, AlarmId::kSkipBadP);
  EXPECT_EQ(c.number(in.error()), 3051);
}

TEST(SkipRulesInputs, rule_20_fanuc_p1_to_p12_select_one_input_each_as_multi_step_skip) {
  const Control c("fanuc");
  for (int p = 1; p <= 12; ++p) {
    const Inputs in = inputs_of(with_p(p), c);
    EXPECT_EQ(in.count, 1) << "only the selected input ends the block, P" << p;
    EXPECT_EQ(in.kind, canon::SkipKind::kMultiStep);
  }
  EXPECT_EQ(input_alarm(with_p(0), c), AlarmId::kSkipBadP);
  EXPECT_EQ(input_alarm(with_p(13), c), AlarmId::kSkipBadP);
}

TEST(SkipRulesInputs, rule_20_mitsubishi_p_is_a_mask_of_skip_signals) {
  // 5.9: Mitsubishi multi-step skip function 2, P1-P255, bit n-1 = signal n.
  const Control c("mitsubishi");
  const Inputs in = inputs_of(with_p(5), c);  // 0b101: signals 1 and 3
  ASSERT_EQ(in.count, 2);
  EXPECT_EQ(in.addr[0], c.d.fixed_skip_inputs[0]);
  EXPECT_EQ(in.addr[1], c.d.fixed_skip_inputs[2]);
  EXPECT_EQ(in.kind, canon::SkipKind::kMultiStep);
  EXPECT_EQ(inputs_of(with_p(255), c).count, 8);
  for (int p : {0, 256}) {
    auto f = form(with_p(p), c.sw(), false);
    ASSERT_TRUE(f.has_value());
    auto bad = inputs(with_p(p), *f, c.d, c.p);
    ASSERT_FALSE(bad.has_value()) << p;
    EXPECT_EQ(c.code(bad.error()), "P35") << p;
  }
}

TEST(SkipRulesInputs, rule_20_mitsubishi_g31_n_watches_the_signals_of_its_parameter) {
  // G31.2: condition in 1175 + 2 = 1177; 6 = signals 2 and 3.
  const Control c("mitsubishi", {"1177=6"});
  BlockWords b = block();
  b.step = 2;
  const Inputs in = inputs_of(b, c);
  ASSERT_EQ(in.count, 2);
  EXPECT_EQ(in.addr[0], c.d.fixed_skip_inputs[1]);
  EXPECT_EQ(in.addr[1], c.d.fixed_skip_inputs[2]);
  const Control none("mitsubishi", {"1177=0"});
  EXPECT_EQ(input_alarm(b, none), AlarmId::kSkipBadP) << "no signal set";
}

TEST(SkipRulesInputs, rules_38_39_p98_watches_no_input_p99_the_skip_signal) {
  const Control c("fanuc");
  const Inputs p98 = inputs_of(with_p(98, {kZ}), c);
  EXPECT_EQ(p98.kind, canon::SkipKind::kTorque);
  EXPECT_EQ(p98.count, 0);
  const Inputs p99 = inputs_of(with_p(99, {kZ}), c);
  EXPECT_EQ(p99.kind, canon::SkipKind::kTorque);
  ASSERT_EQ(p99.count, 1);
  EXPECT_EQ(p99.addr[0], addr('X', 0, 4));
}

// ---------------------------------------------------------------- feed

FeedState feeds(double modal, double last_cutting = 0.0) {
  FeedState s;
  s.modal_mm_per_min = modal;
  s.last_cutting_mm_per_min = last_cutting;
  return s;
}

TEST(SkipRulesFeed, rule_07_mitsubishi_f_in_the_block_is_used_and_not_made_modal) {
  const Control c("mitsubishi", {"1174=250"});
  BlockWords b = block();
  b.f_mm_per_min = 100.0;
  EXPECT_DOUBLE_EQ(*feed(b, feeds(300.0), c.sw(), c.p), 100.0);
  EXPECT_FALSE(block_f_is_modal(c.sw()));
  EXPECT_TRUE(block_f_is_modal(Control("fanuc").sw()));
}

TEST(SkipRulesFeed, rule_07_mitsubishi_no_f_uses_1174_skip_f_not_the_modal_f) {
  const Control c("mitsubishi", {"1174=250"});
  EXPECT_DOUBLE_EQ(*feed(block(), feeds(300.0), c.sw(), c.p), 250.0);
}

TEST(SkipRulesFeed, rule_07_mitsubishi_g31_n_without_f_uses_its_own_feed_parameter) {
  // G31.1: condition 1175, feed 1176 (the parameter after the condition).
  const Control c("mitsubishi", {"1174=250", "1176=80"});
  BlockWords b = block();
  b.step = 1;
  EXPECT_DOUBLE_EQ(*feed(b, feeds(300.0), c.sw(), c.p), 80.0);
}

TEST(SkipRulesFeed, rule_08_mitsubishi_no_f_and_skip_f_zero_is_p603) {
  const Control c("mitsubishi", {"1174=0"});
  auto f = feed(block(), feeds(300.0), c.sw(), c.p);
  ASSERT_FALSE(f.has_value());
  EXPECT_EQ(c.code(f.error()), "P603");
}

TEST(SkipRulesFeed, rule_09_nct_skipf_0_uses_the_specified_or_modal_f) {
  const Control c("nct", {"90101=0", "90102=40"});
  EXPECT_DOUBLE_EQ(*feed(block(), feeds(300.0), c.sw(), c.p), 300.0);
}

TEST(SkipRulesFeed, rule_09_nct_skipf_1_uses_g31fd_whatever_f_says) {
  const Control c("nct", {"90101=1", "90102=40"});
  BlockWords b = block();
  b.f_mm_per_min = 150.0;
  EXPECT_DOUBLE_EQ(*feed(b, feeds(150.0), c.sw(), c.p), 40.0);
}

TEST(SkipRulesFeed, rule_10_compass_f_omitted_uses_the_last_non_rapid_feed) {
  // The modal F may have changed on a rapid block since (G00 F..); CompassNC
  // takes the F of the last cutting move.
  const Control c("compass");
  EXPECT_DOUBLE_EQ(*feed(block(), feeds(900.0, 120.0), c.sw(), c.p), 120.0);
  BlockWords b = block();
  b.f_mm_per_min = 60.0;
  EXPECT_DOUBLE_EQ(*feed(b, feeds(60.0, 120.0), c.sw(), c.p), 60.0) << "F in the block";
}

TEST(SkipRulesFeed, rule_49_fanuc_runs_at_the_modal_f_and_refuses_feed_zero) {
  const Control c("fanuc");
  EXPECT_DOUBLE_EQ(*feed(block(), feeds(300.0), c.sw(), c.p), 300.0);
  auto zero = feed(block(), feeds(0.0), c.sw(), c.p);
  ASSERT_FALSE(zero.has_value());
  EXPECT_EQ(zero.error().id, AlarmId::kSkipNoFeed);
  EXPECT_EQ(c.code(zero.error()), "PS0011");
}

// ----------------------------------------------------------- detection

TEST(SkipRulesDetection, rule_13_sk0_sets_the_active_level) {
  EXPECT_FALSE(detection_of(block(), Control("fanuc")).active_low);
  EXPECT_TRUE(detection_of(block(), Control("fanuc", {"6200#1=1"})).active_low);
}

TEST(SkipRulesDetection, rule_14_tsg_chooses_level_or_edge_detection) {
  EXPECT_FALSE(detection_of(block(), Control("fanuc")).edge);
  EXPECT_TRUE(detection_of(block(), Control("fanuc", {"6200#0=1"})).edge);
}

TEST(SkipRulesDetection, rules_13_14_tsg_and_sk0_apply_to_skip_to_skip4_only) {
  // Seed 000: 6200 sets SKIP and SKIP2-SKIP4; SKIP5-SKIP12 stay level inputs
  // active at 1.
  const Control c("fanuc", {"6200#0=1", "6200#1=1"});
  const Detection p4 = detection_of(with_p(4), c);
  EXPECT_TRUE(p4.edge);
  EXPECT_TRUE(p4.active_low);
  const Detection p5 = detection_of(with_p(5), c);
  EXPECT_FALSE(p5.edge);
  EXPECT_FALSE(p5.active_low);
}

TEST(SkipRulesDetection, rule_15_an_input_active_at_the_start_ends_the_block_on_mitsubishi) {
  EXPECT_TRUE(detection_of(block(), Control("mitsubishi")).active_at_start_ends);
}

TEST(SkipRulesDetection, rule_18_compass_waits_for_the_rising_edge) {
  const Detection d = detection_of(block(), Control("compass"));
  EXPECT_TRUE(d.edge);
  EXPECT_FALSE(d.active_low);
  EXPECT_FALSE(d.active_at_start_ends);
}

TEST(SkipRulesDetection, rule_11_skf_0_no_override_no_acc_dec_and_rule_27_immediate_stop) {
  const Detection d = detection_of(block(), Control("fanuc"));
  EXPECT_TRUE(d.feed_fixed);
  EXPECT_FALSE(d.accel);
  EXPECT_EQ(d.stop, canon::SkipStop::kImmediate);
}

TEST(SkipRulesDetection, rule_11_skf_1_override_and_acc_dec_act_the_axes_decelerate) {
  const Detection d = detection_of(block(), Control("fanuc", {"6200#7=1"}));
  EXPECT_FALSE(d.feed_fixed);
  EXPECT_TRUE(d.accel);
  EXPECT_EQ(d.stop, canon::SkipStop::kDecelerate);
}

TEST(SkipRulesDetection, rule_12_mitsubishi_override_fixed_override_zero_stops_no_acc_dec) {
  const Detection d = detection_of(block(), Control("mitsubishi"));
  EXPECT_TRUE(d.feed_fixed);
  EXPECT_TRUE(d.override_zero_stops);
  EXPECT_FALSE(d.accel);
}

TEST(SkipRulesDetection, rule_27_nct_decelerates_mitsubishi_stops_immediately) {
  EXPECT_EQ(detection_of(block(), Control("nct")).stop, canon::SkipStop::kDecelerate);
  EXPECT_EQ(detection_of(block(), Control("mitsubishi")).stop, canon::SkipStop::kImmediate);
}

TEST(SkipRulesDetection, rule_35_mitsubishi_machine_lock_ignores_the_skip_signal) {
  EXPECT_FALSE(detection_of(block(), Control("mitsubishi")).ignore_inputs);
  EXPECT_TRUE(detection_of(block(), Control("mitsubishi", {"90010=1"})).ignore_inputs);
}

TEST(SkipRulesDetection, rule_35_mitsubishi_z_cancel_ignores_it_for_a_z_only_g31) {
  const Control c("mitsubishi", {"90011=1"});
  EXPECT_TRUE(detection_of(block({kZ}), c).ignore_inputs);
  EXPECT_FALSE(detection_of(block({kX, kZ}), c).ignore_inputs);
  EXPECT_FALSE(detection_of(block({kX}), c).ignore_inputs);
}

TEST(SkipRulesDetection, rule_35_fanuc_machine_lock_still_monitors_the_skip_signal) {
  EXPECT_FALSE(detection_of(block(), Control("fanuc", {"90010=1"})).ignore_inputs);
}

TEST(SkipRulesDetection, rule_21_how_the_position_is_latched_is_the_machines_setting) {
  const Control c("fanuc");
  config::MachineConfig mc;
  mc.latch = canon::SkipLatch::kSampled;
  mc.latch_delay_s = 0.002;
  mc.servo_delay_comp = false;
  const Detection d = detection_of(block(), c, mc);
  EXPECT_EQ(d.latch, canon::SkipLatch::kSampled);
  EXPECT_DOUBLE_EQ(d.latch_delay_s, 0.002);
  EXPECT_FALSE(d.servo_delay_comp);
  EXPECT_EQ(detection_of(block(), c).latch, canon::SkipLatch::kExact);
}

// ---------------------------------------------------------------- miss

TEST(SkipRulesMiss, rule_33_k1_alarms_on_a_miss_k0_does_not) {
  const Control c("fanuc");
  BlockWords b = block();
  b.k = word(1);
  EXPECT_TRUE(*alarm_on_miss(b, c.sw(), c.p));
  b.k = word(0);
  EXPECT_FALSE(*alarm_on_miss(b, c.sw(), c.p));
}

TEST(SkipRulesMiss, rule_33_k_omitted_parameter_90001_decides) {
  const Control off("fanuc");
  EXPECT_FALSE(*alarm_on_miss(block(), off.sw(), off.p));
  const Control on("fanuc", {"90001=1"});
  EXPECT_TRUE(*alarm_on_miss(block(), on.sw(), on.p));
  BlockWords k0 = block();
  k0.k = word(0);
  EXPECT_FALSE(*alarm_on_miss(k0, on.sw(), on.p)) << "K0 overrides the parameter";
}

TEST(SkipRulesMiss, rule_33_k_other_than_0_or_1_is_refused) {
  const Control c("fanuc");
  BlockWords b = block();
  b.k = word(2);
  auto k = alarm_on_miss(b, c.sw(), c.p);
  ASSERT_FALSE(k.has_value());
  EXPECT_EQ(k.error().id, AlarmId::kSkipSyntax);
}

// NCT stores the programmed end point on a miss (rule 22) and goes on.
TEST(SkipRulesMiss, rules_22_34_mitsubishi_nct_and_compass_complete_a_miss_normally) {
  for (const char* name : {"mitsubishi", "nct", "compass"}) {
    const Control c(name);
    auto k = alarm_on_miss(block(), c.sw(), c.p);
    ASSERT_TRUE(k.has_value()) << name;
    EXPECT_FALSE(*k) << name;
  }
}

TEST(SkipRulesMiss, rule_45_k1_applies_to_p98_p99) {
  const Control c("fanuc");
  BlockWords b = with_p(99, {kZ});
  b.k = word(1);
  ASSERT_TRUE(form(b, c.sw(), false).has_value());
  EXPECT_TRUE(*alarm_on_miss(b, c.sw(), c.p));
}

}  // namespace
}  // namespace skipnc::interp::skip_rules
