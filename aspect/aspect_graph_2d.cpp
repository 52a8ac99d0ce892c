#include "aspect/aspect_graph_2d.hpp"

#include "util/progress_bar.hpp"
#include "skeleton/visibility_complex_2d.hpp"
#include "skeleton/visibility_graph_2d.hpp"
#include "skeleton/visibility_polygon_2d.hpp"
#include "util/union_find.hpp"

#include <CGAL/Arr_observer.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <numeric>
#include <optional>
#include <set>

namespace exactvis {
namespace {

// Cartesian kernel over a lazy exact number type, not CGAL's Epeck: Epeck computes constructions first in
// interval arithmetic and trusts the kind of result found there, and CGAL's line-line intersection reports
// "no intersection" when its interval numerators overflow (coordinates beyond ~1e102, whose cubes overflow),
// which made the arrangement sweep dereference an empty result. Lazy_exact_nt's finiteness test falls back to
// the exact value, so every decision here is exact for any double input. Same speed on the benchmark grids.
using K = CGAL::Simple_cartesian<CGAL::Lazy_exact_nt<mpq_class>>;
using Traits = CGAL::Arr_segment_traits_2<K>;
using Arr = CGAL::Arrangement_2<Traits>;

K::Point_2 to_cgal(const Point2& p) {
  return K::Point_2(K::FT(mpq_class(p.x.mpq())), K::FT(mpq_class(p.y.mpq())));
}
Point2 from_cgal(const K::Point_2& p) {
  const mpq_class x = CGAL::exact(p.x()), y = CGAL::exact(p.y());
  return Point2(Exact(x.get_mpq_t()), Exact(y.get_mpq_t()));
}

// An exact point strictly inside bounded face f: from the midpoint of an outer boundary edge, go into the
// face (its left side) half-way to the first boundary point met.
K::Point_2 interior_point(Arr::Face_const_handle f) {
  const auto h = f->outer_ccb();
  const K::Point_2 s = h->source()->point(), t = h->target()->point();
  const K::Point_2 m = CGAL::midpoint(s, t);
  const K::Vector_2 n(-(t.y() - s.y()), t.x() - s.x());
  std::optional<K::FT> best;
  auto scan = [&](Arr::Ccb_halfedge_const_circulator c) {
    const auto start = c;
    do {
      if (c != h && c != h->twin()) {
        const K::Point_2 a = c->source()->point(), b = c->target()->point();
        const K::Vector_2 e = b - a;
        const K::FT den = n.x() * e.y() - n.y() * e.x();
        if (den != 0) {
          const K::Vector_2 am = a - m;
          const K::FT lambda = (am.x() * e.y() - am.y() * e.x()) / den;
          const K::FT mu = (am.x() * n.y() - am.y() * n.x()) / den;
          if (lambda > 0 && mu >= 0 && mu <= 1 && (!best || lambda < *best)) best = lambda;
        }
      }
    } while (++c != start);
  };
  scan(f->outer_ccb());
  for (auto it = f->inner_ccbs_begin(); it != f->inner_ccbs_end(); ++it) scan(*it);
  return m + (*best / 2) * n;
}

std::vector<Point2> ccb_points(Arr::Ccb_halfedge_const_circulator c) {
  std::vector<Point2> out;
  const auto start = c;
  do out.push_back(from_cgal(c->source()->point()));
  while (++c != start);
  return out;
}

bool inside_ring_points(const std::vector<Point2>& r, const Point2& p, bool* on_edge) {
  bool in = false;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point2 &a = r[i], &b = r[(i + 1) % r.size()];
    const Sign o = orientation2(a, b, p);
    if (o == Sign::Zero && dot_sign(p, a, p, b) != Sign::Positive) *on_edge = true;
    if ((a.y > p.y) != (b.y > p.y) && (o == Sign::Positive) == (b.y > p.y)) in = !in;
  }
  return in;
}

// Reports the arrangement sweep's progress: CGAL's sweep creates each edge when it reaches the edge's right
// end, so the x of that end, relative to the frame's x-range, grows from 0 to 1 (display only, doubles).
class SweepProgress : public CGAL::Arr_observer<Arr> {
 public:
  static constexpr std::uint64_t kSteps = 1000;
  SweepProgress(Arr& arr, ProgressBar& bar, double x0, double x1) : CGAL::Arr_observer<Arr>(arr), bar_(bar), x0_(x0), x1_(x1) {}
  void after_create_edge(Arr::Halfedge_handle e) override {
    const double x = CGAL::to_double(e->curve().right().x());
    const double f = x1_ > x0_ ? (x - x0_) / (x1_ - x0_) : 1.0;
    const auto step = static_cast<std::uint64_t>(std::clamp(f, 0.0, 1.0) * kSteps);
    if (step > done_) {
      bar_.advance(step - done_);
      done_ = step;
    }
  }
  void finish() {
    if (done_ < kSteps) bar_.advance(kSteps - done_);
    done_ = kSteps;
  }

 private:
  ProgressBar& bar_;
  double x0_, x1_;
  std::uint64_t done_ = 0;
};

}  // namespace

