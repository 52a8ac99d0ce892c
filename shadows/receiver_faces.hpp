#pragma once
// The faces of a receiver cut by its discontinuity curves, and the conforming triangulation (docs/theory.md
// section 11, "Faces and mesh").
//
// In the receiver's (u, v) frame, the triangle's three sides and every curve (EV and D0 segments; EEE
// polylines through exact points of the conic) are inserted as constraints into a CGAL constrained Delaunay
// triangulation with exact constructions (crossings of constraints are exact rational points). The faces are
// the classes of triangles connected across unconstrained edges: exactly the bounded faces of the
// arrangement of the constraints. Each face gets an exact sample point (the centroid of its largest
// triangle: strictly inside the face) and its exact (u, v) area.
#include "kernel/number_types.hpp"
#include "shadows/receiver_frame.hpp"

#include <array>
#include <vector>

namespace exactvis::shadows {

struct ReceiverFaces {
  std::vector<std::array<Exact, 2>> vertices;      // (u, v), exact
  std::vector<std::array<int, 3>> triangles;       // counterclockwise in (u, v)
  std::vector<int> triangle_face;                  // face of each triangle
  struct Face {
    Exact area_uv = 0;                             // exact (u, v) area
    std::array<Exact, 2> sample;                   // strictly inside
    int triangles = 0;
  };
  std::vector<Face> faces;
};

// Input: the curves as polylines of exact (u, v) points (each polyline >= 2 points); pieces outside the
// closed unit triangle are clipped away exactly (an EEE arc may overshoot the receiver's side by less than
// its 2^-40 end resolution, see discontinuity_curves.hpp). Output: the triangulation and its faces. Cost: O((n + k) log n) for n constraint points and k
// crossings.
ReceiverFaces receiver_faces(const std::vector<std::vector<std::array<Exact, 2>>>& polylines);

}  // namespace exactvis::shadows
