#include "machine/mesh.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/file.hpp"
#include "machine/geometry_math.hpp"

namespace skipnc::machine::geo {
namespace {

constexpr std::uint32_t kLeafSize = 4;  // triangles per leaf of the hierarchy
constexpr int kStackDepth = 64;         // deeper than any tree of 2^32 triangles
// A triangle with less area than this (mm^2) has no normal: dropped.
constexpr double kMinArea = 1e-18;
// The largest STL read (triangles): 50 bytes each in binary, 2.5 GB.
constexpr std::uint64_t kMaxTriangles = 50'000'000;

Vec3 cross(Vec3 a, Vec3 b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// The point of triangle t closest to p (Ericson, Real-Time Collision
// Detection, 5.1.5: by the Voronoi regions of its corners and edges).
Vec3 closest_on_triangle(const Triangle& t, Vec3 p) noexcept {
  const Vec3 ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return t.a;
  const Vec3 bp = p - t.b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return t.b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return t.a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - t.c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return t.c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return t.a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return t.b + (t.c - t.b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denom = 1.0 / (va + vb + vc);
  return t.a + ab * (vb * denom) + ac * (vc * denom);
}

double box_distance(const Aabb& b, Vec3 p) noexcept {
  return geo::box_distance(b.lo, b.hi, p);
}

bool boxes_overlap(const Aabb& a, const Aabb& b) noexcept {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&
         a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
}

// The first instant the centre, moving a -> b, comes within r of triangle t
// from farther away: face, then edges, then corners; the earliest wins.
bool triangle_contact(const Triangle& tr, Vec3 a, Vec3 b, double r, double& t_out,
                      Vec3& point) noexcept {
  double best = kInf;
  // Face: from its outer side only.
  if (double t = 0.0; plane_root(tr.a, tr.n, a, b, r, t)) {
    const Vec3 q = lerp(a, b, t) - tr.n * r;
    // Inside the triangle: on the inner side of each edge.
    const Vec3 e[3] = {tr.b - tr.a, tr.c - tr.b, tr.a - tr.c};
    const Vec3 v[3] = {tr.a, tr.b, tr.c};
    bool in = true;
    for (int i = 0; i < 3 && in; ++i) in = dot(cross(e[i], q - v[i]), tr.n) >= 0.0;
    if (in) {
      best = t;
      point = q;
    }
  }
  // Edges: the cylinder of radius r about the edge's line, between its ends.
  const Vec3 v[3] = {tr.a, tr.b, tr.c};
  for (int i = 0; i < 3; ++i) {
    const Vec3 p = v[i], e0 = v[(i + 1) % 3] - p;
    const double len = length(e0);
    if (len == 0.0) continue;
    const Vec3 e = e0 * (1.0 / len);
    double t = 0.0, s = 0.0;
    if (line_root(p, e, len, a, b, r, t, s) && t < best) {
      best = t;
      point = p + e * s;
    }
    // Its first corner (each corner is the first of one edge).
    if (point_root(p, a, b, r, t) && t < best) {
      best = t;
      point = p;
    }
  }
  if (best == kInf) return false;
  t_out = best;
  return true;
}

// Ray (from o along unit d) through triangle t at a distance > 0
// (Moller-Trumbore).
bool ray_hits(const Triangle& t, Vec3 o, Vec3 d) noexcept {
  const Vec3 e1 = t.b - t.a, e2 = t.c - t.a;
  const Vec3 p = cross(d, e2);
  const double det = dot(e1, p);
  if (std::fabs(det) < 1e-300) return false;
  const double inv = 1.0 / det;
  const Vec3 s = o - t.a;
  const double u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 q = cross(s, e1);
  const double v = dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  return dot(e2, q) * inv > 0.0;
}

// The corners of a triangle in a fixed order (lexicographic), so that the
// same face written with its corners in another order compares equal.
std::array<double, 9> corners_key(const Triangle& t) noexcept {
  std::array<Vec3, 3> v{t.a, t.b, t.c};
  auto less = [](const Vec3& p, const Vec3& q) {
    return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : p.z < q.z);
  };
  std::sort(v.begin(), v.end(), less);
  return {v[0].x, v[0].y, v[0].z, v[1].x, v[1].y, v[1].z, v[2].x, v[2].y, v[2].z};
}

// Drops every triangle with the same corners as an earlier one, keeping the
// order of the others: a face given twice (or a thousand times) is one
// face. Each copy would be tested by every query that reaches it, and would
// count twice in inside()'s crossings. Sorts 4-byte indices: no copy of
// the triangles.
void drop_coincident(std::vector<Triangle>& tris) {
  std::vector<std::uint32_t> order(tris.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t p, std::uint32_t q) {
    return corners_key(tris[p]) < corners_key(tris[q]);
  });
  std::vector<bool> dup(tris.size(), false);
  bool any = false;
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (corners_key(tris[order[k]]) == corners_key(tris[order[k - 1]])) {
      dup[order[k]] = true;
      any = true;
    }
  }
  if (!any) return;
  std::size_t out = 0;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    if (!dup[i]) tris[out++] = tris[i];
  }
  tris.resize(out);
}

