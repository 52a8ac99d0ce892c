// bench_aspect: the exact aspect graph of random convex polytopes (aspect/convex_aspect_graph) against the
// number of face planes m: regions, adjacencies and time, orthographic and perspective; growth exponents
// between successive sizes (log time / log m), time per region, and the ratio to the smallest size measured
// in the same run. docs/performance.md, "Aspect graphs of convex models". Non-convex models
// (aspect/orthographic_aspect_graph): two random convex polytopes side by side (each of `--pair-points`
// points), orthographic; growth against the number of triangles n. `--plane-pair-points`: the same pairs,
// perspective viewpoints on the plane z = H through both bodies (aspect/plane_aspect_graph). `--row-boxes`:
// k unit boxes in a row with gaps of 1 (outside the class of §10.5 from k = 3), orthographic through
// aspect/general_orthographic_aspect_graph (free event arcs, then an exact aspect per evaluated cell), with
// the free-arc time apart and, for k = 2, the ratio to the §10.5 method on the same model.
//
// Usage: bench_aspect [--points 8,16,32,64,128] [--perspective-points 8,16,32] [--pair-points 4,6,8,12]
//                     [--plane-pair-points 4,8] [--row-boxes 2,3,4] [--seed S] [--repeat R]
#include "aspect/convex_aspect_graph.hpp"
#include "aspect/closed_solid_fronts.hpp"
#include "aspect/convex_model.hpp"
#include "aspect/direction_event_arcs.hpp"
#include "aspect/general_orthographic_aspect_graph.hpp"
#include "aspect/orthographic_aspect_graph.hpp"
#include "aspect/plane_aspect_graph.hpp"
#include "aspect/random_convex_polytope.hpp"
#include "bench/bench_util.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <time.h>

using namespace exactvis;

namespace {

double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

struct Row {
  std::size_t triangles = 0, planes = 0, regions = 0, adjacency = 0;
  double seconds = 0, wall = 0;
};

Row measure(int points, std::uint64_t seed, ViewModel view, int repeat) {
  const Scene s = random_convex_polytope(seed, points, 1 << 20);
  Row r;
  r.triangles = s.triangles.size();
  std::vector<double> times, walls;
  for (int k = 0; k < repeat; ++k) {
    const double t0 = cpu_now(), w0 = bench::now();
    const ConvexModel m = convex_model(s);
    const AspectGraph3 g = convex_aspect_graph(s, m, view);
    times.push_back(cpu_now() - t0);
    walls.push_back(bench::now() - w0);
    r.planes = m.planes.size();
    r.regions = g.regions.size();
    r.adjacency = g.adjacency.size();
  }
  std::sort(times.begin(), times.end());
  std::sort(walls.begin(), walls.end());
  r.seconds = times[times.size() / 2];
  r.wall = walls[walls.size() / 2];
  return r;
}

void table(const char* title, const std::vector<std::string>& sizes, std::uint64_t seed, ViewModel view, int repeat) {
  std::printf("%s\n%8s %9s %7s %9s %10s %10s %10s %10s %8s %8s\n", title, "points", "triangles", "planes", "regions",
              "adjacency", "cpu_s", "wall_s", "us/region", "ratio", "growth");
  Row first, prev;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const Row r = measure(std::atoi(sizes[i].c_str()), seed, view, repeat);
    if (i == 0) first = r;
    const double growth = i == 0 ? 0 : std::log(r.seconds / prev.seconds) / std::log(double(r.planes) / prev.planes);
    std::printf("%8s %9zu %7zu %9zu %10zu %10.4f %10.4f %10.2f %8.1f %8.2f\n", sizes[i].c_str(), r.triangles,
                r.planes, r.regions, r.adjacency, r.seconds, r.wall, 1e6 * r.seconds / r.regions,
                r.seconds / first.seconds, growth);
    std::fflush(stdout);
    prev = r;
  }
}

// Two random convex polytopes (seeds seed and seed + 1), the second moved by three radii along x.
Scene polytope_pair(int points, std::uint64_t seed) {
  const int range = 1 << 20;
  Scene a = random_convex_polytope(seed, points, range);
  const Scene b = random_convex_polytope(seed + 1, points, range);
  const int off = static_cast<int>(a.vertices.size());
  for (const Point3& p : b.vertices) a.vertices.push_back({p.x + 3.0 * range, p.y + range / 3, p.z + range / 5});
  for (const auto& t : b.triangles)
    a.triangles.push_back({a.faces_read + t.id, {t.v[0] + off, t.v[1] + off, t.v[2] + off}, 0});
  a.faces_read += b.faces_read;
  return a;
}

