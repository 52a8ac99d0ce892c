#include "region/stabbing_pair.hpp"

#include <stdexcept>

namespace exactvis::region {
namespace {

// Oriented edge lines of `poly` such that the directed line through its centroid in direction `dir`
// passes every edge positively (so does every line crossing relint(poly) in that direction).
void add_oriented_edges(const Polygon3& poly, const Vec3<Exact>& dir, std::vector<PluckerLine<Exact>>& out) {
  const RationalPoint3 c = centroid(poly);
  const auto probe = line_through(c, c + dir);
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    auto e = line_through(a, b);
    const Sign s = side_of_lines(probe, e);
    if (s == Sign::Zero) throw std::logic_error("stabbing_pairs: probe line meets a polygon edge");
    out.push_back(s == Sign::Positive ? e : reversed(e));
  }
}

}  // namespace

std::vector<StabbingPair> stabbing_pairs(const Polygon3& source, const std::array<RationalPoint3, 3>& target) {
  return stabbing_pairs(source, Polygon3{target[0], target[1], target[2]});
}

std::vector<StabbingPair> stabbing_pairs(const Polygon3& source, const Polygon3& tri) {
  std::vector<StabbingPair> pairs;
  if (is_degenerate(source)) return pairs;
  if (is_degenerate(tri)) return pairs;
  const Plane3 ps = plane_of(source);
  const Plane3 pt = plane_of(tri);
  for (int ss : {+1, -1}) {
    const Plane3 pt_side = ss > 0 ? pt : pt.flipped();  // value > 0 on the side where S' lies
    const Polygon3 s_part = clip_polygon(source, pt_side);
    if (is_degenerate(s_part) || lies_in_plane(s_part, pt_side)) continue;
    for (int ts : {+1, -1}) {
      const Plane3 ps_side = ts > 0 ? ps : ps.flipped();  // value > 0 on the side where T' lies
      const Polygon3 t_part = clip_polygon(tri, ps_side);
      if (is_degenerate(t_part) || lies_in_plane(t_part, ps_side)) continue;
      StabbingPair pair;
      pair.source = s_part;
      pair.target = t_part;
      pair.source_plane = ps_side;
      pair.target_plane = pt_side;
      // Stabbers cross plane(S) towards T' (along +normal of ps_side) and plane(T) away from S'
      // (along -normal of pt_side).
      add_oriented_edges(s_part, ps_side.normal, pair.edge_lines);
      add_oriented_edges(t_part, -pt_side.normal, pair.edge_lines);
      pairs.push_back(std::move(pair));
    }
  }
  return pairs;
}

}  // namespace exactvis::region
