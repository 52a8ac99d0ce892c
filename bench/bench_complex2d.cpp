// bench_complex2d: 2D visibility complex construction time vs n and vs k, and visibility-polygon queries
// per second (our exact angular sweep, the walk in the stored complex, CGAL's
// Triangular_expansion_visibility_2) on the same scenes.
// Usage: bench_complex2d [--max-n N] [--max-old N] [--queries Q] [--rounds R] [--sections 1,2,3]
// (--max-old: largest n for the per-vertex sweep; --rounds: interleaved timing rounds of the walk and CGAL's
// TEV in section 3). Prints tables (docs/performance.md).
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
#include <memory>
#include <random>
#include <string>

using namespace exactvis;
using namespace exactvis::bench;

namespace {


// CGAL's exact triangular expansion (Epeck) on the framed scene, with every query point located once
// (not timed as part of the visibility query, like TriVis which locates separately).
struct CgalTev {
  using K = CGAL::Exact_predicates_exact_constructions_kernel;
  using Traits = CGAL::Arr_segment_traits_2<K>;
  using Arr = CGAL::Arrangement_2<Traits>;
  Arr arr;
  std::unique_ptr<CGAL::Triangular_expansion_visibility_2<Arr, CGAL::Tag_true>> tev;
  std::vector<typename Arr::Face_const_handle> faces;
  std::vector<K::Point_2> points;
  double build_seconds = 0;