// Pairs of `sizes` points each: the graph `build(pair, fronts)` (timed with closed_solid_fronts, median CPU and
// wall seconds) and its curves `count(pair, fronts)` (great circles or trace lines, not timed), cells, regions,
// adjacency, growth against n.
template <class Build, class Count>
void polytope_pair_table(const char* title, const char* curve_column, const std::vector<std::string>& sizes,
                         std::uint64_t seed, int repeat, Build&& build, Count&& count) {
  std::printf("%s (growth = d log time / d log n)\n%8s %9s %8s %9s %9s %10s %10s %10s %10s %8s %8s\n", title,
              "points", "triangles", curve_column, "cells", "regions", "adjacency", "cpu_s", "wall_s", "us/cell",
              "ratio", "growth");
  double first = 0, prev = 0;
  std::size_t prev_n = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const Scene s = polytope_pair(std::atoi(sizes[i].c_str()), seed);
    std::vector<double> times, walls;
    std::size_t curves = 0, cells = 0, regions = 0, adjacency = 0;
    for (int k = 0; k < repeat; ++k) {
      const double t0 = cpu_now(), w0 = bench::now();
      const ClosedSolidFronts f = closed_solid_fronts(s);
      if (!f.ok) return (void)std::printf("rejected: %s\n", f.problem.c_str());
      const AspectGraph3 g = build(s, f);
      times.push_back(cpu_now() - t0);
      walls.push_back(bench::now() - w0);
      curves = count(s, f);
      cells = g.cells[0] + g.cells[1] + g.cells[2];
      regions = g.regions.size();
      adjacency = g.adjacency.size();
    }
    std::sort(times.begin(), times.end());
    std::sort(walls.begin(), walls.end());
    const double t = times[times.size() / 2], w = walls[walls.size() / 2];
    if (i == 0) first = t;
    const std::size_t n = s.triangles.size();
    const double growth = i == 0 ? 0 : std::log(t / prev) / std::log(double(n) / prev_n);
    std::printf("%8s %9zu %8zu %9zu %9zu %10zu %10.4f %10.4f %10.2f %8.1f %8.2f\n", sizes[i].c_str(), n, curves,
                cells, regions, adjacency, t, w, 1e6 * t / cells, t / first, growth);
    std::fflush(stdout);
    prev = t;
    prev_n = n;
  }
}

void pair_table(const std::vector<std::string>& sizes, std::uint64_t seed, int repeat) {
  polytope_pair_table(
      "non-convex: two convex polytopes side by side, orthographic", "circles", sizes, seed, repeat,
      [](const Scene& s, const ClosedSolidFronts& f) {
        return orthographic_aspect_graph(s, f, nullptr, /*with_cells=*/false);
      },
      [](const Scene& s, const ClosedSolidFronts& f) { return orthographic_aspect_circles(s, f); });
}

// The pairs on the plane z = 2^17 (through both bodies: the second is raised by 2^20 / 5).
void plane_pair_table(const std::vector<std::string>& sizes, std::uint64_t seed, int repeat) {
  const Exact h(1 << 17);
  polytope_pair_table(
      "non-convex: two convex polytopes side by side, on the plane z = 131072", "lines", sizes, seed, repeat,
      [&](const Scene& s, const ClosedSolidFronts& f) {
        return plane_aspect_graph(s, f, h, nullptr, /*with_cells=*/false);
      },
      [&](const Scene& s, const ClosedSolidFronts& f) { return plane_aspect_lines(s, f, h); });
}

// k unit boxes [2i, 2i+1] x [0,1] x [0,1], 12 outward triangles each.
Scene row_of_boxes(int k) {
  std::vector<Point3> v;
  std::vector<std::array<int, 3>> t;
  for (int i = 0; i < k; ++i) {
    const int b = static_cast<int>(v.size());
    for (int c = 0; c < 8; ++c) v.push_back({double(2 * i + (c & 1)), double((c >> 1) & 1), double((c >> 2) & 1)});
    const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : q) {
      t.push_back({b + f[0], b + f[1], b + f[2]});
      t.push_back({b + f[0], b + f[2], b + f[3]});
    }
  }
  Scene s;
  s.vertices = v;
  for (std::size_t i = 0; i < t.size(); ++i) s.triangles.push_back({static_cast<std::int64_t>(i), t[i], 0});
  s.objects.push_back({"row"});
  s.faces_read = static_cast<std::int64_t>(t.size());
  return s;
}

