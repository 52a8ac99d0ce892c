#pragma once
// Job façade: the 2D visibility complex of a planar scene (free bitangents, edges, faces), what `exactvis
// complex2d` computes (docs/cli.md "complex2d"; skeleton/visibility_complex_2d.hpp for the definitions).
//
//   #include <exactvis/api/complex2d.hpp>
//   exactvis::Scene2D scene = exactvis::load_scene2d("scene2d.json");
//   exactvis::VisibilityComplex2D cx = exactvis::visibility_complex(scene);
//   nlohmann::ordered_json j = exactvis::api::complex2d_json(scene, cx);  // `complex2d --json`
//
// Conventions: coordinates are exact rationals (JSON numbers when exactly doubles, else "num/den"); a
// bitangent is named by its two vertices and objects and its kind (L/R: which side of the line the objects
// lie on); its maximal free segment ends on an object or at infinity (null).
#include "planar/scene2d.hpp"
#include "skeleton/visibility_complex_2d.hpp"

#include <nlohmann/json.hpp>

namespace exactvis::api {

// Input: the scene and its complex. Output: the JSON document `exactvis complex2d --json` prints:
// {"counts", "bitangents", "edges", "faces", "visibility_graph", "gluing_consistent"} in that order.
nlohmann::ordered_json complex2d_json(const Scene2D& scene, const VisibilityComplex2D& cx);

}  // namespace exactvis::api
