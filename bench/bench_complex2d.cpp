// bench_complex2d: 2D visibility complex construction time vs n and vs k, and visibility-polygon queries
// per second (our exact angular sweep, the walk in the stored complex, CGAL's
// Triangular_expansion_visibility_2) on the same scenes.
// Usage: bench_complex2d [--max-n N] [--max-old N] [--queries Q] (--max-old: largest n for the per-vertex
// sweep). Prints tables (docs/performance.md).
#include "bench/bench_scenes_2d.hpp"
#include "bench/bench_util.hpp"
#include "skeleton/complex_walk_2d.hpp"
#include "skeleton/visibility_complex_2d.hpp"
#include "skeleton/visibility_polygon_2d.hpp"

#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arr_walk_along_line_point_location.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangular_expansion_visibility_2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

using namespace exactvis;
using namespace exactvis::bench;

namespace {


template <class K>
double cgal_tev_queries_per_second(const Scene2D& framed, const std::vector<Point2>& qs, double* build_seconds) {
  using Traits = CGAL::Arr_segment_traits_2<K>;
  using Arr = CGAL::Arrangement_2<Traits>;
  std::vector<typename Traits::Segment_2> segs;
  for (int v = 0; v < framed.num_vertices(); ++v)
    segs.emplace_back(typename K::Point_2(framed.points[v].ax, framed.points[v].ay),
                      typename K::Point_2(framed.points[framed.next[v]].ax, framed.points[framed.next[v]].ay));
  const double t0 = now();
  Arr arr;
  CGAL::insert(arr, segs.begin(), segs.end());
  CGAL::Triangular_expansion_visibility_2<Arr, CGAL::Tag_true> tev(arr);
  CGAL::Arr_naive_point_location<Arr> locator(arr);
  // locate once (not timed as part of the visibility query, like TriVis which locates separately)
  std::vector<typename Arr::Face_const_handle> faces;
  for (const Point2& q : qs) {
    const auto obj = locator.locate(typename K::Point_2(q.ax, q.ay));
    faces.push_back(*boost::get<typename Arr::Face_const_handle>(&obj));
  }
  const double t1 = now();
  std::size_t sink = 0;
  for (std::size_t i = 0; i < qs.size(); ++i) {
    Arr out;
    tev.compute_visibility(typename K::Point_2(qs[i].ax, qs[i].ay), faces[i], out);
    sink += out.number_of_vertices();
  }
  const double t2 = now();
  *build_seconds = t1 - t0;
  if (sink == 0) std::printf("(empty)\n");
  return qs.size() / (t2 - t1);
}

}  // namespace