void row_boxes_table(const std::vector<std::string>& sizes, int repeat) {
  std::printf("general orthographic (aspect/general_orthographic_aspect_graph): k boxes in a row "
              "(growth = d log time / d log n)\n%6s %9s %8s %8s %9s %9s %9s %10s %10s %10s %8s %8s\n",
              "boxes", "triangles", "ev_arcs", "circles", "cells", "evaluated", "regions", "arcs_cpu_s", "cpu_s",
              "us/cell", "ratio", "growth");
  double first = 0, prev = 0;
  std::size_t prev_n = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const Scene s = row_of_boxes(std::atoi(sizes[i].c_str()));
    std::vector<double> times, arc_times;
    GeneralOrthographicResult r;
    for (int k = 0; k < repeat; ++k) {
      const double a0 = cpu_now();
      (void)direction_event_arcs(s);
      arc_times.push_back(cpu_now() - a0);
      const double t0 = cpu_now();
      r = general_orthographic_aspect_graph(s, nullptr, /*with_cells=*/false);
      times.push_back(cpu_now() - t0);
    }
    if (!r.ok) return (void)std::printf("refused: %s\n", r.problem.c_str());
    std::sort(times.begin(), times.end());
    std::sort(arc_times.begin(), arc_times.end());
    const double t = times[times.size() / 2], ta = arc_times[arc_times.size() / 2];
    const std::size_t cells = r.graph.cells[0] + r.graph.cells[1] + r.graph.cells[2];
    if (i == 0) first = t;
    const std::size_t n = s.triangles.size();
    const double growth = i == 0 ? 0 : std::log(t / prev) / std::log(double(n) / prev_n);
    std::printf("%6s %9zu %8zu %8zu %9zu %9zu %9zu %10.3f %10.3f %10.1f %8.1f %8.2f\n", sizes[i].c_str(), n,
                r.ev_arcs, r.circles, cells, r.evaluated_cells, r.graph.regions.size(), ta, t, 1e6 * t / cells,
                t / first, growth);
    if (sizes[i] == "2") {  // the same model by the method of §10.5
      const double t0 = cpu_now();
      const ClosedSolidFronts f = closed_solid_fronts(s);
      const AspectGraph3 g = orthographic_aspect_graph(s, f, nullptr, false);
      const double tc = cpu_now() - t0;
      std::printf("       two boxes by §10.5: %zu regions in %.4f cpu s; general / §10.5 = %.0f\n", g.regions.size(), tc,
                  t / tc);
    }
    std::fflush(stdout);
    prev = t;
    prev_n = n;
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string points = "8,16,32,64,128", persp = "8,16,32", pairs = "4,6,8,12", plane_pairs, row_boxes;
  std::uint64_t seed = 1;
  int repeat = 3;
  bench::require_option_pairs(argc, argv, 1, "bench_aspect");
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--points") points = argv[i + 1];
    else if (a == "--perspective-points") persp = argv[i + 1];
    else if (a == "--pair-points") pairs = argv[i + 1];
    else if (a == "--plane-pair-points") plane_pairs = argv[i + 1];
    else if (a == "--row-boxes") row_boxes = argv[i + 1];
    else if (a == "--seed") seed = std::strtoull(argv[i + 1], nullptr, 10);
    else if (a == "--repeat") repeat = std::max(1, std::atoi(argv[i + 1]));
    else return bench::unknown_option("bench_aspect", a);
  }
  table("orthographic (regions on the viewing sphere; growth = d log time / d log planes)", bench::split(points), seed,
        ViewModel::Orthographic, repeat);
  table("perspective (regions of space outside the model)", bench::split(persp), seed, ViewModel::Perspective, repeat);
  pair_table(bench::split(pairs), seed, repeat);
  if (!plane_pairs.empty()) plane_pair_table(bench::split(plane_pairs), seed, repeat);
  if (!row_boxes.empty()) row_boxes_table(bench::split(row_boxes), repeat);
  return 0;
}
