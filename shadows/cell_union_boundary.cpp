#include "shadows/cell_union_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

namespace exactvis::shadows {
namespace {

Exact cross(const ChartPoint& a, const ChartPoint& b) { return a[0] * b[1] - a[1] * b[0]; }
ChartPoint minus(const ChartPoint& a, const ChartPoint& b) { return {a[0] - b[0], a[1] - b[1]}; }

// A supporting line a x + b y + c = 0 normalised exactly: a = 1, or a = 0 and b = 1. Points on it are
// parametrised by t = y when a = 1 (the line is not horizontal), t = x when a = 0.
using LineKey = std::array<Exact, 3>;

struct Run {
  Exact t0, t1;  // t0 < t1
};

struct Group {
  std::vector<Run> left, right;  // cells on the left / right of the +t direction
};

ChartPoint point_at(const LineKey& k, const Exact& t) {
  if (k[0] != 0) return {-(k[1] * t + k[2]), t};
  return {t, -k[2]};
}

// Union of runs as sorted disjoint runs (touching runs merged).
std::vector<Run> merged(std::vector<Run> r) {
  std::sort(r.begin(), r.end(), [](const Run& a, const Run& b) { return a.t0 < b.t0; });
  std::vector<Run> out;
  for (auto& x : r) {
    if (!out.empty() && x.t0 <= out.back().t1) {
      if (x.t1 > out.back().t1) out.back().t1 = x.t1;
    } else {
      out.push_back(std::move(x));
    }
  }
  return out;
}

// a \ b for sorted disjoint runs (closures of the open differences; empty pieces dropped).
std::vector<Run> difference(const std::vector<Run>& a, const std::vector<Run>& b) {
  std::vector<Run> out;
  std::size_t j = 0;
  for (const Run& x : a) {
    while (j < b.size() && b[j].t1 <= x.t0) ++j;
    Exact start = x.t0;
    for (std::size_t k = j; k < b.size() && b[k].t0 < x.t1; ++k) {
      if (b[k].t0 > start) out.push_back({start, b[k].t0});
      if (b[k].t1 > start) start = b[k].t1;
    }
    if (start < x.t1) out.push_back({start, x.t1});
  }
  return out;
}

struct Edge {
  ChartPoint from, to;
};

// Position of w in the clockwise turn from ref (ref excluded): 0 in (0, pi), 1 at pi, 2 in (pi, 2 pi).
int turn_class(const ChartPoint& ref, const ChartPoint& w) {
  const int c = CGAL::sign(cross(ref, w));
  return c < 0 ? 0 : (c == 0 ? 1 : 2);
}

Exact twice_signed_area(const std::vector<ChartPoint>& loop) {
  Exact a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) a += cross(loop[i], loop[(i + 1) % loop.size()]);
  return a;
}

// Rotation to the canonical first vertex (smallest; of two visits, the one followed by the smaller vertex).
void rotate_canonical(std::vector<ChartPoint>& loop) {
  std::size_t best = 0;
  const std::size_t n = loop.size();
  for (std::size_t i = 1; i < n; ++i) {
    if (loop[i] < loop[best] || (loop[i] == loop[best] && loop[(i + 1) % n] < loop[(best + 1) % n])) best = i;
  }
  std::rotate(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(best), loop.end());
}

bool on_segment(const ChartPoint& p, const ChartPoint& a, const ChartPoint& b) {
  if (cross(minus(b, a), minus(p, a)) != 0) return false;
  return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= p[1] &&
         p[1] <= std::max(a[1], b[1]);
}

// 1 inside, 0 on the boundary, -1 outside (crossing number, exact).
int locate(const ChartPoint& p, const std::vector<ChartPoint>& loop) {
  bool inside = false;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const ChartPoint& a = loop[i];
    const ChartPoint& b = loop[(i + 1) % loop.size()];
    if (on_segment(p, a, b)) return 0;
    if ((a[1] > p[1]) != (b[1] > p[1])) {
      const int s = CGAL::sign(cross(minus(b, a), minus(p, a)));
      if (b[1] > a[1] ? s > 0 : s < 0) inside = !inside;
    }
  }
  return inside ? 1 : -1;
}

}  // namespace

