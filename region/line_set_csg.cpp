#include "region/line_set_csg.hpp"

#include "kernel/segment_triangle_intersection.hpp"
#include "region/back_face_culling.hpp"
#include "region/occluder_shaft.hpp"
#include "region/polyhedral_cone6.hpp"
#include "region/real_line_test.hpp"

#include <algorithm>
#include <functional>
#include <random>
#include <stdexcept>

namespace exactvis::region {
namespace {

struct Piece {
  PolyhedralCone6 cone;
  RealLineTest test;
  std::size_t next = 0;  // first occluder not yet subtracted
};

class PairQuery {
 public:
  // occluders: the pair's shaft occluders; is_free: the exact re-check of a candidate witness segment
  // against every occluder; stream: varies the random sequence per target.
  PairQuery(std::vector<ShaftOccluder> occluders,
            std::function<bool(const RationalPoint3&, const RationalPoint3&)> is_free, std::uint64_t stream,
            const StabbingPair& pair, const VisibilityOptions& options, VisibilityStats& stats)
      : is_free_(std::move(is_free)), pair_(pair), options_(options), stats_(stats),
        rng_(options.seed * 0x9E3779B97F4A7C15ull + stream), occluders_(std::move(occluders)) {}

  std::optional<Witness> run() {
    stats_.occluders_considered += static_cast<std::int64_t>(occluders_.size());
    if (auto w = sample()) {
      stats_.accepted_by_sampling = true;
      return w;
    }
    std::stable_sort(occluders_.begin(), occluders_.end(),
                     [](const ShaftOccluder& x, const ShaftOccluder& y) { return x.blocked_samples > y.blocked_samples; });
    effective_.assign(occluders_.size(), false);

    std::optional<PolyhedralCone6> k0 = whole_space_cone();
    for (const auto& e : pair_.edge_lines) {
      k0 = intersect_open_halfspace(*k0, side_functional(e));
      if (!k0) return std::nullopt;
    }
    Piece first{*k0, test(*k0), 0};
    if (!first.test.has_real_lines) return std::nullopt;
    std::vector<Piece> stack{std::move(first)};
    while (!stack.empty()) {
      // The budget is checked between occluders: the overshoot is at most one occluder's splits.
      if (options_.split_budget > 0 && stats_.splits >= options_.split_budget) {
        gave_up_ = true;
        return std::nullopt;
      }
      stats_.cones_alive_max = std::max<std::int64_t>(stats_.cones_alive_max, static_cast<std::int64_t>(stack.size()));
      Piece piece = std::move(stack.back());
      stack.pop_back();
      std::size_t j = piece.next;
      while (j < occluders_.size() && !touches(piece.cone, occluders_[j])) ++j;
      if (j == occluders_.size()) {
        if (auto w = witness_from(piece)) return w;
        throw std::logic_error("from-region query: a cone with real lines yielded no free witness segment");
      }
      if (!effective_[j]) {
        effective_[j] = true;
        ++stats_.effective_occluders;
      }
      std::vector<Piece> outside;
      split(std::move(piece.cone), std::move(piece.test), occluders_[j], 0, false, false, outside);
      for (auto& p : outside) {
        p.next = j + 1;
        stack.push_back(std::move(p));
      }
    }
    return std::nullopt;
  }

 private:
  RealLineTest test(const PolyhedralCone6& cone) {
    ++stats_.real_line_tests;
    RealLineTest t = test_real_lines(cone);
    stats_.face_tests += t.faces_examined;
    return t;
  }

  // Could some line of the cone meet the occluder (all edge sides >= 0, or all <= 0)?
  bool touches(const PolyhedralCone6& cone, const ShaftOccluder& occ) const {
    bool plus = true, minus = true;
    for (std::size_t k = 0; k < occ.edges.size(); ++k) {
      const HalfspaceRelation r = relation_to_halfspace(cone, occ.edges[k]);
      if (r == HalfspaceRelation::Outside) plus = false;
      if (r == HalfspaceRelation::Inside) minus = false;
      if (!plus && !minus) return false;
    }
    return true;
  }

  // Pieces of cone minus the occluder's line set: lines that pass the edges with mixed signs.
  // cone and t are taken by value and moved along: a surviving piece is never copied.
  void split(PolyhedralCone6 cone, RealLineTest t, const ShaftOccluder& occ, std::size_t k, bool pos,
             bool neg, std::vector<Piece>& out) {
    if (pos && neg) {
      out.push_back(Piece{std::move(cone), std::move(t), 0});
      return;
    }
    if (k == occ.edges.size()) return;  // every edge passed on one side: the lines hit the occluder
    const ConeVector6& w = occ.edges[k];
    // The ray signs once: they give the relation and, when w crosses the cone through its rays, both parts
    // (split_crossing: the same cones as intersecting with w and with -w, for about half the work).
    const HyperplaneSigns signs = hyperplane_signs(cone, w);
    const HalfspaceRelation r = signs.relation;
    if (r == HalfspaceRelation::Inside) return split(std::move(cone), std::move(t), occ, k + 1, true, neg, out);
    if (r == HalfspaceRelation::Outside) return split(std::move(cone), std::move(t), occ, k + 1, pos, true, out);
    if (!signs.by_lineality) {
      std::array<PolyhedralCone6, 2> parts = split_crossing(cone, w, signs);
      for (int side = 0; side < 2; ++side) {
        ++stats_.splits;
        ++stats_.cones_created;
        RealLineTest pt = test(parts[side]);
        if (!pt.has_real_lines) continue;
        split(std::move(parts[side]), std::move(pt), occ, k + 1, pos || side == 0, neg || side == 1, out);
      }
      return;
    }
    for (int s : {+1, -1}) {
      ++stats_.splits;
      auto part = intersect_open_halfspace(cone, s > 0 ? w : w.negated());
      if (!part) continue;
      ++stats_.cones_created;
      RealLineTest pt = test(*part);
      if (!pt.has_real_lines) continue;
      split(std::move(*part), std::move(pt), occ, k + 1, pos || s > 0, neg || s < 0, out);
    }
  }

