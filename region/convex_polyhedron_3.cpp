#include "region/convex_polyhedron_3.hpp"

#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace exactvis::region {

ConvexPolyhedron3 box_polyhedron(const RationalPoint3& lo, const RationalPoint3& hi) {
  ConvexPolyhedron3 box;
  if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) return box;
  // Vertex k has x = hi.x iff bit 0, y = hi.y iff bit 1, z = hi.z iff bit 2.
  for (int k = 0; k < 8; ++k)
    box.vertices.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  const Exact zero(0), one(1);
  auto face = [&](Vec3<Exact> inward, Exact offset, std::vector<int> loop) {
    box.faces.push_back({Plane3{inward, offset}, std::move(loop)});
  };
  // Loops counter-clockwise seen from outside (outward normal = -inward).
  face({one, zero, zero}, lo.x, {0, 4, 6, 2});     // x = lo.x, outward -x
  face({-one, zero, zero}, -hi.x, {1, 3, 7, 5});   // x = hi.x, outward +x
  face({zero, one, zero}, lo.y, {0, 1, 5, 4});     // y = lo.y, outward -y
  face({zero, -one, zero}, -hi.y, {2, 6, 7, 3});   // y = hi.y, outward +y
  face({zero, zero, one}, lo.z, {0, 2, 3, 1});     // z = lo.z, outward -z
  face({zero, zero, -one}, -hi.z, {4, 5, 7, 6});   // z = hi.z, outward +z
  return box;
}

ConvexPolyhedron3 clip_polyhedron(const ConvexPolyhedron3& poly, const Plane3& keep) {
  if (poly.empty()) return poly;
  const std::size_t n = poly.vertices.size();
  std::vector<Sign> side(n);
  bool any_positive = false, any_negative = false;
  for (std::size_t i = 0; i < n; ++i) {
    side[i] = plane_side(keep, poly.vertices[i]);
    any_positive |= side[i] == Sign::Positive;
    any_negative |= side[i] == Sign::Negative;
  }
  if (!any_negative) return poly;               // entirely kept
  if (!any_positive) return ConvexPolyhedron3{};  // nothing with interior left

  ConvexPolyhedron3 out;
  std::vector<int> renumber(n, -1);
  auto kept_vertex = [&](int v) {
    if (renumber[v] < 0) {
      renumber[v] = static_cast<int>(out.vertices.size());
      out.vertices.push_back(poly.vertices[v]);
    }
    return renumber[v];
  };
  std::vector<Exact> value(n);
  std::vector<bool> has_value(n, false);
  auto exact_value = [&](int v) -> const Exact& {
    if (!has_value[v]) value[v] = keep.value(poly.vertices[v]), has_value[v] = true;
    return value[v];
  };
  // The crossing point of each cut edge, shared by the two faces of the edge.
  std::unordered_map<std::uint64_t, int> crossing;
  auto crossing_vertex = [&](int a, int b) {
    const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::uint32_t(std::max(a, b));
    auto it = crossing.find(key);
    if (it != crossing.end()) return it->second;
    const Exact& va = exact_value(a);
    const Exact t = va / (va - exact_value(b));
    const RationalPoint3& pa = poly.vertices[a];
    out.vertices.push_back(pa + t * (poly.vertices[b] - pa));
    const int id = static_cast<int>(out.vertices.size()) - 1;
    crossing.emplace(key, id);
    return id;
  };
  // Cap boundary: each clipped face whose loop runs along the cut plane from a to b contributes the cap edge
  // b -> a (shared edges run opposite ways in adjacent faces of a consistently oriented surface).
  std::unordered_map<int, int> cap_next;
  std::vector<char> cut;  // cut[out vertex]: lies on the cut plane
  auto mark_cut = [&](int v) {
    if (cut.size() <= static_cast<std::size_t>(v)) cut.resize(v + 1, 0);
    cut[v] = 1;
  };
  auto is_cut = [&](int v) { return static_cast<std::size_t>(v) < cut.size() && cut[v]; };
  bool face_in_plane = false;
  for (const auto& face : poly.faces) {
    bool all_zero = true;
    for (int v : face.loop) all_zero &= side[v] == Sign::Zero;
    if (all_zero) face_in_plane = true;  // then it is the cap (the polyhedron lies on the kept side)
    std::vector<int> loop;
    const std::size_t m = face.loop.size();
    for (std::size_t i = 0; i < m; ++i) {
      const int a = face.loop[i], b = face.loop[(i + 1) % m];
      if (side[a] != Sign::Negative) {
        const int id = kept_vertex(a);
        if (side[a] == Sign::Zero) mark_cut(id);
        loop.push_back(id);
      }
      if ((side[a] == Sign::Positive && side[b] == Sign::Negative) ||
          (side[a] == Sign::Negative && side[b] == Sign::Positive)) {
        const int id = crossing_vertex(a, b);
        mark_cut(id);
        loop.push_back(id);
      }
    }
    if (loop.size() < 3) continue;  // touches the kept part in an edge or a point only
    if (!all_zero) {
      const std::size_t k = loop.size();
      for (std::size_t i = 0; i < k; ++i) {
        const int a = loop[i], b = loop[(i + 1) % k];
        if (is_cut(a) && is_cut(b)) {
          if (!cap_next.emplace(b, a).second) throw std::logic_error("clip_polyhedron: cap vertex used twice");
        }
      }
    }
    out.faces.push_back({face.plane, std::move(loop)});
  }
  if (!face_in_plane && !cap_next.empty()) {
    std::vector<int> cap;
    const int start = cap_next.begin()->first;
    int v = start;
    do {
      cap.push_back(v);
      auto it = cap_next.find(v);
      if (it == cap_next.end() || cap.size() > cap_next.size())
        throw std::logic_error("clip_polyhedron: cap boundary is not one closed loop");
      v = it->second;
    } while (v != start);
    if (cap.size() != cap_next.size()) throw std::logic_error("clip_polyhedron: cap boundary has several loops");
    out.faces.push_back({keep, std::move(cap)});
  }
  return out;
}

