// Scene geometry: the parts a probe ball, a tool or a probe body can touch,
// in machine coordinates (mm), and exact contact along a straight segment.
//
// A part is a union of solids (boxes, vertical cylinders, spheres,
// half-spaces) minus its holes (vertical cylindrical bores, box pockets).
// Its surface is kept as a list of features (faces, walls, edges, corners,
// rims), each with a closed-form contact solution for a ball whose centre
// moves on a line: ball-vs-plane is linear, ball-vs-cylinder (outside and
// inside), ball-vs-edge, ball-vs-corner and ball-vs-sphere are quadratics,
// ball-vs-rim (a circular edge, a torus) is a quartic whose real roots are
// isolated by its derivatives. The first contact is the smallest root over
// all features whose contact point lies on the part's surface.
//
// Nothing here allocates after construction.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace skipnc::machine::geo {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) noexcept {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
  }
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) noexcept {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  friend constexpr Vec3 operator*(Vec3 a, double k) noexcept { return {a.x * k, a.y * k, a.z * k}; }
  friend constexpr Vec3 operator*(double k, Vec3 a) noexcept { return a * k; }
  friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
};

constexpr double dot(Vec3 a, Vec3 b) noexcept {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline double length(Vec3 a) noexcept {
  return std::sqrt(dot(a, a));
}
constexpr Vec3 lerp(Vec3 a, Vec3 b, double t) noexcept {
  return a + (b - a) * t;
}
// Distance from p to the axis-aligned box lo..hi (0 inside it).
inline double box_distance(Vec3 lo, Vec3 hi, Vec3 p) noexcept {
  const double dx = std::max({lo.x - p.x, 0.0, p.x - hi.x});
  const double dy = std::max({lo.y - p.y, 0.0, p.y - hi.y});
  const double dz = std::max({lo.z - p.z, 0.0, p.z - hi.z});
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

enum class ShapeKind : std::uint8_t { kBox, kCylinder, kSphere, kHalfSpace };

// A solid or a hole. Cylinders have a vertical (Z) axis.
struct Shape {
  ShapeKind kind = ShapeKind::kBox;
  Vec3 lo;              // box: minimum corner; cylinder: (x, y, bottom)
  Vec3 hi;              // box: maximum corner; cylinder: (x, y, top)
  Vec3 center;          // sphere: centre; half-space: a point of the plane
  Vec3 normal;          // half-space: unit normal pointing out of the material
  double radius = 0.0;  // cylinder, sphere
};

Shape make_box(Vec3 lo, Vec3 hi);
Shape make_cylinder(double x, double y, double radius, double bottom, double top);
Shape make_sphere(Vec3 center, double radius);
Shape make_half_space(Vec3 point, Vec3 normal);  // normal need not be unit

// Signed distance from p to the shape's surface: negative inside.
double signed_distance(const Shape& s, Vec3 p) noexcept;

// Where a part stands: its shapes are given in a frame whose origin is
// `origin` (machine coordinates) and whose axes are the machine's turned by
// the rotation `r` (columns: the frame's X, Y, Z axes in machine
// coordinates). A rigid motion keeps distances, so every contact is solved in
// the part's own frame, in the same closed form, and turned back.
struct Placement {
  Vec3 origin;
  // Row-major; identity: not turned.
  double r[3][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};

  // The frame's X axis turned about Z, counter-clockwise seen from +Z.
  static Placement about_z(Vec3 origin, double angle_rad) noexcept {
    return turned_by(origin, 0.0, 0.0, angle_rad);
  }
  // Turned about the base frame's X, then its Y, then its Z (each
  // counter-clockwise seen from the axis' plus side): R = Rz Ry Rx.
  static Placement turned_by(Vec3 origin, double ax, double ay, double az) noexcept {
    const double cx = std::cos(ax), sx = std::sin(ax), cy = std::cos(ay), sy = std::sin(ay);
    const double cz = std::cos(az), sz = std::sin(az);
    return Placement{origin,
                     {{cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
                      {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
                      {-sy, cy * sx, cy * cx}}};
  }
  // This placement applied after `inner` (a frame given in this one).
  Placement then(const Placement& inner) const noexcept {
    Placement out{to_machine(inner.origin)};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        out.r[i][j] = r[i][0] * inner.r[0][j] + r[i][1] * inner.r[1][j] + r[i][2] * inner.r[2][j];
      }
    }
    return out;
  }
  bool turned() const noexcept {
    return r[0][1] != 0.0 || r[0][2] != 0.0 || r[1][0] != 0.0 || r[1][2] != 0.0 || r[2][0] != 0.0 ||
           r[2][1] != 0.0 || r[0][0] != 1.0 || r[1][1] != 1.0 || r[2][2] != 1.0;
  }
  // Z stays Z: turned about Z only, so a vertical column stays vertical.
  bool upright() const noexcept {
    return r[2][0] == 0.0 && r[2][1] == 0.0 && r[0][2] == 0.0 && r[1][2] == 0.0 && r[2][2] == 1.0;
  }
  constexpr Vec3 turn(Vec3 v) const noexcept {
    return {r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z,
            r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
            r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z};
  }
  constexpr Vec3 unturn(Vec3 v) const noexcept {
    return {r[0][0] * v.x + r[1][0] * v.y + r[2][0] * v.z,
            r[0][1] * v.x + r[1][1] * v.y + r[2][1] * v.z,
            r[0][2] * v.x + r[1][2] * v.y + r[2][2] * v.z};
  }
  constexpr Vec3 to_local(Vec3 p) const noexcept { return unturn(p - origin); }
  constexpr Vec3 to_machine(Vec3 q) const noexcept { return origin + turn(q); }
};

class TriMesh;  // mesh.hpp

// A part on a rotary table: the machine axis `axis` (A, B or C) turns the
// table frame about its own X, Y or Z (`about` 0, 1, 2) by sign * the axis
// position in degrees; the part stands in the table frame at `inner`.
struct Rotary {
  int axis = -1;  // machine axis index; -1: the part does not turn
  int about = 2;
  double sign = -1.0;
  Placement table;
  Placement inner;

  bool turns() const noexcept { return axis >= 0; }
  Placement at(double deg) const noexcept {
    const double a = sign * deg * 3.14159265358979323846 / 180.0;
    const Placement turn = Placement::turned_by(Vec3{}, about == 0 ? a : 0.0, about == 1 ? a : 0.0,
                                                about == 2 ? a : 0.0);
    return table.then(turn).then(inner);
  }
};

struct Part {
  std::string name;
  std::vector<Shape> solids;
  std::vector<Shape> holes;  // boxes and cylinders; cut from this part's solids only
  Placement place;           // the shapes are in this frame (a rotary table's at its zero)
  // Closed triangle meshes (STL), solids of the part that its holes do not cut.
  std::vector<std::shared_ptr<const TriMesh>> meshes;
  Rotary rotary;
};

struct Contact {
  double t = 0.0;  // fraction of the segment, in [0, 1]
  Vec3 point;      // where the ball touches the surface
  Vec3 normal;     // unit, from the surface toward the ball centre
  int part = -1;
};

// A vertical cylinder (tool, probe body, setter disc).
struct Column {
  double x = 0.0;
  double y = 0.0;
  double radius = 0.0;
  double bottom = 0.0;
  double top = 0.0;
};

// The first contact of a ball of `radius` whose centre moves from a to b
// with the axis-aligned box lo..hi: its faces, edges and corners, each in
// closed form as for a part's box. part is -1. A ball that overlaps the box
// at a does not touch it.
bool box_first_contact(Vec3 lo, Vec3 hi, Vec3 a, Vec3 b, double radius, Contact& out) noexcept;

// How far two columns overlap: the smaller of the radial and the vertical
// overlap (the distance to push them apart along XY or Z); <= 0 when apart.
double column_overlap(const Column& a, const Column& b) noexcept;

// The first instant t in [0, 1] at which column `a`, translated by t * move,
// overlaps the fixed column `b` by at least `depth` (> 0), having overlapped
// it by less just before. False when it does not happen in the segment.
bool column_first_overlap(const Column& a, Vec3 move, const Column& b, double depth,
                          double& t) noexcept;

class Material {
 public:
  Material() = default;
  explicit Material(std::vector<Part> parts);

  bool empty() const noexcept { return parts_.empty(); }
  const std::vector<Part>& parts() const noexcept { return parts_; }
  std::size_t feature_count() const noexcept { return features_.size(); }

  // Parts on rotary tables: where the machine's axes stand at the start and
  // the end of the period to come (positions indexed by machine axis). The
  // other queries see the parts as they stand at the end; first_contact
  // moves the ball's start and end into each part's frame at their own
  // instants and joins them by a straight line there (the chord of the
  // turn: for a table turning by w radians in the period, the ball's path
  // in the part's frame is off that line by at most R w^2 / 8 at radius R
  // from the table's axis; 0.014 um at 100 mm and 10 rpm in 1 ms).
  bool turns() const noexcept { return !turning_.empty(); }
  void set_turns(const double* before, const double* after) noexcept;

  // The first instant at which a ball of `radius` whose centre moves from a
  // to b touches the material while approaching it. A ball that already
  // overlaps the material at a does not "touch" what it overlaps.
  // `backward`: a is where the ball is at the period's end, b at its start
  // (a contact searched back in time).
  bool first_contact(Vec3 a, Vec3 b, double radius, Contact& out,
                     bool backward = false) const noexcept;
  // Distance from p to the material; 0 inside it.
  // With `cap`: min(distance, cap), found faster far from the material.
  double distance(Vec3 p, double cap = std::numeric_limits<double>::infinity()) const noexcept;
  // How deep p is inside the material (0 outside); a CSG estimate near holes.
  double depth(Vec3 p) const noexcept;
  // A lower bound of distance(p): the distance to the nearest box that holds
  // a part's solids or meshes; 0 when a part is unbounded or turns. Cheap
  // (no feature is looked at): a probe far from every part skips the searches.
  double clearance(Vec3 p) const noexcept;
  // The first part the column overlaps by more than `tol`, or -1. A column
  // standing wholly inside one of the part's holes over the part's height
  // does not overlap it.
  int column_hits(const Column& c, double tol) const noexcept;

 private:
  enum class FeatureKind : std::uint8_t {
    kPlane,      // p: a point, n: unit normal out of the material
    kOuterWall,  // p: axis (x, y), r: radius (a boss, seen from outside)
    kInnerWall,  // p: axis (x, y), r: radius (a bore, seen from inside)
    kSegment,    // p -> q, with its end points
    kBall,       // p: centre, r: radius (0: a corner)
    kCircle,     // p: centre, r: radius, horizontal (a rim)
  };
  struct Feature {
    FeatureKind kind = FeatureKind::kPlane;
    bool of_hole = false;
    int part = 0;
    int owner = 0;  // solid index, or hole index when of_hole
    Vec3 p;
    Vec3 q;
    Vec3 n;
    double r = 0.0;
  };
  // Makes the features of one solid (or hole) of a part into a list.
  struct FeatureMaker {
    std::vector<Feature>& out;
    int part;
    int owner;
    bool of_hole;
    Feature make(FeatureKind k) const noexcept {
      Feature f;
      f.kind = k;
      f.part = part;
      f.owner = owner;
      f.of_hole = of_hole;
      return f;
    }
    void plane(Vec3 p, Vec3 n) const {
      Feature f = make(FeatureKind::kPlane);
      f.p = p;
      f.n = n;
      out.push_back(f);
    }
  };
  void add_solid_features(int part, int solid);
  void add_hole_features(int part, int hole);
  void add_rims(int part, int hole, int solid);
  bool contact_with(const Feature& f, Vec3 a, Vec3 b, double radius, Contact& c) const noexcept;
  // The steps of contact_with, inlined into it (a hot path: every feature
  // near the probe's path, every period).
  [[gnu::always_inline]] bool accept_contact(const Feature& f, Vec3 a, Vec3 b, double t, Vec3 point,
                                             Contact& c) const noexcept;
  [[gnu::always_inline]] bool wall_contact(const Feature& f, Vec3 a, Vec3 b, double radius,
                                           Contact& c) const noexcept;
  [[gnu::always_inline]] bool segment_contact(const Feature& f, Vec3 a, Vec3 b, double radius,
                                              Contact& c) const noexcept;
  [[gnu::always_inline]] bool circle_contact(const Feature& f, Vec3 a, Vec3 b, double radius,
                                             Contact& c) const noexcept;
  bool valid(const Feature& f, Vec3 q) const noexcept;
  double feature_distance(const Feature& f, Vec3 p, Vec3& closest) const noexcept;
  double part_sdf(const Part& part, Vec3 p) const noexcept;
  double part_depth(const Part& part, Vec3 q) const noexcept;
  bool leaning_column_hits(std::size_t part, const Column& world, double tol) const noexcept;

  // Each part's features (a run of features_, in part order) and the box,
  // in the part's frame, that holds its solids (and so every feature): a
  // query that cannot reach the box skips the part (most servo periods).
  struct PartBounds {
    std::size_t begin = 0, end = 0;
    Vec3 lo, hi;
    bool bounded = true;  // false with a half-space solid
  };
  bool beyond(const PartBounds& b, Vec3 lo, Vec3 hi) const noexcept;
  // The same box in machine coordinates, for the column queries (valid: the
  // part neither turns nor has a half-space; a little larger when placed
  // turned). A column that does not reach it overlaps nothing of the part.
  struct WorldBox {
    Vec3 lo, hi;
    bool valid = false;
  };
  static WorldBox world_box(const Part& part, const PartBounds& b) noexcept;
  static bool misses(const WorldBox& w, const Column& c) noexcept;

  std::vector<Part> parts_;
  std::vector<Placement> start_;      // per part: where it stands at the period's start
  std::vector<std::size_t> turning_;  // the parts on rotary tables
  std::vector<Feature> features_;
  std::vector<PartBounds> bounds_;
  std::vector<WorldBox> world_;
  WorldBox all_;  // the parts' boxes together (valid when each is)
};

// Real roots of c[0] + c[1] t + ... + c[n] t^n (n <= 4) in [lo, hi], in
// increasing order. Returns how many were written to `roots` (at most n).
int polynomial_roots(const double* c, int n, double lo, double hi, double* roots) noexcept;

}  // namespace skipnc::machine::geo