  std::optional<Witness> witness_from(const Piece& piece) {
    for (int attempt = 0; attempt < 64; ++attempt) {
      auto cand = line_in_cone(piece.cone, piece.test, pair_, rng_);
      if (!cand) continue;
      // Free of every subtracted occluder by construction; re-check against all candidates, which also
      // covers the measure-zero blockers the CSG may ignore (docs/theory.md §5.4).
      if (is_free_(cand->p, cand->q)) return Witness{cand->p, cand->q};
    }
    return std::nullopt;
  }

  // Does the open segment (p, q) meet the occluder (its triangle, or its panel or pair as a fan of triangles)? Double geometry: it only orders the occluders.
  static bool blocks(const ShaftOccluder& occ, const Point3& p, const Point3& q) {
    if (occ.panel_loop) {
      const std::vector<Point3>& l = *occ.panel_loop;
      for (std::size_t i = 1; i + 1 < l.size(); ++i)
        if (open_segment_meets_closed_triangle(p, q, l[0], l[i], l[i + 1])) return true;
      return false;
    }
    return open_segment_meets_closed_triangle(p, q, occ.corners_d[0], occ.corners_d[1], occ.corners_d[2]);
  }

  // Sample segments are cast with double endpoints (the counts only order the occluders); a sample that
  // looks free is redone with its exact rational endpoints and accepted only after the exact check.
  std::optional<Witness> sample() {
    const auto src = approximate_polygon(pair_.source), dst = approximate_polygon(pair_.target);
    for (int s = 0; s < options_.samples; ++s) {
      ++stats_.samples_cast;
      const auto ws = random_weights(src.size(), rng_), wt = random_weights(dst.size(), rng_);
      const Point3 p = weighted_point_approx(src, ws), q = weighted_point_approx(dst, wt);
      bool free = true;
      for (auto& occ : occluders_)
        if (blocks(occ, p, q)) {
          ++occ.blocked_samples;
          free = false;
        }
      if (!free) continue;
      const RationalPoint3 pe = weighted_point(pair_.source, ws), qe = weighted_point(pair_.target, wt);
      if (is_free_(pe, qe)) return Witness{pe, qe};
    }
    return std::nullopt;
  }

  std::function<bool(const RationalPoint3&, const RationalPoint3&)> is_free_;
  const StabbingPair& pair_;
  const VisibilityOptions& options_;
  VisibilityStats& stats_;
  std::mt19937_64 rng_;
  std::vector<ShaftOccluder> occluders_;
  std::vector<bool> effective_;

 public:
  bool gave_up_ = false;  // the split budget ran out (run() returned no witness without a proof)
};

}  // namespace

PairVisibility pair_visibility(const Scene& scene, const std::vector<std::int64_t>& candidates, std::int64_t target,
                               const StabbingPair& pair, const VisibilityOptions& options) {
  PairVisibility out;
  PairQuery query(
      shaft_occluders(scene, candidates, target, pair),
      [&](const RationalPoint3& p, const RationalPoint3& q) { return segment_is_free(scene, candidates, p, q, target); },
      static_cast<std::uint64_t>(target), pair, options, out.stats);
  out.witness = query.run();
  out.gave_up = query.gave_up_;
  return out;
}

PairVisibility pair_visibility(const Scene& scene, const HierarchyCandidates& finder, const Box3& box, std::int64_t target,
                               const StabbingPair& pair, const VisibilityOptions& options) {
  PairVisibility out;
  // The re-check of a witness visits only the hierarchy near the segment (the same answer).
  auto is_free = [&](const RationalPoint3& p, const RationalPoint3& q) {
    return segment_is_free(scene, finder, box, p, q, target);
  };
  std::vector<ShaftOccluder> occluders = shaft_occluders(scene, finder, box, target, pair);
  if (finder.back_faces) finder.back_faces->drop_back_faces(occluders, finder.excluded);
  if (finder.panels) merge_coplanar_panels(occluders, *finder.panels, pair, target, finder.excluded, finder.whole_panels);
  PairQuery query(std::move(occluders), is_free, static_cast<std::uint64_t>(target), pair, options, out.stats);
  out.witness = query.run();
  out.gave_up = query.gave_up_;
  return out;
}

PairVisibility pair_visibility(const std::vector<std::array<RationalPoint3, 3>>& occluders, std::uint64_t stream,
                               const StabbingPair& pair, const VisibilityOptions& options) {
  PairVisibility out;
  PairQuery query(
      shaft_occluders(occluders, pair),
      [&](const RationalPoint3& p, const RationalPoint3& q) { return segment_is_free(occluders, p, q); }, stream,
      pair, options, out.stats);
  out.witness = query.run();
  out.gave_up = query.gave_up_;
  return out;
}

}  // namespace exactvis::region
