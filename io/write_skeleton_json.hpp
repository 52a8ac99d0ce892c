#pragma once
// JSON and text forms of the 3D visibility skeleton (docs/cli.md "skeleton"; the shape is issue 14's).
#include "kernel/scene.hpp"
#include "skeleton/visibility_skeleton_3d.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace exactvis {

// Which nodes and arcs to write (indices into the skeleton, increasing); see skeleton_selection.
struct SkeletonSelection {
  std::vector<int> nodes, arcs;
};

// Everything: all nodes and arcs.
SkeletonSelection full_selection(const Skeleton3D& skeleton);

// Input: the scene, its skeleton and a selection. Output (keys in this order):
// {"counts": {"nodes": {"VV": n, "VEE": n, "EEEE": n, "FVE": n, "FEE": n, "VEF": n, "EEEF": n, "EEP": n,
//   "VEFF": n, "degenerate": n}, "arcs": {"EV": n, "EEE": n}},
//  "nodes": [{"kind", "vertices": [ids], "edges": [[a, b], ...], "faces": [triangle ids], ("branch": k,
//   EEEE only), "line": {"through": [P, Q]}, "ends": [END, END], "valid": bool, "arcs": [indices]}, ...],
//  "arcs": [{"kind": "EV", "vertex": v, "edge": [a, b], "t": [t0, t1], "nodes": [i, j], "ends": [END, END]}
//   | {"kind": "EEE", "edges": [[a, b], [c, d], [e, f]], "t": [t0, t1], "nodes": [i, j], "ends": [..]}, ...]}
// with END = {"triangle": id, "object": name} or null. P, Q are the node's spanned segment ends (exact
// coordinates: numbers, "num/den" or "a+b*sqrt(c)" as in `events`); node "ends" are the objects beyond P
// and beyond Q; arc "ends" are [behind the first generator, beyond the last] (EV: behind V, beyond E).
// Node counts by kind count the valid nodes; "degenerate" counts the arc ends that fail the validity test
// (skeleton/node_validity.hpp; they are listed with "valid": false).
// Indices refer to the written lists (renumbered for a pair slice); counts count the written lists.
nlohmann::ordered_json skeleton_to_json(const Scene& scene, const Skeleton3D& skeleton, const SkeletonSelection& sel);

// The text form: counts by node kind and arc kind, and the time, e.g.
// "nodes: 12 (VV 4, VEE 6, EEEE 2, FVE 0, FEE 0, VEF 0, EEEF 0, EEP 0, VEFF 0, degenerate 0)\narcs: 20 (EV 16, EEE 4)\n
// time: 0.012 s\n".
std::string skeleton_to_text(const Skeleton3D& skeleton, const SkeletonSelection& sel, double seconds);

}  // namespace exactvis