ConvexPolyhedron3 intersect_halfspaces(const RationalPoint3& lo, const RationalPoint3& hi,
                                       const std::vector<Plane3>& keep) {
  ConvexPolyhedron3 p = box_polyhedron(lo, hi);
  for (const Plane3& h : keep) {
    if (p.empty()) break;
    p = clip_polyhedron(p, h);
  }
  return p;
}

Exact volume(const ConvexPolyhedron3& poly) {
  Exact six_v(0);
  if (poly.empty()) return six_v;
  const RationalPoint3& r = poly.vertices[0];
  for (const auto& face : poly.faces) {
    const RationalPoint3& a = poly.vertices[face.loop[0]];
    for (std::size_t i = 1; i + 1 < face.loop.size(); ++i) {
      const RationalPoint3& b = poly.vertices[face.loop[i]];
      const RationalPoint3& c = poly.vertices[face.loop[i + 1]];
      six_v += dot(a - r, cross(b - a, c - a));
    }
  }
  return six_v / Exact(6);
}

std::vector<std::array<RationalPoint3, 3>> boundary_triangles(const ConvexPolyhedron3& poly) {
  std::vector<std::array<RationalPoint3, 3>> out;
  for (const auto& face : poly.faces)
    for (std::size_t i = 1; i + 1 < face.loop.size(); ++i)
      out.push_back({poly.vertices[face.loop[0]], poly.vertices[face.loop[i]], poly.vertices[face.loop[i + 1]]});
  return out;
}

Containment locate(const ConvexPolyhedron3& poly, const RationalPoint3& x) {
  if (poly.empty()) return Containment::Outside;
  bool boundary = false;
  for (const auto& face : poly.faces) {
    const Sign s = plane_side(face.plane, x);
    if (s == Sign::Negative) return Containment::Outside;
    boundary |= s == Sign::Zero;
  }
  return boundary ? Containment::Boundary : Containment::Interior;
}

std::vector<Polygon3> polygon_outside(const Polygon3& poly, const ConvexPolyhedron3& solid) {
  if (solid.empty()) return {poly};
  // A separating face plane: poly is on its closed outer side (and not in the plane).
  for (const auto& face : solid.faces) {
    bool below = false, above = false;
    for (const RationalPoint3& x : poly) {
      const Sign s = plane_side(face.plane, x);
      below |= s == Sign::Negative;
      above |= s == Sign::Positive;
    }
    if (below && !above) return {poly};
  }
  std::vector<Polygon3> out;
  Polygon3 rest = poly;
  for (const auto& face : solid.faces) {
    bool off_plane = false;
    for (const RationalPoint3& x : rest) off_plane |= plane_side(face.plane, x) != Sign::Zero;
    if (!off_plane) continue;  // rest lies in this face's plane: nothing of it is strictly outside the plane
    Polygon3 outer = clip_polygon(rest, face.plane.flipped());
    if (!is_degenerate(outer)) out.push_back(std::move(outer));
    rest = clip_polygon(rest, face.plane);
    if (is_degenerate(rest)) break;
  }
  return out;
}

}  // namespace exactvis::region
