// Discontinuity meshing growth (docs/performance.md "shadows"): generated scenes of growing size with one
// square area light under the ceiling (room) or above the centre (town); per size the light-restricted event
// enumeration (the baseline, measured in the same run), the per-receiver work (curves, triangulation, one
// exact backprojection per face, optionally per mesh vertex), counts and growth exponents.
//
// Usage: bench_shadows [--kind room|town] [--sizes 250,500,1000] [--seed 1] [--vertex-irradiance]
//                      [--threads N (0: all cores)] [--no-shaft] [--no-cull] [--polyline]
// --polyline: every receiver with a conic arc takes the certified polyline arrangement first
// (ShadowOptions::polyline_first; a cross-check of CGAL's conic arrangement: compare the face counts).
// --no-shaft / --no-cull: without the per-receiver shaft restriction / the blocker-blocker EV cull (the
// baselines; same output). cpu_s: process CPU seconds (user + system, all threads), the growth exponent's
// figure; shaft%: shaft candidates kept of those in the receiver-light boxes.
#include "bench/bench_util.hpp"
#include "events/light_source.hpp"
#include "kernel/scene_generators.hpp"
#include "shadows/shadow_mesh.hpp"

#include <sys/resource.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

namespace {
// User + system CPU seconds of the process (all threads): the figure to compare on a shared machine.
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}
}  // namespace

int main(int argc, char** argv) {
  std::string kind = "room", sizes = "250,500,1000,2000";
  std::uint64_t seed = 1;
  bool vertex_irradiance = false, shaft = true, cull = true, polyline = false;
  int threads = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--kind" && i + 1 < argc) kind = argv[++i];
    else if (a == "--sizes" && i + 1 < argc) sizes = argv[++i];
    else if (a == "--seed" && i + 1 < argc) seed = std::stoull(argv[++i]);
    else if (a == "--threads" && i + 1 < argc) threads = std::stoi(argv[++i]);
    else if (a == "--vertex-irradiance") vertex_irradiance = true;
    else if (a == "--no-shaft") shaft = false;
    else if (a == "--no-cull") cull = false;
    else if (a == "--polyline") polyline = true;
    else {
      std::fprintf(stderr, "usage: bench_shadows [--kind room|town] [--sizes a,b,c] [--seed S] [--vertex-irradiance] [--threads N] [--no-shaft] [--no-cull] [--polyline]\n");
      return 2;
    }
  }
  std::unique_ptr<tbb::global_control> gc;
  if (threads > 0) gc = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  std::printf("kind %s, seed %llu, vertex irradiance %s, shaft %s, blocker EV cull %s\n", kind.c_str(),
              static_cast<unsigned long long>(seed), vertex_irradiance ? "yes" : "no", shaft ? "on" : "off",
              cull ? "on" : "off");
  std::printf("%8s %9s %7s %6s %7s %5s %6s %7s %5s %5s %5s %6s %6s %6s %8s %8s %9s %8s %8s %6s %7s\n", "tris", "receivers",
              "EVcurv", "BBcurv", "EEEcurv", "D0", "faces", "umbra", "arcs", "poly", "fail", "ev_s", "bb_s", "eee_s",
              "events_s", "recv_s", "ms/recv", "recv/ev", "cpu_s", "shaft%", "growth");
  double prev_n = 0, prev_t = 0;
  for (const auto& item : exactvis::bench::split(sizes)) {
    const long n = std::stol(item);
    exactvis::Scene scene = exactvis::generate_scene(kind, n, seed);
    const exactvis::Box3 b = exactvis::bounding_box(scene);
    const double cx = (b.lo.x + b.hi.x) / 2, cy = (b.lo.y + b.hi.y) / 2;
    const double sx = (b.hi.x - b.lo.x) * 0.05, sy = (b.hi.y - b.lo.y) * 0.05;
    const double z = kind == "room" ? b.hi.z - 0.02 * (b.hi.z - b.lo.z) : b.hi.z + 0.5 * (b.hi.z - b.lo.z);
    const exactvis::LightSource light = exactvis::append_light_polygon(
        scene, {{cx - sx, cy - sy, z}, {cx + sx, cy - sy, z}, {cx + sx, cy + sy, z}, {cx - sx, cy + sy, z}});
    exactvis::shadows::ShadowOptions opt;
    opt.light = light.triangles;
    opt.vertex_irradiance = vertex_irradiance;
    opt.shaft_restriction = shaft;
    opt.blocker_cull = cull;
    opt.polyline_first = polyline;
    const double c0 = cpu_seconds();
    const auto res = exactvis::shadows::compute_shadows(scene, opt);
    const double cpu = cpu_seconds() - c0;
    std::uint64_t ev = 0, bb = 0, eee = 0, d0 = 0, faces = 0, umbra = 0;
    for (const auto& r : res.receivers) {
      for (const auto& c : r.curves) {
        if (c.order == 0) ++d0;
        else if (c.kind == exactvis::shadows::DiscontinuityCurve::Kind::EV) ++(c.blocker_blocker ? bb : ev);
        else ++eee;
      }
      for (const auto& f : r.faces) {
        ++faces;
        umbra += f.light_class == exactvis::shadows::LightClass::Umbra;
      }
    }
    const double growth = prev_n > 0 ? std::log(cpu / prev_t) / std::log(n / prev_n) : 0;
    std::printf("%8ld %9zu %7llu %6llu %7llu %5llu %6llu %7llu %5llu %5llu %5llu %6.2f %6.2f %6.2f %8.2f %8.2f %9.2f %8.2f %8.2f %6.1f %7s\n",
                n, res.receivers.size(), (unsigned long long)ev, (unsigned long long)bb, (unsigned long long)eee,
                (unsigned long long)d0, (unsigned long long)faces, (unsigned long long)umbra,
                (unsigned long long)res.stats.conic_arcs, (unsigned long long)res.stats.polyline_arrangements,
                (unsigned long long)res.stats.arrangement_failures,
                res.stats.seconds_ev - res.stats.seconds_blocker_ev, res.stats.seconds_blocker_ev, res.stats.seconds_eee,
                res.stats.seconds_events, res.stats.seconds_receivers,
                1000 * res.stats.seconds_receivers / std::max<std::size_t>(1, res.receivers.size()),
                res.stats.seconds_receivers / std::max(1e-9, res.stats.seconds_events), cpu,
                100.0 * res.stats.shaft_candidates / std::max<std::uint64_t>(1, res.stats.shaft_box_candidates),
                prev_n > 0 ? std::to_string(growth).substr(0, 4).c_str() : "-");
    if (polyline)
      std::printf("  polyline first: %llu receivers also built by CGAL's conic traits, %llu with another face count\n",
                  (unsigned long long)res.stats.cross_checked, (unsigned long long)res.stats.cross_mismatches);
    std::fflush(stdout);
    prev_n = static_cast<double>(n);
    prev_t = cpu;
  }
  return 0;
}