  CgalTev(const Scene2D& framed, const std::vector<Point2>& qs) {
    std::vector<typename Traits::Segment_2> segs;
    for (int v = 0; v < framed.num_vertices(); ++v)
      segs.emplace_back(K::Point_2(framed.points[v].ax, framed.points[v].ay),
                        K::Point_2(framed.points[framed.next[v]].ax, framed.points[framed.next[v]].ay));
    const double t0 = now();
    CGAL::insert(arr, segs.begin(), segs.end());
    tev = std::make_unique<CGAL::Triangular_expansion_visibility_2<Arr, CGAL::Tag_true>>(arr);
    CGAL::Arr_naive_point_location<Arr> locator(arr);
    for (const Point2& q : qs) {
      points.emplace_back(q.ax, q.ay);
      const auto obj = locator.locate(points.back());
      faces.push_back(*boost::get<typename Arr::Face_const_handle>(&obj));
    }
    build_seconds = now() - t0;
  }
  // All queries once: seconds; *vertices receives the total output size.
  double round(std::size_t* vertices) {
    const double t0 = now();
    std::size_t sink = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      Arr out;
      tev->compute_visibility(points[i], faces[i], out);
      sink += out.number_of_vertices();
    }
    *vertices = sink;
    return now() - t0;
  }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int max_n = 4096, max_old = 4096, queries = 200, rounds = 5;
  std::string sections = "1,2,3";
  bench::require_option_pairs(argc, argv, 1, "bench_complex2d");
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--max-n")) max_n = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--max-old")) max_old = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--queries")) queries = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--rounds")) rounds = std::max(1, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--sections")) sections = argv[i + 1];
    else return bench::unknown_option("bench_complex2d", std::string(argv[i]));
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
  const auto wanted = split(sections);
  auto section = [&](const char* k) { return std::find(wanted.begin(), wanted.end(), k) != wanted.end(); };
  if (section("1")) {
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
  }
  if (section("2")) {
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
  }
  if (section("3")) {
    std::printf("\n# 3. visibility polygon queries per second (grid layout, %d random free points)\n", queries);
    std::printf("#    single = one angular sweep per point; batch = visibility_polygons (one rotational sweep for\n"
                "#    all points) on the same points, and on 10x as many points; walk = visibility_polygon_in_complex\n"
                "#    (walk in the stored complex, one point at a time; walk10x = visibility_polygons_in_complex on the 10x\n"
                "#    points, all cores); CGAL TEV = Triangular_expansion_visibility_2 (Epeck) on the same points. walk and\n"
                "#    CGAL TEV: median of %d interleaved rounds over all points (us/q min..max of the rounds in the last\n"
                "#    columns); one-time costs: complex s = visibility_complex, index s = complex_walk_index, CGAL s =\n"
                "#    arrangement + TEV + point location; events/q = mean hit-edge changes, cand/q = candidates of the\n"
              "#    faces visited, tested/q = those tested exactly, the others outside the swept triangles' boxes)\n",
                rounds);
    std::printf("%8s %11s %11s %13s %10s %12s %12s %10s %10s %10s %11s %17s %17s %9s %9s %8s %9s %9s %9s\n", "n",
                "single q/s", "batch q/s", "batch10x q/s", "walk q/s", "walk10x q/s", "CGAL q/s", "us/q walk",
                "us/q CGAL", "walk/CGAL", "us/q single", "walk us/q rounds", "CGAL us/q rounds", "complex s",
                "index s", "CGAL s", "events/q", "cand/q", "tested/q");
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
      CgalTev cgal(framed, qs);
      ComplexWalkStats2D total;
      std::size_t walk_vertices = 0, cgal_vertices = 0;
      for (const Point2& q : qs) {  // counters and output size (not timed)
        ComplexWalkStats2D st;
        walk_vertices += visibility_polygon_in_complex(index, framed, q, &st).vertices.size();
        total.events += st.events, total.faces += st.faces, total.candidates += st.candidates;
        total.candidates_tested += st.candidates_tested;
      }
      std::vector<double> walk_rounds, cgal_rounds;
      for (int r = 0; r < rounds; ++r) {
        for (int k = 0; k < 2; ++k) {
          if ((r + k) % 2 == 0) {
            const double tw = now();
            std::size_t v = 0;
            for (const Point2& q : qs) v += visibility_polygon_in_complex(index, framed, q).vertices.size();
            walk_rounds.push_back(now() - tw);
            if (v != walk_vertices) std::printf("MISMATCH walk rounds\n");
          } else {
            cgal_rounds.push_back(cgal.round(&cgal_vertices));
          }
        }
      }
      const double tw0 = now();
      sink += visibility_polygons_in_complex(index, framed, qs10).size();
      const double walk10 = qs10.size() / (now() - tw0);
      for (std::size_t i = 0; i < std::min<std::size_t>(qs.size(), 20); ++i)  // not timed: same output as the sweep
        if (visibility_polygon_in_complex(index, framed, qs[i]).vertices != visibility_polygon(framed, qs[i]).vertices)
          std::printf("MISMATCH walk/sweep at query %zu\n", i);
      // (CGAL TEV with Exact_predicates_inexact_constructions_kernel throws Bad_object_cast on these scenes,
      //  so the comparison uses the exact-constructions kernel, like our exact output.)
      const double wq = 1e6 * median(walk_rounds) / qs.size(), cq = 1e6 * median(cgal_rounds) / qs.size();
      auto range = [&](const std::vector<double>& v) {
        char b[64];
        std::snprintf(b, sizeof b, "%.0f..%.0f", 1e6 * *std::min_element(v.begin(), v.end()) / qs.size(),
                      1e6 * *std::max_element(v.begin(), v.end()) / qs.size());
        return std::string(b);
      };
      std::printf("%8d %11.1f %11.1f %13.1f %10.1f %12.1f %12.1f %10.1f %10.1f %10.2f %11.1f %17s %17s %9.3f %9.3f "
                  "%8.3f %9.1f %9.1f %9.1f\n",
                  framed.num_vertices(), ours, batch, batch10, 1e6 / wq, walk10, 1e6 / cq, wq, cq, wq / cq, 1e6 / ours,
                  range(walk_rounds).c_str(), range(cgal_rounds).c_str(), tc1 - tc0, tc2 - tc1, cgal.build_seconds,
                  double(total.events) / qs.size(), double(total.candidates) / qs.size(),
                  double(total.candidates_tested) / qs.size());
      std::fflush(stdout);
      if (sink == 0 || cgal_vertices == 0) std::printf("(empty)\n");
    }
  }
  return 0;
}