ChartRegion cell_union_boundary(const std::vector<std::vector<ChartPoint>>& cells) {
  // Edge intervals grouped by their exact supporting line.
  std::map<LineKey, Group> groups;
  for (const auto& cell : cells) {
    for (std::size_t i = 0; i < cell.size(); ++i) {
      const ChartPoint& p = cell[i];
      const ChartPoint& q = cell[(i + 1) % cell.size()];
      const Exact a = p[1] - q[1], b = q[0] - p[0];
      const Exact c = -(a * p[0] + b * p[1]);
      LineKey key;
      Exact tp, tq;
      if (a != 0) {
        key = {Exact(1), b / a, c / a};
        tp = p[1], tq = q[1];
      } else {
        if (b == 0) throw std::invalid_argument("cell_union_boundary: repeated vertex in a cell");
        key = {Exact(0), Exact(1), c / b};
        tp = p[0], tq = q[0];
      }
      Group& g = groups[key];
      if (tp < tq) g.left.push_back({tp, tq});
      else g.right.push_back({tq, tp});
    }
  }
  struct KeyedRun {
    const LineKey* key;
    Run run;
    bool forward;  // +t direction (covered side on the left of +t)
  };
  std::vector<KeyedRun> runs;
  for (auto& [key, g] : groups) {
    const std::vector<Run> l = merged(std::move(g.left)), r = merged(std::move(g.right));
    for (Run& x : difference(l, r)) runs.push_back({&key, std::move(x), true});
    for (Run& x : difference(r, l)) runs.push_back({&key, std::move(x), false});
  }
  // Every run is cut at the ends of other runs lying inside it (a loop touching another one there), so that
  // loops are linked at every point where boundaries meet (the arrangement's vertices).
  std::vector<ChartPoint> ends;
  for (const auto& kr : runs) ends.push_back(point_at(*kr.key, kr.run.t0)), ends.push_back(point_at(*kr.key, kr.run.t1));
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  std::vector<std::array<double, 2>> ends_d;
  for (const auto& e : ends) ends_d.push_back({CGAL::to_double(e[0]), CGAL::to_double(e[1])});
  std::vector<Edge> edges;
  for (const auto& kr : runs) {
    const LineKey& k = *kr.key;
    const bool by_y = k[0] != 0;
    const double lo = CGAL::to_double(kr.run.t0), hi = CGAL::to_double(kr.run.t1);
    const double margin = 1e-9 * (std::abs(lo) + std::abs(hi)) + 1e-300;
    std::vector<Exact> cuts;
    for (std::size_t i = 0; i < ends.size(); ++i) {
      const double td = ends_d[i][by_y ? 1 : 0];
      if (td < lo - margin || td > hi + margin) continue;  // filter: certainly outside [t0, t1]
      const Exact& t = ends[i][by_y ? 1 : 0];
      if (!(kr.run.t0 < t && t < kr.run.t1)) continue;
      const Exact on = by_y ? ends[i][0] + k[1] * ends[i][1] + k[2] : ends[i][1] + k[2];
      if (on == 0) cuts.push_back(t);
    }
    std::sort(cuts.begin(), cuts.end());
    std::vector<Exact> ts{kr.run.t0};
    for (auto& c : cuts) ts.push_back(std::move(c));
    ts.push_back(kr.run.t1);
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
      if (kr.forward) edges.push_back({point_at(k, ts[i]), point_at(k, ts[i + 1])});
      else edges.push_back({point_at(k, ts[i + 1]), point_at(k, ts[i])});
    }
  }
  // Loops: at a vertex with several outgoing edges, the first clockwise from the arriving edge's reverse.
  std::map<ChartPoint, std::vector<std::size_t>> outgoing;
  for (std::size_t i = 0; i < edges.size(); ++i) outgoing[edges[i].from].push_back(i);
  std::vector<char> used(edges.size(), 0);
  std::vector<std::vector<ChartPoint>> loops;
  for (std::size_t e0 = 0; e0 < edges.size(); ++e0) {
    if (used[e0]) continue;
    std::vector<ChartPoint> loop;
    std::size_t e = e0;
    do {
      used[e] = 1;
      loop.push_back(edges[e].from);
      const auto it = outgoing.find(edges[e].to);
      if (it == outgoing.end()) throw std::logic_error("cell_union_boundary: open boundary");
      const std::vector<std::size_t>& out = it->second;
      std::size_t next = out.front();
      if (out.size() > 1) {
        const ChartPoint& v = edges[e].to;
        const ChartPoint ref = minus(edges[e].from, v);
        std::optional<ChartPoint> best_dir;
        int best_class = 3;
        for (std::size_t k : out) {
          const ChartPoint w = minus(edges[k].to, v);
          const int c = turn_class(ref, w);
          // Smaller clockwise angle from ref: an earlier class, or in one class counterclockwise of the best.
          if (c < best_class || (c == best_class && CGAL::sign(cross(*best_dir, w)) > 0)) {
            best_class = c;
            best_dir = w;
            next = k;
          }
        }
      }
      if (used[next] && next != e0) throw std::logic_error("cell_union_boundary: boundary edges do not link");
      e = next;
    } while (e != e0);
    // Vertices where the loop goes straight on (another loop touched it there) are not corners.
    for (bool again = true; again && loop.size() > 3;) {
      again = false;
      for (std::size_t i = 0; i < loop.size() && loop.size() > 3; ++i) {
        const std::size_t n = loop.size();
        const ChartPoint& a = loop[(i + n - 1) % n];
        const ChartPoint& b = loop[i];
        const ChartPoint& c = loop[(i + 1) % n];
        if (cross(minus(b, a), minus(c, b)) == 0) {
          loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(i));
          again = true;
          --i;
        }
      }
    }
    rotate_canonical(loop);
    loops.push_back(std::move(loop));
  }
  ChartRegion out;
  std::vector<std::vector<ChartPoint>> holes;
  std::vector<Exact> outer_area;
  for (auto& loop : loops) {
    const Exact a2 = twice_signed_area(loop);
    out.area += a2;
    if (a2 > 0) {
      out.pieces.push_back({std::move(loop), {}});
      outer_area.push_back(a2);
    } else {
      holes.push_back(std::move(loop));
    }
  }
  out.area /= 2;
  if (!holes.empty() && out.pieces.empty()) throw std::logic_error("cell_union_boundary: a hole without outer loop");
  // Each hole to the smallest outer loop containing it, decided at a point of the hole (a vertex or an edge
  // midpoint) off that loop: loops of different faces meet at isolated points only.
  std::vector<std::size_t> by_area(out.pieces.size());
  for (std::size_t i = 0; i < by_area.size(); ++i) by_area[i] = i;
  std::sort(by_area.begin(), by_area.end(), [&](std::size_t a, std::size_t b) { return outer_area[a] < outer_area[b]; });
  for (auto& h : holes) {
    std::size_t owner = by_area.front();
    if (out.pieces.size() > 1) {
      bool found = false;
      for (std::size_t oi : by_area) {
        const auto& outer = out.pieces[oi].outer;
        int where = 0;
        for (std::size_t k = 0; k < h.size() && where == 0; ++k) {
          where = locate(h[k], outer);
          if (where == 0) {
            const ChartPoint& b = h[(k + 1) % h.size()];
            where = locate({(h[k][0] + b[0]) / 2, (h[k][1] + b[1]) / 2}, outer);
          }
        }
        if (where == 0) throw std::logic_error("cell_union_boundary: a hole on an outer loop");
        if (where > 0) {
          owner = oi;
          found = true;
          break;
        }
      }
      if (!found) throw std::logic_error("cell_union_boundary: a hole outside every outer loop");
    }
    out.pieces[owner].holes.push_back(std::move(h));
  }
  for (auto& p : out.pieces)
    std::sort(p.holes.begin(), p.holes.end(), [](const auto& a, const auto& b) { return a.front() < b.front() || (a.front() == b.front() && a[1] < b[1]); });
  std::sort(out.pieces.begin(), out.pieces.end(), [](const auto& a, const auto& b) {
    return a.outer.front() < b.outer.front() || (a.outer.front() == b.outer.front() && a.outer[1] < b.outer[1]);
  });
  return out;
}

}  // namespace exactvis::shadows
