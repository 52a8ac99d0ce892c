#include "aspect/convex_aspect_graph.hpp"

#include "aspect/aspect_regions.hpp"
#include "aspect/plane_arrangement_3.hpp"

#include <map>
#include <stdexcept>
#include <unordered_map>

namespace exactvis {

namespace {

// n scaled so that its first largest-|.| component is +1, and the offset with it.
std::pair<Vec3<Exact>, Exact> unoriented(const Vec3<Exact>& n, const Exact& c) {
  int a = 0;
  for (int i = 1; i < 3; ++i)
    if (CGAL::abs(n[i]) > CGAL::abs(n[a])) a = i;
  const Exact s = n[a];
  return {{n.x / s, n.y / s, n.z / s}, c / s};
}

// view_plane: for ViewModel::Plane, the viewpoint plane.
AspectGraph3 build(const ConvexModel& model, ViewModel view, const ArrangementPlane* view_plane,
                   void (*progress)(double)) {
  if (!model.convex) throw std::invalid_argument("convex_aspect_graph: the model is not convex");
  const int m = static_cast<int>(model.planes.size());
  const bool ortho = view == ViewModel::Orthographic;
  // Arrangement planes and, per model plane k, its arrangement plane g[k] and orientation o[k] (the model
  // plane's positive side is the arrangement plane's side o[k]).
  std::vector<ArrangementPlane> planes;
  std::vector<int> g(m), o(m, 1);
  if (ortho) {
    std::map<std::array<Exact, 3>, int> index;
    for (int k = 0; k < m; ++k) {
      Vec3<Exact> n = model.planes[k].normal;  // largest |component| is 1
      int a = 0;
      for (int i = 1; i < 3; ++i)
        if (CGAL::abs(n[i]) > CGAL::abs(n[a])) a = i;
      if (n[a] < 0) n = -n, o[k] = -1;
      auto [it, fresh] = index.emplace(std::array<Exact, 3>{n.x, n.y, n.z}, static_cast<int>(planes.size()));
      if (fresh) planes.push_back({n, Exact(0)});
      g[k] = it->second;
    }
  } else {
    for (int k = 0; k < m; ++k) planes.push_back({model.planes[k].normal, model.planes[k].offset}), g[k] = k;
  }
  // The viewpoint plane: a face plane, or one more arrangement plane.
  int on = -1;
  if (view_plane) {
    const auto key = unoriented(view_plane->normal, view_plane->offset);
    for (int k = 0; k < m && on < 0; ++k)
      if (unoriented(planes[k].normal, planes[k].offset) == key) on = k;
    if (on < 0) on = static_cast<int>(planes.size()), planes.push_back(*view_plane);
  }
  const PlaneArrangement arr = plane_arrangement(planes, progress);

  // Model-plane sign of a cell: '+', '0' or '-'.
  const auto model_sign = [&](const ArrangementCell& c, int k) {
    const char s = c.signs[g[k]];
    if (s == '0' || o[k] > 0) return s;
    return s == '+' ? '-' : '+';
  };
  const int n = static_cast<int>(arr.cells.size());
  std::vector<AspectCell> cells(n);
  std::vector<bool> keep(n, false);
  std::unordered_map<std::string, int> aspect_ids;
  std::vector<std::string> aspect_keys;
  for (int c = 0; c < n; ++c) {
    const ArrangementCell& a = arr.cells[c];
    std::string key(m, '0');
    bool seen = false;
    for (int k = 0; k < m; ++k)
      if (model_sign(a, k) == '+') key[k] = '1', seen = true;
    cells[c].dimension = ortho ? a.dimension - 1 : a.dimension;
    cells[c].facets = a.facets;
    // Orthographic: every direction sees a face (the outward normals span R^3 positively); the origin is not
    // a direction. Perspective: a point sees a face iff it is outside the closed model.
    keep[c] = seen && cells[c].dimension >= 0 && (on < 0 || a.signs[on] == '0');
    auto [it, fresh] = aspect_ids.emplace(key, static_cast<int>(aspect_keys.size()));
    if (fresh) aspect_keys.push_back(key);
    cells[c].aspect = it->second;
  }
  const AspectRegions regions = aspect_regions(cells, keep);

  AspectGraph3 out;
  out.view = view;
  for (int c = 0; c < n; ++c)
    if (keep[c]) ++out.cells[cells[c].dimension];
  for (std::size_t r = 0; r < regions.members.size(); ++r) {
    AspectRegion3 region;
    region.dimension = regions.dimension[r];
    const int best = region_sample_cell(regions, r, cells);
    const std::string& key = aspect_keys[cells[best].aspect];
    for (int k = 0; k < m; ++k)
      if (key[k] == '1') region.aspect.insert(region.aspect.end(), model.planes[k].triangles.begin(),
                                              model.planes[k].triangles.end());
    std::sort(region.aspect.begin(), region.aspect.end());
    region.sample = arr.cells[best].sample;
    if (ortho) {
      Exact big(0);
      for (int i = 0; i < 3; ++i) big = std::max(big, CGAL::abs(region.sample[i]));
      for (int i = 0; i < 3; ++i) region.sample[i] /= big;
    }
    out.regions.push_back(std::move(region));
  }
  for (const auto& adj : regions.adjacency) {
    AspectAdjacency3 a;
    a.a = adj.a;
    a.b = adj.b;
    for (int k = 0; k < m; ++k) {
      if (model_sign(arr.cells[adj.lower], k) != '0' || model_sign(arr.cells[adj.upper], k) != '+') continue;
      AspectEvent3 e;
      e.vertex = model.planes[k].vertex;
      e.edge = model.planes[k].edge;
      e.triangles = model.planes[k].triangles;
      a.events.push_back(std::move(e));
    }
    out.adjacency.push_back(std::move(a));
  }
  return out;
}

}  // namespace

AspectGraph3 convex_aspect_graph(const Scene& scene, const ConvexModel& model, ViewModel view,
                                 void (*progress)(double)) {
  if (view == ViewModel::Plane) throw std::invalid_argument("convex_aspect_graph: use convex_aspect_graph_on_plane");
  (void)scene;
  return build(model, view, nullptr, progress);
}

AspectGraph3 convex_aspect_graph_on_plane(const Scene& scene, const ConvexModel& model, const Vec3<Exact>& normal,
                                          const Exact& offset, void (*progress)(double)) {
  if (normal.x == 0 && normal.y == 0 && normal.z == 0)
    throw std::invalid_argument("convex_aspect_graph_on_plane: zero normal");
  (void)scene;
  const ArrangementPlane p{normal, offset};
  return build(model, ViewModel::Plane, &p, progress);
}

}  // namespace exactvis
