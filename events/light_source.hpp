#pragma once
// The light of light-restricted events: a named object of the scene, or a polygon given on the command line.
#include "kernel/scene.hpp"

#include <string>
#include <vector>

namespace exactvis {

struct LightSource {
  std::vector<int> triangles;  // indices into Scene::triangles
  bool appended = false;       // true when a polygon was added to the scene
  std::string name;            // object name
};

// Input: the scene and a spec: the exact name of a scene object, or a polygon "x,y,z;x,y,z;x,y,z[;...]"
// (planar or not, >= 3 points, fan-triangulated from its first point; every fan triangle must have non-zero
// area). A polygon is appended to `scene` as object "light": its vertices get the next vertex ids in the
// order given, its triangles the next triangle ids. Output: the light. Throws std::invalid_argument with a
// one-line message for an unknown name or a malformed / degenerate polygon.
LightSource select_light(Scene& scene, const std::string& spec);

}  // namespace exactvis
