// Tries to refute the answers of `exactvis validate --bsp ... --occluders brushes -o REPORT.json` on a real map
// with an independent exact check (docs/performance.md, "Validating Quake 3 visdata exactly"):
//   hidden pairs: N random segments between random points of the two clusters' leaf volumes (exact rational
//                 convex combinations of a leaf's vertices), each tested exactly against every solid world
//                 brush given by its sides' half-spaces (Liang-Barsky clipping with GMP rationals, no
//                 polyhedron or triangle code): a segment whose ends lie in no brush and which meets none
//                 refutes the answer;
//   visible pairs: the witness segment tested the same way (ends outside every brush, segment meeting none).
// Usage: bench_quake3_refute MAP REPORT.json [--segments N] [--seed S] [--cover K]
//   --cover K: first, per cluster, the share of K random points of its leaves that lie in a solid brush.
// Prints per map: pairs, hidden, segments tried, refuted hidden pairs, witnesses failing; exit 1 on any.
#include "bench/bench_util.hpp"
#include "io/quake3_bsp.hpp"
#include "io/quake3_geometry.hpp"

#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace exactvis;
using namespace exactvis::quake3;

namespace {

using Q3 = std::array<mpq_class, 3>;

struct HalfspaceBrush {
  std::vector<std::pair<Q3, mpq_class>> sides;  // n . x <= d
  double lo[3], hi[3];                          // a box around it (from the float planes' polytope, padded)
};

Q3 q3(const RationalPoint3& p) { return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq()), mpq_class(p.z.mpq())}; }

mpq_class dot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

bool inside(const HalfspaceBrush& b, const Q3& x) {
  for (int k = 0; k < 3; ++k)
    if (x[k].get_d() < b.lo[k] || x[k].get_d() > b.hi[k]) return false;
  for (const auto& [n, d] : b.sides)
    if (dot(n, x) > d) return false;
  return true;
}