// Entry time (0..1) of the segment o -> o + d into box b, or a value above 1
// when it misses it.
double segment_box_entry(const Aabb& b, Vec3 o, Vec3 d) noexcept {
  double t0 = 0.0, t1 = 1.0;
  const double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
  const double oo[3] = {o.x, o.y, o.z}, dd[3] = {d.x, d.y, d.z};
  for (int k = 0; k < 3; ++k) {
    if (dd[k] == 0.0) {
      if (oo[k] < lo[k] || oo[k] > hi[k]) return 2.0;
      continue;
    }
    double ta = (lo[k] - oo[k]) / dd[k], tb = (hi[k] - oo[k]) / dd[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return 2.0;
  }
  return t0;
}

bool ray_box(const Aabb& b, Vec3 o, Vec3 inv_d) noexcept {
  double t0 = 0.0, t1 = kInf;
  const double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
  const double oo[3] = {o.x, o.y, o.z}, id[3] = {inv_d.x, inv_d.y, inv_d.z};
  for (int k = 0; k < 3; ++k) {
    double ta = (lo[k] - oo[k]) * id[k], tb = (hi[k] - oo[k]) * id[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// Horizontal distance from (x, y) to the part of triangle t between z0 and
// z1 (the triangle clipped to that slab, projected on XY); kInf when none of
// it is in the slab.
double slab_distance_xy(const Triangle& t, double x, double y, double z0, double z1) noexcept {
  std::array<Vec3, 9> poly{t.a, t.b, t.c};
  std::array<Vec3, 9> next{};
  std::size_t n = 3;
  auto clip = [&](double level, bool keep_above) {
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 p = poly[i], q = poly[(i + 1) % n];
      const bool pin = keep_above ? p.z >= level : p.z <= level;
      const bool qin = keep_above ? q.z >= level : q.z <= level;
      if (pin) next[m++] = p;
      if (pin != qin) next[m++] = lerp(p, q, (level - p.z) / (q.z - p.z));
    }
    poly = next;
    n = m;
  };
  clip(z0, true);
  if (n > 0) clip(z1, false);
  if (n == 0) return kInf;
  // Inside the projected polygon: the same side of every edge.
  int pos = 0, neg = 0;
  double best = kInf;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = poly[i], q = poly[(i + 1) % n];
    const double ex = q.x - p.x, ey = q.y - p.y;
    const double c = ex * (y - p.y) - ey * (x - p.x);
    if (c > 0.0) ++pos;
    if (c < 0.0) ++neg;
    const double ee = ex * ex + ey * ey;
    const double s = ee > 0.0 ? std::clamp((ex * (x - p.x) + ey * (y - p.y)) / ee, 0.0, 1.0) : 0.0;
    const double dx = x - (p.x + ex * s), dy = y - (p.y + ey * s);
    best = std::min(best, std::sqrt(dx * dx + dy * dy));
  }
  if (n >= 3 && (pos == 0 || neg == 0) && pos + neg > 0) return 0.0;
  return best;
}

}  // namespace

void Aabb::add(Vec3 p) noexcept {
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
}

void Aabb::add(const Aabb& b) noexcept {
  add(b.lo);
  add(b.hi);
}

TriMesh::TriMesh(std::vector<Triangle> triangles) {
  tris_.reserve(triangles.size());
  for (Triangle t : triangles) {
    const Vec3 n = cross(t.b - t.a, t.c - t.a);
    const double l = length(n);
    if (!(l > 2.0 * kMinArea)) continue;
    t.n = n * (1.0 / l);
    tris_.push_back(t);
  }
  drop_coincident(tris_);
  if (tris_.empty()) return;
  nodes_.reserve(2 * (tris_.size() / kLeafSize + 1) + 1);
  nodes_.emplace_back();
  build(0, 0, static_cast<std::uint32_t>(tris_.size()));
}

// Fills node `node` for triangles [first, first + count): a leaf, or two
// children split at the median of the centres along the widest axis.
void TriMesh::build(std::uint32_t node, std::uint32_t first, std::uint32_t count) {
  Aabb box, centres;
  for (std::uint32_t i = first; i < first + count; ++i) {
    const Triangle& t = tris_[i];
    box.add(t.a);
    box.add(t.b);
    box.add(t.c);
    centres.add((t.a + t.b + t.c) * (1.0 / 3.0));
  }
  nodes_[node].box = box;
  if (count <= kLeafSize) {
    nodes_[node].first = first;
    nodes_[node].count = count;
    return;
  }
  const Vec3 ext = centres.hi - centres.lo;
  const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
  auto key = [axis](const Triangle& t) {
    const Vec3 c = t.a + t.b + t.c;
    return axis == 0 ? c.x : (axis == 1 ? c.y : c.z);
  };
  const std::uint32_t half = count / 2;
  std::nth_element(tris_.begin() + first, tris_.begin() + first + half,
                   tris_.begin() + first + count,
                   [&](const Triangle& p, const Triangle& q) { return key(p) < key(q); });
  const auto left = static_cast<std::uint32_t>(nodes_.size());
  nodes_[node].first = left;
  nodes_[node].count = 0;
  nodes_.emplace_back();
  nodes_.emplace_back();
  build(left, first, half);
  build(left + 1, first + half, count - half);
}

bool TriMesh::first_contact(Vec3 a, Vec3 b, double radius, double& t, Vec3& point,
                            Vec3& normal) const noexcept {
  if (nodes_.empty()) return false;
  Aabb sweep;
  sweep.add(a - Vec3{radius, radius, radius});
  sweep.add(a + Vec3{radius, radius, radius});
  sweep.add(b - Vec3{radius, radius, radius});
  sweep.add(b + Vec3{radius, radius, radius});
  std::array<std::uint32_t, kStackDepth> stack{};
  int top = 0;
  stack[top++] = 0;
  bool found = false;
  const Vec3 r3{radius, radius, radius};
  // When the centre enters a node's box grown by the radius: no contact
  // inside it comes earlier, so a node entered at or after the best contact
  // so far is passed over (the order of the search, and so the contact chosen
  // among equal ones, is as before). Overlapping triangles behind the
  // first contact are not tested.
  auto entry = [&](const Node& nd) {
    return segment_box_entry(Aabb{nd.box.lo - r3, nd.box.hi + r3}, a, b - a);
  };
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    if (!boxes_overlap(nd.box, sweep)) continue;
    if (found && entry(nd) >= t) continue;
    if (nd.count == 0) {
      stack[top++] = nd.first;
      stack[top++] = nd.first + 1;
      continue;
    }
    for (std::uint32_t i = nd.first; i < nd.first + nd.count; ++i) {
      double ti = 0.0;
      Vec3 q;
      if (triangle_contact(tris_[i], a, b, radius, ti, q) && (!found || ti < t)) {
        found = true;
        t = ti;
        point = q;
      }
    }
  }
  if (found) {
    Vec3 n = lerp(a, b, t) - point;
    const double l = length(n);
    normal = l > 0.0 ? n * (1.0 / l) : Vec3{0, 0, 1};
  }
  return found;
}

