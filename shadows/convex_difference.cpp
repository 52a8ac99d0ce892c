#include "shadows/convex_difference.hpp"

#include "kernel/bounded_double.hpp"

#include <algorithm>
#include <optional>
#include <utility>

namespace exactvis::shadows {
namespace {

using Enclosure = std::pair<double, double>;

// A vertex with the enclosures of its coordinates (the filter's input).
struct Vtx {
  ChartPoint p;
  Enclosure ex, ey;
};

Vtx vtx(ChartPoint p) {
  const Enclosure ex = enclosing_interval(p[0]), ey = enclosing_interval(p[1]);
  return {std::move(p), ex, ey};
}

// The line a x + b y + c = 0 through p, q: positive on the left of p -> q. Exact, with enclosures.
struct Line {
  Exact a, b, c;
  BoundedDouble ba, bb, bc;
};

Line line_through(const ChartPoint& p, const ChartPoint& q) {
  Line l;
  l.a = p[1] - q[1];
  l.b = q[0] - p[0];
  l.c = -(l.a * p[0] + l.b * p[1]);
  l.ba = BoundedDouble(enclosing_interval(l.a));
  l.bb = BoundedDouble(enclosing_interval(l.b));
  l.bc = BoundedDouble(enclosing_interval(l.c));
  return l;
}

Exact value(const Line& l, const ChartPoint& p) { return l.a * p[0] + l.b * p[1] + l.c; }

int side(const Line& l, const Vtx& v) {
  const BoundedDouble s = l.ba * BoundedDouble(v.ex) + l.bb * BoundedDouble(v.ey) + l.bc;
  if (const std::optional<Sign> c = s.certified_sign()) return to_int(*c);
  return CGAL::sign(value(l, v.p));
}

int orientation(const ChartPoint& a, const ChartPoint& b, const ChartPoint& c) {
  const Vtx va = vtx(a), vb = vtx(b), vc = vtx(c);
  const BoundedDouble ax(va.ex), ay(va.ey);
  const BoundedDouble d = (BoundedDouble(vb.ex) - ax) * (BoundedDouble(vc.ey) - ay) -
                          (BoundedDouble(vb.ey) - ay) * (BoundedDouble(vc.ex) - ax);
  if (const std::optional<Sign> s = d.certified_sign()) return to_int(*s);
  return CGAL::sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

struct Box {
  double lo[2], hi[2];
};

struct Cell {
  std::vector<Vtx> v;
  Box box;
};

Box box_of(const std::vector<Vtx>& v) {
  Box b{{v.front().ex.first, v.front().ey.first}, {v.front().ex.second, v.front().ey.second}};
  for (const Vtx& x : v) {
    b.lo[0] = std::min(b.lo[0], x.ex.first), b.hi[0] = std::max(b.hi[0], x.ex.second);
    b.lo[1] = std::min(b.lo[1], x.ey.first), b.hi[1] = std::max(b.hi[1], x.ey.second);
  }
  return b;
}

// The enclosure boxes meet in more than their boundary; else the interiors are disjoint.
bool boxes_overlap(const Box& a, const Box& b) {
  return a.lo[0] < b.hi[0] && b.lo[0] < a.hi[0] && a.lo[1] < b.hi[1] && b.lo[1] < a.hi[1];
}

Cell make_cell(std::vector<Vtx> v) {
  Cell c;
  c.box = box_of(v);
  c.v = std::move(v);
  return c;
}

// The parts of a convex cell on the closed negative and positive sides of l, each empty unless one of the
// cell's vertices lies strictly on that side (then it has positive area). Crossing points exact.
std::pair<std::vector<Vtx>, std::vector<Vtx>> split(const std::vector<Vtx>& cell, const Line& l) {
  const std::size_t n = cell.size();
  std::vector<int> s(n);
  bool any_neg = false, any_pos = false;
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = side(l, cell[i]);
    any_neg |= s[i] < 0;
    any_pos |= s[i] > 0;
  }
  std::pair<std::vector<Vtx>, std::vector<Vtx>> out;
  if (!any_pos) {
    if (any_neg) out.first = cell;
    return out;
  }
  if (!any_neg) {
    out.second = cell;
    return out;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (s[i] <= 0) out.first.push_back(cell[i]);
    if (s[i] >= 0) out.second.push_back(cell[i]);
    if (s[i] * s[j] < 0) {
      const Exact vi = value(l, cell[i].p), vj = value(l, cell[j].p);
      const Exact t = vi / (vi - vj);
      const ChartPoint& a = cell[i].p;
      const ChartPoint& b = cell[j].p;
      const Vtx x = vtx({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
      out.first.push_back(x);
      out.second.push_back(x);
    }
  }
  return out;
}

struct Subtrahend {
  std::vector<Line> lines;  // H on the left of each
  Box box;
};

// Appends the cells of c minus h to out.
void subtract(Cell&& c, const Subtrahend& h, std::vector<Cell>& out) {
  if (!boxes_overlap(c.box, h.box)) {
    out.push_back(std::move(c));
    return;
  }
  bool inside = true;  // every vertex of c in the closed h
  for (const Line& l : h.lines) {
    bool any_pos = false, any_neg = false;
    for (const Vtx& x : c.v) {
      const int s = side(l, x);
      any_pos |= s > 0;
      any_neg |= s < 0;
    }
    if (!any_pos) {  // c on the closed outer side of one edge line: interiors disjoint
      out.push_back(std::move(c));
      return;
    }
    inside &= !any_neg;
  }
  if (inside) return;
  std::vector<Cell> pieces;
  std::vector<Vtx> rest = c.v;
  for (const Line& l : h.lines) {
    auto [neg, pos] = split(rest, l);
    if (!neg.empty()) pieces.push_back(make_cell(std::move(neg)));
    rest = std::move(pos);
    if (rest.empty()) break;
  }
  if (rest.empty()) {  // c ∩ h has zero area: c stays whole
    out.push_back(std::move(c));
    return;
  }
  for (auto& p : pieces) out.push_back(std::move(p));
}

}  // namespace

std::vector<ChartPoint> normalized_convex_polygon(const std::vector<ChartPoint>& points) {
  std::vector<ChartPoint> v;
  for (const auto& p : points)
    if (v.empty() || v.back() != p) v.push_back(p);
  while (v.size() > 1 && v.back() == v.front()) v.pop_back();
  bool changed = true;
  while (changed && v.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < v.size() && v.size() >= 3; ++i) {
      const std::size_t n = v.size();
      if (orientation(v[(i + n - 1) % n], v[i], v[(i + 1) % n]) == 0) {
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        --i;
      }
    }
  }
  if (v.size() < 3) return {};
  if (orientation(v[0], v[1], v[2]) < 0) std::reverse(v.begin(), v.end());
  return v;
}

ConvexDifference convex_difference(const std::vector<ChartPoint>& base,
                                   const std::vector<std::vector<ChartPoint>>& subtrahends) {
  std::vector<Vtx> b;
  for (const auto& p : base) b.push_back(vtx(p));
  std::vector<Cell> cells;
  cells.push_back(make_cell(std::move(b)));
  for (const auto& poly : subtrahends) {
    if (cells.empty()) break;
    Subtrahend h;
    std::vector<Vtx> hv;
    for (const auto& p : poly) hv.push_back(vtx(p));
    h.box = box_of(hv);
    for (std::size_t i = 0; i < poly.size(); ++i) h.lines.push_back(line_through(poly[i], poly[(i + 1) % poly.size()]));
    std::vector<Cell> next;
    next.reserve(cells.size() + 4);
    for (auto& c : cells) subtract(std::move(c), h, next);
    cells = std::move(next);
  }
  std::vector<std::vector<ChartPoint>> polys;
  polys.reserve(cells.size());
  for (const auto& c : cells) {
    std::vector<ChartPoint> p;
    p.reserve(c.v.size());
    for (const auto& x : c.v) p.push_back(x.p);
    polys.push_back(std::move(p));
  }
  ConvexDifference out;
  out.cells = cells.size();
  out.region = cell_union_boundary(polys);
  return out;
}

}  // namespace exactvis::shadows
