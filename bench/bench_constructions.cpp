// Cost of the exact constructions and of the segment-triangle tests per call, on random inputs (doubles
// uniform in [-1, 1]) and on adversarial ones (small-integer coordinates: many coplanar / meeting cases).
// Prints a table (see docs/performance.md, "Constructions").
//
// Usage: bench_constructions [N]   (N calls per row, default 20000)
#include "kernel/line_plane_intersection.hpp"
#include "kernel/line_through_point_meeting_two_lines.hpp"
#include "kernel/lines_through_four_lines.hpp"
#include "kernel/segment_triangle_intersection.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace exactvis;

namespace {

std::vector<Point3> points(int n, bool small_int, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> k(-3, 3);
  std::vector<Point3> v;
  for (int i = 0; i < n; ++i)
    v.push_back(small_int ? Point3{double(k(rng)), double(k(rng)), double(k(rng))} : Point3{u(rng), u(rng), u(rng)});
  return v;
}

template <class F>
double time_per_call_us(int n, F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  long sink = 0;
  for (int i = 0; i < n; ++i) sink += f(i);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (sink == -1) std::puts("");  // keep the results alive
  return s / n * 1e6;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 20000;
  if (argc > 1) {
    char* end = nullptr;
    const long v = std::strtol(argv[1], &end, 10);
    if (*end != '\0' || v <= 0 || v > 10000000) {
      std::fprintf(stderr, "bench_constructions: error: N must be a positive integer (got '%s')\n", argv[1]);
      return 2;
    }
    n = static_cast<int>(v);
  }
  std::printf("N = %d calls per row; microseconds per call\n\n%-40s %12s %14s\n", n, "operation", "random",
              "small-int");
  for (int row = 0; row < 5; ++row) {
    double us[2];
    for (int mode = 0; mode < 2; ++mode) {
      const auto p = points(8 * n + 8, mode == 1, 100 + row);
      std::vector<PluckerLine<Exact>> lines;
      for (int i = 0; i + 1 < 8 * n + 8; i += 2)
        lines.push_back(exact_line_through(p[i], p[i + 1] == p[i] ? Point3{p[i].x + 1, p[i].y, p[i].z} : p[i + 1]));
      switch (row) {
        case 0:
          us[mode] = time_per_call_us(n, [&](int i) {
            const auto r = lines_through_four_lines({lines[4 * i], lines[4 * i + 1], lines[4 * i + 2], lines[4 * i + 3]});
            return static_cast<long>(r.lines.size());
          });
          break;
        case 1:
          us[mode] = time_per_call_us(n, [&](int i) {
            return static_cast<long>(line_through_point_meeting_two_lines(p[3 * i], lines[2 * i], lines[2 * i + 1]).kind);
          });
          break;
        case 2:
          us[mode] = time_per_call_us(n, [&](int i) {
            return static_cast<long>(line_plane_intersection(p[5 * i], p[5 * i + 1], p[5 * i + 2], p[5 * i + 3], p[5 * i + 4]).kind);
          });
          break;
        case 3:
          us[mode] = time_per_call_us(n, [&](int i) {
            return static_cast<long>(
                segment_meets_closed_triangle(p[5 * i], p[5 * i + 1], p[5 * i + 2], p[5 * i + 3], p[5 * i + 4]));
          });
          break;
        default:
          us[mode] = time_per_call_us(n, [&](int i) {
            return static_cast<long>(
                open_segment_meets_closed_triangle(p[5 * i], p[5 * i + 1], p[5 * i + 2], p[5 * i + 3], p[5 * i + 4]));
          });
      }
    }
    static const char* names[] = {"lines_through_four_lines", "line_through_point_meeting_two_lines",
                                  "line_plane_intersection (points)", "segment_meets_closed_triangle",
                                  "open_segment_meets_closed_triangle"};
    std::printf("%-40s %12.3f %14.3f\n", names[row], us[0], us[1]);
  }
  return 0;
}
