#include "planar/scene2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace exactvis {
namespace {

std::string where(const Point2& p) {
  std::ostringstream s;
  s << "(" << p.ax << ", " << p.ay << ")";
  return s.str();
}

std::string where_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

Exact twice_area(const std::vector<Point2>& r) {
  Exact a = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point2& p = r[i];
    const Point2& q = r[(i + 1) % r.size()];
    a += p.x * q.y - p.y * q.x;
  }
  return a;
}

// a.y > p.y, exact; decided from the interval enclosures when they do not overlap.
bool above(const Point2& a, const Point2& p) {
  if (a.iy.inf() > p.iy.sup()) return true;
  if (a.iy.sup() < p.iy.inf()) return false;
  return a.y > p.y;
}

// p certainly outside the bounding box of segment ab (interval enclosures; never wrong, may say false).
bool outside_box(const Point2& a, const Point2& b, const Point2& p) {
  return p.ix.sup() < std::min(a.ix.inf(), b.ix.inf()) || p.ix.inf() > std::max(a.ix.sup(), b.ix.sup()) ||
         p.iy.sup() < std::min(a.iy.inf(), b.iy.inf()) || p.iy.inf() > std::max(a.iy.sup(), b.iy.sup());
}


struct EdgeRef {
  int a, b;        // vertex ids
  double lo, hi;   // x-extent (enclosing), for the sweep filter
};

void check_edges(const Scene2D& s) {
  const int n = s.num_vertices();
  std::vector<EdgeRef> edges;
  edges.reserve(n);
  for (int v = 0; v < n; ++v) {
    const Point2& a = s.points[v];
    const Point2& b = s.points[s.next[v]];
    edges.push_back({v, s.next[v], std::min(a.ix.inf(), b.ix.inf()), std::max(a.ix.sup(), b.ix.sup())});
  }
  std::sort(edges.begin(), edges.end(), [](const EdgeRef& x, const EdgeRef& y) { return x.lo < y.lo; });
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const EdgeRef& e = edges[i];
    const Point2 &a = s.points[e.a], &b = s.points[e.b];
    for (std::size_t j = i + 1; j < edges.size() && edges[j].lo <= e.hi; ++j) {
      const EdgeRef& f = edges[j];
      const Point2 &c = s.points[f.a], &d = s.points[f.b];
      if (e.b == f.a || f.b == e.a) {  // consecutive: must not fold back onto each other
        const int shared = e.b == f.a ? e.b : e.a;
        const int other_e = shared == e.b ? e.a : e.b;
        const int other_f = shared == f.a ? f.b : f.a;
        if (e.b == f.a && f.b == e.a) continue;  // impossible for rings of >= 3 vertices
        const Point2 &o = s.points[shared], &p = s.points[other_e], &q = s.points[other_f];
        if (orientation2(o, p, q) == Sign::Zero && dot_sign(o, p, o, q) == Sign::Positive)
          throw Scene2DError("consecutive edges overlap at vertex " + where(o));
        continue;
      }
      if (segments_intersect(a, b, c, d))
        throw Scene2DError("polygon edges intersect: " + where(a) + "-" + where(b) + " and " + where(c) + "-" +
                           where(d) + " (polygons must be simple and disjoint)");
    }
  }
}

}  // namespace

bool inside_ring(const std::vector<Point2>& pts, int first, int size, const Point2& p) {
  bool in = false;
  for (int i = 0; i < size; ++i) {
    const Point2& a = pts[first + i];
    const Point2& b = pts[first + (i + 1) % size];
    const bool a_above = above(a, p), b_above = above(b, p);
    if (a_above == b_above) continue;
    // edge crosses the horizontal line through p; is the crossing right of p?
    const Sign o = orientation2(a, b, p);
    if ((o == Sign::Positive) == b_above) in = !in;
  }
  return in;
}

bool on_ring(const std::vector<Point2>& pts, int first, int size, const Point2& p) {
  for (int i = 0; i < size; ++i) {
    const Point2& a = pts[first + i];
    const Point2& b = pts[first + (i + 1) % size];
    if (outside_box(a, b, p)) continue;
    if (orientation2(a, b, p) == Sign::Zero && dot_sign(p, a, p, b) != Sign::Positive) return true;
  }
  return false;
}

