#pragma once
// Independent slow oracle for the exact kernel: plain GMP rationals (gmpxx mpq_class), written without any
// exactvis header and computed by different methods (explicit intersection points, barycentric
// coordinates, parameter-interval clipping, the ruled quadric through three lines) so that tests comparing
// against it can fail. Shared by every module's tests.
#include <gmpxx.h>

#include <array>
#include <optional>
#include <string>
#include <utility>

namespace oracle {

struct QVec {
  mpq_class x, y, z;
};

QVec qvec(double x, double y, double z);  // exact: every finite double is a rational
QVec operator+(const QVec& a, const QVec& b);
QVec operator-(const QVec& a, const QVec& b);
QVec operator*(const mpq_class& s, const QVec& a);
mpq_class dot(const QVec& a, const QVec& b);
QVec cross(const QVec& a, const QVec& b);
bool is_zero(const QVec& a);
bool operator==(const QVec& a, const QVec& b);

int sign(const mpq_class& x);

// Directed line through p then q: d = q - p, m = p x q.
struct QLine {
  QVec d, m;
};
QLine line_through(const QVec& p, const QVec& q);
// side(a,b) = d_a.m_b + d_b.m_a, and the quadric d.m.
mpq_class side(const QLine& a, const QLine& b);
mpq_class quadric(const QLine& a);
// The point of a real line closest to the origin, d x m / |d|^2 (requires d != 0).
QVec point_on(const QLine& l);
// True iff point p lies on line l (p x d = m).
bool on_line(const QVec& p, const QLine& l);

// orient3d(a,b,c,d) = sign det[b-a; c-a; d-a], computed as minus the 4x4 determinant of the homogeneous
// coordinates (rows (a,1), (b,1), (c,1), (d,1)) by cofactor expansion.
int orient3d(const QVec& a, const QVec& b, const QVec& c, const QVec& d);

// Parameter interval {s in [0,1] : a + s (b - a) in conv{t0,t1,t2}} for a != b, empty when no point;
// degenerate (zero-area) triangles are their segment or point. Coplanar case by clipping against the
// edges' in-plane half-planes, transversal case by the explicit crossing point and its barycentric
// coordinates, degenerate triangles by solving the segment-segment system exactly.
std::optional<std::pair<mpq_class, mpq_class>> segment_triangle_interval(const QVec& a, const QVec& b,
                                                                         const QVec& t0, const QVec& t1,
                                                                         const QVec& t2);

bool oracle_point_in_closed_triangle(const QVec& p, const QVec& t0, const QVec& t1, const QVec& t2);
// Relative interior: of the triangle if it has area, of its segment (endpoints excluded) if its corners are
// collinear and not all equal, the point itself if all corners coincide.
bool oracle_point_in_triangle_relative_interior(const QVec& p, const QVec& t0, const QVec& t1, const QVec& t2);
bool oracle_closed_segment_meets_closed_triangle(const QVec& a, const QVec& b, const QVec& t0, const QVec& t1,
                                                 const QVec& t2);
// Open segment (a,b) (empty if a == b) vs closed triangle.
bool oracle_open_segment_meets_closed_triangle(const QVec& a, const QVec& b, const QVec& t0, const QVec& t1,
                                               const QVec& t2);
// a, b strictly on opposite sides of the plane of a triangle with area, crossing point in its interior.
bool oracle_segment_crosses_triangle_interior(const QVec& a, const QVec& b, const QVec& t0, const QVec& t1,
                                              const QVec& t2);

// Axis-aligned boxes [lo, hi] (closed) and (lo, hi) (open).
bool oracle_point_in_closed_box(const QVec& p, const QVec& lo, const QVec& hi);
bool oracle_point_in_open_box(const QVec& p, const QVec& lo, const QVec& hi);

// Line with coordinates a[i] + b[i] sqrt(root), i = 0..5 as (d, m): a line over Q(sqrt(root)).
struct RootLine {
  std::array<mpq_class, 6> a, b;
  mpq_class root;
};
// x + y sqrt(root) == 0, exactly (root >= 0).
bool is_zero_in_extension(const mpq_class& x, const mpq_class& y, const mpq_class& root);
// Sign of x + y sqrt(root) (root >= 0), exactly.
int sign_in_extension(const mpq_class& x, const mpq_class& y, const mpq_class& root);
// sign(side(x, l)) for a line over Q(sqrt(root)) and a rational line.
int side_sign(const RootLine& x, const QLine& l);
// Point with coordinates a[i] + b[i] sqrt(root).
struct RootPoint {
  std::array<mpq_class, 3> a, b;
  mpq_class root;
};
// True iff p lies on line x (p x d = m, exactly in Q(sqrt(root))); the roots of p and x must agree or be 0.
bool on_line(const RootPoint& p, const RootLine& x);
// True iff p lies on the rational line l.
bool on_line(const RootPoint& p, const QLine& l);
// Checks by substitution that x is a real line (d != 0, d.m = 0) meeting each of the four lines
// (side = 0). On failure returns false and says why in *why.
bool check_transversal(const RootLine& x, const std::array<QLine, 4>& lines, std::string* why);
// True iff the two lines (same root) are proportional (the same undirected line).
bool same_line(const RootLine& x, const RootLine& y);

// Number of transversals of four lines counted through the ruled quadric S through l1, l2, l3:
// S = {X : det[X x d_i - m_i]_{i=1..3} = 0} (a quadric: the cubic terms cancel); each point of l4 on S
// (projectively, roots at infinity included) gives one transversal.
// Returns 0, 1 or 2; -1 if l4 lies on S (infinitely many); -2 if l1, l2, l3 are not pairwise skew
// (precondition); -3 if the restriction to l4 is not quadratic (an oracle bug).
int count_transversals_via_quadric(const std::array<QLine, 4>& lines);

}  // namespace oracle
