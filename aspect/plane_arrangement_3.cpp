#include "aspect/plane_arrangement_3.hpp"

#include "kernel/filtered_predicate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

namespace exactvis {

namespace {

PredicateCounter side_counter("plane_arrangement_side");
PredicateCounter direction_counter("plane_arrangement_direction");

Interval enclose(const Exact& x) {
  const auto [lo, hi] = enclosing_interval(x);
  return Interval(lo, hi);
}
Vec3<Interval> enclose(const Vec3<Exact>& v) { return {enclose(v.x), enclose(v.y), enclose(v.z)}; }

char sign_char(Sign s) { return s == Sign::Positive ? '+' : (s == Sign::Negative ? '-' : '0'); }
char sign_char(int s) { return s > 0 ? '+' : (s < 0 ? '-' : '0'); }

// A point with its interval enclosure (computed once, used by every plane's filter).
struct FilteredPoint {
  Vec3<Exact> exact;
  Vec3<Interval> box;
  explicit FilteredPoint(Vec3<Exact> p) : exact(std::move(p)), box(enclose(exact)) {}
};

// The largest power of two <= x (x > 0), exactly.
Exact power_of_two_below(const Exact& x) {
  int e = 0;
  std::frexp(CGAL::to_double(x), &e);
  Exact p(std::ldexp(1.0, std::max(e - 1, -1000)));
  while (p > x) p /= 2;
  while (p * 2 <= x) p *= 2;
  return p;
}

class Builder {
 public:
  Builder(const std::vector<ArrangementPlane>& planes, void (*progress)(double)) : P_(planes), progress_(progress) {
    for (const auto& p : P_) {
      n_.push_back(enclose(p.normal)), c_.push_back(enclose(p.offset));
      nd_.push_back({CGAL::to_double(p.normal.x), CGAL::to_double(p.normal.y), CGAL::to_double(p.normal.z)});
      cd_.push_back(CGAL::to_double(p.offset));
    }
  }

  PlaneArrangement run() {
    build_lines();
    const int first_face = static_cast<int>(A_.cells.size());
    // 2-faces from edges (the edge list is complete here), then 3-cells from 2-faces.
    for (int e = A_.vertices; e < first_face; ++e) {
      if (progress_ && (e & 1023) == 0) progress_(0.2 + 0.3 * (e - A_.vertices) / std::max(1, first_face - A_.vertices));
      faces_around_edge(e);
    }
    const int first_volume = static_cast<int>(A_.cells.size());
    A_.edges = first_face - A_.vertices;
    A_.faces = first_volume - first_face;
    for (int f = first_face; f < first_volume; ++f) {
      if (progress_ && (f & 1023) == 0) progress_(0.5 + 0.5 * (f - first_face) / std::max(1, first_volume - first_face));
      volumes_around_face(f);
    }
    if (progress_) progress_(1);
    A_.volumes = static_cast<int>(A_.cells.size()) - first_volume;
    return std::move(A_);
  }

 private:
  struct Line {
    Vec3<Exact> point, direction;
    std::vector<int> planes;  // planes holding the line
  };

  // sign(n_k . x - c_k)
  Sign side(int k, const FilteredPoint& x) const {
    // Layer 1 is skipped (the inputs are kept as enclosing intervals, not doubles): interval, then exact.
    return filtered_sign_with(side_counter, [] { return std::optional<Sign>{}; }, [&](auto nt) {
      using NT = typename decltype(nt)::type;
      if constexpr (std::is_same_v<NT, Interval>) return n_[k].x * x.box.x + n_[k].y * x.box.y + n_[k].z * x.box.z - c_[k];
      else return NT(dot(P_[k].normal, x.exact) - P_[k].offset);
    });
  }
  // sign(n_k . w)
  Sign along(int k, const FilteredPoint& w) const {
    return filtered_sign_with(direction_counter, [] { return std::optional<Sign>{}; }, [&](auto nt) {
      using NT = typename decltype(nt)::type;
      if constexpr (std::is_same_v<NT, Interval>) return n_[k].x * w.box.x + n_[k].y * w.box.y + n_[k].z * w.box.z;
      else return NT(dot(P_[k].normal, w.exact));
    });
  }
  // The sign vector at x; `zeros` (ascending) are planes known to hold x (by construction), not evaluated.
  std::string signs_at(const FilteredPoint& x, const std::vector<int>& zeros = {}) const {
    std::string s(P_.size(), '0');
    std::size_t z = 0;
    for (std::size_t k = 0; k < P_.size(); ++k) {
      if (z < zeros.size() && zeros[z] == static_cast<int>(k)) {
        ++z;
        continue;
      }
      s[k] = sign_char(side(static_cast<int>(k), x));
    }
    return s;
  }
  // Whether x has sign signs[k] on every plane where that is not zero (the zeros hold by construction).
  bool has_nonzero_signs(const FilteredPoint& x, const std::string& signs) const {
    for (std::size_t k = 0; k < P_.size(); ++k)
      if (signs[k] != '0' && sign_char(side(static_cast<int>(k), x)) != signs[k]) return false;
    return true;
  }