double TriMesh::surface_distance(Vec3 p, double cap) const noexcept {
  double best = cap;
  if (nodes_.empty()) return best;
  std::array<std::uint32_t, kStackDepth> stack{};
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    if (box_distance(nd.box, p) >= best) continue;
    if (nd.count == 0) {
      // The nearer child last, so that it is searched first.
      const double dl = box_distance(nodes_[nd.first].box, p);
      const double dr = box_distance(nodes_[nd.first + 1].box, p);
      stack[top++] = dl < dr ? nd.first + 1 : nd.first;
      stack[top++] = dl < dr ? nd.first : nd.first + 1;
      continue;
    }
    for (std::uint32_t i = nd.first; i < nd.first + nd.count; ++i) {
      best = std::min(best, length(p - closest_on_triangle(tris_[i], p)));
    }
  }
  return best;
}

bool TriMesh::inside(Vec3 p) const noexcept {
  if (nodes_.empty() || box_distance(nodes_[0].box, p) > 0.0) return false;
  // Crossings of a ray in a direction no face of a machined part lies along:
  // odd inside a closed mesh.
  const Vec3 d0{0.8017837257372732, 0.5345224838248488, 0.2672612419124244};
  const Vec3 inv{1.0 / d0.x, 1.0 / d0.y, 1.0 / d0.z};
  std::array<std::uint32_t, kStackDepth> stack{};
  int top = 0;
  stack[top++] = 0;
  int crossings = 0;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    if (!ray_box(nd.box, p, inv)) continue;
    if (nd.count == 0) {
      stack[top++] = nd.first;
      stack[top++] = nd.first + 1;
      continue;
    }
    for (std::uint32_t i = nd.first; i < nd.first + nd.count; ++i) {
      if (ray_hits(tris_[i], p, d0)) ++crossings;
    }
  }
  return (crossings % 2) == 1;
}

