#pragma once
// The exact discontinuity mesh of area lights on receiver triangles (docs/theory.md section 11): per receiver,
// its discontinuity curves (shadows/discontinuity_curves.hpp), the faces of their exact arrangement of
// segments and conic arcs (shadows/conic_arrangement.hpp), a conforming triangulation for display
// (shadows/receiver_faces.hpp, EEE arcs as chords), each face classified umbra / penumbra / lit by the exact
// backprojection at its sample point (shadows/backprojection.hpp) with the light fraction and irradiance
// there (shadows/point_irradiance.hpp), and the irradiance at every mesh vertex.
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "shadows/backprojection.hpp"
#include "shadows/conic_arrangement.hpp"
#include "shadows/discontinuity_curves.hpp"
#include "shadows/receiver_faces.hpp"
#include "shadows/receiver_frame.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace exactvis::shadows {

struct ShadowOptions {
  std::vector<int> light;                 // indices into Scene::triangles (one or more lights, joined)
  std::vector<std::int64_t> receivers;    // indices; empty: every triangle not in `light`
  bool vertex_irradiance = true;          // backproject at every mesh vertex (for the mesh files)
  bool progress = false;
  bool parallel = true;                   // oneTBB over receivers
  // Include blocker-blocker EV and EEE events (shadows/blocker_events.hpp, shadows/blocker_eee_events.hpp).
  bool blocker_events = true;
  // Backproject each receiver's points against the blockers of its shaft conv(light ∪ receiver)
  // (shadows/receiver_shaft.hpp) instead of an index query per point; off: the per-point index query.
  // The output is identical either way (docs/theory.md section 11; tests/shadows/test_receiver_shaft).
  bool shaft_restriction = true;
  // The blocker-blocker EV cull through the light's tetrahedra (BlockerEvOptions::cull; same events).
  bool blocker_cull = true;
  EeeCurveOptions eee;
  // Every receiver with a conic arc takes the certified polyline arrangement first (CGAL's conic traits
  // only where it is not certified): a cross-check of the two (bench_shadows --polyline).
  bool polyline_first = false;
};

struct FaceShading {
  LightClass light_class = LightClass::Lit;
  double area = 0;                        // 3D area (double: the frame's scale is a square root)
  double area_uv_value = 0;               // area in the receiver's (u, v) frame
  // Exact (u, v) area: set when no face of the receiver is bounded by a conic arc (`area_exact`).
  bool area_exact = false;
  Exact area_uv = 0;
  bool conic_bounded = false;             // some boundary edge of the face is a conic arc
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
  // (u, v) triangulation for display; its triangle_face holds, for each triangle, the index into `faces` of
  // the arrangement face containing its triangulation face's sample (EEE arcs are chords in the mesh).
  ReceiverFaces mesh;
  std::vector<FaceShading> faces;         // the bounded faces of the exact arrangement of the curves
  std::size_t conic_arcs = 0;             // EEE curves in the arrangement as exact conic arcs
  std::size_t chord_curves = 0;           // EEE curves entered as chords (degenerate conic, see conic_arrangement)
  // CGAL's conic arrangement failed on this receiver (conic_arrangement.hpp): `faces` are then the
  // triangulation's faces (EEE arcs as chords), as before the arrangement existed.
  bool arrangement_failed = false;
  bool polyline_arrangement = false;      // faces from the certified polyline fallback (conic_arrangement.hpp)
  std::vector<Vec3<Exact>> vertices;      // mesh vertices in 3D (exact)
  std::vector<double> vertex_irradiance;  // empty unless ShadowOptions::vertex_irradiance
};

struct ShadowStats {
  std::uint64_t ev_events = 0, eee_events = 0;
  std::uint64_t blocker_ev_events = 0;    // blocker-blocker EV events with a kept interval
  std::uint64_t blocker_eee_events = 0;   // blocker-blocker EEE events (with a free interval)
  std::uint64_t backprojections = 0;
  std::uint64_t conic_arcs = 0, chord_curves = 0;    // over all receivers
  std::uint64_t arrangement_failures = 0;            // receivers whose conic arrangement failed
  // Receivers whose faces come from the certified polyline arrangement (shadows/polyline_arrangement.hpp:
  // exact faces, double areas) after CGAL's conic traits failed, and its chords over those receivers.
  std::uint64_t polyline_arrangements = 0, polyline_pieces = 0;
  // ShadowOptions::polyline_first: receivers where CGAL's conic arrangement was built too, and those where
  // its face count differs from the polyline arrangement's.
  std::uint64_t cross_checked = 0, cross_mismatches = 0;
  // Arcs whose end pieces entered as chords after a first CGAL failure, and faces (plus lenses) without a
  // certified sample (conic_arrangement.hpp).
  std::uint64_t trimmed_arcs = 0, uncertified_samples = 0;
  // Shaft restriction (ShadowOptions::shaft_restriction): triangles meeting the boxes of light triangle and
  // receiver, those kept by the exact shaft test (both summed over receivers and light triangles), and
  // backprojected points outside their closed receiver (indexed backprojection instead; expected 0).
  std::uint64_t shaft_box_candidates = 0, shaft_candidates = 0, shaft_outside_points = 0;
  double seconds_events = 0, seconds_receivers = 0;  // events: EV (light and blocker-blocker) + EEE + curves
  double seconds_ev = 0, seconds_eee = 0;  // seconds_ev includes seconds_blocker_ev, seconds_eee _blocker_eee
  double seconds_blocker_ev = 0, seconds_blocker_eee = 0;
};

struct ShadowResult {
  std::vector<ReceiverShadows> receivers;  // in the order of ShadowOptions::receivers (or of the scene)
  ShadowStats stats;
};

// Input: a receiver's discontinuity curves and its frame. Output: the curves in the receiver's (u, v) frame
// as the exact arrangement takes them (conic_arrangement.hpp): every point mapped exactly, EEE curves with
// their conic, the others polylines; same order as `curves`. Cost: O(points).
std::vector<ArrangementCurve> arrangement_curves(const std::vector<DiscontinuityCurve>& curves,
                                                 const ReceiverFrame& frame);

// Input: scene (loaded, with the light's triangles in it), options (light non-empty). Output: the mesh.
// Exact except where the types say double. Cost: the light-restricted EV and EEE enumeration
// (docs/performance.md), then per receiver its curves' triangulation and one backprojection per face and
// per mesh vertex.
ShadowResult compute_shadows(const Scene& scene, const ShadowOptions& options);

}  // namespace exactvis::shadows
