#include "region/from_region_visibility.hpp"

#include "region/hierarchy_candidates.hpp"
#include "region/line_set_csg.hpp"
#include "region/stabbing_pair.hpp"

#include <stdexcept>

namespace exactvis::region {
namespace {

std::vector<RationalPoint3> with_triangle(const Polygon3& poly, const std::array<RationalPoint3, 3>& t) {
  std::vector<RationalPoint3> pts = poly;
  pts.insert(pts.end(), t.begin(), t.end());
  return pts;
}

}  // namespace

VisibilityResult visible_from_polygon(const Scene& scene, const CandidateFinder& candidates, const Polygon3& source,
                                      std::int64_t triangle_index, const VisibilityOptions& options) {
  VisibilityResult result;
  result.triangle_index = triangle_index;
  const auto before = exact_evaluations_total();
  const auto tri = triangle_points(scene, triangle_index);
  const Box3 box = enclosing_box(with_triangle(source, tri));
  // With a hierarchy, each pair gathers its shaft occluders through it (the same occluders, §5.2) and the
  // box's candidates are never listed.
  const HierarchyCandidates* gather = hierarchy_of(candidates);
  const std::vector<std::int64_t> cands = gather ? std::vector<std::int64_t>{} : candidates(box);
  const std::vector<StabbingPair> pairs = stabbing_pairs(source, tri);
  result.stats.stabbing_pairs = static_cast<std::int64_t>(pairs.size());
  for (const auto& pair : pairs) {
    const PairVisibility pv = gather ? pair_visibility(scene, *gather, box, triangle_index, pair, options)
                                     : pair_visibility(scene, cands, triangle_index, pair, options);
    accumulate(result.stats, pv.stats);
    if (const auto& w = pv.witness) {
      result.visible = true;
      result.witness = w;
      if (options.round_witness)
        if (auto r = round_witness(scene, candidates, [&](const RationalPoint3& p) { return in_closed_polygon(p, source); },
                                   triangle_index, *w))
          result.witness = r;
      break;
    }
  }
  result.stats.exact_evaluations = static_cast<std::int64_t>(exact_evaluations_total() - before);
  return result;
}

VisibilityResult visible_from_box(const Scene& scene, const CandidateFinder& candidates, const Box3& cell,
                                  std::int64_t triangle_index, const VisibilityOptions& options) {
  for (int k = 0; k < 3; ++k)
    if (!(cell.lo[k] < cell.hi[k])) throw std::invalid_argument("view cell must have lo < hi in every coordinate");
  return visible_from_box(scene, candidates, exact_box(cell), triangle_index, options);
}

VisibilityResult visible_from_box(const Scene& scene, const CandidateFinder& candidates, const RationalBox3& cell,
                                  std::int64_t triangle_index, const VisibilityOptions& options) {
  for (int k = 0; k < 3; ++k)
    if (!(cell.lo[k] < cell.hi[k])) throw std::invalid_argument("view cell must have lo < hi in every coordinate");
  VisibilityResult result;
  result.triangle_index = triangle_index;
  const auto before = exact_evaluations_total();
  const auto tri = triangle_points(scene, triangle_index);

  // Part of T inside the closed cell.
  Polygon3 t_in{tri[0], tri[1], tri[2]};
  for (int axis = 0; axis < 3; ++axis)
    for (bool high : {false, true}) {
      Plane3 pl;
      pl.normal = {Exact(0), Exact(0), Exact(0)};
      pl.normal[axis] = high ? Exact(-1) : Exact(1);
      pl.offset = high ? Exact(-cell.hi[axis]) : cell.lo[axis];
      t_in = clip_polygon(t_in, pl);
    }
  if (!is_degenerate(t_in)) {
    std::vector<RationalPoint3> pts{tri.begin(), tri.end()};
    pts.push_back(cell.lo);
    pts.push_back(cell.hi);
    const auto cands = candidates(enclosing_box(pts));
    if (auto w = witness_inside_cell(scene, cands, t_in, tri, cell, triangle_index, options.seed)) {
      result.visible = true;
      result.witness = w;
      if (options.round_witness)
        if (auto r = round_witness(scene, candidates, [&](const RationalPoint3& p) { return in_closed_box(p, cell); },
                                   triangle_index, *w))
          result.witness = r;
      result.stats.exact_evaluations = static_cast<std::int64_t>(exact_evaluations_total() - before);
      return result;
    }
    throw std::logic_error("from-region query: no witness found for a target inside the view cell");
  }

  // Otherwise every free segment leaves the cell through a face that T is (partly) in front of.
  for (int axis = 0; axis < 3 && !result.visible; ++axis)
    for (bool high : {false, true}) {
      const Exact& plane = high ? cell.hi[axis] : cell.lo[axis];
      bool in_front = false;
      for (const auto& c : tri) in_front |= high ? (c[axis] > plane) : (c[axis] < plane);
      if (!in_front) continue;
      VisibilityResult face = visible_from_polygon(scene, candidates, box_face(cell, axis, high), triangle_index, options);
      accumulate(result.stats, face.stats);
      if (face.visible) {
        result.visible = true;
        result.witness = face.witness;
        if (options.round_witness)
          if (auto r = round_witness(scene, candidates, [&](const RationalPoint3& p) { return in_closed_box(p, cell); },
                                     triangle_index, *face.witness))
            result.witness = r;
        break;
      }
    }
  result.stats.exact_evaluations = static_cast<std::int64_t>(exact_evaluations_total() - before);
  return result;
}

}  // namespace exactvis::region
