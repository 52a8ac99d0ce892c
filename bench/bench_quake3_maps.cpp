// Reads Quake 3 maps and reports their sizes, the time of each step and the format facts checked on them
// (docs/theory.md, "Quake 3 maps"; docs/performance.md, "Quake 3 maps").
// Usage: bench_quake3_maps [--samples N] [--seed S] [SOURCE ...]
//   SOURCE: a .bsp, a .pk3 (all its maps) or ARCHIVE.pk3:MEMBER; default: every .pk3 under
//   /usr/share/games/openarena (Debian's openarena-data).
// Per map: clusters, world leaves, solid (cluster -1) leaves, brushes (all / world / solid), visdata bytes,
// read time, exact leaf volumes time, brush polytopes time, triangles of both occluder sets, and checks:
//   vol  = the world leaves' exact volumes sum to the world box's (the tree partitions the box);
//   bnd  = cluster leaves not on the world box's boundary whose exact volume leaves the compiler's integer
//          leaf bounds widened by 2 (q3map2 rounds its own double-precision cells to integers, and ours
//          differ from those by ~1e-4 as the planes are float32; expected 0, a wrong front/back convention
//          breaks it; q3map2's bounds of leaves on the world box are smaller than their cells: not compared);
//   edge = cluster leaves touching the world box's boundary (0 for a map whose outside was filled as solid);
//   self = clusters not visible from themselves in the visdata (expected 0);
//   brush centres: for each world brush, whether the leaf containing its polytope's vertex centroid (an
//          interior point) is solid (cluster -1), by kind: solid (no detail bit), solid detail, non-solid
//          (also by shader);
//   samples: N random points of the world box (fixed seed), by (leaf is solid?) x (inside a solid brush?).
// The last lines total the facts over all maps.
#include "bench/bench_util.hpp"
#include "io/load_scene.hpp"
#include "io/quake3_bsp.hpp"
#include "io/quake3_geometry.hpp"

#include <CGAL/number_utils.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace exactvis;
using namespace exactvis::quake3;

