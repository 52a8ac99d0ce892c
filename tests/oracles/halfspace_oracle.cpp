#include "oracles/halfspace_oracle.hpp"

namespace oracle {

namespace {
mpq_class det3(const QVec& a, const QVec& b, const QVec& c) { return dot(a, cross(b, c)); }
}  // namespace

std::vector<QVec> halfspace_vertices(const std::vector<QHalfspace>& h) {
  std::vector<QVec> out;
  const std::size_t k = h.size();
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j)
      for (std::size_t l = j + 1; l < k; ++l) {
        // Solve rows n_i, n_j, n_l against (d_i, d_j, d_l) by Cramer's rule on the columns.
        const QVec& a = h[i].n; const QVec& b = h[j].n; const QVec& c = h[l].n;
        const QVec cx{a.x, b.x, c.x}, cy{a.y, b.y, c.y}, cz{a.z, b.z, c.z}, rhs{h[i].d, h[j].d, h[l].d};
        const mpq_class D = det3(cx, cy, cz);
        if (D == 0) continue;
        const QVec p{det3(rhs, cy, cz) / D, det3(cx, rhs, cz) / D, det3(cx, cy, rhs) / D};
        bool inside = true;
        for (const auto& s : h) inside = inside && dot(s.n, p) >= s.d;
        if (!inside) continue;
        bool seen = false;
        for (const auto& q : out) seen = seen || q == p;
        if (!seen) out.push_back(p);
      }
  return out;
}

bool spans_3d(const std::vector<QVec>& p) {
  for (std::size_t i = 1; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      for (std::size_t l = j + 1; l < p.size(); ++l)
        if (det3(p[i] - p[0], p[j] - p[0], p[l] - p[0]) != 0) return true;
  return false;
}

mpq_class enclosed_volume(const std::vector<std::array<QVec, 3>>& triangles) {
  mpq_class six(0);
  for (const auto& t : triangles) six += det3(t[0], t[1], t[2]);
  return six / 6;
}

}  // namespace oracle