Scene2D make_scene2d(const std::vector<PolygonInput2D>& polygons) {
  Scene2D s;
  s.num_objects = static_cast<int>(polygons.size());
  for (int obj = 0; obj < s.num_objects; ++obj) {
    const auto& rings = polygons[obj].rings;
    if (rings.empty()) throw Scene2DError("polygon " + std::to_string(obj) + " has no vertices");
    for (std::size_t r = 0; r < rings.size(); ++r) {
      const auto& ring = rings[r];
      const std::string name = "polygon " + std::to_string(obj) + (r ? " hole " + std::to_string(r - 1) : "");
      if (ring.size() < 3) throw Scene2DError(name + " has fewer than 3 vertices");
      const Exact area = twice_area(ring);
      if (CGAL::sign(area) == CGAL::ZERO) throw Scene2DError(name + " has zero area");
      const bool hole = r > 0;
      // object on the left: outer ring counterclockwise (area > 0), hole clockwise
      const bool reverse = hole ? (CGAL::sign(area) > 0) : (CGAL::sign(area) < 0);
      Ring2D rg;
      rg.first = s.num_vertices();
      rg.size = static_cast<int>(ring.size());
      rg.object = obj;
      rg.hole = hole;
      const int ring_id = static_cast<int>(s.rings.size());
      for (int i = 0; i < rg.size; ++i) {
        const int src = reverse ? (rg.size - 1 - i) : i;
        s.points.push_back(ring[src]);
        s.ring_of.push_back(ring_id);
        s.input_index.push_back(src);
        s.next.push_back(rg.first + (i + 1) % rg.size);
        s.prev.push_back(rg.first + (i + rg.size - 1) % rg.size);
      }
      s.rings.push_back(rg);
    }
  }
  // duplicate vertices
  {
    std::vector<int> order(s.num_vertices());
    for (int i = 0; i < s.num_vertices(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      const Point2 &p = s.points[a], &q = s.points[b];
      return p.x < q.x || (p.x == q.x && p.y < q.y);
    });
    for (std::size_t i = 1; i < order.size(); ++i)
      if (s.points[order[i]] == s.points[order[i - 1]])
        throw Scene2DError("duplicate vertex " + where(s.points[order[i]]));
  }
  check_edges(s);
  // nesting: rings are now pairwise disjoint, so one vertex decides containment
  const auto& P = s.points;
  for (std::size_t r = 0; r < s.rings.size(); ++r) {
    const Ring2D& R = s.rings[r];
    const Point2& p = P[R.first];
    if (R.hole) {
      int o = static_cast<int>(r);
      while (s.rings[o].hole) --o;
      if (!inside_ring(P, s.rings[o].first, s.rings[o].size, p))
        throw Scene2DError("hole of polygon " + std::to_string(R.object) + " is not inside its outer boundary");
      for (std::size_t h = o + 1; h < s.rings.size() && s.rings[h].object == R.object; ++h)
        if (h != r && inside_ring(P, s.rings[h].first, s.rings[h].size, p))
          throw Scene2DError("holes of polygon " + std::to_string(R.object) + " are nested");
      continue;
    }
    // an outer ring must not lie in another object's solid part
    for (std::size_t o = 0; o < s.rings.size(); ++o) {
      const Ring2D& O = s.rings[o];
      if (O.hole || O.object == R.object) continue;
      if (!inside_ring(P, O.first, O.size, p)) continue;
      bool in_hole = false;
      for (std::size_t h = o + 1; h < s.rings.size() && s.rings[h].object == O.object; ++h)
        if (inside_ring(P, s.rings[h].first, s.rings[h].size, p)) in_hole = true;
      if (!in_hole)
        throw Scene2DError("polygons " + std::to_string(O.object) + " and " + std::to_string(R.object) +
                           " overlap (one lies inside the other)");
    }
  }
  return s;
}

namespace {

// Bounding box of the vertices' interval enclosures ([0,1]^2 for an empty scene).
struct VertexBox {
  double lo_x = 0, lo_y = 0, hi_x = 1, hi_y = 1;
};

VertexBox vertex_box(const Scene2D& s) {
  VertexBox b;
  if (s.points.empty()) return b;
  b.lo_x = b.hi_x = s.points[0].ax;
  b.lo_y = b.hi_y = s.points[0].ay;
  for (const Point2& p : s.points) {
    b.lo_x = std::min(b.lo_x, p.ix.inf());
    b.hi_x = std::max(b.hi_x, p.ix.sup());
    b.lo_y = std::min(b.lo_y, p.iy.inf());
    b.hi_y = std::max(b.hi_y, p.iy.sup());
  }
  return b;
}

// A frame corner below `lo` (outward = -1) or above `hi` (outward = +1): the integer floor/ceil of the
// widened value, or the next double when rounding left it on the vertex box (huge coordinates, m = 1).
double outward(double v, double m, int direction) {
  const double inf = std::numeric_limits<double>::infinity();
  const double c = direction < 0 ? std::floor(v - m) : std::ceil(v + m);
  if (direction < 0 ? c < v : c > v) return c;
  return std::nextafter(v, direction * inf);
}

FrameBox2D frame_box_of(const VertexBox& b, double margin_ratio) {
  FrameBox2D f;
  if (!(margin_ratio >= 0) || !std::isfinite(margin_ratio)) return f;
  // Half sides first, so a scene spanning more than the largest double does not overflow before the margin
  // is applied (halving and doubling are exact; without overflow this is margin * larger side, as before).
  const double half = std::max(b.hi_x / 2 - b.lo_x / 2, b.hi_y / 2 - b.lo_y / 2);
  const double m = std::max(1.0, margin_ratio == 0 ? 0.0 : 2 * (margin_ratio * half));
  f.lo_x = outward(b.lo_x, m, -1);
  f.lo_y = outward(b.lo_y, m, -1);
  f.hi_x = outward(b.hi_x, m, +1);
  f.hi_y = outward(b.hi_y, m, +1);
  f.representable = std::isfinite(f.lo_x) && std::isfinite(f.lo_y) && std::isfinite(f.hi_x) && std::isfinite(f.hi_y);
  return f;
}

bool box_contains(const FrameBox2D& f, const Point2& p) {
  return Exact(f.lo_x) < p.x && p.x < Exact(f.hi_x) && Exact(f.lo_y) < p.y && p.y < Exact(f.hi_y);
}

}  // namespace