namespace {

struct Bounds {
  double lo[3], hi[3];
};
Bounds bounds_of(const region::ConvexPolyhedron3& p) {
  Bounds b{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
  for (const auto& v : p.vertices)
    for (int k = 0; k < 3; ++k) {
      const auto [lo, hi] = enclosing_interval(v[k]);
      b.lo[k] = std::min(b.lo[k], lo);
      b.hi[k] = std::max(b.hi[k], hi);
    }
  return b;
}

// "pak1-maps.pk3:oa_dm1.bsp" for ".../pak1-maps.pk3:maps/oa_dm1.bsp", the file name for a plain .bsp.
std::string label(const std::string& source) {
  const std::size_t colon = source.rfind(".pk3:");
  if (colon == std::string::npos) return source.substr(source.rfind('/') + 1);
  const std::string archive = source.substr(0, colon + 4), member = source.substr(colon + 5);
  return archive.substr(archive.rfind('/') + 1) + ":" + member.substr(member.rfind('/') + 1);
}

struct Totals {
  int maps = 0, failed = 0, detail_shader_maps = 0, maps_without_vis = 0;
  long detail_shaders = 0, world_brushes = 0, solid_brushes = 0, detail_solid_brushes = 0;
  long vol_bad = 0, bnd_bad = 0, self_bad = 0, edge_leaves = 0;
  std::map<std::string, std::array<long, 2>> centre;  // kind -> {in cluster -1, in a cluster}
  std::map<std::string, std::array<long, 2>> nonsolid;  // non-solid shader -> {centres in cluster -1, in a cluster}
  long leaky_maps = 0, preorder_bad = 0, nonworld_leaves = 0, nonworld_leaf_not_cluster0 = 0;
  long solid_vertices = 0, solid_vertices_not_double = 0;
  long samples[2][2] = {{0, 0}, {0, 0}};               // [leaf solid][in solid brush]
};

void report(const std::string& source, int n_samples, std::uint64_t seed, Totals& tot) {
  const double t0 = bench::now();
  const BspMap map = read_bsp(source);
  const double t_read = bench::now() - t0;

  const double t1 = bench::now();
  const std::vector<region::ConvexPolyhedron3> leaves = leaf_volumes(map);
  const double t_leaves = bench::now() - t1;

  const BspModel& world = map.models[0];
  const std::vector<std::int32_t> solid = solid_world_brushes(map);
  std::vector<region::ConvexPolyhedron3> brush(map.brushes.size());
  const double t2 = bench::now();
  for (std::int32_t b = world.first_brush; b < world.first_brush + world.n_brushes; ++b)
    brush[b] = brush_polyhedron(map, b);
  const double t_brushes = bench::now() - t2;

  // Exact checks.
  const WorldBox box = world_box(map);
  const Exact box_volume = (box.hi.x - box.lo.x) * (box.hi.y - box.lo.y) * (box.hi.z - box.lo.z);
  Exact sum(0);
  int world_leaves = 0, solid_leaves = 0, empty_leaves = 0, bnd = 0, edge = 0;
  long leaf_tris = 0, brush_tris = 0;
  for (std::size_t i = 0; i < map.leaves.size(); ++i) {
    if (!map.world_leaf[i]) continue;
    ++world_leaves;
    const BspLeaf& l = map.leaves[i];
    if (l.cluster < 0) ++solid_leaves;
    if (leaves[i].empty()) {
      ++empty_leaves;
      continue;
    }
    sum += region::volume(leaves[i]);
    if (l.cluster < 0) leaf_tris += region::boundary_triangles(leaves[i]).size();
    bool out = false, touches = false;
    for (const auto& v : leaves[i].vertices)
      for (int k = 0; k < 3; ++k) {
        out |= v[k] < Exact(l.mins[k] - 2) || v[k] > Exact(l.maxs[k] + 2);
        touches |= v[k] == box.lo[k] || v[k] == box.hi[k];
      }
    if (l.cluster >= 0 && !touches) bnd += out;
    if (l.cluster >= 0 && touches) ++edge;
  }
  const bool vol_ok = sum == box_volume;
  for (std::size_t n = 0; n < map.nodes.size(); ++n)
    for (std::int32_t c : map.nodes[n].children) tot.preorder_bad += c >= 0 && c <= static_cast<std::int32_t>(n);
  for (std::size_t i = 0; i < map.leaves.size(); ++i)
    if (!map.world_leaf[i]) ++tot.nonworld_leaves, tot.nonworld_leaf_not_cluster0 += map.leaves[i].cluster != 0;
  for (std::size_t i = 0; i < map.leaves.size(); ++i)
    if (map.world_leaf[i] && map.leaves[i].cluster < 0)
      for (const auto& v : leaves[i].vertices) {
        double d;
        ++tot.solid_vertices;
        tot.solid_vertices_not_double += !(exact_double(v.x, &d) && exact_double(v.y, &d) && exact_double(v.z, &d));
      }
  tot.leaky_maps += edge > 0;
  int self_bad = 0;
  for (int c = 0; c < map.cluster_count(); ++c) self_bad += !map.cluster_visible(c, c);

  int detail_shaders = 0;
  for (const auto& s : map.shaders) detail_shaders += (s.content_flags & kContentsDetail) != 0;
  int detail_solid = 0;
  for (std::int32_t b : solid) detail_solid += (map.shaders[map.brushes[b].shader].content_flags & kContentsDetail) != 0;

  // Brush centres.
  for (std::int32_t b = world.first_brush; b < world.first_brush + world.n_brushes; ++b) {
    if (brush[b].empty()) continue;
    RationalPoint3 c{Exact(0), Exact(0), Exact(0)};
    for (const auto& v : brush[b].vertices) c = c + v;
    const Exact k(static_cast<int>(brush[b].vertices.size()));
    c = {c.x / k, c.y / k, c.z / k};
    const BspShader& sh = map.shaders[map.brushes[b].shader];
    const bool is_solid = sh.content_flags & kContentsSolid;
    const std::string kind = !is_solid ? "non-solid" : (sh.content_flags & kContentsDetail) ? "solid detail" : "solid, no detail";
    const bool in_solid_space = map.leaves[leaf_containing(map, c)].cluster < 0;
    tot.centre[kind][in_solid_space ? 0 : 1]++;
    if (!is_solid) tot.nonsolid[sh.name + " (contents " + std::to_string(sh.content_flags) + ")"][in_solid_space ? 0 : 1]++;
  }

  // Samples.
  std::vector<Bounds> brush_bounds(map.brushes.size());
  for (std::int32_t b : solid) brush_bounds[b] = bounds_of(brush[b]);
  std::mt19937_64 rng(seed);
  long samples[2][2] = {{0, 0}, {0, 0}};
  for (int s = 0; s < n_samples; ++s) {
    RationalPoint3 p;
    double d[3];
    for (int k = 0; k < 3; ++k) {
      // A random rational of the box: lo + (hi - lo) * u, u = m / 2^20.
      const Exact u(static_cast<double>(rng() >> 44) / 1048576.0);
      p[k] = box.lo[k] + (box.hi[k] - box.lo[k]) * u;
      d[k] = CGAL::to_double(p[k]);
    }
    const bool leaf_solid = map.leaves[leaf_containing(map, p)].cluster < 0;
    bool in_brush = false;
    for (std::int32_t b : solid) {
      const Bounds& bb = brush_bounds[b];
      if (brush[b].empty() || d[0] < bb.lo[0] || d[0] > bb.hi[0] || d[1] < bb.lo[1] || d[1] > bb.hi[1] ||
          d[2] < bb.lo[2] || d[2] > bb.hi[2])
        continue;
      if (region::locate(brush[b], p) != region::Containment::Outside) {
        in_brush = true;
        break;
      }
    }
    samples[leaf_solid][in_brush]++;
  }
  for (std::int32_t b : solid) brush_tris += region::boundary_triangles(brush[b]).size();

  std::printf("%-44s %6d %6d %6d %6d %6zu %6d %6zu %9zu %7.3f %8.3f %8.3f %8ld %8ld  vol=%s bnd=%d self=%d "
              "edge=%d empty=%d detail_shaders=%d detail_solid=%d  samples(solid leaf: %ld in/%ld out of solid "
              "brushes; cluster leaf: %ld in/%ld out)\n",
              label(source).c_str(), map.cluster_count(), world_leaves, solid_leaves,
              static_cast<int>(map.brushes.size()), static_cast<std::size_t>(world.n_brushes),
              static_cast<int>(solid.size()), map.faces.size(), map.vis.bits.size() + (map.vis.n_vecs ? 8 : 0),
              t_read, t_leaves, t_brushes, leaf_tris, brush_tris, vol_ok ? "ok" : "BAD", bnd, self_bad, edge,
              empty_leaves, detail_shaders, detail_solid, samples[1][1], samples[1][0], samples[0][1],
              samples[0][0]);
  std::fflush(stdout);
  ++tot.maps;
  tot.detail_shaders += detail_shaders;
  tot.detail_shader_maps += detail_shaders > 0;
  tot.maps_without_vis += map.vis.n_vecs == 0;
  tot.world_brushes += world.n_brushes;
  tot.solid_brushes += solid.size();
  tot.detail_solid_brushes += detail_solid;
  tot.vol_bad += !vol_ok;
  tot.bnd_bad += bnd;
  tot.self_bad += self_bad;
  tot.edge_leaves += edge;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) tot.samples[a][b] += samples[a][b];
}

}  // namespace

