#pragma once
// Job façade: the 3D visibility skeleton (nodes: extremal stabbing lines; arcs: the free intervals of the EV
// and EEE critical line sets cut at the nodes), what `exactvis skeleton` computes (docs/cli.md "skeleton",
// definitions in docs/theory.md section 9).
//
//   #include <exactvis/api/skeleton.hpp>
//   exactvis::Scene scene = exactvis::load_scene("scene.obj");
//   exactvis::api::SkeletonRequest req;
//   req.pair = exactvis::api::parse_skeleton_pair(scene, "box,ground");   // optional: one object pair
//   exactvis::Skeleton3D sk = exactvis::api::skeleton(scene, req);
//   nlohmann::ordered_json j = exactvis::api::skeleton_json(scene, sk);   // `skeleton --json`
//
// Conventions: ids are the scene's (vertex ids, edges [a, b] with a < b, stable triangle ids); exact numbers
// in JSON are numbers when exactly doubles, else "num/den" or "a+b*sqrt(c)"; a node's or arc's end objects
// are the first triangles met beyond its generators (null: the line leaves the scene).
#include "kernel/scene.hpp"
#include "skeleton/skeleton_pair.hpp"
#include "skeleton/visibility_skeleton_3d.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <utility>

namespace exactvis::api {

struct SkeletonRequest {
  // Only the nodes and arcs whose maximal free segments end on these two objects (either order), built
  // lazily (skeleton/skeleton_pair.hpp); std::nullopt: the whole skeleton.
  std::optional<std::pair<SkeletonPairSide, SkeletonPairSide>> pair;
  bool progress_bar = false;  // progress bars on stderr
};

// `--pair A,B`: each side an object's exact name, else a stable triangle id of the scene. Throws
// std::invalid_argument("--pair 'A,B': expected two objects A,B (object names or triangle ids)") or
// ("--pair 'A,Z': 'Z' is neither an object name nor a triangle id of the scene").
std::pair<SkeletonPairSide, SkeletonPairSide> parse_skeleton_pair(const Scene& scene, const std::string& spec);

// Input: a scene and a request. Output: the skeleton (exact; with a pair, exactly that pair's slice of the
// full skeleton). Cost: the EV and EEE enumerations of `events` dominate (docs/performance.md).
Skeleton3D skeleton(const Scene& scene, const SkeletonRequest& request);

// The JSON `exactvis skeleton --json` prints (docs/cli.md): {"counts", "nodes", "arcs"}, every node and arc.
nlohmann::ordered_json skeleton_json(const Scene& scene, const Skeleton3D& skeleton);

}  // namespace exactvis::api
