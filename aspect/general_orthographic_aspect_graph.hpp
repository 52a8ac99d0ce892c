#pragma once
// The exact orthographic aspect graph of a general polyhedral model whose free event arcs are all EV arcs
// (docs/theory.md §10.10): closed solids outside the class of §10.5 such as three boxes in a row.
//
// The free arcs of aspect/direction_event_arcs bound the regions: the aspect is constant on every connected
// set of directions missing them (theory §10.9). Every EV arc lies on the great circle of its family's plane,
// and its ends are rational directions. The partition used is the arrangement of those great circles (with the
// three coordinate circles, so that they span R^3; aspect/great_circle_arrangement, exact), each arc of it
// split at the free arcs' ends strictly inside it: every cell is then either inside the closure of a free arc
// or disjoint from all of them (a cell's interior meets no end). Faces (open, off every circle) and cells
// off every free arc have one aspect on a neighbourhood, so only faces and the cells on free arcs are
// evaluated, by aspect/direction_aspect at an exact rational sample (the other cells take a neighbouring
// face's aspect); aspect/aspect_regions merges cells into regions. Free EEE arcs (conics, theory §10.11) are
// cut at the circles (aspect/eee_arc_insertion) and split the faces they cross; EEE arcs lying on a great circle
// (three edges parallel to one plane) are handled like EV arcs; an EEE arc crossing a free arc of a circle at an
// irrational direction gives that point the intersection of the aspects of the circle's pieces next to it; two
// free EEE arcs crossing inside a face (aspect/eee_crossings) cut each other into segments, the face's components
// are traced as a plane graph (aspect/eee_face_split), and the crossing gets the intersection of the aspects of
// either arc's two segments next to it.
// Models whose EEE arcs fall outside the subset of §10.11 are refused with one line.
#include "aspect/aspect_graph_3d.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace exactvis {

struct GeneralOrthographicResult {
  bool ok = false;
  std::string problem;  // when !ok: one line without the file name
  AspectGraph3 graph;
  std::size_t circles = 0, ev_arcs = 0, eee_arcs = 0, evaluated_cells = 0;
  // Each crossing of a free EEE arc with a free arc of a great circle at an irrational direction (docs/theory.md
  // 10.11, "Irrational crossings"): a double approximation of the direction and its exact aspect (the
  // intersection of the aspects of the circle's two pieces next to it), for tests.
  struct IrrationalCrossing {
    std::array<double, 3> direction{};
    std::vector<std::int64_t> aspect;
  };
  std::vector<IrrationalCrossing> irrational_crossings;
  // Each crossing of two free EEE arcs inside a face of the circles (docs/theory.md 10.11, "EEE x EEE
  // crossings"): a double approximation and its exact aspect (the intersection of the aspects of either arc's two
  // segments next to it), for tests.
  std::vector<IrrationalCrossing> eee_crossings;
};

// Input: a model whose triangles meet only in shared corners and edges. Output: the orthographic aspect graph
// (regions with exact samples; adjacency with one EV event per circle holding the lower cell, a free arc
// through it, and one EEE event per free EEE arc holding it; every cell with a rational sample, its sample and
// sign vector in `sampled_cells` when `with_cells`), or ok = false when a free EEE arc is outside the subset. Cost: the free arcs (aspect/direction_event_arcs: O(v e n log n) EV, O(e^3 n^2) EEE), the O(m^2) cells
// of m circles, and one exact per-direction aspect (O(n) Boolean operations on O(n) polygons) per face and
// per cell on a free arc (with EEE arcs: per cell with a rational sample), on all cores. `progress` (optional)
// receives the fraction done.
GeneralOrthographicResult general_orthographic_aspect_graph(const Scene& scene, void (*progress)(double) = nullptr,
                                                            bool with_cells = true);

}  // namespace exactvis