int main(int argc, char** argv) {
  int n_samples = 2000;
  std::uint64_t seed = 1;
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--samples" && i + 1 < argc) n_samples = std::stoi(argv[++i]);
    else if (a == "--seed" && i + 1 < argc) seed = std::stoull(argv[++i]);
    else inputs.push_back(a);
  }
  if (inputs.empty()) {
    const std::filesystem::path root = "/usr/share/games/openarena";
    std::error_code ec;
    for (const auto& e : std::filesystem::recursive_directory_iterator(root, ec))
      if (e.path().extension() == ".pk3") inputs.push_back(e.path().string());
    std::sort(inputs.begin(), inputs.end());
    if (inputs.empty()) {
      std::fprintf(stderr, "bench_quake3_maps: no maps given and none under %s (apt-get install openarena-data)\n",
                   root.c_str());
      return 1;
    }
  }
  std::printf("%-44s %6s %6s %6s %6s %6s %6s %6s %9s %7s %8s %8s %8s %8s\n", "map", "clust", "leaves", "solidL",
              "brush", "worldB", "solidB", "faces", "vis B", "read s", "leaves s", "brush s", "leaf tri",
              "brush tri");
  Totals tot;
  const double t0 = bench::now();
  for (const std::string& input : inputs) {
    std::vector<std::string> sources;
    try {
      sources = bsp_sources(input);
    } catch (const InputError& e) {
      if (std::string(e.what()).find("holds no map") == std::string::npos) std::printf("%s\n", e.what());
      continue;
    }
    for (const std::string& s : sources) {
      try {
        report(s, n_samples, seed, tot);
      } catch (const InputError& e) {
        std::printf("%s\n", e.what());
        ++tot.failed;
      }
    }
  }
  std::printf("\n%d maps read (%d failed) in %.1f s; %d without visdata\n", tot.maps, tot.failed,
              bench::now() - t0, tot.maps_without_vis);
  std::printf("leaf volumes sum to the world box: %s (%ld maps not); cluster leaves off the box outside their integer bounds: %ld; "
              "clusters not self-visible: %ld; cluster leaves on the world box: %ld\n",
              tot.vol_bad ? "NO" : "all maps", tot.vol_bad, tot.bnd_bad, tot.self_bad, tot.edge_leaves);
  std::printf("shaders with the detail bit: %ld in %d maps; world brushes %ld, solid %ld, solid with the detail bit "
              "%ld\n",
              tot.detail_shaders, tot.detail_shader_maps, tot.world_brushes, tot.solid_brushes,
              tot.detail_solid_brushes);
  for (const auto& [kind, n] : tot.centre)
    std::printf("brush centres, %-16s: %ld in solid space (cluster -1), %ld in a cluster\n", kind.c_str(), n[0], n[1]);
  std::printf("non-solid brushes (by shader) with some centre in solid space: in solid space / in a cluster\n");
  for (const auto& [name, n] : tot.nonsolid)
    if (n[0] > 0) std::printf("  %5ld / %5ld  %s\n", n[0], n[1], name.c_str());
  std::printf("maps with cluster leaves on the world box (leaked): %ld; node children not after their parent: %ld; "
              "leaves outside the world tree: %ld (%ld of them not cluster 0)\n",
              tot.leaky_maps, tot.preorder_bad, tot.nonworld_leaves, tot.nonworld_leaf_not_cluster0);
  std::printf("corners of the solid leaves: %ld, not exactly doubles: %ld\n", tot.solid_vertices,
              tot.solid_vertices_not_double);
  std::printf("samples: solid leaf & in a solid brush %ld, solid leaf & in none %ld, cluster leaf & in a solid "
              "brush %ld, cluster leaf & in none %ld\n",
              tot.samples[1][1], tot.samples[1][0], tot.samples[0][1], tot.samples[0][0]);
  return 0;
}
