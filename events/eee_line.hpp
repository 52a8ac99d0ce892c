#pragma once
// The line of an EEE family at a rational parameter (docs/theory.md section 6): L(t) passes through
// P(t) = A1 + t (B1 - A1) on E1 and meets the supporting lines of E2 and E3. Used for output (end lines,
// event surfaces); the event computation itself is in events/eee_events.cpp.
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <optional>

namespace exactvis {

struct EeeLine {
  Vec3<Exact> point;        // P(t) on E1
  Vec3<Exact> dir;          // direction (n2 x n3 of the planes through P(t) and E2's, E3's lines), != 0
  std::array<Exact, 3> s;   // the line meets generator k's supporting line at point + s[k] dir (s[0] = 0)
};

// Input: the scene and the three edges (vertex ids; E1 = edges[0]), rational t. Output: the line, or
// std::nullopt when it is not defined at t (P(t) on E2's or E3's line, or the transversal is parallel to
// E2's or E3's line there). Exact.
std::optional<EeeLine> eee_line_at(const Scene& scene, const std::array<std::array<int, 2>, 3>& edges,
                                   const Exact& t);

}  // namespace exactvis
