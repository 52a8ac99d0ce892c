#include "region/footprint_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace exactvis::region {
namespace {

constexpr int kMaxCells = 2048;  // per axis

double cross(const XyPoint& o, const XyPoint& a, const XyPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain in doubles, counterclockwise, collinear points dropped. A wrong rounding decision
// only drops a point within rounding distance of the hull's boundary, which the caller's margin covers.
std::vector<XyPoint> hull_of(std::vector<XyPoint> p) {
  std::sort(p.begin(), p.end(), [](const XyPoint& a, const XyPoint& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(std::unique(p.begin(), p.end(), [](const XyPoint& a, const XyPoint& b) { return a.x == b.x && a.y == b.y; }), p.end());
  if (p.size() < 3) return p;
  std::vector<XyPoint> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

}  // namespace

FootprintGrid::FootprintGrid(const std::vector<Box3>& boxes) : items_(boxes.size()) {
  if (items_ == 0) return;
  double X0 = boxes[0].lo.x, X1 = boxes[0].hi.x, Y0 = boxes[0].lo.y, Y1 = boxes[0].hi.y;
  for (const Box3& b : boxes) {
    X0 = std::min(X0, b.lo.x), X1 = std::max(X1, b.hi.x);
    Y0 = std::min(Y0, b.lo.y), Y1 = std::max(Y1, b.hi.y);
  }
  const double ex = X1 - X0, ey = Y1 - Y0;
  // The margin dwarfs the rounding of every double below (relative 1e-16 of these magnitudes).
  margin_ = 1e-9 * (std::max({std::abs(X0), std::abs(X1), std::abs(Y0), std::abs(Y1)}) + ex + ey + 1);
  const double n = static_cast<double>(items_);
  if (ex > 0 && ey > 0) {
    nx_ = static_cast<int>(std::ceil(std::sqrt(n * ex / ey)));
    nx_ = std::clamp(nx_, 1, kMaxCells);
    ny_ = std::clamp(static_cast<int>(std::ceil(n / nx_)), 1, kMaxCells);
  } else {
    nx_ = ex > 0 ? std::min<int>(kMaxCells, static_cast<int>(items_)) : 1;
    ny_ = ey > 0 ? std::min<int>(kMaxCells, static_cast<int>(items_)) : 1;
  }
  x0_ = X0, y0_ = Y0;
  hx_ = ex > 0 ? ex / nx_ : 1;
  hy_ = ey > 0 ? ey / ny_ : 1;
  auto row_of = [&](double y) { return std::clamp(static_cast<int>(std::floor((y - y0_) / hy_)), 0, ny_ - 1); };
  // Counting sort of (cell, item) pairs into CSR.
  const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  first_.assign(cells + 1, 0);
  auto for_cells = [&](const Box3& b, auto&& g) {
    const int c0 = column_of(b.lo.x - margin_), c1 = column_of(b.hi.x + margin_);
    const int r0 = row_of(b.lo.y - margin_), r1 = row_of(b.hi.y + margin_);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) g(static_cast<std::size_t>(r) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(c));
  };
  for (const Box3& b : boxes) for_cells(b, [&](std::size_t c) { ++first_[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) first_[c + 1] += first_[c];
  list_.resize(first_[cells]);
  std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
  for (std::size_t i = 0; i < items_; ++i)
    for_cells(boxes[i], [&](std::size_t c) { list_[fill[c]++] = static_cast<std::uint32_t>(i); });
}

int FootprintGrid::column_of(double x) const {
  const double t = std::floor((x - x0_) / hx_);
  if (!(t > 0)) return 0;  // also NaN-safe
  return t >= nx_ - 1 ? nx_ - 1 : static_cast<int>(t);
}

int FootprintGrid::covered_rows(const std::vector<XyPoint>& points, XyPoint origin, std::vector<Span>& rows) const {
  const std::vector<XyPoint> h = hull_of(points);
  double ylo = h[0].y, yhi = h[0].y;
  for (const XyPoint& p : h) ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
  auto row_of = [&](double y) {
    const double t = std::floor((y - y0_) / hy_);
    if (!(t > 0)) return 0;
    return t >= ny_ - 1 ? ny_ - 1 : static_cast<int>(t);
  };
  const int r0 = row_of(ylo - margin_), r1 = row_of(yhi + margin_);
  constexpr double inf = std::numeric_limits<double>::infinity();
  rows.clear();
  for (int r = r0; r <= r1; ++r) {
    // The band of row r (unbounded at the grid's first and last rows, where outside points are clamped),
    // widened by the margin.
    const double b0 = (r == 0 ? -inf : y0_ + r * hy_) - margin_, b1 = (r == ny_ - 1 ? inf : y0_ + (r + 1) * hy_) + margin_;
    double xlo = inf, xhi = -inf;
    for (std::size_t i = 0; i < h.size(); ++i) {
      const XyPoint& p = h[i];
      const XyPoint& q = h[(i + 1) % h.size()];
      double t0 = 0, t1 = 1;
      if (p.y == q.y) {
        if (p.y < b0 || p.y > b1) continue;
      } else {
        double ta = (b0 - p.y) / (q.y - p.y), tb = (b1 - p.y) / (q.y - p.y);
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta), t1 = std::min(t1, tb);
        if (t0 > t1) continue;
      }
      for (const double t : {t0, t1}) {
        const double x = p.x + t * (q.x - p.x);
        xlo = std::min(xlo, x), xhi = std::max(xhi, x);
      }
    }
    Span s;
    s.row = r;
    if (xlo <= xhi) s.c0 = column_of(xlo - margin_), s.c1 = column_of(xhi + margin_);
    rows.push_back(s);
  }
  return std::clamp(row_of(origin.y) - r0, 0, static_cast<int>(rows.size()) - 1);
}

FootprintGrid::Visit FootprintGrid::begin_visit() const {
  struct Stamps {
    std::vector<std::uint32_t> stamp;
    std::uint32_t generation = 0;
  };
  thread_local Stamps tls;
  if (tls.stamp.size() < items_) tls.stamp.resize(items_, 0);
  if (++tls.generation == 0) {  // wrapped: forget every old stamp
    std::fill(tls.stamp.begin(), tls.stamp.end(), 0);
    tls.generation = 1;
  }
  return {tls.stamp.data(), tls.generation};
}

}  // namespace exactvis::region
