// Scene I/O and spatial index throughput on generated scenes of growing size.
// Usage: bench_scene_io [max_triangles=1000000] [kind=town]
// For N = 10^3 .. max (x10): generate, write OBJ, load it back (OpenMesh + exact re-read), build the AABB
// tree, and run 10 000 small box queries and 10 000 segment queries. Prints a table with times, rates and the
// growth factor of each step from the previous row (linear growth = 10x per row).
#include "io/load_scene.hpp"
#include "io/write_mesh.hpp"
#include "kernel/scene_generators.hpp"
#include "kernel/triangle_index.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

using namespace exactvis;

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv) {
  const std::int64_t max_n = argc > 1 ? std::stoll(argv[1]) : 1000000;
  const std::string kind = argc > 2 ? argv[2] : "town";
  const std::string path = (std::filesystem::temp_directory_path() / ("bench_scene_io_" + kind + ".obj")).string();
  std::printf("%-9s %9s %9s %9s %9s %12s %12s %12s\n", "triangles", "gen s", "write s", "load s", "tree s",
              "box q/s", "segment q/s", "cand/segment");
  double prev[4] = {0, 0, 0, 0};
  for (std::int64_t n = 1000; n <= max_n; n *= 10) {
    auto t0 = std::chrono::steady_clock::now();
    const Scene g = generate_scene(kind, n, 1);
    const double gen = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    write_scene_mesh(path, g);
    const double write = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    const Scene s = load_scene(path);
    const double load = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    const TriangleIndex index(s);
    const double tree = seconds_since(t0);
    const Box3 all = bounding_box(s);
    std::mt19937_64 rng(1);
    auto coord = [&](int k) {
      const double u = static_cast<double>(rng() >> 11) / 9007199254740992.0;
      return all.lo[k] + u * (all.hi[k] - all.lo[k]);
    };
    const int queries = 10000;
    std::size_t found = 0;
    t0 = std::chrono::steady_clock::now();
    for (int q = 0; q < queries; ++q) {
      Box3 b;
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = coord(k);
        b.hi[k] = b.lo[k] + 1.0;
      }
      found += index.candidates_in_box(b).size();
    }
    const double box_rate = queries / seconds_since(t0);
    std::size_t candidates = 0;
    t0 = std::chrono::steady_clock::now();
    for (int q = 0; q < queries; ++q) {
      const Point3 a{coord(0), coord(1), coord(2)}, b{coord(0), coord(1), coord(2)};
      candidates += index.triangles_meeting_segment(a, b).size();
    }
    const double seg_rate = queries / seconds_since(t0);
    std::printf("%-9lld %9.3f %9.3f %9.3f %9.3f %12.0f %12.0f %12.1f\n", static_cast<long long>(n), gen, write, load,
                tree, box_rate, seg_rate, static_cast<double>(candidates) / queries);
    if (prev[0] > 0)
      std::printf("%-9s %8.1fx %8.1fx %8.1fx %8.1fx\n", "  growth", gen / prev[0], write / prev[1], load / prev[2],
                  tree / prev[3]);
    prev[0] = gen, prev[1] = write, prev[2] = load, prev[3] = tree;
    (void)found;
  }
  std::filesystem::remove(path);
  return 0;
}
