// The stock that cutting moves remove (machine/stock.hpp, docs/scene.md
// [stock]): which cells a pass lowers, and that a probe ball touches the cut
// stock exactly as it touches a part of the same shape. Expected values are
// worked out by hand from the geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/geometry.hpp"
#include "machine/scene.hpp"
#include "machine/stock.hpp"

namespace skipnc::machine {
namespace {

using geo::Contact;
using geo::Stock;
using geo::Vec3;

// 20 x 10 x 10 mm, top at Z0, in 0.5 mm cells: 40 x 20 of them.
Stock block() {
  return Stock({0, 0, -10}, {20, 10, 0}, 0.5);
}

double centre_x(const Stock& s, int i) {
  return 0.5 * (s.x0(i) + s.x1(i));
}
double centre_y(const Stock& s, int j) {
  return 0.5 * (s.y0(j) + s.y1(j));
}

// Distance from (x, y) to the segment (ax, ay) - (bx, by).
double to_segment(double x, double y, double ax, double ay, double bx, double by) {
  const double wx = bx - ax, wy = by - ay;
  const double s = std::clamp(((x - ax) * wx + (y - ay) * wy) / (wx * wx + wy * wy), 0.0, 1.0);
  return std::hypot(x - ax - s * wx, y - ay - s * wy);
}

TEST(Stock, GridEndsOnTheBoxFaces) {
  const Stock s({0, 0, -5}, {10.2, 3, 0}, 0.5);
  EXPECT_EQ(s.nx(), 21);  // 10.2 / 0.5 = 20.4: 21 cells of 0.4857 mm
  EXPECT_EQ(s.ny(), 6);
  EXPECT_DOUBLE_EQ(s.x1(20), 10.2);
  EXPECT_DOUBLE_EQ(s.top(20, 5), 0.0);
  EXPECT_EQ(Stock::cell_count({0, 0, -5}, {10.2, 3, 0}, 0.5), 126.0);
}

TEST(Stock, AStraightPassLowersExactlyTheCellsWithinTheRadius) {
  Stock s = block();
  // A 3 mm radius tool from X2 to X12 along Y5, its tip at Z-0.2. No cell
  // centre is exactly 3 mm from the path (they are at odd quarters of a mm).
  const double removed = s.cut({2, 5, -0.2}, {12, 5, -0.2}, 3.0);
  int cut = 0;
  for (int j = 0; j < s.ny(); ++j) {
    for (int i = 0; i < s.nx(); ++i) {
      const bool under = to_segment(centre_x(s, i), centre_y(s, j), 2, 5, 12, 5) <= 3.0;
      EXPECT_EQ(s.top(i, j), under ? -0.2 : 0.0) << "cell " << i << ", " << j;
      cut += under ? 1 : 0;
    }
  }
  // 12 rows of cells within the band, with rounded ends: at least the
  // 20 cells along the path in each row.
  EXPECT_GT(cut, 12 * 20);
  EXPECT_NEAR(removed, cut * 0.25 * 0.2, 1e-12);
  EXPECT_NEAR(s.removed_volume(), removed, 1e-12);
  // A second pass over the same cells at the same height removes nothing.
  EXPECT_EQ(s.cut({2, 5, -0.2}, {12, 5, -0.2}, 3.0), 0.0);
  s.reset();
  EXPECT_EQ(s.removed_volume(), 0.0);
}

TEST(Stock, ARampLowersACellToTheLowestTipWhileItIsUnderTheTool) {
  Stock s = block();
  // Down from Z0 at X2 to Z-1 at X12. The cell centred at (6.25, 5.25) is
  // under the 3 mm tool until the tip's X passes 6.25 + sqrt(9 - 0.25^2).
  s.cut({2, 5, 0}, {12, 5, -1}, 3.0);
  const double x_leave = 6.25 + std::sqrt(9.0 - 0.0625);
  EXPECT_NEAR(s.top(12, 10), -(x_leave - 2.0) / 10.0, 1e-12);
  // A cell the tool reaches only at the end of the path: its lowest is the end.
  EXPECT_NEAR(s.top(28, 10), -1.0, 1e-12);  // centre (14.25, 5.25)
  // Never below the bottom.
  s.cut({0, 0, -50}, {20, 10, -50}, 30.0);
  EXPECT_EQ(s.top(0, 0), -10.0);
  EXPECT_NEAR(s.removed_volume(), 20.0 * 10.0 * 10.0, 1e-9);
}

// A simple generator for the seeded segments (the same on every platform).
struct Lcg {
  std::uint64_t state;
  double next(double lo, double hi) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(state >> 11U) * 0x1.0p-53;
  }
};

TEST(Stock, ABallOnAFlatCutTopLatchesAsOnABox) {
  Stock s = block();
  // Faced 0.2 mm over the whole block: the same solid as a box with its top at Z-0.2.
  s.cut({-10, 5, -0.2}, {30, 5, -0.2}, 12.0);
  geo::Part part;
  part.solids.push_back(geo::make_box({0, 0, -10}, {20, 10, -0.2}));
  const geo::Material box({part});
  const double r = 1.0;
  Contact cs, cb;
  // Straight down onto the faced top, at a cell's centre and on a cell's corner.
  for (const Vec3 at : {Vec3{6.25, 4.75, 0}, Vec3{6.5, 5.0, 0}}) {
    ASSERT_TRUE(s.first_contact(at + Vec3{0, 0, 10}, at + Vec3{0, 0, -5}, r, cs));
    ASSERT_TRUE(box.first_contact(at + Vec3{0, 0, 10}, at + Vec3{0, 0, -5}, r, cb));
    EXPECT_NEAR(cs.t, cb.t, 1e-12);
    EXPECT_NEAR(cs.point.z, -0.2, 1e-12);
    EXPECT_NEAR(cs.normal.z, 1.0, 1e-12);
  }
  // Seeded segments at the faces, edges and corners of the block from every
  // side, each starting clear of it.
  Lcg g{7};
  int touched = 0;
  for (int k = 0; k < 4000; ++k) {
    const Vec3 a{g.next(-6, 26), g.next(-6, 16), g.next(-4, 6)};
    const Vec3 b{g.next(-3, 23), g.next(-3, 13), g.next(-3, 2)};
    if (box.distance(a) <= r) continue;
    const bool hit_s = s.first_contact(a, b, r, cs);
    const bool hit_b = box.first_contact(a, b, r, cb);
    ASSERT_EQ(hit_s, hit_b) << k;
    if (!hit_s) continue;
    ++touched;
    // The instant along the segment, as a latched position: to 1e-6 mm.
    EXPECT_LT(length(lerp(a, b, cs.t) - lerp(a, b, cb.t)), 1e-6) << k;
    EXPECT_LT(length(cs.point - cb.point), 1e-6) << k;
  }
  EXPECT_GT(touched, 400);
  // The distance the probe's deflection is taken from agrees too.
  for (int k = 0; k < 500; ++k) {
    const Vec3 p{g.next(-3, 23), g.next(-3, 13), g.next(-3, 3)};
    EXPECT_NEAR(s.distance(p), box.distance(p), 1e-9) << k;
    EXPECT_NEAR(s.distance(p, 0.5), std::min(box.distance(p), 0.5), 1e-9) << k;
  }
}

TEST(Stock, ABallApproachingAStepLatchesOnItsEdge) {
  Stock s = block();
  // A 5 mm tool along X4.9 takes every cell whose centre is left of X9.9
  // down to Z-2: a step at X10, from Z-2 up to Z0.
  s.cut({4.9, -10, -2}, {4.9, 20, -2}, 5.0);
  EXPECT_EQ(s.top(19, 3), -2.0);  // the cell from X9.5 to X10
  EXPECT_EQ(s.top(20, 3), 0.0);   // from X10
  const double r = 1.0;
  Contact c;
  // Straight down 0.5 mm left of the step: the ball meets the step's top
  // edge when its centre is sqrt(1 - 0.5^2) above it, before the floor.
  ASSERT_TRUE(s.first_contact({9.5, 3.3, 5}, {9.5, 3.3, -5}, r, c));
  EXPECT_NEAR(5.0 - 10.0 * c.t, std::sqrt(0.75), 1e-12);
  EXPECT_NEAR(c.point.x, 10.0, 1e-12);
  EXPECT_NEAR(c.point.z, 0.0, 1e-12);
  EXPECT_NEAR(c.normal.x, -0.5, 1e-12);
  // Along +X with the centre 0.5 mm above the step's top: the edge again,
  // the centre sqrt(0.75) short of it.
  ASSERT_TRUE(s.first_contact({2, 3.3, 0.5}, {15, 3.3, 0.5}, r, c));
  EXPECT_NEAR(2.0 + 13.0 * c.t, 10.0 - std::sqrt(0.75), 1e-12);
  EXPECT_NEAR(c.point.z, 0.0, 1e-12);
  // Along +X between the floor and the top: the wall, 1 mm short of it.
  ASSERT_TRUE(s.first_contact({2, 3.3, -0.8}, {15, 3.3, -0.8}, r, c));
  EXPECT_NEAR(2.0 + 13.0 * c.t, 9.0, 1e-12);
  EXPECT_NEAR(c.normal.x, -1.0, 1e-12);
  // Down onto the floor, clear of the step: the floor at Z-2.
  ASSERT_TRUE(s.first_contact({5, 3.3, 5}, {5, 3.3, -5}, r, c));
  EXPECT_NEAR(5.0 - 10.0 * c.t, -1.0, 1e-12);
  // A ray far past the stock (as the reach check casts) finds the same edge.
  Contact far;
  ASSERT_TRUE(s.first_contact({9.5, 3.3, 5}, {9.5, 3.3, -99995}, r, far));
  EXPECT_NEAR(5.0 - 100000.0 * far.t, std::sqrt(0.75), 1e-9);
}

TEST(Stock, ColumnsMeetTheCellsWhoseCentresTheyCover) {
  Stock s = block();
  s.cut({-10, 5, -0.2}, {30, 5, -0.2}, 12.0);
  // A tool standing on the faced top does not hit it; 0.1 mm lower it does.
  EXPECT_FALSE(s.column_hits(geo::Column{8, 5, 5, -0.2, 100}, 1e-9));
  EXPECT_TRUE(s.column_hits(geo::Column{8, 5, 5, -0.3, 100}, 1e-9));
  // Beside the block: a cell counts when its centre is within the radius.
  // The nearest centres, (0.25, 4.75) and (0.25, 5.25), are 0.430 mm away.
  EXPECT_FALSE(s.column_hits(geo::Column{-0.1, 5, 0.4, -5, 100}, 1e-9));
  EXPECT_TRUE(s.column_hits(geo::Column{-0.1, 5, 0.45, -5, 100}, 1e-9));
  // Inside the material a point is deep by its distance to the top.
  EXPECT_NEAR(s.depth({8, 5, -0.7}), 0.5, 1e-12);
  EXPECT_EQ(s.depth({8, 5, 0.1}), 0.0);
  EXPECT_EQ(s.distance({8, 5, -0.7}), 0.0);
}

// mill3 with G54 at (100, 50, -200).
const config::MachineConfig& stock_shop() {
  static const auto m = config::parse_machine(R"(extends = "mill3"
[work_offsets]
G54 = { X = 100.0, Y = 50.0, Z = -200.0 }
)",
                                              "shop.toml");
  return *m;
}

