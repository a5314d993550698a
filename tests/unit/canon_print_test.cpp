// The canonical text form: numbers read back exactly, in the shortest form.
#include <gtest/gtest.h>

#include <charconv>
#include <iterator>
#include <limits>
#include <random>
#include <string>

#include "canon/print.hpp"

namespace skipnc::canon {
namespace {

std::string x_of(double v) {
  AxisVec t;
  t[0] = v;
  const std::string line = to_string(Stamped{Feed{t, 1.0, false}, 1}, AxisNames{});
  return line.substr(8, line.find(' ', 8) - 8);  // "1 FEED X<v> ..."
}

TEST(CanonPrint, NumbersAreTheShortestTextThatReadsBack) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long long> d(-999999999999LL, 999999999999LL);
  for (int i = 0; i < 200000; ++i) {
    double v = static_cast<double>(d(rng)) / 1000.0;
    if (i % 3 == 1) v = static_cast<double>(d(rng)) * 1e-7;
    if (i % 3 == 2) v = static_cast<double>(d(rng) % 1000000) / 1000.0 + 0.1;
    char buf[40];
    const auto r = std::to_chars(buf, buf + sizeof buf, v + 0.0);
    ASSERT_EQ(x_of(v), std::string(buf, r.ptr)) << v;
  }
}

TEST(CanonPrint, LinesOfEachCommand) {
  AxisVec t;
  t[0] = 10.5;
  t[1] = -0.001;
  t[2] = -0.0;
  EXPECT_EQ(to_string(Stamped{Rapid{t, true}, 3}, AxisNames{}), "3 RAPID X10.5 Y-0.001 Z0");
  EXPECT_EQ(to_string(Stamped{Feed{t, 250.0, true}, 4}, AxisNames{}),
            "4 FEED X10.5 Y-0.001 Z0 F250 EXACT");
  Arc a;
  a.target = t;
  a.center0 = 5.25;
  a.center1 = -1.0;
  a.ccw = true;
  a.feed_mm_per_min = 100.0;
  EXPECT_EQ(to_string(Stamped{a, 5}, AxisNames{}), "5 ARC_CCW X10.5 Y-0.001 Z0 CX=5.25 CY=-1 F100");
  EXPECT_EQ(to_string(Stamped{Dwell{1.5}, 6}, AxisNames{}), "6 DWELL 1.5");
}

// A writer that remembers each field's last text writes the same lines as
// format_to, which starts afresh each time, whatever the order of values:
// a field's value again, another field's, -0 after 0, values that are not
// whole micrometres, huge and tiny ones.
TEST(CanonPrint, RememberedFieldsWriteTheSameLines) {
  const double pool[] = {0.0,
                         -0.0,
                         5.0,
                         500.0,
                         1e-7,
                         999.9995,
                         -16.241,
                         30.14,
                         1e20,
                         -1e20,
                         1e300,
                         647.0794312013581,
                         13.074000000000002,
                         0.1 + 0.2,
                         -999999.999,
                         1234567.891,
                         std::numeric_limits<double>::quiet_NaN()};
  std::mt19937_64 rng(35);
  std::uniform_int_distribution<std::size_t> pick(0, std::size(pool) - 1);
  AxisNames names;
  names.count = 4;
  TextWriter writer(names);
  fmt::memory_buffer remembered;
  fmt::memory_buffer fresh;
  for (std::uint32_t line = 1; line < 20000; ++line) {
    AxisVec t;
    for (int i = 0; i < names.count; ++i) t[i] = pool[pick(rng)];
    Stamped s{Rapid{t, true}, line};
    if (line % 3 == 1) s.cmd = Feed{t, pool[pick(rng)], false};
    if (line % 3 == 2) {
      Arc a;
      a.target = t;
      a.center0 = pool[pick(rng)];
      a.center1 = pool[pick(rng)];
      a.feed_mm_per_min = pool[pick(rng)];
      s.cmd = a;
    }
    writer.append(remembered, s);
    format_to(fresh, s, names);
  }
  ASSERT_EQ(fmt::to_string(remembered), fmt::to_string(fresh));
}

}  // namespace
}  // namespace skipnc::canon
