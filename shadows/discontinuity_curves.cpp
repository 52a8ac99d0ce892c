#include "shadows/discontinuity_curves.hpp"

#include "kernel/predicates.hpp"
#include "kernel/rational_between.hpp"
#include "kernel/ray_first_hit.hpp"
#include "region/convex_polygon_3.hpp"
#include "shadows/eee_interval_split.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace exactvis::shadows {
namespace {

using Edge = std::array<int, 2>;

struct LightFeatures {
  std::set<int> vertices;
  std::set<Edge> edges;
  std::set<std::int64_t> ids;  // stable ids of the light triangles
};

LightFeatures light_features(const Scene& scene, const std::vector<int>& light) {
  LightFeatures f;
  for (int li : light) {
    const auto& t = scene.triangles[li];
    f.ids.insert(t.id);
    for (int k = 0; k < 3; ++k) {
      f.vertices.insert(t.v[k]);
      f.edges.insert({std::min(t.v[k], t.v[(k + 1) % 3]), std::max(t.v[k], t.v[(k + 1) % 3])});
    }
  }
  return f;
}

Vec3<Exact> rational_point(const Point3& p) { return to_rational(p); }

Point3 to_double(const Vec3<Exact>& v) { return {CGAL::to_double(v.x), CGAL::to_double(v.y), CGAL::to_double(v.z)}; }

// The point where the line through a and b meets the plane of the frame, if it crosses it in one point.
std::optional<Vec3<Exact>> line_meets_plane(const Vec3<Exact>& a, const Vec3<Exact>& b, const ReceiverFrame& f) {
  const Vec3<Exact> d = b - a;
  const Exact den = dot(f.chart.normal, d);
  if (den == 0) return std::nullopt;
  const Exact s = (f.chart.offset - dot(f.chart.normal, a)) / den;
  return a + s * d;
}

// EV order: 1 when an edge at V other than E's endpoints' lies in the wedge plane (V, E), else 2.
int ev_order(const Scene& scene, const std::map<int, std::set<int>>& neighbours, int v, const Edge& e) {
  const auto it = neighbours.find(v);
  if (it == neighbours.end()) return 2;
  const Point3& V = scene.vertices[v];
  const Point3& A = scene.vertices[e[0]];
  const Point3& B = scene.vertices[e[1]];
  for (int w : it->second) {
    if (w == e[0] || w == e[1]) continue;
    if (orient3d(V, A, B, scene.vertices[w]) == Sign::Zero) return 1;
  }
  return 2;
}

// A rational strictly beyond the irrational parameter `end`, away from `inside`, within 2^-40 of it: an arc
// extended past its true end by so little is a dangling piece (it cannot close a face), while an arc
// stopping short would leave a gap between faces.
Exact beyond(const RootNumber& end, const RootNumber& inside) {
  const RootNumber step(Exact(std::ldexp(1.0, -40)));
  return inside > end ? rational_strictly_between(end - step, end) : rational_strictly_between(end, end + step);
}

}  // namespace

std::optional<DiscontinuityCurve> eee_curve(const Scene& scene, const EeeEvent& event, const RootNumber& t0,
                                            const RootNumber& t1, const Exact& inside, const ReceiverFrame& frame,
                                            int samples) {
  auto point_at = [&](const Exact& t) -> std::optional<Vec3<Exact>> {
    const auto s = eee_generator_segment(scene, event, t);
    if (!s) return std::nullopt;
    return line_meets_plane(s->front, s->front + s->direction, frame);
  };
  Exact q0, q1;
  const bool e0 = root_number_rational(t0, &q0), e1 = root_number_rational(t1, &q1);
  if (!e0) q0 = beyond(t0, RootNumber(inside));
  if (!e1) q1 = beyond(t1, RootNumber(inside));
  const int n = std::max(2, samples);
  DiscontinuityCurve c;
  c.kind = DiscontinuityCurve::Kind::EEE;
  c.order = 2;
  c.edges = event.edges;
  c.t0 = t0;
  c.t1 = t1;
  for (int k = 0; k <= n; ++k) {
    const Exact t = q0 + Exact(k, n) * (q1 - q0);
    auto x = point_at(t);
    if (!x && (k == 0 || k == n)) {  // the extended end has no plane point: stop inside instead
      const RootNumber& end = k == 0 ? t0 : t1;
      x = point_at(rational_strictly_between(end < RootNumber(inside) ? end : RootNumber(inside),
                                             end < RootNumber(inside) ? RootNumber(inside) : end));
    }
    if (!x) return std::nullopt;  // cannot happen inside a free interval (lines there are not singular)
    c.points.push_back(*x);
  }
  c.ends_exact = e0 && e1;
  c.ends = {to_double(c.points.front()), to_double(c.points.back())};
  c.conic = eee_conic(scene, event.edges, frame);
  return c;
}