  // The cell with sign vector `signs`: existing, or new with the given sample and dimension.
  int cell(const std::string& signs, int dimension, const std::function<Vec3<Exact>()>& sample, bool* fresh) {
    auto [it, inserted] = by_signs_.emplace(signs, static_cast<int>(A_.cells.size()));
    *fresh = inserted;
    if (inserted) {
      ArrangementCell c;
      c.dimension = dimension;
      c.signs = signs;
      c.sample = sample();
      A_.cells.push_back(std::move(c));
    }
    return it->second;
  }

  void build_lines() {
    const int m = static_cast<int>(P_.size());
    std::map<std::array<Exact, 6>, int> line_index;
    std::map<std::array<Exact, 3>, int> vertex_index;
    std::vector<std::vector<Exact>> crossings;  // per line: sorted distinct parameters
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j) {
        if (progress_ && j == i + 1) progress_(0.2 * (1 - double(m - i) * (m - i) / (double(m) * m)));
        Vec3<Exact> d = cross(P_[i].normal, P_[j].normal);
        if (d.x == 0 && d.y == 0 && d.z == 0) continue;
        int a = 0;
        for (int k = 1; k < 3; ++k)
          if (CGAL::abs(d[k]) > CGAL::abs(d[a])) a = k;
        const Exact det = d[a];  // = (n_i x n_j)_a: the 2x2 determinant in the other two coordinates
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const auto& ni = P_[i].normal;
        const auto& nj = P_[j].normal;
        Vec3<Exact> p;
        p[a] = 0;
        p[b] = (P_[i].offset * nj[c] - P_[j].offset * ni[c]) / det;
        p[c] = (ni[b] * P_[j].offset - nj[b] * P_[i].offset) / det;
        d = {d.x / det, d.y / det, d.z / det};
        const std::array<Exact, 6> key{d.x, d.y, d.z, p.x, p.y, p.z};
        if (!line_index.emplace(key, static_cast<int>(lines_.size())).second) continue;
        Line line{p, d, {}};
        const FilteredPoint fp(p), fd(d);
        std::vector<Exact> t;
        for (int k = 0; k < m; ++k) {
          const Sign s = along(k, fd);
          if (s == Sign::Zero) {
            if (side(k, fp) == Sign::Zero) line.planes.push_back(k);
          } else {
            const bool through_point = p.x == 0 && p.y == 0 && p.z == 0 && P_[k].offset == 0;  // central case
            t.push_back(through_point ? Exact(0) : (P_[k].offset - dot(P_[k].normal, p)) / dot(P_[k].normal, d));
          }
        }
        std::sort(t.begin(), t.end());
        t.erase(std::unique(t.begin(), t.end()), t.end());
        lines_.push_back(std::move(line));
        crossings.push_back(std::move(t));
      }
    // Vertices first (so that cells are ordered by dimension), then the edges of every line.
    std::vector<std::vector<int>> line_vertices(lines_.size());
    for (std::size_t l = 0; l < lines_.size(); ++l)
      for (const Exact& t : crossings[l]) {
        const Vec3<Exact> v = lines_[l].point + Vec3<Exact>(t * lines_[l].direction.x, t * lines_[l].direction.y,
                                                            t * lines_[l].direction.z);
        auto [it, fresh] = vertex_index.emplace(std::array<Exact, 3>{v.x, v.y, v.z}, static_cast<int>(A_.cells.size()));
        if (fresh) {
          ArrangementCell c;
          c.dimension = 0;
          c.signs = signs_at(FilteredPoint(v));
          c.sample = v;
          by_signs_.emplace(c.signs, it->second);
          A_.cells.push_back(std::move(c));
        }
        line_vertices[l].push_back(it->second);
      }
    A_.vertices = static_cast<int>(A_.cells.size());
    for (std::size_t l = 0; l < lines_.size(); ++l) {
      const Line& L = lines_[l];
      const auto& t = crossings[l];
      const auto at = [&](const Exact& s) {
        return L.point + Vec3<Exact>(s * L.direction.x, s * L.direction.y, s * L.direction.z);
      };
      const auto add_edge = [&](const Vec3<Exact>& sample, std::vector<int> ends) {
        ArrangementCell c;
        c.dimension = 1;
        c.signs = signs_at(FilteredPoint(sample), L.planes);
        c.sample = sample;
        c.facets = std::move(ends);
        if (!by_signs_.emplace(c.signs, static_cast<int>(A_.cells.size())).second)
          throw std::logic_error("plane_arrangement: two edges with one sign vector");
        A_.cells.push_back(std::move(c));
        edge_line_.push_back(static_cast<int>(l));
      };
      if (t.empty()) {
        add_edge(L.point, {});
        continue;
      }
      add_edge(at(t.front() - 1), {line_vertices[l].front()});
      for (std::size_t k = 0; k + 1 < t.size(); ++k)
        add_edge(at((t[k] + t[k + 1]) / 2), {line_vertices[l][k], line_vertices[l][k + 1]});
      add_edge(at(t.back() + 1), {line_vertices[l].back()});
    }
  }

