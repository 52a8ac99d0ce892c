#include "oracles/exterior_oracle.hpp"

#include <random>

namespace oracle {
namespace {

// A point of the ray beyond which no scene triangle lies: along an axis where d is non-zero, a parameter
// where that coordinate has passed every vertex coordinate (plus one).
QVec far_point(const std::vector<Triangle>& scene, const QVec& q, const QVec& d) {
  const mpq_class* qc[3] = {&q.x, &q.y, &q.z};
  const mpq_class* dc[3] = {&d.x, &d.y, &d.z};
  int axis = 0;
  while (sign(*dc[axis]) == 0) ++axis;
  mpq_class s = 1;
  for (const Triangle& t : scene)
    for (const QVec& v : t) {
      const mpq_class* vc[3] = {&v.x, &v.y, &v.z};
      mpq_class sv = (*vc[axis] - *qc[axis]) / *dc[axis];
      if (sv + 1 > s) s = sv + 1;
    }
  return q + s * d;
}

mpq_class ratio(long num, long den) {
  mpq_class r(num, den);
  r.canonicalize();
  return r;
}

bool coplanar(const Triangle& a, const Triangle& b) {
  for (const QVec& v : b)
    if (orient3d(a[0], a[1], a[2], v) != 0) return false;
  return true;
}

}  // namespace

bool open_ray_escapes(const std::vector<Triangle>& scene, std::size_t skip, const QVec& q, const QVec& d) {
  const QVec f = far_point(scene, q, d);
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (i == skip) continue;
    const Triangle& t = scene[i];
    if (oracle_open_segment_meets_closed_triangle(q, f, t[0], t[1], t[2])) return false;
    if (oracle_point_in_closed_triangle(f, t[0], t[1], t[2])) return false;
  }
  return true;
}

bool exterior_witness_is_valid(const std::vector<Triangle>& scene, std::size_t target, const QVec& q, const QVec& d,
                               std::string* why) {
  auto fail = [&](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (target >= scene.size()) return fail("target out of range");
  const Triangle& t = scene[target];
  if (!oracle_point_in_triangle_relative_interior(q, t[0], t[1], t[2])) return fail("q is not in relint T");
  if (is_zero(d)) return fail("d is zero");
  // The open ray must not meet T itself either (it does only when it runs inside plane(T)).
  if (!open_ray_escapes(scene, scene.size(), q, d)) {
    if (!open_ray_escapes(scene, target, q, d)) return fail("the open ray meets another triangle");
    return fail("the open ray runs inside T");
  }
  return true;
}

std::optional<std::pair<QVec, QVec>> find_robust_escaping_ray(const std::vector<Triangle>& scene, std::size_t target,
                                                              int samples, unsigned long seed) {
  std::mt19937_64 rng(seed);
  const Triangle& t = scene[target];
  const QVec n = cross(t[1] - t[0], t[2] - t[0]);
  std::vector<QVec> vertices;
  for (const Triangle& o : scene)
    for (const QVec& v : o) vertices.push_back(v);
  for (int k = 0; k < samples; ++k) {
    const long w0 = 1 + static_cast<long>(rng() % 1024), w1 = 1 + static_cast<long>(rng() % 1024),
               w2 = 1 + static_cast<long>(rng() % 1024);
    const mpq_class sum = w0 + w1 + w2;
    const QVec q = (ratio(w0, 1) / sum) * t[0] + (mpq_class(w1) / sum) * t[1] + (mpq_class(w2) / sum) * t[2];
    QVec d;
    if (k % 8 == 7 && !vertices.empty()) {
      // Towards a point near a scene vertex: finds narrow gaps next to vertices more often than uniform rays.
      const QVec& v = vertices[rng() % vertices.size()];
      const QVec jitter{ratio(static_cast<long>(rng() % 2049) - 1024, 1L << 20),
                        ratio(static_cast<long>(rng() % 2049) - 1024, 1L << 20),
                        ratio(static_cast<long>(rng() % 2049) - 1024, 1L << 20)};
      d = (v + jitter) - q;
    } else {
      d = {mpq_class(static_cast<long>(rng() % 2049) - 1024), mpq_class(static_cast<long>(rng() % 2049) - 1024),
           mpq_class(static_cast<long>(rng() % 2049) - 1024)};
    }
    if (is_zero(d) || sign(dot(d, n)) == 0) continue;
    bool on_other = false;
    for (std::size_t i = 0; i < scene.size() && !on_other; ++i)
      if (i != target && oracle_point_in_closed_triangle(q, scene[i][0], scene[i][1], scene[i][2]) &&
          !coplanar(t, scene[i]))
        on_other = true;
    if (on_other) continue;
    if (open_ray_escapes(scene, target, q, d)) return std::make_pair(q, d);
  }
  return std::nullopt;
}

}  // namespace oracle
