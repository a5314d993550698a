// The stock: a block of material that cutting moves remove, so that a
// program can machine a part and then probe what it made (docs/scene.md,
// `[stock]`).
//
// It is a Z-dexel height map: the box is cut into a grid of cells on X and
// Y, and each cell holds one column of material from the box's bottom up to
// its own top. A flat-ended tool lowers the top of every cell whose centre
// comes within its radius to the tip's Z there, so what the cells can show
// is what a tool coming from above leaves: pockets, steps, faced tops, not
// undercuts; side walls are as fine as the grid.
//
// A probe ball touches the cells as boxes, each in the same closed form as
// a part's box (faces, edges, corners: geo::box_first_contact), so a latch
// on a cut face is exact, not sampled. A tool or probe-body column meets a
// cell when the cell's centre is within its radius, the same rule the cut
// uses: a tool that has cut a cell does not then collide with it.
//
// The cells are allocated once; nothing allocates afterwards.
#pragma once

#include <limits>
#include <vector>

#include "machine/geometry.hpp"

namespace skipnc::machine::geo {

class Stock {
 public:
  Stock() = default;  // no stock
  // The box lo..hi in cells of at most `cell` mm on X and on Y (a whole
  // number of cells on each side, so the grid ends on the box's faces).
  Stock(Vec3 lo, Vec3 hi, double cell);

  // How many cells that grid has (what the scene checks before making it:
  // the constructor allocates them all).
  static double cell_count(Vec3 lo, Vec3 hi, double cell) noexcept;

  bool empty() const noexcept { return tops_.empty(); }
  // Every cell back to the box's top.
  void reset() noexcept;

  const Vec3& lo() const noexcept { return lo_; }
  const Vec3& hi() const noexcept { return hi_; }
  int nx() const noexcept { return nx_; }
  int ny() const noexcept { return ny_; }
  double x0(int i) const noexcept { return lo_.x + dx_ * i; }
  double x1(int i) const noexcept { return i + 1 == nx_ ? hi_.x : lo_.x + dx_ * (i + 1); }
  double y0(int j) const noexcept { return lo_.y + dy_ * j; }
  double y1(int j) const noexcept { return j + 1 == ny_ ? hi_.y : lo_.y + dy_ * (j + 1); }
  // The top of cell (i, j); at the bottom (lo.z) when cut through.
  double top(int i, int j) const noexcept { return tops_[static_cast<std::size_t>(j * nx_ + i)]; }

  // A flat-ended tool of `radius` whose tip's centre moves from a to b: each
  // cell whose centre comes within the radius of the tip's XY path is
  // lowered to the lowest tip Z while it is within. Returns the volume
  // removed, mm^3.
  double cut(Vec3 a, Vec3 b, double radius) noexcept;
  // The volume removed since reset(), mm^3.
  double removed_volume() const noexcept;

  // As Material: the first touch of a ball whose centre moves a -> b (part
  // is -1), the distance to the material (0 inside; at most `cap`), how
  // deep a point is inside it.
  bool first_contact(Vec3 a, Vec3 b, double radius, Contact& out) const noexcept;
  double distance(Vec3 p, double cap = std::numeric_limits<double>::infinity()) const noexcept;
  double depth(Vec3 p) const noexcept;
  // A lower bound of distance(p): the distance to the box (infinite without a stock).
  double clearance(Vec3 p) const noexcept;
  // Does a cell whose centre lies more than `tol` inside the column's radius
  // overlap the column's height by more than `tol`?
  bool column_hits(const Column& c, double tol) const noexcept;

 private:
  // The cells (on one axis) that [a, b] can reach, one more on each side
  // for rounding; false when none.
  bool span(double a, double b, bool on_y, int& first, int& last) const noexcept;
  double& top_at(int i, int j) noexcept { return tops_[static_cast<std::size_t>(j * nx_ + i)]; }

  Vec3 lo_, hi_;
  int nx_ = 0, ny_ = 0;
  double dx_ = 0.0, dy_ = 0.0;
  std::vector<double> tops_;  // row by row (j), nx_ cells a row
};

// What a probe ball can touch: the parts and, when there is one, the stock.
class Solids {
 public:
  explicit Solids(const Material& material, const Stock* stock = nullptr) noexcept
      : material_(&material), stock_(stock != nullptr && !stock->empty() ? stock : nullptr) {}

  // `backward` as Material::first_contact (the stock does not move).
  bool first_contact(Vec3 a, Vec3 b, double radius, Contact& out,
                     bool backward = false) const noexcept;
  double distance(Vec3 p, double cap = std::numeric_limits<double>::infinity()) const noexcept;
  double depth(Vec3 p) const noexcept;
  // A lower bound of distance(p), as Material::clearance.
  double clearance(Vec3 p) const noexcept;

 private:
  const Material* material_;
  const Stock* stock_;
};

}  // namespace skipnc::machine::geo