std::array<Exact, 6> eee_conic(const Scene& scene, const std::array<std::array<int, 2>, 3>& edges,
                               const ReceiverFrame& frame) {
  // n_i(u, v) = c_i + u a_i + v b_i, vectors; det(n1, n2, n3) expanded multilinearly.
  std::array<std::array<Vec3<Exact>, 3>, 3> terms;  // [i][0] = c_i, [1] = a_i, [2] = b_i
  for (int i = 0; i < 3; ++i) {
    const Vec3<Exact> A = rational_point(scene.vertices[edges[i][0]]);
    const Vec3<Exact> d = rational_point(scene.vertices[edges[i][1]]) - A;
    terms[i][0] = cross(d, frame.origin - A);
    terms[i][1] = cross(d, frame.e1);
    terms[i][2] = cross(d, frame.e2);
  }
  // coefficient of u^p v^q: choice j_i in {0: 1, 1: u, 2: v} per factor.
  Exact c[4][4];
  for (auto& row : c)
    for (auto& x : row) x = 0;
  for (int j0 = 0; j0 < 3; ++j0)
    for (int j1 = 0; j1 < 3; ++j1)
      for (int j2 = 0; j2 < 3; ++j2) {
        const int pu = (j0 == 1) + (j1 == 1) + (j2 == 1), pv = (j0 == 2) + (j1 == 2) + (j2 == 2);
        c[pu][pv] += dot(terms[0][j0], cross(terms[1][j1], terms[2][j2]));
      }
  return {c[2][0], c[1][1], c[0][2], c[1][0], c[0][1], c[0][0]};
}

std::map<std::int64_t, std::vector<DiscontinuityCurve>> event_curves(const Scene& scene, const TriangleIndex& index,
                                                                     const std::vector<int>& light,
                                                                     const EvResult& ev, const EeeResult& eee,
                                                                     const std::vector<std::int64_t>& receivers,
                                                                     const EeeCurveOptions& options) {
  std::map<std::int64_t, std::vector<DiscontinuityCurve>> out;
  std::map<std::int64_t, ReceiverFrame> frames;  // by stable id
  for (std::int64_t r : receivers) frames.emplace(scene.triangles[r].id, receiver_frame(scene, r));
  const LightFeatures lf = light_features(scene, light);
  std::map<int, std::set<int>> neighbours;
  for (const auto& t : scene.triangles)
    for (int k = 0; k < 3; ++k) {
      neighbours[t.v[k]].insert(t.v[(k + 1) % 3]);
      neighbours[t.v[k]].insert(t.v[(k + 2) % 3]);
    }
  for (const auto& e : ev.events) {
    const bool lv = lf.vertices.count(e.vertex) > 0;
    const bool le = lf.edges.count({e.edge[0], e.edge[1]}) > 0;
    if (lv && le) continue;  // both on the light
    const Vec3<Exact> V = rational_point(scene.vertices[e.vertex]);
    for (const auto& iv : e.intervals) {
      std::int64_t rid = lv ? iv.front_object : iv.back_object;
      if (!lv && !le) {  // blocker-blocker: the line ends on the light at one end, on the receiver at the other
        const bool fl = lf.ids.count(iv.front_object) > 0, bl = lf.ids.count(iv.back_object) > 0;
        if (fl == bl) continue;
        rid = fl ? iv.back_object : iv.front_object;
      }
      const auto fr = frames.find(rid);
      if (rid < 0 || fr == frames.end()) continue;
      const Exact t0 = rational_parameter(iv.t0), t1 = rational_parameter(iv.t1);
      const auto x0 = line_meets_plane(V, ev_edge_point(scene, e.edge, t0), fr->second);
      const auto x1 = line_meets_plane(V, ev_edge_point(scene, e.edge, t1), fr->second);
      if (!x0 || !x1 || *x0 == *x1) continue;
      DiscontinuityCurve c;
      c.kind = DiscontinuityCurve::Kind::EV;
      c.order = ev_order(scene, neighbours, e.vertex, e.edge);
      c.receiver = rid;
      c.vertex = e.vertex;
      c.edge = e.edge;
      c.light_vertex = lv;
      c.blocker_blocker = !lv && !le;
      c.t0 = iv.t0;
      c.t1 = iv.t1;
      c.points = {*x0, *x1};
      c.ends = {to_double(*x0), to_double(*x1)};
      out[rid].push_back(std::move(c));
    }
  }
  const Box3 box = bounding_box(scene);
  for (const auto& e : eee.events) {
    int light_edge = -1;
    for (int k = 0; k < 3; ++k)
      if (lf.edges.count(e.edges[k])) light_edge = light_edge < 0 ? k : 3;  // 3: several light edges
    if (light_edge == 3) continue;
    const bool bb = light_edge < 0;  // blocker-blocker (shadows/blocker_eee_events.hpp)
    for (const auto& iv : e.intervals) {
      // Light edge: the receiver is beyond the generator point farthest from the light's point (which must be
      // outermost); blocker-blocker: per piece, the end that is not on the light.
      bool forward = true;
      if (!bb) {
        const auto seg = eee_generator_segment(scene, e, iv.sample_t);
        if (!seg) continue;
        const auto pts = eee_line_points(scene, e, RootNumber(iv.sample_t));
        const std::optional<Vec3<RootNumber>> lp = light_edge == 0 ? std::optional(pts.on_e1)
                                                   : light_edge == 1 ? pts.on_e2 : pts.on_e3;
        if (!lp) continue;
        Vec3<Exact> lq;
        if (!root_number_rational(lp->x, &lq.x) || !root_number_rational(lp->y, &lq.y) ||
            !root_number_rational(lp->z, &lq.z))
          continue;
        if (lq == seg->back) forward = true;
        else if (lq == seg->front) forward = false;
        else continue;  // the light's point lies between blockers' points
      }
      // Exact pieces of constant end objects; runs of pieces ending on one receiver (and, blocker-blocker,
      // on the light at the other end) become curves.
      const std::vector<EeeEndPiece> pieces = split_eee_interval(scene, index, box, e, iv);
      auto receiver_of = [&](const EeeEndPiece& p) -> std::int64_t {
        std::int64_t rid = -1;
        if (!bb) {
          rid = forward ? p.front : p.back;
        } else {
          const bool fl = lf.ids.count(p.front) > 0, bl = lf.ids.count(p.back) > 0;
          if (fl != bl) rid = fl ? p.back : p.front;
        }
        return rid >= 0 && frames.count(rid) ? rid : -1;
      };
      for (std::size_t k = 0; k < pieces.size();) {
        const std::int64_t rid = receiver_of(pieces[k]);
        std::size_t last = k;
        while (last + 1 < pieces.size() && receiver_of(pieces[last + 1]) == rid) ++last;
        if (rid >= 0) {
          if (auto c = eee_curve(scene, e, pieces[k].t0, pieces[last].t1, pieces[k].sample_t, frames.at(rid),
                                 options.samples)) {
            c->receiver = rid;
            c->light_edge = light_edge;
            c->blocker_blocker = bb;
            out[rid].push_back(std::move(*c));
          }
        }
        k = last + 1;
      }
    }
  }
  return out;
}

