#include "region/exterior_visibility.hpp"

#include "kernel/ray_blocker.hpp"
#include "region/cell_visibility.hpp"
#include "region/from_region_visibility.hpp"

#include <glm/geometric.hpp>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace exactvis::region {
namespace {

glm::vec3 to_float(const RationalPoint3& p) {
  return {static_cast<float>(CGAL::to_double(p.x)), static_cast<float>(CGAL::to_double(p.y)),
          static_cast<float>(CGAL::to_double(p.z))};
}

constexpr int kFirstRound = 32;  // proposals before the enclosure test

// A random direction with double components (exact as rationals): uniform on the sphere up to rounding
// (rejection from the cube), never zero.
Vec3<Exact> random_direction(std::mt19937_64& rng) {
  for (;;) {
    double c[3];
    double r2 = 0;
    for (double& x : c) {
      x = std::ldexp(static_cast<double>(rng() >> 11), -52) - 1.0;  // [-1, 1), multiples of 2^-52
      r2 += x * x;
    }
    if (r2 > 1.0 || r2 < 1e-6) continue;
    return {Exact(c[0]), Exact(c[1]), Exact(c[2])};
  }
}

// The nearest double to x below (down = true) or above it.
double widen(double x, double by, bool down) {
  const double y = down ? x - by : x + by;
  if (down ? y < x : y > x) return y;
  return std::nextafter(x, down ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity());
}

}  // namespace

RationalBox3 exterior_enclosing_box(const Scene& scene) {
  if (scene.triangles.empty()) throw std::invalid_argument("exterior visibility needs at least one triangle");
  const Box3 b = bounding_box(scene);
  double extent = 0;
  for (int k = 0; k < 3; ++k) extent = std::max(extent, b.hi[k] - b.lo[k]);
  // A power of two near extent / 16 (1 for a scene of zero extent, which has no triangles anyway).
  const double margin = extent > 0 && std::isfinite(extent) ? std::ldexp(1.0, std::ilogb(extent) - 4) : 1.0;
  Box3 out;
  for (int k = 0; k < 3; ++k) {
    out.lo[k] = widen(b.lo[k], margin, true);
    out.hi[k] = widen(b.hi[k], margin, false);
  }
  return exact_box(out);
}

ExteriorClassifier::ExteriorClassifier(const Scene& scene, const TriangleIndex& index, const FloatRayCaster* caster,
                                       const ExteriorOptions& options)
    : scene_(scene),
      index_(index),
      caster_(caster),
      options_(options),
      scene_box_(bounding_box(scene)),
      box_(exterior_enclosing_box(scene)),
      finder_(index_candidates(index)) {
  if (options_.use_enclosure) shells_.emplace(scene);
}