// Does the closed segment [p, q] meet the closed brush?
bool meets(const HalfspaceBrush& b, const Q3& p, const Q3& q) {
  for (int k = 0; k < 3; ++k) {
    const double lo = std::min(p[k].get_d(), q[k].get_d()), hi = std::max(p[k].get_d(), q[k].get_d());
    if (hi < b.lo[k] || lo > b.hi[k]) return false;
  }
  const Q3 d{q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  mpq_class t0 = 0, t1 = 1;
  for (const auto& [n, off] : b.sides) {
    const mpq_class a = dot(n, d), r = off - dot(n, p);
    if (a == 0) {
      if (r < 0) return false;
    } else if (a > 0) {
      const mpq_class t = r / a;
      if (t < t1) t1 = t;
    } else {
      const mpq_class t = r / a;
      if (t > t0) t0 = t;
    }
    if (t0 > t1) return false;
  }
  return true;
}

mpq_class parse_number(const nlohmann::json& v) {
  if (v.is_string()) return mpq_class(v.get<std::string>());
  return mpq_class(v.get<double>());
}

// A random point of the leaf: uniform in its bounding box (dyadic rationals), rejected until it lies in the
// closed leaf (exact); the vertex centroid after 200 misses.
Q3 random_point(const region::ConvexPolyhedron3& leaf, std::mt19937_64& rng) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const auto& v : leaf.vertices)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], CGAL::to_double(v[k])), hi[k] = std::max(hi[k], CGAL::to_double(v[k]));
  std::uniform_real_distribution<double> u(0, 1);
  for (int attempt = 0; attempt < 200; ++attempt) {
    const RationalPoint3 x{Exact(lo[0] + u(rng) * (hi[0] - lo[0])), Exact(lo[1] + u(rng) * (hi[1] - lo[1])),
                           Exact(lo[2] + u(rng) * (hi[2] - lo[2]))};
    if (region::locate(leaf, x) != region::Containment::Outside) return q3(x);
  }
  return q3(region::centroid(leaf.vertices));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_quake3_refute MAP REPORT.json [--segments N] [--seed S]\n");
    return 2;
  }
  int segments = 1000, cover = 0;
  std::uint64_t seed = 1;
  bench::require_option_pairs(argc, argv, 3, "bench_quake3_refute");
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--segments") segments = std::stoi(argv[i + 1]);
    else if (a == "--seed") seed = std::stoull(argv[i + 1]);
    else if (a == "--cover") cover = std::stoi(argv[i + 1]);
    else return bench::unknown_option("bench_quake3_refute", a);
  }
  const double t_start = bench::now();
  const BspMap map = read_bsp(argv[1]);
  std::ifstream in(argv[2]);
  const nlohmann::json report = nlohmann::json::parse(in);
  if (report["occluders"] != "brushes") {
    std::fprintf(stderr, "%s: occluders must be brushes\n", argv[2]);
    return 2;
  }
  std::vector<HalfspaceBrush> brushes;
  std::vector<std::int32_t> brush_index;
  for (const OpaqueSolid& s : opaque_solids(map, Occluders::Brushes)) {
    brush_index.push_back(s.index);
    HalfspaceBrush b;
    const BspBrush& br = map.brushes[static_cast<std::size_t>(s.index)];
    for (int k = 0; k < br.n_sides; ++k) {
      const BspPlane& pl = map.planes[static_cast<std::size_t>(map.brush_sides[static_cast<std::size_t>(br.first_side + k)].plane)];
      b.sides.push_back({{mpq_class(double(pl.normal[0])), mpq_class(double(pl.normal[1])), mpq_class(double(pl.normal[2]))},
                         mpq_class(double(pl.dist))});
    }
    for (int k = 0; k < 3; ++k) b.lo[k] = 1e300, b.hi[k] = -1e300;
    for (const auto& v : s.volume.vertices)
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], CGAL::to_double(v[k]) - 1e-3);
        b.hi[k] = std::max(b.hi[k], CGAL::to_double(v[k]) + 1e-3);
      }
    brushes.push_back(std::move(b));
  }
  const std::vector<region::ConvexPolyhedron3> volumes = leaf_volumes(map);
  const std::vector<ClusterRegion> regions = cluster_regions(map, volumes);
  auto free_segment = [&](const Q3& p, const Q3& q) {
    for (const auto& b : brushes)
      if (meets(b, p, q)) return false;
    return true;
  };
  std::mt19937_64 rng(seed);
  if (cover > 0) {
    // Per cluster: the share of `cover` random points of its leaves inside a solid brush, and the shader of
    // the brush met most often.
    for (std::size_t c = 0; c < regions.size(); ++c) {
      if (regions[c].volumes.empty()) continue;
      int in = 0;
      std::map<std::int32_t, int> by;
      for (int k = 0; k < cover; ++k) {
        const Q3 x = random_point(regions[c].volumes[rng() % regions[c].volumes.size()], rng);
        for (std::size_t i = 0; i < brushes.size(); ++i)
          if (inside(brushes[i], x)) {
            ++in, ++by[brush_index[i]];
            break;
          }
      }
      std::int32_t top = -1;
      int most = 0;
      for (const auto& [b, n] : by)
        if (n > most) top = b, most = n;
      std::printf("cluster %zu: %zu leaves, %d of %d points in a solid brush; most: brush %d (%s, %d points)\n", c,
                  regions[c].volumes.size(), in, cover, top,
                  top >= 0 ? map.shaders[static_cast<std::size_t>(map.brushes[static_cast<std::size_t>(top)].shader)].name.c_str() : "-",
                  most);
    }
  }
  long pairs = 0, hidden = 0, tried = 0, refuted = 0, bad_witness = 0, no_free_point = 0;
  for (const auto& p : report["pairs"]) {
    ++pairs;
    const int a = p["from"], b = p["to"];
    if (p["exact"].get<bool>()) {
      const Q3 x{parse_number(p["witness"][0][0]), parse_number(p["witness"][0][1]), parse_number(p["witness"][0][2])};
      const Q3 y{parse_number(p["witness"][1][0]), parse_number(p["witness"][1][1]), parse_number(p["witness"][1][2])};
      if (!free_segment(x, y)) {
        ++bad_witness;
        std::printf("witness of %d -> %d meets a brush\n", a, b);
      }
      continue;
    }
    ++hidden;
    const auto& ra = regions[static_cast<std::size_t>(a)];
    const auto& rb = regions[static_cast<std::size_t>(b)];
    if (ra.volumes.empty() || rb.volumes.empty()) continue;
    int free_ends = 0;
    for (int s = 0; s < segments; ++s) {
      const Q3 x = random_point(ra.volumes[rng() % ra.volumes.size()], rng);
      const Q3 y = random_point(rb.volumes[rng() % rb.volumes.size()], rng);
      bool ends_free = true;
      for (const auto& br : brushes) ends_free = ends_free && !inside(br, x) && !inside(br, y);
      if (!ends_free) continue;
      ++free_ends;
      ++tried;
      if (free_segment(x, y)) {
        ++refuted;
        std::printf("hidden %d -> %d refuted by (%g %g %g) (%g %g %g)\n", a, b, x[0].get_d(), x[1].get_d(),
                    x[2].get_d(), y[0].get_d(), y[1].get_d(), y[2].get_d());
        break;
      }
    }
    no_free_point += free_ends == 0;
  }
  std::printf("%s: %ld pairs, %ld hidden (%ld without a sampled free pair of ends), %ld segments tried, "
              "%ld hidden pairs refuted, %ld witnesses failing; %zu solid brushes; %.1f s\n",
              map.source.c_str(), pairs, hidden, no_free_point, tried, refuted, bad_witness, brushes.size(),
              bench::now() - t_start);
  return refuted || bad_witness ? 1 : 0;
}
