// bench_segments2d: segment-to-segment visibility answered from the visibility complex
// (segment_visibility_in_complex) vs. the O(n^4) cell sampling without the complex (segment_visibility),
// on grid scenes of convex 8-gons that scale. Reports the time per query, the walks per query and the
// share of visible pairs; the two methods' answers are compared on every query where both run.
// Usage: bench_segments2d [--max-n N] [--max-ref N] [--pairs P]
#include "bench/bench_scenes_2d.hpp"
#include "bench/bench_util.hpp"
#include "skeleton/complex_segment_visibility_2d.hpp"
#include "skeleton/segment_visibility_2d.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

using namespace exactvis;
using namespace exactvis::bench;

int main(int argc, char** argv) {
  int max_n = 2048, max_ref = 256, pairs = 40;
  bench::require_option_pairs(argc, argv, 1, "bench_segments2d");
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--max-n")) max_n = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--max-ref")) max_ref = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--pairs")) pairs = std::atoi(argv[i + 1]);
    else return bench::unknown_option("bench_segments2d", std::string(argv[i]));
  }
  std::printf("# segment-to-segment visibility, %d random pairs of short segments (length ~1.6) per scene\n", pairs);
  std::printf("# complex = segment_visibility_in_complex (index built once, time below excludes it); ref = O(n^4)\n");
  std::printf("%7s %9s %9s %10s %12s %12s %12s %10s %8s\n", "n", "pairs K", "visible", "index s", "complex ms/q",
              "walks/q", "lines/q", "ref ms/q", "ref/cx");
  for (int polygons = 4; polygons * 8 <= max_n; polygons *= 4) {
    const Scene2D s = make_scene("grid", polygons, 8, polygons);
    const double ti = now();
    const VisibilityComplex2D cx = visibility_complex(s);
    const ComplexWalkIndex2D ix = complex_walk_index(s, cx);
    const double t_index = now() - ti;
    const int m = static_cast<int>(std::ceil(std::sqrt(polygons)));
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-4, 10.0 * m);
    std::vector<std::array<Point2, 4>> qs;
    while (static_cast<int>(qs.size()) < pairs) {
      const double ax = u(rng), ay = u(rng), bx = u(rng), by = u(rng);
      const std::array<Point2, 4> q{Point2(ax, ay), Point2(ax + 1.5, ay + 0.5), Point2(bx, by), Point2(bx + 0.5, by - 1.5)};
      if (!open_segment_free(s, q[0], q[1]) || !open_segment_free(s, q[2], q[3]) || inside_obstacle(s, q[0]) ||
          inside_obstacle(s, q[2]))
        continue;
      qs.push_back(q);
    }
    int visible = 0;
    std::size_t walks = 0, gaps = 0;
    std::vector<bool> answers;
    const double t0 = now();
    for (const auto& q : qs) {
      ComplexSegmentStats2D st;
      const bool v = segment_visibility_in_complex(ix, q[0], q[1], q[2], q[3], &st).visible;
      visible += v;
      answers.push_back(v);
      walks += st.walks;
      gaps += st.breakpoints;
    }
    const double t_cx = (now() - t0) / qs.size();
    double t_ref = 0;
    const bool run_ref = s.num_vertices() <= max_ref;
    if (run_ref) {
      const double r0 = now();
      for (std::size_t i = 0; i < qs.size(); ++i)
        if (segment_visibility(s, qs[i][0], qs[i][1], qs[i][2], qs[i][3]).visible != answers[i])
          std::printf("MISMATCH at pair %zu\n", i);
      t_ref = (now() - r0) / qs.size();
    }
    std::printf("%7d %9zu %9d %10.3f %12.3f %12.1f %12.1f %10.3f %8.1f\n", s.num_vertices(),
                cx.graph.strict_pairs.size(), visible, t_index, 1e3 * t_cx, double(walks) / qs.size(),
                double(gaps) / qs.size(), run_ref ? 1e3 * t_ref : 0.0, run_ref ? t_ref / t_cx : 0.0);
    std::fflush(stdout);
  }
  return 0;
}