ExteriorTriangle ExteriorClassifier::classify(std::int64_t t, VisibilityStats* stats, ExteriorCounts* counts) const {
  ExteriorTriangle out;
  const auto tri = triangle_points(scene_, t);
  const Polygon3 poly{tri[0], tri[1], tri[2]};
  auto accept = [&](const ExteriorWitness& w, ExteriorStage stage) {
    out.visible = true;
    out.stage = stage;
    out.witness = options_.round_witness ? round_exterior_witness(scene_, index_, scene_box_, t, w) : w;
    return out;
  };

  // Stage 1: Embree proposals, each re-checked exactly (a valid witness proves positive measure by itself):
  // a first round of kFirstRound rays, the rest after the enclosure test (for triangles in deep pockets).
  std::mt19937_64 rng(mix_seed(options_.seed, static_cast<std::uint64_t>(t)));
  const Vec3<Exact> n = cross(tri[1] - tri[0], tri[2] - tri[0]);
  const RationalPoint3 c = centroid(poly);
  const std::int64_t ignore[1] = {t};
  auto propose = [&](int from, int to) -> std::optional<ExteriorWitness> {
    if (caster_ == nullptr) return std::nullopt;
    for (int k = from; k < to; ++k) {
      ExteriorWitness w;
      if (k < 2) {
        w.q = c;
        w.d = k == 0 ? n : Vec3<Exact>{-n.x, -n.y, -n.z};
      } else {
        w.q = random_interior_point(poly, rng);
        w.d = random_direction(rng);
      }
      // Proposals in doubles where possible, so that an accepted witness needs no rounding (one exact check).
      const RationalPoint3 qd = round_to_doubles(w.q);
      if (!(qd == w.q) && in_triangle_relative_interior(qd, tri)) w.q = qd;
      const Vec3<Exact> dd = round_to_doubles(w.d);
      if (CGAL::sign(dd.x) != 0 || CGAL::sign(dd.y) != 0 || CGAL::sign(dd.z) != 0) w.d = dd;
      const glm::vec3 o = to_float(w.q), d = to_float(w.d);
      if (!(glm::dot(d, d) > 0) || !std::isfinite(glm::dot(d, d))) continue;
      if (counts) ++counts->proposals_cast;
      if (caster_->occluded(o, d, 0.0f, std::numeric_limits<float>::infinity(), ignore)) continue;
      if (counts) ++counts->proposals_checked;
      if (check_exterior_witness(scene_, index_, scene_box_, t, w) == ExteriorWitnessCheck::Valid) return w;
      if (counts) ++counts->proposals_rejected;
    }
    return std::nullopt;
  };
  const int first_round = std::min(options_.rays, kFirstRound);
  if (auto w = propose(0, first_round)) return accept(*w, ExteriorStage::Proposal);

  // Stage 2: a closed shell around T (every ray from T meets it).
  if (shells_) {
    if (auto proof = enclosing_shell(scene_, index_, scene_box_, *shells_, t)) {
      out.visible = false;
      out.stage = ExteriorStage::Enclosure;
      out.enclosure = std::move(*proof);
      return out;
    }
  }

  // Stage 2b: the sides of T its own closed shell blocks (Lemma 5.6.5).
  std::optional<OwnShellSides> sides;
  if (shells_) sides = own_shell_sides(scene_, index_, scene_box_, *shells_, t);
  if (sides && sides->blocked[0] && sides->blocked[1]) {
    out.visible = false;
    out.stage = ExteriorStage::Enclosure;
    out.sides = std::move(*sides);
    return out;
  }

  if (auto w = propose(first_round, options_.rays)) return accept(*w, ExteriorStage::Proposal);

  // Stage 3 (Theorem 5.6.1): T is exterior visible iff it is visible from some face of the enclosing box;
  // when one side of T is blocked, from the parts of the faces on the other side.
  std::optional<Plane3> open_side;
  if (sides && (sides->blocked[0] || sides->blocked[1])) {
    const Plane3 plane = plane_through(tri[0], tri[1], tri[2]);
    open_side = sides->blocked[0] ? plane.flipped() : plane;
  }
  for (int axis = 0; axis < 3; ++axis)
    for (const bool high : {false, true}) {
      Polygon3 source = box_face(box_, axis, high);
      if (open_side) {
        source = clip_polygon(source, *open_side);
        // Consecutive repeats (a vertex on the plane) are dropped; a part of zero area sees nothing.
        Polygon3 clean;
        for (const RationalPoint3& p : source)
          if (clean.empty() || !(clean.back() == p)) clean.push_back(p);
        while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
        if (is_degenerate(clean)) continue;
        source = std::move(clean);
      }
      const VisibilityResult r = visible_from_polygon(scene_, finder_, source, t, options_.query);
      if (stats) accumulate(*stats, r.stats);
      if (!r.visible) continue;
      const ExteriorWitness w = witness_from_segment(r.witness->p, r.witness->q);
      const ExteriorWitnessCheck check = check_exterior_witness(scene_, index_, scene_box_, t, w);
      // The query proved positive measure; its witness is an escaping ray (conditions 1, 2, 4). Condition 3
      // (robustness by itself) holds for almost every free segment and is not needed here.
      if (check != ExteriorWitnessCheck::Valid && check != ExteriorWitnessCheck::OnOtherTriangle)
        throw std::logic_error("exterior visibility: a from-region witness is not an escaping ray (triangle index " +
                               std::to_string(t) + ")");
      if (check == ExteriorWitnessCheck::Valid) return accept(w, ExteriorStage::QueryVisible);
      out.visible = true;
      out.stage = ExteriorStage::QueryVisible;
      out.witness = w;
      return out;
    }
  out.visible = false;
  out.stage = ExteriorStage::QueryHidden;
  return out;
}

ExteriorVisibility exterior_visibility(const Scene& scene, const TriangleIndex& index, const FloatRayCaster* caster,
                                       const ExteriorOptions& options) {
  check_thread_count(options.threads);
  const ExteriorClassifier classifier(scene, index, caster, options);
  ExteriorVisibility out;
  out.enclosing_box = classifier.enclosing_box();
  out.triangles.resize(scene.triangles.size());
  tbb::enumerable_thread_specific<ExteriorCounts> counts;
  tbb::enumerable_thread_specific<VisibilityStats> stats;
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t(0), scene.triangles.size(), [&](std::size_t i) {
      out.triangles[i] = classifier.classify(static_cast<std::int64_t>(i), &stats.local(), &counts.local());
      if (options.on_triangle_done) options.on_triangle_done();
    });
  });
  for (const ExteriorCounts& c : counts) {
    out.counts.proposals_cast += c.proposals_cast;
    out.counts.proposals_checked += c.proposals_checked;
    out.counts.proposals_rejected += c.proposals_rejected;
  }
  for (const VisibilityStats& s : stats) accumulate(out.query_stats, s);
  for (const ExteriorTriangle& r : out.triangles) {
    (r.visible ? out.counts.visible : out.counts.hidden) += 1;
    switch (r.stage) {
      case ExteriorStage::Proposal: ++out.counts.by_proposal; break;
      case ExteriorStage::Enclosure: ++out.counts.by_enclosure; break;
      case ExteriorStage::QueryVisible: ++out.counts.by_query_visible; break;
      case ExteriorStage::QueryHidden: ++out.counts.by_query_hidden; break;
    }
  }
  return out;
}

}  // namespace exactvis::region
