#include "region/exterior_enclosure.hpp"

#include "kernel/ray_blocker.hpp"
#include "kernel/segment_triangle_intersection.hpp"
#include "region/convex_polygon_3.hpp"
#include "region/exterior_witness.hpp"
#include "util/union_find.hpp"

#include <algorithm>
#include <functional>
#include <array>
#include <limits>
#include <numeric>
#include <random>
#include <tuple>

namespace exactvis::region {
namespace {

// Vertex ids merged by exact position: canonical[v] is the smallest vertex index at v's position.
std::vector<int> canonical_vertices(const Scene& scene) {
  const auto& V = scene.vertices;
  std::vector<int> order(V.size());
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](int i) { return std::make_tuple(V[i].x, V[i].y, V[i].z); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  std::vector<int> canonical(V.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    canonical[order[k]] = (k > 0 && key(order[k]) == key(order[k - 1])) ? canonical[order[k - 1]] : order[k];
  return canonical;
}

bool contains(const Box3& outer, const Box3& inner) {
  for (int k = 0; k < 3; ++k)
    if (inner.lo[k] < outer.lo[k] || inner.hi[k] > outer.hi[k]) return false;
  return true;
}

// Crossing parity of the ray from q along d with the shell's triangles: the number of crossings, or -1 when
// the ray meets the shell anywhere but in a transversal crossing of a relative interior (not generic).
// Triangles for which skip(c) is true are left out (the caller knows the ray cannot meet them).
int crossings(const Scene& scene, const TriangleIndex& index, const Box3& scene_box, const SceneShells& shells,
              int shell, const RationalPoint3& q, const Vec3<Exact>& d,
              const std::function<bool(std::int64_t)>& skip = nullptr) {
  const RaySpan span = ray_span(scene_box, q, d);
  int count = 0;
  bool generic = true;
  visit_ray_candidates(index, span, [&](std::int64_t c) {
    if (shells.shell_of(c) != shell || (skip && skip(c))) return true;
    const auto o = triangle_points(scene, c);
    // q is off the shell (the caller checked relint T against it), so the closed segment meets o iff the
    // ray does at some s > 0; far is beyond every triangle.
    if (!segment_meets_closed_triangle(q, span.far, o[0], o[1], o[2])) return true;
    if (segment_crosses_triangle_interior(q, span.far, o[0], o[1], o[2])) {
      ++count;
      return true;
    }
    generic = false;
    return false;
  });
  return generic ? count : -1;
}

}  // namespace

SceneShells::SceneShells(const Scene& scene) {
  const std::vector<int> canonical = canonical_vertices(scene);
  UnionFind uf(scene.vertices.size());
  for (const auto& t : scene.triangles) {
    uf.unite(canonical[t.v[0]], canonical[t.v[1]]);
    uf.unite(canonical[t.v[0]], canonical[t.v[2]]);
  }
  std::vector<int> shell_of_root(scene.vertices.size(), -1);
  shell_of_.resize(scene.triangles.size());
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const int root = uf.find(canonical[scene.triangles[i].v[0]]);
    if (shell_of_root[root] < 0) {
      shell_of_root[root] = static_cast<int>(closed_.size());
      closed_.push_back(true);
      box_.push_back(triangle_box(scene, scene.triangles[i]));
    }
    const int s = shell_of_root[root];
    shell_of_[i] = s;
    const Box3 b = triangle_box(scene, scene.triangles[i]);
    for (int k = 0; k < 3; ++k) {
      box_[s].lo[k] = std::min(box_[s].lo[k], b.lo[k]);
      box_[s].hi[k] = std::max(box_[s].hi[k], b.hi[k]);
    }
  }
  // Edge multiplicities: a shell is closed iff every edge occurs an even number of times.
  std::vector<std::tuple<int, int, int>> edges;  // (shell, smaller vertex, larger vertex)
  edges.reserve(3 * scene.triangles.size());
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const auto& t = scene.triangles[i];
    for (int k = 0; k < 3; ++k) {
      const int a = canonical[t.v[k]], b = canonical[t.v[(k + 1) % 3]];
      edges.emplace_back(shell_of_[i], std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if ((j - i) % 2 == 1) closed_[static_cast<std::size_t>(std::get<0>(edges[i]))] = false;
    i = j;
  }
  for (int s = 0; s < shells(); ++s)
    if (closed_[static_cast<std::size_t>(s)]) closed_list_.push_back(s);
}

int SceneShells::closed_shells() const { return static_cast<int>(closed_list_.size()); }

bool meets_relative_interior(const std::array<RationalPoint3, 3>& other, const std::array<RationalPoint3, 3>& t) {
  const Plane3 plane = plane_through(t[0], t[1], t[2]);
  Polygon3 c{other[0], other[1], other[2]};
  c = clip_polygon(c, plane);
  c = clip_polygon(c, plane.flipped());
  for (int k = 0; k < 3 && !c.empty(); ++k) {
    const RationalPoint3& a = t[k];
    const Vec3<Exact> inward = cross(plane.normal, t[(k + 1) % 3] - a);
    c = clip_polygon(c, Plane3{inward, dot(inward, a)});
  }
  if (c.empty()) return false;
  // c = other ∩ t, convex; it meets relint t iff the mean of its vertices (a combination with positive
  // weights) does: if the mean is on an edge line, every vertex is, and c lies in that edge.
  return in_triangle_relative_interior(centroid(c), t);
}

std::optional<EnclosureProof> enclosing_shell(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                                              const SceneShells& shells, std::int64_t triangle_index) {
  const SceneTriangle& t = scene.triangles[static_cast<std::size_t>(triangle_index)];
  const Box3 tbox = triangle_box(scene, t);
  const int own = shells.shell_of(triangle_index);
  std::vector<std::int64_t> touching;  // triangles meeting closed T, fetched once when first needed
  bool touching_known = false;
  const auto tri = triangle_points(scene, triangle_index);
  const RationalPoint3 q = centroid(Polygon3{tri[0], tri[1], tri[2]});
  for (const int s : shells.closed_list()) {
    if (s == own || !contains(shells.box(s), tbox)) continue;
    if (!touching_known) {
      touching = index.triangles_meeting_triangle(scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2));
      touching_known = true;
    }
    bool disjoint = true;
    for (const std::int64_t o : touching)
      if (shells.shell_of(o) == s && meets_relative_interior(triangle_points(scene, o), tri)) {
        disjoint = false;
        break;
      }
    if (!disjoint) continue;
    // Generic directions: integer vectors from a fixed seed (the same proof on every run).
    std::mt19937_64 rng(0x9e3779b97f4a7c15ULL ^ static_cast<std::uint64_t>(triangle_index));
    for (int attempt = 0; attempt < 8; ++attempt) {
      auto comp = [&] { return Exact(static_cast<long>(rng() % (1u << 21)) - (1L << 20)); };
      const Vec3<Exact> d{comp(), comp(), comp()};
      if (CGAL::sign(d.x) == 0 && CGAL::sign(d.y) == 0 && CGAL::sign(d.z) == 0) continue;
      const int n = crossings(scene, index, scene_box, shells, s, q, d);
      if (n < 0) continue;
      if (n % 2 == 1) return EnclosureProof{s, q, d, n};
      break;  // even: this shell does not enclose T
    }
  }
  return std::nullopt;
}

std::optional<OwnShellSides> own_shell_sides(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                                             const SceneShells& shells, std::int64_t triangle_index) {
  const int own = shells.shell_of(triangle_index);
  if (!shells.closed(own)) return std::nullopt;
  const SceneTriangle& t = scene.triangles[static_cast<std::size_t>(triangle_index)];
  const auto tri = triangle_points(scene, triangle_index);
  auto coplanar = [&](std::int64_t o) { return coplanar_triangles(scene, triangle_index, o); };
  // No other non-coplanar triangle of the shell may meet relint T (Lemma 5.6.5).
  for (const std::int64_t o : index.triangles_meeting_triangle(scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2)))
    if (o != triangle_index && shells.shell_of(o) == own && !coplanar(o) &&
        meets_relative_interior(triangle_points(scene, o), tri))
      return std::nullopt;
  OwnShellSides out;
  out.q = centroid(Polygon3{tri[0], tri[1], tri[2]});
  const Vec3<Exact> n = cross(tri[1] - tri[0], tri[2] - tri[0]);
  // T and the triangles coplanar with it are never met by a ray leaving plane(T).
  auto skip = [&](std::int64_t o) { return o == triangle_index || coplanar(o); };
  std::mt19937_64 rng(0x51ed270b27c8e0d1ULL ^ static_cast<std::uint64_t>(triangle_index));
  for (int side = 0; side < 2; ++side) {
    bool decided = false;
    for (int attempt = 0; attempt < 8 && !decided; ++attempt) {
      auto comp = [&] { return Exact(static_cast<long>(rng() % (1u << 21)) - (1L << 20)); };
      Vec3<Exact> d{comp(), comp(), comp()};
      const int s = CGAL::sign(dot(d, n));
      if (s == 0) continue;
      if ((s > 0) != (side == 0)) d = Vec3<Exact>{-d.x, -d.y, -d.z};
      const int count = crossings(scene, index, scene_box, shells, own, out.q, d, skip);
      if (count < 0) continue;
      out.d[side] = d;
      out.crossings[side] = count;
      out.blocked[side] = count % 2 == 1;
      decided = true;
    }
    if (!decided) return std::nullopt;
  }
  return out;
}

}  // namespace exactvis::region
