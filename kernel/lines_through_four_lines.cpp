#include "kernel/lines_through_four_lines.hpp"

#include <gmp.h>

#include <stdexcept>
#include <utility>

namespace exactvis {
namespace {

using Row = std::vector<Exact>;
using Matrix = std::vector<Row>;

bool is_zero(const Vec3<Exact>& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

// Scale a nonzero rational vector to a primitive integer vector with the same direction (positive factor):
// keeps the numbers of the later quadratic small.
Row primitive(Row v) {
  mpz_t l, g, t;
  mpz_init_set_ui(l, 1);
  mpz_init_set_ui(g, 0);
  mpz_init(t);
  for (const Exact& x : v) mpz_lcm(l, l, mpq_denref(x.mpq()));
  for (Exact& x : v) {
    x *= Exact(ExactInt(l));
    mpz_gcd(g, g, mpq_numref(x.mpq()));
  }
  if (mpz_sgn(g) != 0)
    for (Exact& x : v) x /= Exact(ExactInt(g));
  mpz_clear(l);
  mpz_clear(g);
  mpz_clear(t);
  return v;
}

// Basis of the right nullspace of an m x n rational matrix (exact Gauss-Jordan elimination).
Matrix nullspace(Matrix a, int n) {
  const int m = static_cast<int>(a.size());
  std::vector<int> pivot_col;
  int row = 0;
  for (int col = 0; col < n && row < m; ++col) {
    int p = row;
    while (p < m && a[p][col] == 0) ++p;
    if (p == m) continue;
    std::swap(a[p], a[row]);
    const Exact inv = Exact(1) / a[row][col];
    for (int c = col; c < n; ++c) a[row][c] *= inv;
    for (int r = 0; r < m; ++r)
      if (r != row && a[r][col] != 0) {
        const Exact f = a[r][col];
        for (int c = col; c < n; ++c) a[r][c] -= f * a[row][c];
      }
    pivot_col.push_back(col);
    ++row;
  }
  Matrix basis;
  std::vector<bool> is_pivot(n, false);
  for (int c : pivot_col) is_pivot[c] = true;
  for (int f = 0; f < n; ++f) {
    if (is_pivot[f]) continue;
    Row v(n, Exact(0));
    v[f] = 1;
    for (int r = 0; r < static_cast<int>(pivot_col.size()); ++r) v[pivot_col[r]] = -a[r][f];
    basis.push_back(primitive(std::move(v)));
  }
  return basis;
}

// An owned GMP integer with value semantics. (CGAL::Gmpz shares its representation between copies, so
// writing through mpz() would change every copy.)
struct Z {
  mpz_t v;
  Z() { mpz_init(v); }
  Z(const Z& o) { mpz_init_set(v, o.v); }
  Z& operator=(const Z& o) {
    if (this != &o) mpz_set(v, o.v);
    return *this;
  }
  ~Z() { mpz_clear(v); }
};
using IntRow = std::vector<Z>;

// Basis of the right nullspace of an m x n rational matrix, as primitive integer vectors, computed without
// rationals (GCD-heavy): each row is scaled to integers, then fraction-free (Bareiss) elimination to an
// echelon form, then fraction-free back substitution. Same vectors as nullspace(), several times faster.
Matrix integer_nullspace(const Matrix& a, int n) {
  const int m = static_cast<int>(a.size());
  std::vector<IntRow> e(m, IntRow(n));
  Z l, t;
  for (int r = 0; r < m; ++r) {
    mpz_set_ui(l.v, 1);
    for (int c = 0; c < n; ++c) mpz_lcm(l.v, l.v, mpq_denref(a[r][c].mpq()));
    for (int c = 0; c < n; ++c) {
      mpz_divexact(t.v, l.v, mpq_denref(a[r][c].mpq()));
      mpz_mul(e[r][c].v, t.v, mpq_numref(a[r][c].mpq()));
    }
  }
  std::vector<int> pc;  // pivot column of each echelon row
  Z prev;
  mpz_set_ui(prev.v, 1);
  int row = 0;
  for (int col = 0; col < n && row < m; ++col) {
    int p = row;
    while (p < m && mpz_sgn(e[p][col].v) == 0) ++p;
    if (p == m) continue;
    std::swap(e[p], e[row]);
    for (int i = row + 1; i < m; ++i) {
      for (int j = col + 1; j < n; ++j) {
        // e[i][j] = (e[row][col] e[i][j] - e[i][col] e[row][j]) / prev, an exact division (Bareiss).
        mpz_mul(t.v, e[row][col].v, e[i][j].v);
        mpz_submul(t.v, e[i][col].v, e[row][j].v);
        mpz_divexact(e[i][j].v, t.v, prev.v);
      }
      mpz_set_ui(e[i][col].v, 0);
    }
    mpz_set(prev.v, e[row][col].v);
    pc.push_back(col);
    ++row;
  }
  std::vector<bool> is_pivot(n, false);
  for (int c : pc) is_pivot[c] = true;
  Z pivots;
  mpz_set_ui(pivots.v, 1);
  for (int i = 0; i < row; ++i) mpz_mul(pivots.v, pivots.v, e[i][pc[i]].v);
  Matrix basis;
  for (int f = 0; f < n; ++f) {
    if (is_pivot[f]) continue;
    // x_f = product of the pivots makes every back-substitution division exact.
    IntRow x(n);
    mpz_set(x[f].v, pivots.v);
    for (int i = row - 1; i >= 0; --i) {
      mpz_set_ui(t.v, 0);
      for (int j = pc[i] + 1; j < n; ++j) mpz_addmul(t.v, e[i][j].v, x[j].v);
      mpz_divexact(x[pc[i]].v, t.v, e[i][pc[i]].v);
      mpz_neg(x[pc[i]].v, x[pc[i]].v);
    }
    Z g;
    for (const auto& v : x) mpz_gcd(g.v, g.v, v.v);
    if (mpz_sgn(pivots.v) < 0) mpz_neg(g.v, g.v);  // keep x_f > 0, as nullspace() does
    Row out(n);
    for (int j = 0; j < n; ++j) {
      mpz_divexact(x[j].v, x[j].v, g.v);
      out[j] = Exact(ExactInt(x[j].v));
    }
    basis.push_back(std::move(out));
  }
  return basis;
}

PluckerLine<Exact> as_line(const Row& v) { return {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}}; }

struct Signature {
  int positive = 0, negative = 0;
};

// Signature of a symmetric rational matrix by congruence (symmetric Gaussian elimination).
Signature signature(Matrix g) {
  Signature s;
  const int k = static_cast<int>(g.size());
  auto swap_index = [&](int i, int j) {
    std::swap(g[i], g[j]);
    for (auto& r : g) std::swap(r[i], r[j]);
  };
  for (int step = 0; step < k; ++step) {
    int p = step;
    while (p < k && g[p][p] == 0) ++p;
    if (p == k) {
      // Zero diagonal: use e_i + e_j, whose value 2 g_ij is nonzero if g_ij != 0.
      int pi = -1, pj = -1;
      for (int i = step; i < k && pi < 0; ++i)
        for (int j = i + 1; j < k; ++j)
          if (g[i][j] != 0) {
            pi = i;
            pj = j;
            break;
          }
      if (pi < 0) break;  // the rest of the matrix is zero
      for (int c = 0; c < k; ++c) g[pi][c] += g[pj][c];
      for (int r = 0; r < k; ++r) g[r][pi] += g[r][pj];
      p = pi;
    }
    swap_index(step, p);
    const Exact piv = g[step][step];
    (piv > 0 ? s.positive : s.negative)++;
    for (int r = step + 1; r < k; ++r) {
      if (g[r][step] == 0) continue;
      const Exact f = g[r][step] / piv;
      for (int c = step + 1; c < k; ++c) g[r][c] -= f * g[step][c];
      g[r][step] = 0;
      g[step][r] = 0;
    }
  }
  return s;
}

bool perfect_square_root(const Exact& q, Exact* root) {
  if (q < 0) return false;
  const mpz_srcptr num = mpq_numref(q.mpq());
  const mpz_srcptr den = mpq_denref(q.mpq());
  if (!mpz_perfect_square_p(num) || !mpz_perfect_square_p(den)) return false;
  ExactInt rn, rd;
  mpz_sqrt(rn.mpz(), num);
  mpz_sqrt(rd.mpz(), den);
  *root = Exact(rn, rd);
  return true;
}

PluckerLine<RootNumber> rational_line(const Row& v) {
  PluckerLine<RootNumber> l;
  for (int i = 0; i < 6; ++i) l[i] = RootNumber(v[i]);
  return l;
}

// Adds a candidate transversal; lines at infinity (d = 0) are only counted.
void add_solution(LinesThroughFourLines& out, PluckerLine<RootNumber> x) {
  if (CGAL::is_zero(x.d.x) && CGAL::is_zero(x.d.y) && CGAL::is_zero(x.d.z))
    ++out.at_infinity;
  else
    out.lines.push_back(std::move(x));
}

Row combine(const Exact& s, const Row& u, const Exact& t, const Row& v) {
  Row x(6);
  for (int i = 0; i < 6; ++i) x[i] = s * u[i] + t * v[i];
  return x;
}

// Nullspace of dimension 2: x = s u + t v, and d.m(x) = a s^2 + b s t + c t^2 with a = Q(u), b = side(u,v),
// c = Q(v). Roots are taken projectively, so no root is lost when a = 0.
LinesThroughFourLines solve_pencil(const Row& u, const Row& v) {
  LinesThroughFourLines out;
  const auto lu = as_line(u), lv = as_line(v);
  const Exact a = quadric(lu), b = side(lu, lv), c = quadric(lv);
  if (a == 0 && b == 0 && c == 0) {
    out.kind = TransversalKind::Infinite;
    out.family_basis = {lu, lv};
    return out;
  }
  if (a == 0) {
    // t (b s + c t) = 0: t = 0 (x = u) and, if b != 0, (s, t) = (-c, b).
    add_solution(out, rational_line(u));
    if (b != 0) add_solution(out, rational_line(combine(-c, u, b, v)));
    return out;
  }
  const Exact disc = b * b - 4 * a * c;
  if (disc < 0) return out;
  // s/t = (-b +- sqrt(disc)) / (2a), scaled by 2a: x = (-b +- sqrt(disc)) u + 2a v.
  if (disc == 0) {
    add_solution(out, rational_line(combine(-b, u, 2 * a, v)));
    return out;
  }
  Exact r;
  if (perfect_square_root(disc, &r)) {
    add_solution(out, rational_line(combine(-b + r, u, 2 * a, v)));
    add_solution(out, rational_line(combine(-b - r, u, 2 * a, v)));
    return out;
  }
  const Row base = combine(-b, u, 2 * a, v);
  for (int sgn : {1, -1}) {
    PluckerLine<RootNumber> x;
    for (int i = 0; i < 6; ++i) x[i] = RootNumber(base[i], Exact(sgn) * u[i], disc);
    add_solution(out, std::move(x));
  }
  return out;
}

// Nullspace N of dimension k >= 3: the transversals are the isotropic vectors of Q restricted to N.
// An indefinite form has infinitely many; a semidefinite one exactly its kernel.
LinesThroughFourLines solve_higher(const Matrix& n) {
  LinesThroughFourLines out;
  const int k = static_cast<int>(n.size());
  Matrix g(k, Row(k));
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) g[i][j] = side(as_line(n[i]), as_line(n[j]));  // = 2 x bilinear form
  const Signature s = signature(g);
  if (s.positive > 0 && s.negative > 0) {
    out.kind = TransversalKind::Infinite;
    for (const Row& r : n) out.family_basis.push_back(as_line(r));
    return out;
  }
  const Matrix ker = nullspace(g, k);
  std::vector<Row> vectors;
  for (const Row& c : ker) {
    Row x(6, Exact(0));
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < 6; ++j) x[j] += c[i] * n[i][j];
    vectors.push_back(primitive(std::move(x)));
  }
  if (vectors.size() == 1) {
    add_solution(out, rational_line(vectors[0]));
  } else if (vectors.size() >= 2) {
    out.kind = TransversalKind::Infinite;
    for (const Row& r : vectors) out.family_basis.push_back(as_line(r));
  }
  return out;
}

}  // namespace

LinesThroughFourLines lines_through_four_lines(const std::array<PluckerLine<Exact>, 4>& lines) {
  for (const auto& l : lines)
    if (is_zero(l.d) || quadric(l) != 0)
      throw std::invalid_argument("lines_through_four_lines: input is not a real line (d = 0 or d.m != 0)");
  // side(x, l) = d_x . m_l + m_x . d_l: the row (m_l, d_l) applied to x = (d_x, m_x).
  Matrix a;
  for (const auto& l : lines) a.push_back({l.m.x, l.m.y, l.m.z, l.d.x, l.d.y, l.d.z});
  const Matrix n = integer_nullspace(a, 6);
  if (n.size() == 2) return solve_pencil(n[0], n[1]);
  return solve_higher(n);
}

std::array<double, 6> to_double(const PluckerLine<RootNumber>& line) {
  std::array<double, 6> r{};
  for (int i = 0; i < 6; ++i) r[i] = CGAL::to_double(line[i]);
  return r;
}

}  // namespace exactvis