double TriMesh::column_overlap(const Column& c) const noexcept {
  if (nodes_.empty()) return -kInf;
  Aabb col;
  col.add(Vec3{c.x - c.radius, c.y - c.radius, c.bottom});
  col.add(Vec3{c.x + c.radius, c.y + c.radius, c.top});
  std::array<std::uint32_t, kStackDepth> stack{};
  int top = 0;
  stack[top++] = 0;
  double nearest = kInf;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    if (!boxes_overlap(nd.box, col)) continue;
    if (nd.count == 0) {
      stack[top++] = nd.first;
      stack[top++] = nd.first + 1;
      continue;
    }
    for (std::uint32_t i = nd.first; i < nd.first + nd.count; ++i) {
      nearest = std::min(nearest, slab_distance_xy(tris_[i], c.x, c.y, c.bottom, c.top));
    }
  }
  if (nearest < kInf) return c.radius - nearest;
  return inside(Vec3{c.x, c.y, 0.5 * (c.bottom + c.top)}) ? c.radius : -kInf;
}

// --- STL --------------------------------------------------------------------

namespace {

std::unexpected<Error> stl_error(std::string_view name, const std::string& what) {
  return fail(AlarmId::kConfig, "STL '" + std::string(name) + "': " + what);
}

float read_f32(const char* p) noexcept {
  std::uint32_t u = 0;
  for (int i = 3; i >= 0; --i) u = (u << 8U) | static_cast<unsigned char>(p[i]);
  return std::bit_cast<float>(u);
}

Result<std::vector<Triangle>> parse_binary(std::string_view bytes, std::string_view name,
                                           std::uint64_t count, double scale) {
  std::vector<Triangle> out;
  out.reserve(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::size_t at = 84 + 50 * static_cast<std::size_t>(i);
    Vec3 v[3];
    for (int k = 0; k < 3; ++k) {
      const std::size_t off = at + 12 + 12 * static_cast<std::size_t>(k);
      const double x = read_f32(bytes.data() + off), y = read_f32(bytes.data() + off + 4),
                   z = read_f32(bytes.data() + off + 8);
      if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z) ||
          std::fabs(x * scale) > 1e6 || std::fabs(y * scale) > 1e6 || std::fabs(z * scale) > 1e6) {
        return stl_error(name, "facet " + std::to_string(i) + " (byte offset " +
                                   std::to_string(off) + "): vertex " + std::to_string(k + 1) +
                                   " is not a finite coordinate within 1e6 mm");
      }
      v[k] = Vec3{x * scale, y * scale, z * scale};
    }
    out.push_back(Triangle{v[0], v[1], v[2], {}});
  }
  return out;
}

