#include "aspect/partition_picture.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <unordered_map>

namespace exactvis {

namespace {

struct PlaneD {
  double n[3], c;
};

std::vector<PlaneD> planes_d(const ConvexModel& m) {
  std::vector<PlaneD> out;
  for (const auto& p : m.planes)
    out.push_back({{CGAL::to_double(p.normal.x), CGAL::to_double(p.normal.y), CGAL::to_double(p.normal.z)},
                   CGAL::to_double(p.offset)});
  return out;
}

// Region of the viewpoint whose model-plane side values are f(k) > 0 (display: the aspect's lookup).
class RegionLookup {
 public:
  RegionLookup(const ConvexModel& m, const AspectGraph3& g) : m_(m) {
    for (std::size_t r = 0; r < g.regions.size(); ++r) by_aspect_.emplace(g.regions[r].aspect, static_cast<int>(r));
  }
  template <class Side>
  std::int64_t operator()(Side side) const {
    std::vector<std::int64_t> aspect;
    for (std::size_t k = 0; k < m_.planes.size(); ++k)
      if (side(k) > 0) aspect.insert(aspect.end(), m_.planes[k].triangles.begin(), m_.planes[k].triangles.end());
    if (aspect.empty()) return -1;
    std::sort(aspect.begin(), aspect.end());
    const auto it = by_aspect_.find(aspect);
    return it == by_aspect_.end() ? -1 : it->second;
  }

 private:
  const ConvexModel& m_;
  std::map<std::vector<std::int64_t>, int> by_aspect_;
};

Point3 unit(const Point3& p) {
  const double l = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
  return {p.x / l, p.y / l, p.z / l};
}

// The sum of a picture triangle's three corners (3 times its centroid).
Point3 corner_sum(const PartitionPicture& pic, const std::array<int, 3>& t) {
  const Point3& a = pic.points[t[0]];
  const Point3& b = pic.points[t[1]];
  const Point3& c = pic.points[t[2]];
  return {a.x + b.x + c.x, a.y + b.y + c.y, a.z + b.z + c.z};
}

// The unit sphere: an octahedron subdivided `subdivisions` times (points and triangles only).
PartitionPicture subdivided_sphere(int subdivisions) {
  PartitionPicture pic;
  pic.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  pic.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> mid;
    const auto middle = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const Point3& p = pic.points[a];
      const Point3& q = pic.points[b];
      pic.points.push_back(unit({p.x + q.x, p.y + q.y, p.z + q.z}));
      return mid[key] = static_cast<int>(pic.points.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& t : pic.triangles) {
      const int a = middle(t[0], t[1]), b = middle(t[1], t[2]), c = middle(t[2], t[0]);
      next.push_back({t[0], a, c});
      next.push_back({a, t[1], b});
      next.push_back({c, b, t[2]});
      next.push_back({a, b, c});
    }
    pic.triangles = std::move(next);
  }
  return pic;
}

// Great circles of the normals (one per normal up to sign), slightly outside the sphere so they show on top.
void add_great_circles(PartitionPicture& pic, const std::vector<Point3>& normals) {
  std::vector<Point3> drawn;
  for (std::size_t k = 0; k < normals.size(); ++k) {
    const Point3 n = unit(normals[k]);
    bool again = false;
    for (const Point3& m : drawn) again |= std::abs(std::abs(m.x * n.x + m.y * n.y + m.z * n.z) - 1) < 1e-12;
    if (again) continue;
    drawn.push_back(n);
    const Point3 helper = std::abs(n.x) < 0.9 ? Point3{1, 0, 0} : Point3{0, 1, 0};
    const Point3 u = unit({n.y * helper.z - n.z * helper.y, n.z * helper.x - n.x * helper.z, n.x * helper.y - n.y * helper.x});
    const Point3 v{n.y * u.z - n.z * u.y, n.z * u.x - n.x * u.z, n.x * u.y - n.y * u.x};
    std::vector<Point3> curve;
    for (int i = 0; i <= 256; ++i) {
      const double a = 2 * M_PI * i / 256, r = 1.002;
      curve.push_back({r * (std::cos(a) * u.x + std::sin(a) * v.x), r * (std::cos(a) * u.y + std::sin(a) * v.y),
                       r * (std::cos(a) * u.z + std::sin(a) * v.z)});
    }
    pic.curves.push_back(std::move(curve));
    pic.curve_plane.push_back(static_cast<std::int64_t>(k));
  }
}

}  // namespace

PartitionPicture sphere_picture(const ConvexModel& model, const AspectGraph3& graph, int subdivisions) {
  PartitionPicture pic = subdivided_sphere(subdivisions);
  const auto P = planes_d(model);
  const RegionLookup lookup(model, graph);
  for (const auto& t : pic.triangles) {
    const Point3 d = corner_sum(pic, t);
    pic.triangle_region.push_back(lookup([&](std::size_t k) { return P[k].n[0] * d.x + P[k].n[1] * d.y + P[k].n[2] * d.z; }));
  }
  std::vector<Point3> normals;
  for (const auto& p : P) normals.push_back({p.n[0], p.n[1], p.n[2]});
  add_great_circles(pic, normals);
  return pic;
}

