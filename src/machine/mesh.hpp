// Triangle meshes (STL parts): a closed mesh is a solid. Contact of a ball
// whose centre moves on a line is exact: the first instant the centre comes
// within r of a triangle is the earliest of its face (linear), its edges
// (quadratic: a cylinder about the edge) and its corners (quadratic), as
// for the other shapes (geometry.hpp). A bounding-volume hierarchy of boxes
// keeps each query to the few triangles near the segment, so a mesh of a
// million triangles costs a few dozen box tests per servo period.
//
// Nothing here allocates after construction.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/diag.hpp"
#include "machine/geometry.hpp"

namespace skipnc::machine::geo {

struct Triangle {
  Vec3 a, b, c;
  Vec3 n;  // unit, out of the solid (from the vertex order, counter-clockwise seen from outside)
};

struct Aabb {
  Vec3 lo{1e300, 1e300, 1e300};
  Vec3 hi{-1e300, -1e300, -1e300};
  void add(Vec3 p) noexcept;
  void add(const Aabb& b) noexcept;
};

class TriMesh {
 public:
  TriMesh() = default;
  // Degenerate (zero-area) triangles are dropped.
  explicit TriMesh(std::vector<Triangle> triangles);

  std::size_t size() const noexcept { return tris_.size(); }
  const std::vector<Triangle>& triangles() const noexcept { return tris_; }
  const Aabb& bounds() const noexcept { return nodes_.empty() ? empty_ : nodes_[0].box; }

  // The first instant t in [0, 1] at which the ball's centre, moving from a
  // to b, comes within `radius` of the surface (having been farther at a).
  bool first_contact(Vec3 a, Vec3 b, double radius, double& t, Vec3& point,
                     Vec3& normal) const noexcept;
  // Distance from p to the surface (at most `cap`: a search that only needs
  // to know the surface is farther than cap stops at the first boxes), and
  // whether p is inside the solid.
  double surface_distance(Vec3 p,
                          double cap = std::numeric_limits<double>::infinity()) const noexcept;
  bool inside(Vec3 p) const noexcept;
  // How far a vertical column (axis x, y; z from bottom to top; radius)
  // overlaps the surface: radius minus the horizontal distance from its
  // axis to the nearest part of a triangle within its height; <= 0 apart.
  // A column wholly inside the solid overlaps it by its radius.
  double column_overlap(const Column& c) const noexcept;

 private:
  struct Node {
    Aabb box;
    std::uint32_t first = 0;  // leaf: first triangle; inner: left child (right = first + 1)
    std::uint32_t count = 0;  // leaf: triangles; 0: inner node
  };
  void build(std::uint32_t node, std::uint32_t first, std::uint32_t count);

  std::vector<Triangle> tris_;
  std::vector<Node> nodes_;
  Aabb empty_;
};

// Reads an STL file, binary or ASCII, in mm times `scale`. Errors name the
// file and the byte offset (binary) or line (ASCII) and the facet index.
[[nodiscard]] Result<std::vector<Triangle>> read_stl(const std::string& path, double scale);
[[nodiscard]] Result<std::vector<Triangle>> parse_stl(std::string_view bytes, std::string_view name,
                                                      double scale);

}  // namespace skipnc::machine::geo
