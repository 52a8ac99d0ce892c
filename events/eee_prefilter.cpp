#include "events/eee_prefilter.hpp"

#include "kernel/predicates.hpp"

namespace exactvis {

bool edge_rule_possible(const Scene& scene, const SceneEdge& e, const Point3& c, const Point3& d) {
  const Point3& a = scene.vertices[e.v[0]];
  const Point3& b = scene.vertices[e.v[1]];
  bool pos = true, neg = true;  // some X may still have all signs positive / all negative
  for (int ti : e.triangles) {
    const auto& t = scene.triangles[ti];
    int w = t.v[0];
    for (int k = 0; k < 3; ++k)
      if (t.v[k] != e.v[0] && t.v[k] != e.v[1]) w = t.v[k];
    const Point3& pw = scene.vertices[w];
    // orient3d(a, b, X, w) is linear (affine) in X.
    const Sign sc = orient3d(a, b, c, pw), sd = orient3d(a, b, d, pw);
    if (sc != Sign::Positive && sd != Sign::Positive) pos = false;
    if (sc != Sign::Negative && sd != Sign::Negative) neg = false;
    if (!pos && !neg) return false;
  }
  return pos || neg;
}

bool eee_pair_possible(const Scene& scene, const SceneEdge& a, const SceneEdge& b) {
  if (a.v[0] == b.v[0] || a.v[0] == b.v[1] || a.v[1] == b.v[0] || a.v[1] == b.v[1]) return false;
  const Point3& a0 = scene.vertices[a.v[0]];
  const Point3& a1 = scene.vertices[a.v[1]];
  const Point3& b0 = scene.vertices[b.v[0]];
  const Point3& b1 = scene.vertices[b.v[1]];
  if (orient3d(a0, a1, b0, b1) == Sign::Zero) return false;  // coplanar supporting lines
  return edge_rule_possible(scene, a, b0, b1) && edge_rule_possible(scene, b, a0, a1);
}

}  // namespace exactvis