AspectGraph2D aspect_graph(const Scene2D& scene, double margin_ratio, bool progress,
                           const std::function<void(std::size_t)>& before_faces) {
  AspectGraph2D g;
  g.framed = with_frame(scene, margin_ratio);
  const Scene2D& s = g.framed;
  const auto& P = s.points;
  const int n_scene = scene.num_vertices();  // frame vertices come after the scene's
  const VisibilityGraph2D vg = visibility_graph(s);
  // candidate events: extensions beyond u of segments (u, w) where the line is tangent at u
  std::vector<std::pair<int, int>> candidates;
  for (const auto& [p, q] : vg.strict_pairs) candidates.emplace_back(p, q), candidates.emplace_back(q, p);
  for (int v = 0; v < n_scene; ++v) candidates.emplace_back(v, s.next[v]), candidates.emplace_back(s.next[v], v);
  std::vector<std::optional<Point2>> event_end(candidates.size());
  {
    ProgressBar bar("aspect2d: event segments", candidates.size(), progress);
    tbb::parallel_for(std::size_t(0), candidates.size(), [&](std::size_t i) {
      const auto [u, w] = candidates[i];
      bar.advance();
      if (u >= n_scene || w >= n_scene) return;
      // direction u - w must point into the open free wedge at u (then the line is tangent there)
      const Point2 ahead(P[u].x + P[u].x - P[w].x, P[u].y + P[u].y - P[w].y);
      if (!in_free_wedge(s, u, P[u], ahead)) return;
      const SegmentEnd2D end = first_contact(s, u, P[u], ahead);
      if (end.kind == SegmentEnd2D::Infinity) return;  // impossible inside the frame
      event_end[i] = end.point;
    });
  }
  std::vector<Traits::Segment_2> segs;
  for (int v = 0; v < s.num_vertices(); ++v) segs.emplace_back(to_cgal(P[v]), to_cgal(P[s.next[v]]));
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (event_end[i]) {
      segs.emplace_back(to_cgal(P[candidates[i].first]), to_cgal(*event_end[i]));
      ++g.event_segments;
    }
  Arr arr;
  {
    const Ring2D& fr = s.rings[s.frame_ring];
    ProgressBar bar("aspect2d: arrangement", SweepProgress::kSteps, progress);
    SweepProgress observer(arr, bar, P[fr.first].ax, P[fr.first + 2].ax);
    CGAL::insert(arr, segs.begin(), segs.end());
    observer.finish();
  }
  // faces, samples, aspects
  std::map<Arr::Face_const_handle, int> index;
  std::vector<Arr::Face_const_handle> handles;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (f->is_unbounded()) continue;
    index[f] = static_cast<int>(handles.size());
    handles.push_back(f);
  }
  g.arrangement_faces = handles.size();
  if (before_faces) before_faces(handles.size());
  g.faces.resize(handles.size());
  std::vector<std::vector<int>> aspect(handles.size());
  std::vector<char> free_face(handles.size(), 0);
  ProgressBar bar("aspect2d: faces", handles.size(), progress);
  tbb::parallel_for(std::size_t(0), handles.size(), [&](std::size_t i) {
    AspectFace2D& face = g.faces[i];
    face.outer = ccb_points(handles[i]->outer_ccb());
    for (auto it = handles[i]->inner_ccbs_begin(); it != handles[i]->inner_ccbs_end(); ++it)
      face.holes.push_back(ccb_points(*it));
    face.sample = from_cgal(interior_point(handles[i]));
    if (!inside_obstacle(s, face.sample)) {
      free_face[i] = 1;
      for (int e : visible_edges(s, face.sample))
        if (e < n_scene) aspect[i].push_back(e);
    }
    bar.advance();
  });
  // merge free faces with equal aspects across arrangement edges
  UnionFind uf(static_cast<int>(handles.size()));
  std::vector<std::pair<int, int>> across;  // (face, face) pairs sharing an edge, with the edge
  std::vector<Arr::Halfedge_const_handle> across_edge;
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    const auto f1 = e->face(), f2 = e->twin()->face();
    if (f1->is_unbounded() || f2->is_unbounded()) continue;
    const int a = index.at(f1), b = index.at(f2);
    if (a == b || !free_face[a] || !free_face[b]) continue;
    if (aspect[a] == aspect[b]) uf.unite(a, b);
    else {
      across.emplace_back(a, b);
      across_edge.push_back(e);
    }
  }
  std::map<int, int> region_of_root;
  for (std::size_t i = 0; i < handles.size(); ++i) {
    if (!free_face[i]) continue;
    const int r = uf.find(static_cast<int>(i));
    auto it = region_of_root.find(r);
    if (it == region_of_root.end()) {
      it = region_of_root.emplace(r, static_cast<int>(g.regions.size())).first;
      g.regions.push_back({aspect[i], {}});
    }
    g.faces[i].region = it->second;
    g.regions[it->second].faces.push_back(static_cast<int>(i));
  }
  std::set<std::pair<int, int>> adj;
  for (std::size_t k = 0; k < across.size(); ++k) {
    const int ra = g.faces[across[k].first].region, rb = g.faces[across[k].second].region;
    if (ra == rb) continue;  // same region reached around: an edge inside a region with different sides? no
    adj.insert({std::min(ra, rb), std::max(ra, rb)});
    g.boundaries.push_back({from_cgal(across_edge[k]->source()->point()), from_cgal(across_edge[k]->target()->point())});
  }
  g.adjacency.assign(adj.begin(), adj.end());
  return g;
}

int region_of(const AspectGraph2D& g, const Point2& p) {
  for (const AspectFace2D& f : g.faces) {
    bool on_edge = false;
    if (!inside_ring_points(f.outer, p, &on_edge)) {
      if (on_edge) return -2;
      continue;
    }
    if (on_edge) return -2;
    bool in_hole = false;
    for (const auto& h : f.holes) {
      bool on_hole_edge = false;
      if (inside_ring_points(h, p, &on_hole_edge)) in_hole = true;
      if (on_hole_edge) return -2;
    }
    if (in_hole) continue;
    return f.region;
  }
  return -1;
}

}  // namespace exactvis
