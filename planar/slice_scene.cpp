#include "planar/slice_scene.hpp"

#include <map>
#include <sstream>

namespace exactvis {
namespace {

[[noreturn]] void fail(const std::string& what) { throw SliceError(what); }

}  // namespace

SlicePlane parse_slice_plane(const std::string& spec) {
  const auto eq = spec.find('=');
  if (eq != 1 || (spec[0] != 'x' && spec[0] != 'y' && spec[0] != 'z'))
    fail("bad --slice '" + spec + "' (expected x=V, y=V or z=V)");
  SlicePlane plane;
  plane.axis = spec[0] - 'x';
  plane.spec = spec;
  try {
    plane.value = parse_rational(spec.substr(2));
  } catch (const std::exception&) {
    fail("bad --slice value '" + spec.substr(2) + "'");
  }
  return plane;
}

std::vector<PolygonInput2D> slice_scene(const Scene& scene, const SlicePlane& plane) {
  const int axis = plane.axis;
  const Exact& value = plane.value;
  const std::string& spec = plane.spec;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  // crossing point of mesh edge (i, j), i < j, keyed by the edge
  std::map<std::pair<int, int>, Point2> crossing;
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> adjacent;  // edge key -> other ends
  auto key_point = [&](int i, int j) {
    if (i > j) std::swap(i, j);
    const auto key = std::make_pair(i, j);
    if (!crossing.count(key)) {
      const Point3 &a = scene.vertices[i], &b = scene.vertices[j];
      const Exact t = (value - Exact(a[axis])) / (Exact(b[axis]) - Exact(a[axis]));
      crossing.emplace(key, Point2(Exact(a[u]) + t * (Exact(b[u]) - Exact(a[u])),
                                   Exact(a[v]) + t * (Exact(b[v]) - Exact(a[v]))));
    }
    return key;
  };
  for (const SceneTriangle& t : scene.triangles) {
    int sg[3];
    for (int k = 0; k < 3; ++k) {
      const int c = CGAL::compare(Exact(scene.corner(t, k)[axis]), value);
      if (c == 0) {
        std::ostringstream s;
        s << "slice plane " << spec << " passes through mesh vertex " << t.v[k] << "; choose another value";
        fail(s.str());
      }
      sg[k] = c;
    }
    if (sg[0] == sg[1] && sg[1] == sg[2]) continue;
    std::vector<std::pair<int, int>> ends;
    for (int k = 0; k < 3; ++k)
      if (sg[k] != sg[(k + 1) % 3]) ends.push_back(key_point(t.v[k], t.v[(k + 1) % 3]));
    adjacent[ends[0]].push_back(ends[1]);
    adjacent[ends[1]].push_back(ends[0]);
  }
  for (const auto& [key, nb] : adjacent)
    if (nb.size() != 2) fail("slice " + spec + " is not a set of closed loops (mesh not watertight or not manifold)");
  // chain loops
  std::vector<std::vector<Point2>> loops;
  std::map<std::pair<int, int>, bool> used;
  for (const auto& [start, nb0] : adjacent) {
    if (used[start]) continue;
    std::vector<Point2> loop;
    auto prev = start, cur = start;
    bool first = true;
    while (true) {
      used[cur] = true;
      loop.push_back(crossing.at(cur));
      const auto& nb = adjacent.at(cur);
      const auto nxt = (first || nb[0] != prev) ? nb[0] : nb[1];
      first = false;
      prev = cur;
      cur = nxt;
      if (cur == start) break;
      if (used[cur]) fail("slice " + spec + " has a loop that does not close");
    }
    loops.push_back(std::move(loop));
  }
  if (loops.empty()) fail("slice " + spec + " misses the scene");
  // nesting depth of each loop: number of loops containing its first vertex (loops are disjoint if valid)
  auto inside = [](const std::vector<Point2>& ring, const Point2& p) {
    bool in = false;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
      const bool a_above = a.y > p.y, b_above = b.y > p.y;
      if (a_above != b_above && (orientation2(a, b, p) == Sign::Positive) == b_above) in = !in;
    }
    return in;
  };
  const std::size_t L = loops.size();
  std::vector<int> depth(L, 0), parent(L, -1);
  for (std::size_t i = 0; i < L; ++i)
    for (std::size_t j = 0; j < L; ++j)
      if (i != j && inside(loops[j], loops[i][0])) ++depth[i];
  for (std::size_t i = 0; i < L; ++i)
    for (std::size_t j = 0; j < L; ++j)
      if (i != j && depth[j] == depth[i] - 1 && inside(loops[j], loops[i][0])) parent[i] = static_cast<int>(j);
  std::vector<PolygonInput2D> polys;
  std::vector<int> poly_of(L, -1);
  for (std::size_t i = 0; i < L; ++i)
    if (depth[i] % 2 == 0) {
      poly_of[i] = static_cast<int>(polys.size());
      polys.push_back({{loops[i]}});
    }
  for (std::size_t i = 0; i < L; ++i)
    if (depth[i] % 2 == 1) {
      if (parent[i] < 0 || poly_of[parent[i]] < 0) fail("slice " + spec + ": inconsistent loop nesting");
      polys[poly_of[parent[i]]].rings.push_back(loops[i]);
    }
  return polys;
}

}  // namespace exactvis
