#include "oracles/aspect_oracle.hpp"

#include <algorithm>
#include <set>

namespace oracle {

namespace {

QVec centroid(const OTriangle& t) { return mpq_class(1, 3) * (t[0] + t[1] + t[2]); }
QVec normal(const OTriangle& t) { return cross(t[1] - t[0], t[2] - t[0]); }

// Is the open segment (a, b) free of every triangle other than `skip`?
bool free_segment(const std::vector<OTriangle>& model, std::size_t skip, const QVec& a, const QVec& b) {
  for (std::size_t k = 0; k < model.size(); ++k)
    if (k != skip && oracle_open_segment_meets_closed_triangle(a, b, model[k][0], model[k][1], model[k][2])) return false;
  return true;
}

// Direction key up to positive scaling: divide by the largest |component| (exact).
std::array<mpq_class, 3> ray_key(const QVec& v) {
  mpq_class big = abs(v.x);
  if (abs(v.y) > big) big = abs(v.y);
  if (abs(v.z) > big) big = abs(v.z);
  return {v.x / big, v.y / big, v.z / big};
}
// Up to any non-zero scaling.
std::array<mpq_class, 3> line_key(const QVec& v) {
  auto k = ray_key(v);
  for (const auto& c : k)
    if (c != 0) {
      if (c < 0) for (auto& x : k) x = -x;
      break;
    }
  return k;
}

}  // namespace

std::vector<int> convex_direction_aspect(const std::vector<OTriangle>& model, const QVec& d) {
  // Far enough: beyond every corner along d (the segment then leaves the model's box).
  mpq_class reach = 1;
  for (const auto& t : model)
    for (const auto& p : t) reach += abs(p.x) + abs(p.y) + abs(p.z);
  const mpq_class len = abs(d.x) + abs(d.y) + abs(d.z);
  std::vector<int> seen;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (sign(dot(normal(model[i]), d)) == 0) continue;  // edge-on: null image
    const QVec c = centroid(model[i]);
    if (free_segment(model, i, c, c + mpq_class(2 * reach / len) * d)) seen.push_back(static_cast<int>(i));
  }
  return seen;
}

std::vector<int> convex_point_aspect(const std::vector<OTriangle>& model, const QVec& p) {
  std::vector<int> seen;
  for (std::size_t i = 0; i < model.size(); ++i) {
    const QVec c = centroid(model[i]);
    if (sign(dot(normal(model[i]), p - c)) == 0) continue;  // edge-on
    if (free_segment(model, i, c, p)) seen.push_back(static_cast<int>(i));
  }
  return seen;
}

GreatCircleCounts great_circle_counts(const std::vector<QVec>& normals) {
  GreatCircleCounts g;
  std::vector<QVec> circles;
  std::set<std::array<mpq_class, 3>> seen;
  for (const auto& n : normals)
    if (seen.insert(line_key(n)).second) circles.push_back(n);
  g.circles = static_cast<std::int64_t>(circles.size());
  // Vertex lines (each two antipodal vertices) and, per line, how many circles hold it.
  std::set<std::array<mpq_class, 3>> lines;
  for (std::size_t i = 0; i < circles.size(); ++i)
    for (std::size_t j = i + 1; j < circles.size(); ++j) lines.insert(line_key(cross(circles[i], circles[j])));
  g.vertices = 2 * static_cast<std::int64_t>(lines.size());
  for (const auto& l : lines) {
    const QVec v{l[0], l[1], l[2]};
    int on = 0;
    for (const auto& c : circles) on += sign(dot(c, v)) == 0;
    g.arcs += 2 * on;  // each of the two vertices splits each of its circles once more
    if (on != 2) g.simple = false;
  }
  g.faces = 2 - g.vertices + g.arcs;
  return g;
}

bool plane_arrangement_is_simple(const std::vector<std::pair<QVec, mpq_class>>& planes) {
  const std::size_t m = planes.size();
  auto det = [](const QVec& a, const QVec& b, const QVec& c) { return dot(a, cross(b, c)); };
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j) {
      if (is_zero(cross(planes[i].first, planes[j].first))) return false;
      for (std::size_t k = j + 1; k < m; ++k) {
        const mpq_class D = det(planes[i].first, planes[j].first, planes[k].first);
        if (D == 0) {
          // Normals coplanar: the three planes share a line iff the system is consistent; treat both as
          // non-generic unless the three are pairwise crossing without a common point (still no vertex).
          // A simple arrangement needs every three to meet in exactly one point.
          return false;
        }
        // The common point by Cramer's rule; a fourth plane through it breaks simplicity.
        const QVec e{planes[i].second, planes[j].second, planes[k].second};
        const QVec& a = planes[i].first;
        const QVec& b = planes[j].first;
        const QVec& c = planes[k].first;
        // Solve [a; b; c] x = e.
        const QVec col0{a.x, b.x, c.x}, col1{a.y, b.y, c.y}, col2{a.z, b.z, c.z};
        const mpq_class Dx = det(e, col1, col2), Dy = det(col0, e, col2), Dz = det(col0, col1, e);
        const mpq_class Dc = det(col0, col1, col2);
        const QVec x{Dx / Dc, Dy / Dc, Dz / Dc};
        for (std::size_t l = k + 1; l < m; ++l)
          if (dot(planes[l].first, x) == planes[l].second) return false;
      }
    }
  return true;
}

}  // namespace oracle
