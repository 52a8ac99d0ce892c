// Benchmark of the 3D visibility skeleton: node and arc counts and build time vs scene size on random
// polytope scenes (k disjoint tetrahedra, as Zhang et al. measure k convex polytopes with n edges in
// total) and on generated towns; growth exponents between rows; per-node cost; the lazy build of one pair
// against the full build of the same scene (ratio measured in the same run). docs/performance.md
// "bench_skeleton" has the figures and the command.
//
// Usage: bench_skeleton [--polytopes 4,8,16,32] [--towns 100,200] [--seed 1]
// An empty list ("--towns ''") skips that table.
#include "bench/bench_util.hpp"
#include "events/scene_adjacency.hpp"
#include "kernel/predicates.hpp"
#include "kernel/scene_generators.hpp"
#include "skeleton/skeleton_pair.hpp"
#include "skeleton/visibility_skeleton_3d.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace exactvis;

namespace {

// k disjoint random tetrahedra, one per cell of a jittered cubic grid (cell side 8, corners multiples of
// 1/64 inside the cell with a margin), each its own object: closed meshes with shared edges.
Scene polytope_scene(int k, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto coord = [&](int cell) { return cell * 8.0 + 1.0 + static_cast<double>(rng() % (6 * 64)) / 64.0; };
  int side = 1;
  while (side * side * side < k) ++side;
  Scene s;
  for (int i = 0; i < k; ++i) {
    const int cx = i % side, cy = (i / side) % side, cz = i / (side * side);
    std::array<Point3, 4> p;
    do {
      for (auto& q : p) q = {coord(cx), coord(cy), coord(cz)};
    } while (orient3d(p[0], p[1], p[2], p[3]) == Sign::Zero);
    const int b = static_cast<int>(s.vertices.size());
    for (const auto& q : p) s.vertices.push_back(q);
    s.objects.push_back({"tet" + std::to_string(i)});
    const int f[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}};
    for (const auto& t : f) s.triangles.push_back({s.faces_read++, {b + t[0], b + t[1], b + t[2]}, i});
  }
  return s;
}

struct Row {
  std::size_t tris = 0, edges = 0, nodes = 0, degenerate = 0, ev_arcs = 0, eee_arcs = 0;
  double events_s = 0, nodes_s = 0, total_s = 0, cpu_s = 0;
};

Row run(const Scene& s) {
  Row r;
  r.tris = s.triangles.size();
  r.edges = build_scene_adjacency(s).edges.size();
  const double t0 = bench::now();
  const std::clock_t c0 = std::clock();
  const Skeleton3D sk = build_skeleton_3d(s);
  r.total_s = bench::now() - t0;
  r.cpu_s = double(std::clock() - c0) / CLOCKS_PER_SEC;
  for (const auto& n : sk.nodes) (n.valid ? r.nodes : r.degenerate) += 1;
  for (const auto& a : sk.arcs) (a.kind == SkeletonArcKind::EV ? r.ev_arcs : r.eee_arcs) += 1;
  r.events_s = sk.stats.seconds_events;
  r.nodes_s = sk.stats.seconds_nodes;
  return r;
}

void header(const char* title) {
  std::printf("\n%s\n%-10s %6s %6s %7s %6s %7s %7s %9s %9s %9s %9s %10s %7s\n", title, "scene", "tris", "edges",
              "nodes", "degen", "EVarcs", "EEEarcs", "events.s", "nodes.s", "total.s", "cpu.s", "us/node", "growth");
}

void print(const std::string& name, const Row& r, const Row* prev) {
  const double per_node = r.nodes + r.degenerate > 0 ? 1e6 * r.total_s / double(r.nodes + r.degenerate) : 0;
  std::printf("%-10s %6zu %6zu %7zu %6zu %7zu %7zu %9.3f %9.3f %9.3f %9.3f %10.1f ", name.c_str(), r.tris, r.edges,
              r.nodes, r.degenerate, r.ev_arcs, r.eee_arcs, r.events_s, r.nodes_s, r.total_s, r.cpu_s, per_node);
  if (prev && prev->total_s > 0 && r.tris > prev->tris)
    std::printf("%7.2f\n", std::log(r.total_s / prev->total_s) / std::log(double(r.tris) / double(prev->tris)));
  else
    std::printf("%7s\n", "-");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> polytopes{"4", "8", "16", "32"}, towns{"100", "200"};
  std::uint64_t seed = 1;
  bench::require_option_pairs(argc, argv, 1, "bench_skeleton");
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    if (a == "--polytopes") polytopes = bench::split(v);
    else if (a == "--towns") towns = bench::split(v);
    else if (a == "--seed") seed = std::stoull(v);
    else return bench::unknown_option("bench_skeleton", a);
  }
  header("full skeleton, k random tetrahedra (growth: exponent of time vs triangles since the previous row)");
  Row prev;
  bool have_prev = false;
  Scene largest;
  double largest_full = 0;
  for (const auto& k : polytopes) {
    const Scene s = polytope_scene(std::stoi(k), seed);
    const Row r = run(s);
    print("tets" + k, r, have_prev ? &prev : nullptr);
    prev = r, have_prev = true;
    largest = s, largest_full = r.total_s;
  }
  header("full skeleton, generated towns");
  have_prev = false;
  for (const auto& n : towns) {
    const Scene s = generate_scene("town", std::stoll(n), seed);
    const Row r = run(s);
    print("town" + n, r, have_prev ? &prev : nullptr);
    prev = r, have_prev = true;
  }
  if (largest.objects.size() >= 3) {
    // Lazy pair: tetrahedron 0 and the one in the opposite corner of the bottom grid layer (the others of
    // that layer between them), against the full build of the same scene (same run).
    int side = 1;
    while (side * side * side < static_cast<int>(largest.objects.size())) ++side;
    const int far = std::min(static_cast<int>(largest.objects.size()) - 1, side * side - 1);
    const double t0 = bench::now();
    const Skeleton3D pair = build_pair_skeleton(largest, {0, -1}, {far, -1});
    const double t = bench::now() - t0;
    const auto blockers = pair_blockers(largest, pair, pair_slice(largest, pair, {0, -1}, {far, -1}), {0, -1}, {far, -1});
    std::printf("\nlazy pair (tet0, tet%d) of the largest polytope scene (%zu triangles): %.4f s, %zu nodes, %zu arcs, "
                "%zu blockers; full build %.3f s; ratio lazy/full %.4f\n",
                far, largest.triangles.size(), t, pair.nodes.size(), pair.arcs.size(), blockers.size(), largest_full,
                t / largest_full);
  }
  return 0;
}
