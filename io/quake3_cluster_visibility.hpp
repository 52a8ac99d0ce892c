#pragma once
// Exact visibility between the clusters of a Quake 3 map, to check its visdata (issue #12,
// `exactvis validate --bsp`). Definitions and the reduction to polygon queries: docs/theory.md §8,
// "Cluster visibility".
//
// Cluster B is visible from cluster A iff some closed segment from a point of int A's region to a point of
// int B's region misses every (closed) opaque solid, i.e. iff such segments have positive measure (so its
// ends lie in no solid: an eye inside a brush is no viewpoint). Occluders: `leaves` (the compiled solid
// space: world leaves of cluster -1) or `brushes` (the world model's solid brushes, detail brushes
// included, which may lie inside cluster leaves, straddle portals and overlap each other). The region of a
// cluster is the union of its leaves' exact volumes (io/quake3_geometry.hpp).
//
// Reductions (proved in docs/theory.md §8.1, §8.2): leaves: A and B see each other iff they share a portal
// (a positive-area piece of a face of one of A's leaves and a face of one of B's leaves), or some portal of
// A (a piece shared with a leaf of another non-solid cluster) sees some portal of B in the sense of region/
// polygon_pair_visibility with the solids' exact boundary triangles as occluders. Brushes: the same with
// *openings* in place of portals: the pieces a leaf of A shares with a leaf of any other cluster, cluster
// -1 included, minus the brushes (convex pieces whose relative interiors lie outside every brush).
#include "io/quake3_geometry.hpp"
#include "region/convex_polygon_3.hpp"
#include "region/visibility_options.hpp"
#include "region/witness.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace exactvis::quake3 {

// A portal: the convex polygon where a face of world leaf `leaf` (cluster c >= 0) and a face of world leaf
// `neighbour` (another cluster >= 0) overlap with positive area, the two leaves on opposite sides.
struct Portal {
  region::Polygon3 polygon;
  std::int32_t leaf = 0, neighbour = 0;
  std::int32_t neighbour_cluster = 0;
  Box3 box;  // encloses the polygon (doubles)
};

// Per cluster (0 .. map.cluster_count() - 1), its portals. Exact. Cost: faces grouped by their exact plane,
// then one convex clip per overlapping pair of opposite faces in a plane.
std::vector<std::vector<Portal>> cluster_portals(const BspMap& map, const std::vector<ConvexPolyhedron3>& volumes);

// Per cluster, its openings for brush occluders (docs/theory.md §8.2): every positive-area piece shared by a
// face of one of its world leaves and a face of a world leaf of another cluster or of cluster -1 (opposite
// sides), minus every brush (region::polygon_outside, brush by brush), as convex polygons of positive area
// whose relative interiors lie outside every closed brush; `neighbour_cluster` may be -1. Exact. Cost: the
// pieces as in cluster_portals, then per piece one polygon_outside per brush whose box meets it (a linear
// scan of the brushes' boxes); clusters in parallel (oneTBB).
std::vector<std::vector<Portal>> cluster_openings(const BspMap& map, const std::vector<ConvexPolyhedron3>& volumes,
                                                  const std::vector<OpaqueSolid>& brushes);

struct ClusterVisibility {
  bool visible = false;
  // When visible: p in A's region, q in B's region (closed), the open segment (p, q) missing every closed
  // solid, and p, q in no solid (so the closed segment misses them too); exact, rounded to doubles when the rounded
  // segment passes the same exact checks (options.round_witness).
  std::optional<region::Witness> witness;
  std::int64_t polygon_queries = 0;  // exact portal-to-portal queries made
};

// Everything the cluster checks share: leaf volumes, cluster regions, portals (leaves) or openings (brushes)
// and the opaque solids (exact volumes and boundary triangles with double boxes). Queries are const and
// thread-safe.
class ClusterVisibilityChecker {
 public:
  ClusterVisibilityChecker(const BspMap& map, Occluders occluders);

  int cluster_count() const { return static_cast<int>(regions_.size()); }
  bool region_empty(int cluster) const { return regions_[static_cast<std::size_t>(cluster)].leaves.empty(); }
  // Per cluster: its portals (Occluders::Leaves) or its openings (Occluders::Brushes).
  const std::vector<std::vector<Portal>>& portals() const { return portals_; }

  // Exact visibility from cluster a's region to cluster b's (a != b; 0 <= a, b < cluster_count(), else
  // std::out_of_range). Deterministic for a given options.seed. Cost: a shared portal decides at once;
  // otherwise random portal-to-portal segments (exactly checked), then one exact query per portal pair until
  // one is visible (all of them when hidden).
  ClusterVisibility check(int a, int b, const region::VisibilityOptions& options = {}) const;

 private:
  struct Solid {
    std::vector<std::array<RationalPoint3, 3>> triangles;
    Box3 box;
    ConvexPolyhedron3 volume;
  };
  std::vector<std::array<RationalPoint3, 3>> occluders_meeting(const Box3& box) const;
  bool is_witness(const region::Witness& w) const;
  bool in_region(int cluster, const RationalPoint3& x) const;  // in the closed region (exact)
  // The vertex centroid of the cluster's first leaf containing x (x itself if none does).
  RationalPoint3 leaf_centre(int cluster, const RationalPoint3& x) const;
  ClusterVisibility check_exact(int a, int b, const region::VisibilityOptions& options) const;

  std::vector<ConvexPolyhedron3> volumes_;
  std::vector<ClusterRegion> regions_;
  std::vector<std::vector<Portal>> portals_;
  std::vector<Solid> solids_;
};

}  // namespace exactvis::quake3
