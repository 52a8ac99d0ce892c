#pragma once
// The critical line of a free EEE arc at an algebraic parameter (in Q(sqrt D)), and the exact checks that make
// the aspect at an irrational crossing of that arc with a free arc of a great circle the intersection of the
// aspects of the circle's two pieces next to it (docs/theory.md 10.11, "Irrational crossings").
#include "aspect/direction_event_arcs.hpp"
#include "kernel/root_number.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <string>


namespace exactvis {

// Input: a free EEE arc and its parameter t (exact, possibly irrational). Output: empty when the EEE line at t
// (through P(t) = A1 + t (B1 - A1), direction f(t)) meets no scene edge (closed segment) other than its three
// generator edges: then near its image point only the three edges' images pass, in front of a constant
// background, and the line is the critical line of no other family (an EV line through V meets the edges at
// V, another EEE line a fourth edge); else one line naming the edge. Exact (Q(sqrt D) arithmetic); O(edges).
std::string eee_line_meets_only_its_edges(const Scene& scene, const DirectionEventArc& arc, const RootNumber& t);

// The arc's direction o f(t) at an exact parameter t, in doubles (for reports and tests, never for decisions).
std::array<double, 3> eee_direction_approx(const Scene& scene, const DirectionEventArc& arc, const RootNumber& t);

}  // namespace exactvis