FrameBox2D frame_box(const Scene2D& scene, double margin_ratio) {
  return frame_box_of(vertex_box(scene), margin_ratio);
}

Scene2D with_frame(const Scene2D& scene, double margin_ratio) {
  const FrameBox2D f = frame_box(scene, margin_ratio);
  if (!(margin_ratio >= 0) || !std::isfinite(margin_ratio))
    throw Scene2DError("frame margin must be a finite number >= 0");
  if (!f.representable)
    throw Scene2DError("the viewpoint frame (the scene's box widened by margin " + where_number(margin_ratio) +
                       " times its size) reaches beyond the largest double (1.8e308); use a smaller margin");
  Scene2D s = scene;
  // frame: obstacle outside, so the free inside is on the right: clockwise
  const Point2 box[4] = {{f.lo_x, f.lo_y}, {f.lo_x, f.hi_y}, {f.hi_x, f.hi_y}, {f.hi_x, f.lo_y}};
  Ring2D rg;
  rg.first = s.num_vertices();
  rg.size = 4;
  rg.object = s.num_objects;
  rg.hole = true;
  const int ring_id = static_cast<int>(s.rings.size());
  for (int i = 0; i < 4; ++i) {
    s.points.push_back(box[i]);
    s.ring_of.push_back(ring_id);
    s.input_index.push_back(i);
    s.next.push_back(rg.first + (i + 1) % 4);
    s.prev.push_back(rg.first + (i + 3) % 4);
  }
  s.rings.push_back(rg);
  s.frame_ring = ring_id;
  return s;
}

bool frame_contains(const Scene2D& framed, const Point2& p) {
  const Ring2D& fr = framed.rings[framed.frame_ring];
  const Point2 &lo = framed.points[fr.first], &hi = framed.points[fr.first + 2];
  return lo.x < p.x && p.x < hi.x && lo.y < p.y && p.y < hi.y;
}

Scene2D with_frame_around(const Scene2D& scene, const std::vector<Point2>& points, double margin_ratio) {
  const VertexBox b = vertex_box(scene);
  FrameBox2D f = frame_box_of(b, margin_ratio);
  const auto contains_all = [&](const FrameBox2D& box) {
    return std::all_of(points.begin(), points.end(), [&](const Point2& p) { return box_contains(box, p); });
  };
  // Each widening more than doubles the margin, so this ends after at most ~1100 steps (then the margin
  // overflows and the next frame is not representable).
  while (f.representable && !contains_all(f)) {
    const double wider = 2 * margin_ratio + 1;
    const FrameBox2D g = frame_box_of(b, wider);
    if (!g.representable) {
      // The doubling overshot the double range: the widest representable margin in between (bisection)
      // is the last chance for points near the largest double.
      double ok = margin_ratio, bad = std::min(wider, std::numeric_limits<double>::max());
      for (int i = 0; i < 200 && ok < bad && std::nextafter(ok, bad) < bad; ++i) {
        const double mid = ok / 2 + bad / 2;
        (frame_box_of(b, mid).representable ? ok : bad) = mid;
      }
      if (contains_all(frame_box_of(b, ok))) margin_ratio = ok;
      break;
    }
    margin_ratio = wider;
    f = g;
  }
  return with_frame(scene, margin_ratio);
}

bool on_boundary(const Scene2D& scene, const Point2& p) {
  for (const Ring2D& r : scene.rings)
    if (on_ring(scene.points, r.first, r.size, p)) return true;
  return false;
}

bool inside_obstacle(const Scene2D& scene, const Point2& p) {
  if (on_boundary(scene, p)) return false;
  // even-odd over all rings gives "inside some object" because rings are disjoint and properly nested,
  // except for the frame, whose outside is the obstacle.
  bool in = false;
  for (std::size_t r = 0; r < scene.rings.size(); ++r) {
    const Ring2D& R = scene.rings[r];
    const bool inside = inside_ring(scene.points, R.first, R.size, p);
    if (static_cast<int>(r) == scene.frame_ring) {
      if (!inside) return true;
      continue;
    }
    if (inside) in = !in;
  }
  return in;
}

}  // namespace exactvis