std::vector<DiscontinuityCurve> contact_curves(const Scene& scene, const TriangleIndex& index,
                                               const std::vector<int>& light, std::int64_t receiver) {
  std::vector<DiscontinuityCurve> out;
  const std::set<int> light_set(light.begin(), light.end());
  const auto& rt = scene.triangles[receiver];
  const ReceiverFrame f = receiver_frame(scene, receiver);
  const region::Plane3 plane{f.chart.normal, f.chart.offset};
  for (std::int64_t ti : index.triangles_meeting_triangle(scene.corner(rt, 0), scene.corner(rt, 1),
                                                           scene.corner(rt, 2))) {
    if (ti == receiver || light_set.count(static_cast<int>(ti))) continue;
    const auto t = region::triangle_points(scene, ti);
    Exact h[3];
    for (int k = 0; k < 3; ++k) h[k] = plane.value(t[k]);
    if (h[0] == 0 && h[1] == 0 && h[2] == 0) continue;  // coplanar: hides nothing from the receiver
    // T meets the plane in a segment (or point): its vertices on it and its edges' crossings.
    std::vector<std::array<Exact, 2>> pts;
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      if (h[k] == 0) pts.push_back(f.to_uv(t[k]));
      if ((h[k] < 0 && h[j] > 0) || (h[k] > 0 && h[j] < 0)) {
        const Exact s = h[k] / (h[k] - h[j]);
        pts.push_back(f.to_uv(t[k] + s * (t[j] - t[k])));
      }
    }
    if (pts.size() < 2) continue;
    std::sort(pts.begin(), pts.end());
    std::array<Exact, 2> a = pts.front(), b = pts.back();
    if (a == b) continue;  // touches at a point
    // Clip [a, b] to u >= 0, v >= 0, 1 - u - v >= 0 (Liang-Barsky, exact).
    Exact lo = 0, hi = 1;
    const std::array<Exact, 2> d{b[0] - a[0], b[1] - a[1]};
    const std::array<std::pair<Exact, Exact>, 3> lin{{{a[0], d[0]}, {a[1], d[1]}, {1 - a[0] - a[1], -d[0] - d[1]}}};
    bool empty = false;
    for (const auto& [val, slope] : lin) {  // val + s * slope >= 0
      if (slope == 0) {
        if (val < 0) empty = true;
      } else if (slope > 0) {
        lo = std::max(lo, -val / slope);
      } else {
        hi = std::min(hi, -val / slope);
      }
    }
    if (empty || !(lo < hi)) continue;
    DiscontinuityCurve c;
    c.kind = DiscontinuityCurve::Kind::EV;
    c.order = 0;
    c.receiver = rt.id;
    c.blocker = scene.triangles[ti].id;
    c.points = {f.to_3d(a[0] + lo * d[0], a[1] + lo * d[1]), f.to_3d(a[0] + hi * d[0], a[1] + hi * d[1])};
    c.ends = {to_double(c.points[0]), to_double(c.points[1])};
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace exactvis::shadows