int main(int argc, char** argv) {
  int max_n = 4096, max_old = 4096, queries = 200;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--max-n")) max_n = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--max-old")) max_old = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--queries")) queries = std::atoi(argv[i + 1]);
  }
  // Visible pairs by either method (the complex's vertices are the bitangents among them).
  auto time_graph = [](const Scene2D& s, VisibilityGraphMethod m, std::size_t* pairs, std::size_t* bitangents) {
    const double t0 = now();
    const auto g = visibility_graph(s, nullptr, m);
    const double t = now() - t0;
    *pairs = g.strict_pairs.size();
    *bitangents = g.bitangents.size();
    return t;
  };
  std::printf("# 1. construction vs n at fixed density (8-gons; grid: open space; row: a corridor of polygons)\n");
  std::printf("#    old = one angular sweep per vertex (2 threads), new = one rotational sweep (2 threads: half-turns)\n");
  std::printf("%6s %7s %9s %8s %10s %10s %8s %12s %12s %11s\n", "layout", "n", "pairs K", "k", "old s", "new s",
              "old/new", "new us/(K+n)", "old s/n^2lgn", "complex s");
  for (const char* layout : {"grid", "row"}) {
    for (int polygons = 16; polygons * 8 <= max_n; polygons *= 2) {
      const Scene2D s = make_scene(layout, polygons, 8, polygons);
      std::size_t pairs = 0, k = 0, pairs2 = 0, k2 = 0;
      const double n = s.num_vertices();
      const bool run_old = polygons * 8 <= max_old;
      const double told = run_old ? time_graph(s, VisibilityGraphMethod::PerVertexSweep, &pairs2, &k2) : 0;
      const double tnew = time_graph(s, VisibilityGraphMethod::RotationalSweep, &pairs, &k);
      if (run_old && (pairs != pairs2 || k != k2)) std::printf("MISMATCH old/new\n");
      const double t0 = now();
      const auto cx = visibility_complex(s);
      const double tcx = now() - t0;
      std::printf("%6s %7d %9zu %8zu %10.3f %10.3f %8.1f %12.2f %12.3e %11.3f\n", layout, s.num_vertices(), pairs, k,
                  told, tnew, run_old ? told / tnew : 0.0, 1e6 * tnew / (pairs + n),
                  told / (n * n * std::log2(n)), tcx);
      std::fflush(stdout);
    }
  }
  std::printf("\n# 2. construction vs k at fixed n (256 8-gons, n = 2048): corridor (row) / grid / ring\n");
  std::printf("%8s %8s %9s %8s %10s %10s %8s %12s\n", "layout", "n", "pairs K", "k", "old s", "new s", "old/new",
              "new us/(K+n)");
  for (const char* layout : {"row", "grid", "ring"}) {
    const Scene2D s = make_scene(layout, 256, 8, 7);
    std::size_t pairs = 0, k = 0, pairs2 = 0, k2 = 0;
    const bool run_old = s.num_vertices() <= max_old;
    const double told = run_old ? time_graph(s, VisibilityGraphMethod::PerVertexSweep, &pairs2, &k2) : 0;
    const double tnew = time_graph(s, VisibilityGraphMethod::RotationalSweep, &pairs, &k);
    if (run_old && (pairs != pairs2 || k != k2)) std::printf("MISMATCH old/new\n");
    std::printf("%8s %8d %9zu %8zu %10.3f %10.3f %8.1f %12.2f\n", layout, s.num_vertices(), pairs, k, told, tnew,
                run_old ? told / tnew : 0.0, 1e6 * tnew / (pairs + s.num_vertices()));
    std::fflush(stdout);
  }
  std::printf("\n# 3. visibility polygon queries per second (grid layout, %d random free points)\n", queries);
  std::printf("#    single = one angular sweep per point; batch = visibility_polygons (one rotational sweep for\n"
              "#    all points) on the same points, and on 10x as many points; walk = visibility_polygon_in_complex\n"
              "#    (walk in the stored complex, one point at a time; walk10x = visibility_polygons_in_complex on the 10x\n"
              "#    points, all cores; the one-time cost is in the last columns: complex s = visibility_complex,\n"
              "#    index s = complex_walk_index; events/q, cand/q = mean hit-edge changes and candidate pivots tested)\n");
  std::printf("%8s %12s %12s %14s %12s %14s %16s %12s %12s %14s %8s %10s %10s %9s %9s\n", "n", "single q/s",
              "batch q/s", "batch10x q/s", "walk q/s", "walk10x q/s", "CGAL TEV q/s", "us/q single", "us/q walk",
              "us/q CGAL TEV", "ratio", "complex s", "index s", "events/q", "cand/q");
  for (int n : {1024, 2048, 4096, 8192}) {
    if (n > 2 * max_n) break;
    const Scene2D scene = make_scene("grid", n / 8, 8, n);
    const Scene2D framed = with_frame(scene, 0.05);
    std::mt19937_64 rng(5);
    const Ring2D& fr = framed.rings[framed.frame_ring];
    const Point2 &lo = framed.points[fr.first], &hi = framed.points[fr.first + 2];
    std::uniform_real_distribution<double> ux(lo.ax, hi.ax), uy(lo.ay, hi.ay);
    std::vector<Point2> qs, qs10;
    while (static_cast<int>(qs10.size()) < 10 * queries) {
      const Point2 q(ux(rng), uy(rng));
      if (!on_boundary(framed, q) && !inside_obstacle(framed, q)) qs10.push_back(q);
    }
    qs.assign(qs10.begin(), qs10.begin() + queries);
    const double t0 = now();
    std::size_t sink = 0;
    for (const Point2& q : qs) sink += visibility_polygon(framed, q).vertices.size();
    const double ours = qs.size() / (now() - t0);
    const double tb0 = now();
    sink += visibility_polygons(framed, qs).size();
    const double batch = qs.size() / (now() - tb0);
    const double tb1 = now();
    sink += visibility_polygons(framed, qs10).size();
    const double batch10 = qs10.size() / (now() - tb1);
    // the walk: complex and index built once (timed apart), then the queries alone
    const double tc0 = now();
    const VisibilityComplex2D complex = visibility_complex(scene);
    const double tc1 = now();
    const ComplexWalkIndex2D index = complex_walk_index(scene, complex);
    const double tc2 = now();
    ComplexWalkStats2D total;
    for (const Point2& q : qs) {
      ComplexWalkStats2D st;
      sink += visibility_polygon_in_complex(index, framed, q, &st).vertices.size();
      total.events += st.events, total.faces += st.faces, total.candidates += st.candidates;
    }
    const double walk = qs.size() / (now() - tc2);
    const double tw0 = now();
    sink += visibility_polygons_in_complex(index, framed, qs10).size();
    const double walk10 = qs10.size() / (now() - tw0);
    for (std::size_t i = 0; i < std::min<std::size_t>(qs.size(), 20); ++i)  // not timed: same output as the sweep
      if (visibility_polygon_in_complex(index, framed, qs[i]).vertices != visibility_polygon(framed, qs[i]).vertices)
        std::printf("MISMATCH walk/sweep at query %zu\n", i);
    double b1 = 0, b2 = 0;
    const double epeck = cgal_tev_queries_per_second<CGAL::Exact_predicates_exact_constructions_kernel>(framed, qs, &b2);
    std::fflush(stdout);
    // (CGAL TEV with Exact_predicates_inexact_constructions_kernel throws Bad_object_cast on these scenes,
    //  so the comparison uses the exact-constructions kernel, like our exact output.)
    (void)b1;
    std::printf("%8d %12.1f %12.1f %14.1f %12.1f %14.1f %16.1f %12.1f %12.1f %14.1f %8.2f %10.3f %10.3f %9.1f %9.1f\n",
                framed.num_vertices(), ours, batch, batch10, walk, walk10, epeck, 1e6 / ours, 1e6 / walk, 1e6 / epeck,
                epeck / ours, tc1 - tc0, tc2 - tc1, double(total.events) / qs.size(),
                double(total.candidates) / qs.size());
    std::fflush(stdout);
    if (sink == 0) std::printf("(empty)\n");
  }
  return 0;
}
