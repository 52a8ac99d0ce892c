#include "io/quake3_cluster_visibility.hpp"

#include "kernel/predicates.hpp"
#include "region/polygon_pair_visibility.hpp"

#include <tbb/parallel_for.h>

#include <map>
#include <random>
#include <stdexcept>
#include <string>

namespace exactvis::quake3 {
namespace {

using region::Plane3;
using region::Polygon3;

struct FaceRef {
  std::int32_t leaf = 0;
  int orientation = 0;  // sign of the inward normal's first non-zero coordinate
  Polygon3 polygon;
  Plane3 plane;  // inward
  Box3 box;
};

bool boxes_meet(const Box3& a, const Box3& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

Box3 union_box(const Box3& a, const Box3& b) {
  Box3 u;
  for (int k = 0; k < 3; ++k) {
    u.lo[k] = std::min(a.lo[k], b.lo[k]);
    u.hi[k] = std::max(a.hi[k], b.hi[k]);
  }
  return u;
}

// The part of convex polygon f inside convex polygon h (coplanar, h's plane normal `n`): f clipped by the
// planes through h's edges perpendicular to the common plane. Exact.
Polygon3 overlap(const Polygon3& f, const Polygon3& h, const Vec3<Exact>& n) {
  const RationalPoint3 inside = region::centroid(h);
  Polygon3 out = f;
  for (std::size_t i = 0; i < h.size() && out.size() >= 3; ++i) {
    const RationalPoint3& u = h[i];
    const RationalPoint3& v = h[(i + 1) % h.size()];
    Plane3 pl = region::plane_through(u, v, u + n);
    if (CGAL::sign(pl.value(inside)) < 0) pl = pl.flipped();
    out = region::clip_polygon(out, pl);
  }
  return out;
}

RationalPoint3 vertex_centroid(const ConvexPolyhedron3& v) { return region::centroid(v.vertices); }

// The face pieces between the world leaves of a cluster and the world leaves of any other cluster (and of
// cluster -1 too when `with_solid_leaves`), per cluster.
std::vector<std::vector<Portal>> face_pieces(const BspMap& map, const std::vector<ConvexPolyhedron3>& volumes,
                                             bool with_solid_leaves) {
  // Faces of the world leaves, grouped by their unoriented exact plane.
  std::map<std::array<Exact, 4>, std::vector<FaceRef>> by_plane;
  for (std::size_t leaf = 0; leaf < map.leaves.size(); ++leaf) {
    if (!map.world_leaf[leaf] || volumes[leaf].empty()) continue;
    if (map.leaves[leaf].cluster < 0 && (!with_solid_leaves || map.leaves[leaf].cluster != -1)) continue;
    const ConvexPolyhedron3& vol = volumes[leaf];
    for (const auto& face : vol.faces) {
      FaceRef ref;
      ref.leaf = static_cast<std::int32_t>(leaf);
      for (const int i : face.loop) ref.polygon.push_back(vol.vertices[static_cast<std::size_t>(i)]);
      ref.plane = face.plane;
      ref.box = region::enclosing_box(ref.polygon);
      const Exact& s = face.plane.normal.x != 0 ? face.plane.normal.x
                       : face.plane.normal.y != 0 ? face.plane.normal.y
                                                  : face.plane.normal.z;
      ref.orientation = CGAL::sign(s);
      by_plane[{face.plane.normal.x / s, face.plane.normal.y / s, face.plane.normal.z / s, face.plane.offset / s}]
          .push_back(std::move(ref));
    }
  }
  std::vector<std::vector<Portal>> out(static_cast<std::size_t>(map.cluster_count()));
  const auto n_clusters = static_cast<std::int32_t>(out.size());
  for (const auto& [key, faces] : by_plane) {
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (std::size_t j = i + 1; j < faces.size(); ++j) {
        const FaceRef& f = faces[i];
        const FaceRef& h = faces[j];
        if (f.orientation == h.orientation) continue;
        const std::int32_t cf = map.leaves[static_cast<std::size_t>(f.leaf)].cluster;
        const std::int32_t ch = map.leaves[static_cast<std::size_t>(h.leaf)].cluster;
        if (cf == ch || !boxes_meet(f.box, h.box)) continue;
        Polygon3 piece = overlap(f.polygon, h.polygon, h.plane.normal);
        if (region::is_degenerate(piece)) continue;
        const Box3 box = region::enclosing_box(piece);
        if (cf >= 0 && cf < n_clusters) out[static_cast<std::size_t>(cf)].push_back({piece, f.leaf, h.leaf, ch, box});
        if (ch >= 0 && ch < n_clusters) out[static_cast<std::size_t>(ch)].push_back({piece, h.leaf, f.leaf, cf, box});
      }
  }
  return out;
}

}  // namespace

std::vector<std::vector<Portal>> cluster_portals(const BspMap& map, const std::vector<ConvexPolyhedron3>& volumes) {
  return face_pieces(map, volumes, false);
}

std::vector<std::vector<Portal>> cluster_openings(const BspMap& map, const std::vector<ConvexPolyhedron3>& volumes,
                                                  const std::vector<OpaqueSolid>& brushes) {
  std::vector<std::vector<Portal>> pieces = face_pieces(map, volumes, true);
  std::vector<Box3> boxes(brushes.size());
  for (std::size_t i = 0; i < brushes.size(); ++i) boxes[i] = region::enclosing_box(brushes[i].volume.vertices);
  std::vector<std::vector<Portal>> out(pieces.size());
  tbb::parallel_for(std::size_t(0), pieces.size(), [&](std::size_t c) {
    for (const Portal& piece : pieces[c]) {
      std::vector<Polygon3> left{piece.polygon};
      for (std::size_t i = 0; i < brushes.size() && !left.empty(); ++i) {
        if (!boxes_meet(boxes[i], piece.box)) continue;
        std::vector<Polygon3> next;
        for (const Polygon3& part : left)
          for (Polygon3& rest : region::polygon_outside(part, brushes[i].volume)) next.push_back(std::move(rest));
        left = std::move(next);
      }
      for (Polygon3& part : left) {
        const Box3 box = region::enclosing_box(part);
        out[c].push_back({std::move(part), piece.leaf, piece.neighbour, piece.neighbour_cluster, box});
      }
    }
  });
  return out;
}

ClusterVisibilityChecker::ClusterVisibilityChecker(const BspMap& map, Occluders occluders) {
  volumes_ = leaf_volumes(map);
  regions_ = cluster_regions(map, volumes_);
  if (occluders == Occluders::Leaves) {
    portals_ = cluster_portals(map, volumes_);
    for (std::size_t leaf = 0; leaf < map.leaves.size(); ++leaf) {
      if (!map.world_leaf[leaf] || map.leaves[leaf].cluster != -1 || volumes_[leaf].empty()) continue;
      solids_.push_back({region::boundary_triangles(volumes_[leaf]), region::enclosing_box(volumes_[leaf].vertices),
                         volumes_[leaf]});
    }
  } else {
    const std::vector<OpaqueSolid> brushes = opaque_solids(map, Occluders::Brushes);
    portals_ = cluster_openings(map, volumes_, brushes);
    for (const OpaqueSolid& b : brushes)
      solids_.push_back({region::boundary_triangles(b.volume), region::enclosing_box(b.volume.vertices), b.volume});
  }
}

std::vector<std::array<RationalPoint3, 3>> ClusterVisibilityChecker::occluders_meeting(const Box3& box) const {
  std::vector<std::array<RationalPoint3, 3>> out;
  for (const Solid& s : solids_)
    if (boxes_meet(s.box, box)) out.insert(out.end(), s.triangles.begin(), s.triangles.end());
  return out;
}

// Exact: the open segment misses every solid's boundary and neither end lies in a solid (so the closed
// segment misses every closed solid).
bool ClusterVisibilityChecker::is_witness(const region::Witness& w) const {
  const Box3 box = region::enclosing_box({w.p, w.q});
  for (const Solid& s : solids_) {
    if (!boxes_meet(s.box, box)) continue;
    if (!region::segment_is_free(s.triangles, w.p, w.q)) return false;
    const ConvexPolyhedron3& vol = s.volume;
    if (region::locate(vol, w.p) != region::Containment::Outside || region::locate(vol, w.q) != region::Containment::Outside)
      return false;
  }
  return true;
}

ClusterVisibility ClusterVisibilityChecker::check(int a, int b, const region::VisibilityOptions& options) const {
  ClusterVisibility out = check_exact(a, b, options);
  if (out.witness && options.round_witness) {
    // A witness with double coordinates when one is near: the ends moved towards the centres of their
    // leaves (the closed segment is at positive distance from every closed solid, so a small move keeps
    // it free), rounded, and accepted only after the same exact checks.
    auto rounded = [](const RationalPoint3& x) {
      return RationalPoint3{Exact(CGAL::to_double(x.x)), Exact(CGAL::to_double(x.y)), Exact(CGAL::to_double(x.z))};
    };
    const RationalPoint3 ca = leaf_centre(a, out.witness->p), cb = leaf_centre(b, out.witness->q);
    Exact t(1, 8);
    for (int attempt = 0; attempt < 16; ++attempt, t /= 8) {
      const region::Witness r{rounded(out.witness->p + t * (ca - out.witness->p)),
                              rounded(out.witness->q + t * (cb - out.witness->q))};
      if (in_region(a, r.p) && in_region(b, r.q) && is_witness(r)) {
        out.witness = r;
        break;
      }
    }
  }
  return out;
}

RationalPoint3 ClusterVisibilityChecker::leaf_centre(int cluster, const RationalPoint3& x) const {
  for (const std::int32_t leaf : regions_[static_cast<std::size_t>(cluster)].leaves)
    if (region::locate(volumes_[static_cast<std::size_t>(leaf)], x) != region::Containment::Outside)
      return vertex_centroid(volumes_[static_cast<std::size_t>(leaf)]);
  return x;
}

bool ClusterVisibilityChecker::in_region(int cluster, const RationalPoint3& x) const {
  for (const std::int32_t leaf : regions_[static_cast<std::size_t>(cluster)].leaves)
    if (region::locate(volumes_[static_cast<std::size_t>(leaf)], x) != region::Containment::Outside) return true;
  return false;
}

ClusterVisibility ClusterVisibilityChecker::check_exact(int a, int b, const region::VisibilityOptions& options) const {
  if (a < 0 || b < 0 || a >= cluster_count() || b >= cluster_count())
    throw std::out_of_range("cluster pair (" + std::to_string(a) + ", " + std::to_string(b) + ") is out of range");
  if (a == b) throw std::invalid_argument("cluster pair (" + std::to_string(a) + ", " + std::to_string(a) + "): the same cluster");
  ClusterVisibility out;
  if (region_empty(a) || region_empty(b)) return out;
  const auto& pa = portals_[static_cast<std::size_t>(a)];
  const auto& pb = portals_[static_cast<std::size_t>(b)];

  // A shared portal: a short segment across it, from inside A's leaf to inside B's leaf.
  for (const Portal& p : pa) {
    if (p.neighbour_cluster != b) continue;
    const RationalPoint3 c = region::centroid(p.polygon);
    const RationalPoint3 ca = vertex_centroid(volumes_[static_cast<std::size_t>(p.leaf)]);
    const RationalPoint3 cb = vertex_centroid(volumes_[static_cast<std::size_t>(p.neighbour)]);
    Exact t(1, 2);
    for (int attempt = 0; attempt < 200; ++attempt, t /= 2) {
      const region::Witness w{c + t * (ca - c), c + t * (cb - c)};
      if (region::locate(volumes_[static_cast<std::size_t>(p.leaf)], w.p) != region::Containment::Interior ||
          region::locate(volumes_[static_cast<std::size_t>(p.neighbour)], w.q) != region::Containment::Interior)
        continue;
      if (is_witness(w)) {
        out.visible = true;
        out.witness = w;
        return out;
      }
    }
    throw std::logic_error("cluster visibility: no witness across a shared portal");
  }

  // Random portal-to-portal segments, checked exactly (relint points of portals and openings lie in no solid).
  std::mt19937_64 rng(options.seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(a) * 1000003u +
                      static_cast<std::uint64_t>(b));
  const int rounds = std::max(1, options.samples / 8);
  for (int r = 0; r < rounds; ++r)
    for (const Portal& x : pa)
      for (const Portal& y : pb) {
        const region::Witness w{region::random_interior_point(x.polygon, rng), region::random_interior_point(y.polygon, rng)};
        if (is_witness(w)) {
          out.visible = true;
          out.witness = w;
          return out;
        }
      }

  // The exact queries, one per portal pair.
  region::VisibilityOptions exact_options = options;
  exact_options.samples = std::min(options.samples, 8);
  for (const Portal& x : pa)
    for (const Portal& y : pb) {
      ++out.polygon_queries;
      const auto occ = occluders_meeting(union_box(x.box, y.box));
      const region::PolygonPairVisibility v = region::visible_between_polygons(x.polygon, y.polygon, occ, exact_options);
      if (v.visible) {
        if (!is_witness(*v.witness)) throw std::logic_error("cluster visibility: a portal witness failed the re-check");
        out.visible = true;
        out.witness = v.witness;
        return out;
      }
    }
  return out;
}

}  // namespace exactvis::quake3
