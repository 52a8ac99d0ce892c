#include "region/wall_umbra.hpp"

#include <algorithm>
#include <array>
#include <numeric>

namespace exactvis::region {
namespace {

template <class NT>
struct P2 {
  NT x, y;
};

template <class NT>
NT cross(const P2<NT>& a, const P2<NT>& b, const P2<NT>& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

template <class NT>
int sgn(const NT& v) {
  return v > NT(0) ? 1 : (v < NT(0) ? -1 : 0);
}

// Conditions (i) and (iii) of wall_umbra.hpp for one wall in number type NT: the cell and every q strictly on
// opposite sides of the wall's line, and the crossing height of every cell-to-target segment with that line
// within the wall's heights.
template <class NT>
bool crossing_height_within(const WallRectangle& wall, const std::array<P2<NT>, 4>& cell_xy, const NT& cz0,
                            const NT& cz1, const std::vector<P2<NT>>& q, const NT& tz0, const NT& tz1) {
  if (q.empty()) return false;
  const P2<NT> a{NT(wall.ax), NT(wall.ay)}, b{NT(wall.bx), NT(wall.by)};
  const int s = sgn(cross(a, b, cell_xy[0]));
  if (s == 0) return false;
  NT a_min, a_max;
  for (std::size_t i = 0; i < 4; ++i) {
    const NT v = cross(a, b, cell_xy[i]) * NT(s);
    if (!(v > NT(0))) return false;  // the cell must be strictly on one side
    if (i == 0 || v < a_min) a_min = v;
    if (i == 0 || v > a_max) a_max = v;
  }
  NT b_min, b_max;
  for (std::size_t j = 0; j < q.size(); ++j) {
    const NT v = -cross(a, b, q[j]) * NT(s);
    if (!(v > NT(0))) return false;  // the target strictly on the other side
    if (j == 0 || v < b_min) b_min = v;
    if (j == 0 || v > b_max) b_max = v;
  }
  const NT wl(wall.z_lo), wh(wall.z_hi);
  for (const NT lambda : {a_min / (a_min + b_max), a_max / (a_max + b_min)}) {
    const NT one_minus = NT(1) - lambda;
    if (one_minus * cz1 + lambda * tz1 > wh) return false;
    if (one_minus * cz0 + lambda * tz0 < wl) return false;
  }
  return true;
}

// Does the closed segment c p meet the wall's footprint [a, b]? Valid when c and p lie strictly on opposite
// sides of the line ab (then: iff a and b lie on opposite closed sides of the line cp).
template <class NT>
bool crosses_footprint(const WallRectangle& wall, const P2<NT>& c, const P2<NT>& p) {
  const P2<NT> a{NT(wall.ax), NT(wall.ay)}, b{NT(wall.bx), NT(wall.by)};
  return sgn(cross(c, p, a)) * sgn(cross(c, p, b)) <= 0;
}

// The test of wall_umbra.hpp in number type NT (double: a proposal; Exact: the proof).
template <class NT>
bool hides(const WallRectangle& wall, const std::array<P2<NT>, 4>& cell_xy, const NT& cz0, const NT& cz1,
           const std::vector<P2<NT>>& q, const NT& tz0, const NT& tz1) {
  // Vertical component first (cheap): the crossing height stays within the wall.
  if (!crossing_height_within(wall, cell_xy, cz0, cz1, q, tz0, tz1)) return false;
  // Horizontal component: every corner-to-point segment crosses [a, b].
  for (const auto& c : cell_xy)
    for (const auto& p : q)
      if (!crosses_footprint(wall, c, p)) return false;
  return true;
}

// The two-wall test (wall_pair_hides_exactly) in number type NT.
template <class NT>
bool pair_hides(const WallRectangle& w1, const WallRectangle& w2, const std::array<P2<NT>, 4>& cell_xy, const NT& cz0,
                const NT& cz1, const std::vector<P2<NT>>& q, const NT& tz0, const NT& tz1) {
  if (!crossing_height_within(w1, cell_xy, cz0, cz1, q, tz0, tz1)) return false;
  if (!crossing_height_within(w2, cell_xy, cz0, cz1, q, tz0, tz1)) return false;
  for (const auto& c : cell_xy)
    for (const auto& p : q)
      if (!crosses_footprint(w1, c, p) && !crosses_footprint(w2, c, p)) return false;
  return true;
}

template <class NT>
std::array<P2<NT>, 4> cell_corners(const NT& x0, const NT& y0, const NT& x1, const NT& y1) {
  return {{{x0, y0}, {x1, y0}, {x0, y1}, {x1, y1}}};
}

// Exact: do the closed footprint segments of the two walls share a point?
bool footprints_meet(const WallRectangle& w1, const WallRectangle& w2) {
  const P2<Exact> a{Exact(w1.ax), Exact(w1.ay)}, b{Exact(w1.bx), Exact(w1.by)};
  const P2<Exact> c{Exact(w2.ax), Exact(w2.ay)}, d{Exact(w2.bx), Exact(w2.by)};
  const int o1 = sgn(cross(a, b, c)), o2 = sgn(cross(a, b, d)), o3 = sgn(cross(c, d, a)), o4 = sgn(cross(c, d, b));
  if (o1 == 0 && o2 == 0) {  // collinear: the projections onto the line overlap
    auto key = [&](const P2<Exact>& p) { return (b.x - a.x) * (p.x - a.x) + (b.y - a.y) * (p.y - a.y); };
    const Exact k1 = key(c), k2 = key(d), len = key(b);
    return !(std::max(k1, k2) < Exact(0) || std::min(k1, k2) > len);
  }
  return o1 * o2 <= 0 && o3 * o4 <= 0;
}

// For every view point x (a corner of a convex region, all strictly off wall j's line), the ray from x
// through e meets wall j's closed footprint. The two orientations are affine in x and so is the sign that
// puts the meeting point ahead of x, so the vertices decide for the whole region.
template <class NT>
bool ray_through_meets(const P2<NT>& e, const WallRectangle& wall, const std::vector<P2<NT>>& views) {
  const P2<NT> a{NT(wall.ax), NT(wall.ay)}, b{NT(wall.bx), NT(wall.by)};
  auto ordered = [&](const P2<NT>& first, const P2<NT>& second) {
    for (const auto& x : views)
      if (sgn(cross(x, e, first)) < 0 || sgn(cross(x, e, second)) > 0) return false;
    return true;
  };
  if (!ordered(a, b) && !ordered(b, a)) return false;
  const NT fe = cross(a, b, e);
  for (const auto& x : views) {
    // The meeting point is x + t (e - x) with t = fx / (fx - fe) > 0. For a chain of two walls this ray-side
    // rule is implied (docs/theory.md §5.10 (3)); longer chains have no such proof, so it is always checked.
    const NT fx = cross(a, b, x);
    if (sgn(fx) == 0 || sgn(fx) * sgn(NT(fx - fe)) <= 0) return false;
  }
  return true;
}

// Seen from every point of the region conv(views), the directions to the two footprints overlap (some ray
// from the point meets both): one footprint's endpoint is seen in front of or behind the other.
template <class NT>
bool views_overlap(const WallRectangle& u, const WallRectangle& v, const std::vector<P2<NT>>& views) {
  const P2<NT> ua{NT(u.ax), NT(u.ay)}, ub{NT(u.bx), NT(u.by)};
  const P2<NT> va{NT(v.ax), NT(v.ay)}, vb{NT(v.bx), NT(v.by)};
  return ray_through_meets(ua, v, views) || ray_through_meets(ub, v, views) || ray_through_meets(va, u, views) ||
         ray_through_meets(vb, u, views);
}

}  // namespace

WallFromCell prepare_wall(const WallRectangle& wall, const Box3& cell) {
  WallFromCell out;
  const P2<double> a{wall.ax, wall.ay}, b{wall.bx, wall.by};
  const std::array<P2<double>, 4> corners{{{cell.lo.x, cell.lo.y}, {cell.hi.x, cell.lo.y}, {cell.lo.x, cell.hi.y}, {cell.hi.x, cell.hi.y}}};
  const double f0 = cross(a, b, corners[0]);
  if (f0 == 0) return out;
  out.side = f0 > 0 ? 1 : -1;
  for (std::size_t i = 0; i < 4; ++i) {
    const double v = cross(a, b, corners[i]) * out.side;
    if (!(v > 0)) return out;
    if (i == 0 || v < out.a_min) out.a_min = v;
    if (i == 0 || v > out.a_max) out.a_max = v;
  }
  out.usable = true;  // heights are checked per target (a cell above a wall still looks down behind it)
  return out;
}

bool wall_may_hide(const WallRectangle& wall, const WallFromCell& prepared, const Box3& cell,
                   const UmbraTarget& target) {
  if (!prepared.usable) return false;
  const P2<double> a{wall.ax, wall.ay}, b{wall.bx, wall.by};
  // Quick rejection before the full double test: some target point not beyond the line.
  for (const auto& p : target.points)
    if (!(-cross(a, b, P2<double>{p.x, p.y}) * prepared.side > 0)) return false;
  const std::array<P2<double>, 4> corners{{{cell.lo.x, cell.lo.y}, {cell.hi.x, cell.lo.y}, {cell.lo.x, cell.hi.y}, {cell.hi.x, cell.hi.y}}};
  std::vector<P2<double>> q;
  q.reserve(target.points.size());
  for (const auto& p : target.points) q.push_back({p.x, p.y});
  return hides<double>(wall, corners, cell.lo.z, cell.hi.z, q, target.z_lo, target.z_hi);
}

bool wall_hides_exactly(const WallRectangle& wall, const RationalBox3& cell, const UmbraTarget& target) {
  const std::array<P2<Exact>, 4> corners{{{cell.lo.x, cell.lo.y}, {cell.hi.x, cell.lo.y}, {cell.lo.x, cell.hi.y}, {cell.hi.x, cell.hi.y}}};
  std::vector<P2<Exact>> q;
  q.reserve(target.points.size());
  for (const auto& p : target.points) q.push_back({Exact(p.x), Exact(p.y)});
  return hides<Exact>(wall, corners, cell.lo.z, cell.hi.z, q, Exact(target.z_lo), Exact(target.z_hi));
}

bool wall_pair_may_hide(const WallRectangle& w1, const WallFromCell& p1, const WallRectangle& w2,
                        const WallFromCell& p2, const Box3& cell, const UmbraTarget& target) {
  if (!p1.usable || !p2.usable) return false;
  const auto corners = cell_corners(cell.lo.x, cell.lo.y, cell.hi.x, cell.hi.y);
  std::vector<P2<double>> q;
  q.reserve(target.points.size());
  for (const auto& p : target.points) q.push_back({p.x, p.y});
  return pair_hides<double>(w1, w2, corners, cell.lo.z, cell.hi.z, q, target.z_lo, target.z_hi);
}

bool wall_may_join_chain(const WallRectangle& wall, const WallFromCell& prepared, const Box3& cell,
                         const UmbraTarget& target) {
  if (!prepared.usable) return false;
  const auto corners = cell_corners(cell.lo.x, cell.lo.y, cell.hi.x, cell.hi.y);
  std::vector<P2<double>> q;
  q.reserve(target.points.size());
  for (const auto& p : target.points) q.push_back({p.x, p.y});
  if (!crossing_height_within(wall, corners, cell.lo.z, cell.hi.z, q, target.z_lo, target.z_hi)) return false;
  for (const auto& c : corners)
    for (const auto& p : q)
      if (crosses_footprint(wall, c, p)) return true;
  return false;
}

bool wall_chain_may_cover(const std::vector<WallRectangle>& walls, const Box3& cell, const UmbraTarget& target) {
  const auto corners = cell_corners(cell.lo.x, cell.lo.y, cell.hi.x, cell.hi.y);
  for (const auto& c : corners)
    for (const auto& p : target.points) {
      const P2<double> q{p.x, p.y};
      if (std::none_of(walls.begin(), walls.end(), [&](const WallRectangle& w) { return crosses_footprint(w, c, q); }))
        return false;
    }
  return !walls.empty();
}

bool wall_chain_hides_exactly(const std::vector<WallRectangle>& walls,
                              const std::vector<std::pair<std::size_t, std::size_t>>& links, const RationalBox3& cell,
                              const UmbraTarget& target) {
  if (walls.empty() || target.points.empty()) return false;
  // Connectivity of the footprints' union: every claimed contact checked exactly, and the contacts join all.
  std::vector<std::size_t> parent(walls.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const auto corners = cell_corners(cell.lo.x, cell.lo.y, cell.hi.x, cell.hi.y);
  std::vector<P2<Exact>> q;
  q.reserve(target.points.size());
  for (const auto& p : target.points) q.push_back({Exact(p.x), Exact(p.y)});
  const Exact tz0(target.z_lo), tz1(target.z_hi);
  // Conditions (i) and (iii) for every wall first: the view-overlap links rely on (i).
  for (const WallRectangle& w : walls)
    if (!crossing_height_within(w, corners, cell.lo.z, cell.hi.z, q, tz0, tz1)) return false;
  // The links that hold (the others are dropped), and the chains they join.
  const std::vector<P2<Exact>> cell_views(corners.begin(), corners.end());
  for (const auto& [i, j] : links) {
    if (i >= walls.size() || j >= walls.size()) continue;
    if (!footprints_meet(walls[i], walls[j]) &&
        !(views_overlap(walls[i], walls[j], cell_views) && views_overlap(walls[i], walls[j], q)))
      continue;
    parent[find(i)] = find(j);
  }
  // Condition (ii'') for some chain: every corner-to-point segment crosses one of its footprints.
  std::vector<char> tried(walls.size(), 0);
  for (std::size_t r = 0; r < walls.size(); ++r) {
    const std::size_t root = find(r);
    if (tried[root]) continue;
    tried[root] = 1;
    bool covered = true;
    for (const auto& c : corners)
      for (const auto& p : q)
        if (covered) {
          bool met = false;
          for (std::size_t w = 0; w < walls.size() && !met; ++w) met = find(w) == root && crosses_footprint(walls[w], c, p);
          covered = met;
        }
    if (covered) return true;
  }
  return false;
}

bool walls_views_may_overlap(const WallRectangle& u, const WallRectangle& v, const Box3& cell,
                             const UmbraTarget& target) {
  const auto corners = cell_corners(cell.lo.x, cell.lo.y, cell.hi.x, cell.hi.y);
  std::vector<P2<double>> q;
  q.reserve(target.points.size());
  for (const auto& p : target.points) q.push_back({p.x, p.y});
  return views_overlap(u, v, std::vector<P2<double>>(corners.begin(), corners.end())) && views_overlap(u, v, q);
}

bool wall_pair_hides_exactly(const WallRectangle& w1, const WallRectangle& w2, const RationalBox3& cell,
                             const UmbraTarget& target) {
  if (!footprints_meet(w1, w2)) return false;
  const auto corners = cell_corners(cell.lo.x, cell.lo.y, cell.hi.x, cell.hi.y);
  std::vector<P2<Exact>> q;
  q.reserve(target.points.size());
  for (const auto& p : target.points) q.push_back({Exact(p.x), Exact(p.y)});
  return pair_hides<Exact>(w1, w2, corners, cell.lo.z, cell.hi.z, q, Exact(target.z_lo), Exact(target.z_hi));
}

}  // namespace exactvis::region
