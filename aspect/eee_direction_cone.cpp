#include "aspect/eee_direction_cone.hpp"

#include <stdexcept>

namespace exactvis {

EeeDirectionCone eee_direction_cone(const std::array<Vec3<Exact>, 3>& A, const std::array<Vec3<Exact>, 3>& u) {
  for (const auto& v : u)
    if (v.x == 0 && v.y == 0 && v.z == 0) throw std::invalid_argument("eee_direction_cone: a zero direction");
  EeeDirectionCone c;
  c.degenerate = dot(u[0], cross(u[1], u[2])) == 0;
  for (auto& row : c.q) row = {Exact(0), Exact(0), Exact(0)};
  for (int i = 0; i < 3; ++i) {
    const Vec3<Exact> w = cross(u[(i + 1) % 3], u[(i + 2) % 3]);
    const Vec3<Exact> m = cross(A[i], u[i]);
    // (w . d)(m . d) = d^T (w m^T + m w^T) / 2 d
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) c.q[r][s] += (w[r] * m[s] + m[r] * w[s]) / 2;
  }
  // n_j(t) = u_j x (A_j - A_1) - t (u_j x u_1) = a_j + t b_j.
  const Vec3<Exact> a2 = cross(u[1], A[1] - A[0]), b2 = -cross(u[1], u[0]);
  const Vec3<Exact> a3 = cross(u[2], A[2] - A[0]), b3 = -cross(u[2], u[0]);
  c.d = {cross(a2, a3), cross(a2, b3) + cross(b2, a3), cross(b2, b3)};
  return c;
}

Exact cone_value(const EeeDirectionCone& c, const Vec3<Exact>& d) {
  Exact v(0);
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) v += d[r] * c.q[r][s] * d[s];
  return v;
}

Vec3<Exact> cone_direction_at(const EeeDirectionCone& c, const Exact& t) {
  return c.d[0] + t * c.d[1] + (t * t) * c.d[2];
}

}  // namespace exactvis