Result<Scene> load_stock(const std::string& text) {
  static const auto d = config::builtin_dialect("fanuc");
  static const config::Parameters p(&*d);
  return parse_scene(text, "stock.scene.toml", stock_shop(), *d, p);
}

TEST(SceneStock, LoadsInAWorkFrame) {
  auto s = load_stock("[stock]\nframe = \"G54\"\nmin = [0, 0, -20]\nmax = [60, 40, 0]\n");
  ASSERT_TRUE(s) << s.error().detail;
  ASSERT_TRUE(s->probing.stock);
  EXPECT_EQ(s->probing.stock->lo, (Vec3{100, 50, -220}));
  EXPECT_EQ(s->probing.stock->hi, (Vec3{160, 90, -200}));
  EXPECT_EQ(s->probing.stock->resolution, 0.5);
  // A frame that only moves it is accepted as well.
  auto moved = load_stock(
      "[[frame]]\nname = \"vise\"\nbase = \"G54\"\norigin = [5, 0, 0]\n"
      "[stock]\nframe = \"vise\"\nmin = [0, 0, -20]\nmax = [60, 40, 0]\nresolution = 0.25\n");
  ASSERT_TRUE(moved) << moved.error().detail;
  EXPECT_EQ(moved->probing.stock->lo, (Vec3{105, 50, -220}));
  EXPECT_EQ(moved->probing.stock->resolution, 0.25);
}

