#pragma once
// The affine frame of a receiver triangle (a, b, c): X = a + u (b - a) + v (c - a). The triangle is
// u >= 0, v >= 0, u + v <= 1; curves, faces and conics of the shadows module are given in (u, v). Exact.
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "shadows/light_plane_2d.hpp"

#include <array>
#include <cstdint>

namespace exactvis::shadows {

struct ReceiverFrame {
  Vec3<Exact> origin, e1, e2;  // a, b - a, c - a
  PlaneChart chart;            // of the receiver's plane
  // (u, v) of X (X is first projected onto the plane along the chart's dropped axis). Exact.
  std::array<Exact, 2> to_uv(const Vec3<Exact>& x) const;
  Vec3<Exact> to_3d(const Exact& u, const Exact& v) const;
  // 3D area of a region of (u, v)-area A is A * area_scale() (|e1 x e2|, a double).
  double area_scale() const;
  Vec3<Exact> normal() const { return chart.normal; }  // e1 x e2
};

ReceiverFrame receiver_frame(const Scene& scene, std::int64_t triangle_index);

}  // namespace exactvis::shadows
