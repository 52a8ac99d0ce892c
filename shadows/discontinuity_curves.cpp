#include "shadows/discontinuity_curves.hpp"

#include "kernel/predicates.hpp"
#include "kernel/rational_between.hpp"
#include "kernel/ray_first_hit.hpp"
#include "region/convex_polygon_3.hpp"

#include <algorithm>
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

Exact approach(const RootNumber& from, const RootNumber& towards) {
  // A rational strictly between `from` and `towards`, within 2^-40 of the gap from `from`.
  RootNumber b = towards;
  Exact q = rational_strictly_between(from < towards ? from : towards, from < towards ? towards : from);
  for (int k = 0; k < 40; ++k) {
    b = RootNumber(q);
    q = rational_strictly_between(from < b ? from : b, from < b ? b : from);
  }
  return q;
}

}  // namespace

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
    if (light_edge < 0 || light_edge == 3) continue;
    for (const auto& iv : e.intervals) {
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
      bool forward;
      if (lq == seg->back) forward = true;
      else if (lq == seg->front) forward = false;
      else continue;  // the light's point lies between blockers' points
      const std::int64_t rid = forward ? iv.front_object : iv.back_object;
      const auto fr = frames.find(rid);
      if (rid < 0 || fr == frames.end()) continue;
      const std::int64_t rindex = scene.index_of_id(rid);
      Exact q0, q1;
      const bool e0 = root_number_rational(iv.t0, &q0), e1 = root_number_rational(iv.t1, &q1);
      if (!e0) q0 = approach(iv.t0, RootNumber(iv.sample_t));
      if (!e1) q1 = approach(iv.t1, RootNumber(iv.sample_t));
      const int n = std::max(2, options.samples);
      std::vector<std::optional<Vec3<Exact>>> on_r(n + 1);
      for (int k = 0; k <= n; ++k) {
        const Exact t = q0 + Exact(k, n) * (q1 - q0);
        const auto s = eee_generator_segment(scene, e, t);
        if (!s) continue;
        const Vec3<Exact> origin = forward ? s->front : s->back;
        const Vec3<Exact> dir = forward ? s->direction : -s->direction;
        if (ray_first_hit(scene, index, box, origin, dir).triangle != rindex) continue;
        on_r[k] = line_meets_plane(origin, origin + dir, fr->second);
      }
      const auto conic = eee_conic(scene, e.edges, fr->second);
      for (int k = 0; k <= n;) {
        if (!on_r[k]) {
          ++k;
          continue;
        }
        int last = k;
        while (last + 1 <= n && on_r[last + 1]) ++last;
        if (last > k) {
          DiscontinuityCurve c;
          c.kind = DiscontinuityCurve::Kind::EEE;
          c.order = 2;
          c.receiver = rid;
          c.edges = e.edges;
          c.light_edge = light_edge;
          c.t0 = k == 0 ? iv.t0 : RootNumber(q0 + Exact(k, n) * (q1 - q0));
          c.t1 = last == n ? iv.t1 : RootNumber(q0 + Exact(last, n) * (q1 - q0));
          for (int j = k; j <= last; ++j) c.points.push_back(*on_r[j]);
          if (last == k + 1) {
            // A third exact conic point between the two (the arc's orientation needs one): the line at the
            // middle parameter, on the same surface; by continuity its plane point lies on the arc between.
            const Exact tm = q0 + Exact(2 * k + 1, 2 * n) * (q1 - q0);
            if (const auto s = eee_generator_segment(scene, e, tm))
              if (const auto x = line_meets_plane(s->front, s->front + s->direction, fr->second))
                c.points.insert(c.points.begin() + 1, *x);
          }
          c.ends_exact = k == 0 && e0 && last == n && e1;
          c.ends = {to_double(c.points.front()), to_double(c.points.back())};
          c.conic = conic;
          out[rid].push_back(std::move(c));
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