// Each bad [stock] is refused at its line.
void expect_stock_error(const std::string& text, std::uint32_t line, std::uint32_t column = 0) {
  auto s = load_stock(text);
  ASSERT_FALSE(s) << text;
  EXPECT_EQ(s.error().id, AlarmId::kConfig);
  EXPECT_EQ(s.error().loc.line, line) << s.error().detail;
  if (column > 0) {
    EXPECT_EQ(s.error().loc.column, column) << s.error().detail;
  }
}

TEST(SceneStock, RefusesWhatCannotBe) {
  // A turned frame: the cells are axis-aligned (at the frame key).
  expect_stock_error(
      "[[frame]]\nname = \"vise\"\nrotation = 2\n"
      "[stock]\nframe = \"vise\"\nmin = [0, 0, -20]\nmax = [60, 40, 0]\n",
      5, 9);
  // More than 4 million cells: at the resolution.
  expect_stock_error("[stock]\nmin = [0, 0, -20]\nmax = [1000, 1000, 0]\nresolution = 0.1\n", 4,
                     14);
  expect_stock_error("[stock]\nmin = [-1e6, -1e6, -1]\nmax = [1e6, 1e6, 0]\nresolution = 0.001\n",
                     4);
  expect_stock_error("[stock]\nmin = [0, 0, 0]\nmax = [10, 10, 0]\n", 3);  // no height
  expect_stock_error("[stock]\nmin = [0, 0]\nmax = [10, 10, 5]\n", 2);     // 2 numbers
  expect_stock_error("[stock]\nmin = [0, 0, 0]\nmax = [1, 1, 1]\nresolution = 0\n", 4);  // too fine
  expect_stock_error("[stock]\nmin = [0, 0, 0]\nmax = [1, 1, 1]\nmaterial = \"steel\"\n", 4);
  expect_stock_error("[stock]\nmax = [1, 1, 1]\n", 1);  // no min
  expect_stock_error("[[stock]]\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n",
                     1);  // one table, not an array
}

}  // namespace
}  // namespace skipnc::machine