  // An exact step eps > 0 (a power of two) such that s + eps' w, 0 < eps' <= eps, keeps the sign of every
  // plane on which s is not zero (the exact bound: half the smallest ratio |n_k . s - c_k| / |n_k . w|).
  Exact exact_step(const ArrangementCell& from, const Vec3<Exact>& w) const {
    bool bounded = false;
    Exact best(0);
    for (std::size_t k = 0; k < P_.size(); ++k) {
      if (from.signs[k] == '0') continue;
      const Exact nw = dot(P_[k].normal, w);
      if (nw == 0) continue;
      const Exact r = CGAL::abs((dot(P_[k].normal, from.sample) - P_[k].offset) / nw);
      if (!bounded || r < best) best = r, bounded = true;
    }
    return bounded ? power_of_two_below(best / 2) : Exact(1);
  }

  // The sample of the cell with sign vector `signs` reached from `from` along w: a step proposed in
  // doubles (a quarter of the smallest ratio, rounded down to a power of two) and accepted only if the
  // moved point has exactly the sign vector `signs` (filtered exact signs); else the exact step.
  Vec3<Exact> moved_sample(const ArrangementCell& from, const Vec3<Exact>& w, const std::string& signs) const {
    const double sx = CGAL::to_double(from.sample.x), sy = CGAL::to_double(from.sample.y),
                 sz = CGAL::to_double(from.sample.z);
    const double wx = CGAL::to_double(w.x), wy = CGAL::to_double(w.y), wz = CGAL::to_double(w.z);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < P_.size(); ++k) {
      if (from.signs[k] == '0') continue;
      const auto& n = nd_[k];
      const double nw = std::abs(n[0] * wx + n[1] * wy + n[2] * wz);
      if (nw == 0) continue;
      best = std::min(best, std::abs(n[0] * sx + n[1] * sy + n[2] * sz - cd_[k]) / nw);
    }
    const auto at = [&](const Exact& eps) {
      return from.sample + Vec3<Exact>(eps * w.x, eps * w.y, eps * w.z);
    };
    if (best > 0 && std::isfinite(best) && best > 1e-280) {
      int e = 0;
      std::frexp(best / 4, &e);
      const Vec3<Exact> p = at(Exact(std::ldexp(1.0, e - 1)));
      // The planes where `signs` is zero hold `from` and contain w (w is built in them), so hold p.
      if (has_nonzero_signs(FilteredPoint(p), signs)) return p;
    }
    return at(exact_step(from, w));
  }

  void faces_around_edge(int e) {
    const Line& L = lines_[edge_line_[e - A_.vertices]];
    for (int k : L.planes) {
      const Vec3<Exact> w0 = cross(P_[k].normal, L.direction);
      const FilteredPoint fw(w0);
      for (int sgn : {1, -1}) {
        std::string s = A_.cells[e].signs;
        for (int j : L.planes)
          if (j != k) s[j] = sign_char(sgn * to_int(along(j, fw)));
        bool fresh = false;
        const int f = cell(s, 2, [&] {
          return moved_sample(A_.cells[e], sgn > 0 ? w0 : -w0, s);
        }, &fresh);
        if (fresh) face_plane_.push_back(k);
        A_.cells[f].facets.push_back(e);
      }
    }
  }

  void volumes_around_face(int f) {
    const int k = face_plane_[f - A_.vertices - A_.edges];
    for (int sgn : {1, -1}) {
      std::string s = A_.cells[f].signs;
      s[k] = sign_char(sgn);
      bool fresh = false;
      const int v = cell(s, 3, [&] {
        return moved_sample(A_.cells[f], sgn > 0 ? P_[k].normal : -P_[k].normal, s);
      }, &fresh);
      A_.cells[v].facets.push_back(f);
    }
  }

  const std::vector<ArrangementPlane>& P_;
  void (*progress_)(double);
  std::vector<Vec3<Interval>> n_;
  std::vector<Interval> c_;
  std::vector<std::array<double, 3>> nd_;  // doubles: only to propose steps
  std::vector<double> cd_;
  PlaneArrangement A_;
  std::unordered_map<std::string, int> by_signs_;
  std::vector<Line> lines_;
  std::vector<int> edge_line_;   // per edge (cell index - vertices): its line
  std::vector<int> face_plane_;  // per 2-face (cell index - vertices - edges): its plane
};

}  // namespace

PlaneArrangement plane_arrangement(const std::vector<ArrangementPlane>& planes, void (*progress)(double)) {
  // The normals must span R^3: some three have a non-zero triple product.
  bool spans = false;
  for (std::size_t i = 0; i < planes.size() && !spans; ++i)
    for (std::size_t j = i + 1; j < planes.size() && !spans; ++j) {
      const Vec3<Exact> d = cross(planes[i].normal, planes[j].normal);
      if (d.x == 0 && d.y == 0 && d.z == 0) continue;
      for (std::size_t k = j + 1; k < planes.size() && !spans; ++k) spans = dot(d, planes[k].normal) != 0;
    }
  if (!spans) throw std::invalid_argument("plane_arrangement: the plane normals do not span R^3");
  return Builder(planes, progress).run();
}

}  // namespace exactvis
