#pragma once
// Scenes and independent checks shared by the shadows test suites. The oracle side (light sampling) uses only
// GMP rationals and tests/oracles (no shadows/ or region/ code).
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "oracles/rational_geometry.hpp"

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace exactvis::shadow_test {

inline void add_object(Scene& s, const std::string& name, const std::vector<Point3>& v,
                       const std::vector<std::array<int, 3>>& t) {
  const int base = static_cast<int>(s.vertices.size());
  const int obj = static_cast<int>(s.objects.size());
  s.objects.push_back({name});
  s.vertices.insert(s.vertices.end(), v.begin(), v.end());
  for (const auto& tri : t)
    s.triangles.push_back({static_cast<std::int64_t>(s.triangles.size()), {base + tri[0], base + tri[1], base + tri[2]}, obj});
  s.faces_read = static_cast<std::int64_t>(s.triangles.size());
}

inline void add_quad(Scene& s, const std::string& name, const std::array<Point3, 4>& q) {
  add_object(s, name, {q[0], q[1], q[2], q[3]}, {{0, 1, 2}, {0, 2, 3}});
}

// The textbook configuration: floor z = 0 ([-4, 12]^2, triangles 0, 1), blocker square [3, 5]^2 at z = 2
// (triangles 2, 3), light square [3, 5]^2 at z = 4 (triangles 4, 5; object "lamp"). By hand (similar
// triangles: the line from light point q through floor point p crosses z = 2 at (q + p) / 2): light point
// q is hidden from p iff both (q_x + p_x) / 2 and (q_y + p_y) / 2 lie in [3, 5]; so the umbra is [3, 5]^2, the
// penumbra [1, 7]^2 minus the umbra, and the visible fraction is 1 - hx * hy with hx = |[6 - p_x, 10 - p_x]
// ∩ [3, 5]| / 2.
inline Scene textbook_scene() {
  Scene s;
  add_quad(s, "floor", {Point3{-4, -4, 0}, Point3{12, -4, 0}, Point3{12, 12, 0}, Point3{-4, 12, 0}});
  add_quad(s, "blocker", {Point3{3, 3, 2}, Point3{5, 3, 2}, Point3{5, 5, 2}, Point3{3, 5, 2}});
  add_quad(s, "lamp", {Point3{3, 3, 4}, Point3{5, 3, 4}, Point3{5, 5, 4}, Point3{3, 5, 4}});
  return s;
}

inline mpq_class hidden_share(const mpq_class& p) {  // |[6 - p, 10 - p] ∩ [3, 5]| / 2
  const mpq_class lo = std::max(mpq_class(3), mpq_class(6 - p)), hi = std::min(mpq_class(5), mpq_class(10 - p));
  return hi > lo ? (hi - lo) / 2 : mpq_class(0);
}
inline mpq_class textbook_fraction(const mpq_class& px, const mpq_class& py) {
  return 1 - hidden_share(px) * hidden_share(py);
}

// Floor, `blockers` random triangles with integer-ish corners strictly between the floor and the light, a
// square light "lamp" at z = 10 over [2, 8]^2.
inline Scene random_blocker_scene(unsigned seed, int blockers) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> xy(0, 40), z(8, 36);
  Scene s;
  add_quad(s, "floor", {Point3{-10, -10, 0}, Point3{20, -10, 0}, Point3{20, 20, 0}, Point3{-10, 20, 0}});
  for (int b = 0; b < blockers; ++b) {
    std::vector<Point3> v;
    for (int k = 0; k < 3; ++k) v.push_back({xy(rng) / 4.0, xy(rng) / 4.0, z(rng) / 4.0});
    const Point3 e1 = v[1] - v[0], e2 = v[2] - v[0];
    const Point3 n = cross(e1, e2);
    if (n.x == 0 && n.y == 0 && n.z == 0) {
      --b;
      continue;
    }
    add_object(s, "blocker" + std::to_string(b), v, {{0, 1, 2}});
  }
  add_quad(s, "lamp", {Point3{2, 2, 10}, Point3{8, 2, 10}, Point3{8, 8, 10}, Point3{2, 8, 10}});
  return s;
}

inline oracle::QVec oracle_point(const Vec3<Exact>& p) {
  return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq()), mpq_class(p.z.mpq())};
}

// The oracle: light point q is visible from p iff the open segment (p, q) meets no closed scene triangle.
inline bool oracle_visible(const Scene& s, const oracle::QVec& p, const oracle::QVec& q) {
  for (const auto& t : s.triangles) {
    const auto a = s.corner(t, 0), b = s.corner(t, 1), c = s.corner(t, 2);
    if (oracle::oracle_open_segment_meets_closed_triangle(p, q, oracle::qvec(a.x, a.y, a.z), oracle::qvec(b.x, b.y, b.z),
                                                          oracle::qvec(c.x, c.y, c.z)))
      return false;
  }
  return true;
}

// A random exact point strictly inside triangle `ti` of the scene (weights in [1, 2^16]).
inline oracle::QVec oracle_random_point(const Scene& s, std::int64_t ti, std::mt19937_64& rng) {
  std::uniform_int_distribution<long> w(1, 1 << 16);
  const long a = w(rng), b = w(rng), c = w(rng);
  const mpq_class sum = a + b + c;
  const auto& t = s.triangles[ti];
  oracle::QVec out{0, 0, 0};
  const long ws[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const auto p = s.corner(t, k);
    out = out + (mpq_class(ws[k]) / sum) * oracle::qvec(p.x, p.y, p.z);
  }
  return out;
}

// A uniformly distributed exact point of triangle `ti` (rational coordinates with denominator 2^20).
inline oracle::QVec oracle_uniform_point(const Scene& s, std::int64_t ti, std::mt19937_64& rng) {
  std::uniform_int_distribution<long> w(0, 1 << 20);
  mpq_class r1(w(rng), 1 << 20), r2(w(rng), 1 << 20);
  if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
  const auto& t = s.triangles[ti];
  const auto a = s.corner(t, 0), b = s.corner(t, 1), c = s.corner(t, 2);
  const oracle::QVec qa = oracle::qvec(a.x, a.y, a.z);
  return qa + r1 * (oracle::qvec(b.x, b.y, b.z) - qa) + r2 * (oracle::qvec(c.x, c.y, c.z) - qa);
}

}  // namespace exactvis::shadow_test