PartitionPicture sphere_picture_of_cells(const AspectGraph3& graph, int subdivisions) {
  PartitionPicture pic = subdivided_sphere(subdivisions);
  std::unordered_map<std::string, int> region_of;
  for (const auto& c : graph.sampled_cells) region_of.emplace(c.signs, c.region);
  std::vector<Point3> normals;
  for (const auto& n : graph.circles) normals.push_back({CGAL::to_double(n.x), CGAL::to_double(n.y), CGAL::to_double(n.z)});
  std::string signs(graph.circles.size(), '0');
  for (const auto& t : pic.triangles) {
    const Point3 d = corner_sum(pic, t);
    for (std::size_t k = 0; k < normals.size(); ++k) {
      // Doubles decide when clearly away from the circle; else exactly (the double centroid as rationals).
      const double f = normals[k].x * d.x + normals[k].y * d.y + normals[k].z * d.z;
      const double bound = 1e-12 * (std::abs(normals[k].x) + std::abs(normals[k].y) + std::abs(normals[k].z)) * 4;
      int sg = f > bound ? 1 : (f < -bound ? -1 : 0);
      if (sg == 0) sg = CGAL::sign(graph.circles[k].x * Exact(d.x) + graph.circles[k].y * Exact(d.y) + graph.circles[k].z * Exact(d.z));
      signs[k] = sg > 0 ? '+' : (sg < 0 ? '-' : '0');
    }
    const auto it = region_of.find(signs);
    pic.triangle_region.push_back(it == region_of.end() ? -1 : it->second);
  }
  add_great_circles(pic, normals);
  return pic;
}

namespace {

// The square [x0, x1] x [y0, y1] of z = h as cells x cells squares, two triangles each.
PartitionPicture square_grid(double h, double x0, double y0, double x1, double y1, int cells) {
  PartitionPicture pic;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) pic.points.push_back({x0 + (x1 - x0) * i / cells, y0 + (y1 - y0) * j / cells, h});
  const auto id = [&](int i, int j) { return j * (cells + 1) + i; };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      pic.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      pic.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return pic;
}

// The line a x + b y = r clipped to the square (Liang-Barsky on a long segment), drawn slightly above it.
void add_trace_line(PartitionPicture& pic, double a, double b, double r, double h, double x0, double y0, double x1,
                    double y1, std::int64_t label) {
  if (a == 0 && b == 0) return;
  const double L = 4 * (std::abs(x1 - x0) + std::abs(y1 - y0) + std::abs(x0) + std::abs(y0) + std::abs(r));
  const double px = a * r / (a * a + b * b), py = b * r / (a * a + b * b);  // closest point to the origin
  const double dx = -b, dy = a;
  double t0 = -L, t1 = L;
  const auto clip = [&](double p, double q) {  // p t <= q
    if (p == 0) return q >= 0;
    const double t = q / p;
    if (p < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    return t0 <= t1;
  };
  if (clip(-dx, px - x0) && clip(dx, x1 - px) && clip(-dy, py - y0) && clip(dy, y1 - py) && t0 < t1) {
    const double z = h + 1e-3 * (std::abs(x1 - x0) + std::abs(y1 - y0));
    pic.curves.push_back({{px + t0 * dx, py + t0 * dy, z}, {px + t1 * dx, py + t1 * dy, z}});
    pic.curve_plane.push_back(label);
  }
}

}  // namespace

PartitionPicture plane_picture(const ConvexModel& model, const AspectGraph3& graph, double h, double x0, double y0,
                               double x1, double y1, int cells) {
  PartitionPicture pic = square_grid(h, x0, y0, x1, y1, cells);
  const auto P = planes_d(model);
  const RegionLookup lookup(model, graph);
  for (const auto& t : pic.triangles) {
    const Point3 m = corner_sum(pic, t);
    const Point3 p{m.x / 3, m.y / 3, h};
    pic.triangle_region.push_back(
        lookup([&](std::size_t k) { return P[k].n[0] * p.x + P[k].n[1] * p.y + P[k].n[2] * p.z - P[k].c; }));
  }
  // Trace lines n_x x + n_y y = c - n_z h.
  for (std::size_t k = 0; k < P.size(); ++k)
    add_trace_line(pic, P[k].n[0], P[k].n[1], P[k].c - P[k].n[2] * h, h, x0, y0, x1, y1, static_cast<std::int64_t>(k));
  return pic;
}

PartitionPicture plane_picture_of_cells(const AspectGraph3& graph, double h, double x0, double y0, double x1,
                                        double y1, int cells) {
  PartitionPicture pic = square_grid(h, x0, y0, x1, y1, cells);
  std::unordered_map<std::string, int> region_of;
  for (const auto& c : graph.sampled_cells) region_of.emplace(c.signs, c.region);
  std::string signs(graph.circles.size(), '0');
  for (const auto& t : pic.triangles) {
    const Point3 m = corner_sum(pic, t);
    // The centroid's double coordinates read as exact rationals; exact signs (display only).
    const Exact x(m.x / 3), y(m.y / 3);
    for (std::size_t k = 0; k < graph.circles.size(); ++k) {
      const int sg = CGAL::sign(graph.circles[k].x * x + graph.circles[k].y * y + graph.circles[k].z);
      signs[k] = sg > 0 ? '+' : (sg < 0 ? '-' : '0');
    }
    const auto it = region_of.find(signs);
    pic.triangle_region.push_back(it == region_of.end() ? -1 : it->second);
  }
  for (std::size_t k = 0; k < graph.circles.size(); ++k)
    add_trace_line(pic, CGAL::to_double(graph.circles[k].x), CGAL::to_double(graph.circles[k].y),
                   -CGAL::to_double(graph.circles[k].z), h, x0, y0, x1, y1, static_cast<std::int64_t>(k));
  return pic;
}

}  // namespace exactvis
