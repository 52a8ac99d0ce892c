#pragma once
// Exact 2D coordinates on a plane of the scene (a light triangle's or a receiver's plane), for the planar
// Boolean operations and triangulations of the shadows module (docs/theory.md section 11).
//
// A plane with normal n is mapped to 2D by dropping its dominant coordinate k (|n_k| largest): the 2D point
// of X is (X[k+1], X[k+2]) (indices mod 3), swapped when n_k < 0 so that the map keeps orientation (a polygon
// counterclockwise seen from the side n points to is counterclockwise in 2D). The map is affine and
// bijective on the plane, so area ratios are exact rationals and lifting back is exact.
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <array>

namespace exactvis::shadows {

struct PlaneChart {
  Vec3<Exact> normal;  // plane normal (not unit), exact
  Exact offset;        // plane: normal . X = offset
  int axis = 2;        // dropped coordinate
  bool swapped = false;

  // The 2D coordinates of X (X need not lie on the plane: it is projected along the dropped axis).
  std::array<Exact, 2> to_2d(const Vec3<Exact>& x) const;
  // The point of the plane with 2D coordinates (a, b). Exact.
  Vec3<Exact> to_3d(const Exact& a, const Exact& b) const;
  // 3D area = 2D area * area_scale() (|n| / |n_k|; a double: the square root is not rational).
  double area_scale() const;
};

// The chart of the plane through a, b, c (not collinear), normal (b - a) x (c - a).
PlaneChart chart_of_triangle(const Vec3<Exact>& a, const Vec3<Exact>& b, const Vec3<Exact>& c);

}  // namespace exactvis::shadows