Result<std::vector<Triangle>> parse_ascii(std::string_view text, std::string_view name,
                                          double scale) {
  std::vector<Triangle> out;
  std::size_t i = 0;
  std::uint32_t line = 1;
  auto skip_blank = [&] {
    while (i < text.size() &&
           (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) {
      if (text[i] == '\n') ++line;
      ++i;
    }
  };
  auto word = [&]() -> std::string_view {
    skip_blank();
    const std::size_t s = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '\r' &&
           text[i] != '\n') {
      ++i;
    }
    return text.substr(s, i - s);
  };
  auto where = [&](std::size_t facet) {
    return "line " + std::to_string(line) + " (facet " + std::to_string(facet) + ")";
  };
  auto expect = [&](std::string_view w, std::size_t facet) -> Result<void> {
    const auto got = word();
    if (got != w) {
      return stl_error(name, where(facet) + ": expected '" + std::string(w) + "', found '" +
                                 std::string(got.substr(0, 40)) + "'");
    }
    return {};
  };
  auto number = [&](std::size_t facet) -> Result<double> {
    const auto w = word();
    double v = 0.0;
    auto r = std::from_chars(w.data(), w.data() + w.size(), v);
    if (r.ec != std::errc{} || r.ptr != w.data() + w.size() || !std::isfinite(v) ||
        std::fabs(v * scale) > 1e6) {
      return stl_error(name, where(facet) + ": '" + std::string(w.substr(0, 40)) +
                                 "' is not a number within 1e6 mm");
    }
    return v * scale;
  };
  if (word() != "solid") return stl_error(name, "line 1: an ASCII STL starts with 'solid'");
  while (i < text.size() && text[i] != '\n') ++i;  // the solid's name
  for (std::size_t facet = 0;; ++facet) {
    const auto w = word();
    if (w == "endsolid") break;
    if (w.empty()) return stl_error(name, where(facet) + ": the file ends before 'endsolid'");
    if (w != "facet") {
      return stl_error(name, where(facet) + ": expected 'facet' or 'endsolid', found '" +
                                 std::string(w.substr(0, 40)) + "'");
    }
    if (out.size() >= kMaxTriangles) {
      return stl_error(name, "more than " + std::to_string(kMaxTriangles) + " facets");
    }
    SKIPNC_TRY(expect("normal", facet));
    for (int k = 0; k < 3; ++k) {
      SKIPNC_TRY(number(facet));
    }
    SKIPNC_TRY(expect("outer", facet));
    SKIPNC_TRY(expect("loop", facet));
    Vec3 v[3];
    for (auto& vk : v) {
      SKIPNC_TRY(expect("vertex", facet));
      double c[3];
      for (double& ck : c) {
        auto n = number(facet);
        SKIPNC_TRY(n);
        ck = *n;
      }
      vk = Vec3{c[0], c[1], c[2]};
    }
    SKIPNC_TRY(expect("endloop", facet));
    SKIPNC_TRY(expect("endfacet", facet));
    out.push_back(Triangle{v[0], v[1], v[2], {}});
  }
  return out;
}

}  // namespace

Result<std::vector<Triangle>> parse_stl(std::string_view bytes, std::string_view name,
                                        double scale) {
  // Binary: an 80-byte header, a facet count, 50 bytes per facet. A binary
  // header may also start with "solid", so the size decides first.
  if (bytes.size() >= 84) {
    std::uint64_t count = 0;
    for (int k = 3; k >= 0; --k) count = (count << 8U) | static_cast<unsigned char>(bytes[80 + k]);
    if (bytes.size() == 84 + 50 * count) {
      if (count > kMaxTriangles) {
        return stl_error(name, "more than " + std::to_string(kMaxTriangles) + " facets");
      }
      return parse_binary(bytes, name, count, scale);
    }
  }
  std::size_t s = 0;
  while (s < bytes.size() &&
         (bytes[s] == ' ' || bytes[s] == '\t' || bytes[s] == '\r' || bytes[s] == '\n')) {
    ++s;
  }
  if (bytes.substr(s, 5) == "solid") return parse_ascii(bytes, name, scale);
  if (bytes.size() >= 84) {
    std::uint64_t count = 0;
    for (int k = 3; k >= 0; --k) count = (count << 8U) | static_cast<unsigned char>(bytes[80 + k]);
    return stl_error(name, "binary STL of " + std::to_string(count) + " facets needs " +
                               std::to_string(84 + 50 * count) + " bytes, the file has " +
                               std::to_string(bytes.size()) + " (cut short at facet " +
                               std::to_string((bytes.size() - 84) / 50) + ", byte offset " +
                               std::to_string(84 + 50 * ((bytes.size() - 84) / 50)) + ")");
  }
  return stl_error(name, "neither an ASCII STL ('solid' ...) nor a binary one (" +
                             std::to_string(bytes.size()) + " bytes, less than 84)");
}

Result<std::vector<Triangle>> read_stl(const std::string& path, double scale) {
  // Read once, into the one string parsed: a file over the cap (or not a
  // regular file) is refused from its size, before a byte is read.
  auto bytes = read_input_file(path, kStlFileInput);
  if (!bytes) return stl_error(path, bytes.error().detail);
  return parse_stl(*bytes, path, scale);
}

}  // namespace skipnc::machine::geo
