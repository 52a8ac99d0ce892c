#pragma once
// The exact discontinuity mesh of area lights on receiver triangles (docs/theory.md section 11): per receiver,
// its discontinuity curves (shadows/discontinuity_curves.hpp), the faces they cut and the conforming
// triangulation (shadows/receiver_faces.hpp), each face classified umbra / penumbra / lit by the exact
// backprojection at its sample point (shadows/backprojection.hpp) with the light fraction and irradiance
// there (shadows/point_irradiance.hpp), and the irradiance at every mesh vertex.
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "shadows/backprojection.hpp"
#include "shadows/discontinuity_curves.hpp"
#include "shadows/receiver_faces.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::shadows {

struct ShadowOptions {
  std::vector<int> light;                 // indices into Scene::triangles (one or more lights, joined)
  std::vector<std::int64_t> receivers;    // indices; empty: every triangle not in `light`
  bool vertex_irradiance = true;          // backproject at every mesh vertex (for the mesh files)
  bool progress = false;
  bool parallel = true;                   // oneTBB over receivers
  EeeCurveOptions eee;
};

struct FaceShading {
  LightClass light_class = LightClass::Lit;
  double area = 0;                        // 3D area (double: the frame's scale is a square root)
  Exact area_uv = 0;                      // exact area in the receiver's (u, v) frame
  Vec3<Exact> sample;                     // strictly inside the face
  bool fraction_exact = true;
  Exact fraction = 1;
  double fraction_value = 1;
  double irradiance = 0;
  std::vector<std::int64_t> blockers;     // stable ids of triangles cutting the backprojection
  std::vector<VisibleLightPart> visible;  // the backprojection at `sample`
};

struct ReceiverShadows {
  std::int64_t triangle = -1;             // index into Scene::triangles
  std::vector<DiscontinuityCurve> curves;
  ReceiverFaces mesh;                     // (u, v) triangulation and faces
  std::vector<FaceShading> faces;         // parallel to mesh.faces
  std::vector<Vec3<Exact>> vertices;      // mesh vertices in 3D (exact)
  std::vector<double> vertex_irradiance;  // empty unless ShadowOptions::vertex_irradiance
};

struct ShadowStats {
  std::uint64_t ev_events = 0, eee_events = 0;
  std::uint64_t backprojections = 0;
  double seconds_events = 0, seconds_receivers = 0;
};

struct ShadowResult {
  std::vector<ReceiverShadows> receivers;  // in the order of ShadowOptions::receivers (or of the scene)
  ShadowStats stats;
};

// Input: scene (loaded, with the light's triangles in it), options (light non-empty). Output: the mesh.
// Exact except where the types say double. Cost: the light-restricted EV and EEE enumeration
// (docs/performance.md), then per receiver its curves' triangulation and one backprojection per face and
// per mesh vertex.
ShadowResult compute_shadows(const Scene& scene, const ShadowOptions& options);

}  // namespace exactvis::shadows
