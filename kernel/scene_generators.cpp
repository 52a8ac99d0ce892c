#include "kernel/scene_generators.hpp"

#include "kernel/predicates.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>

namespace exactvis {
namespace {

// All geometry is built in integer units of 1/64 and converted exactly at the end.
using I = std::int64_t;
constexpr double kUnit = 1.0 / 64.0;

struct Rng {
  std::mt19937_64 engine;
  explicit Rng(std::uint64_t seed) : engine(seed) {}
  // Uniform integer in [lo, hi] (modulo mapping: tiny bias, but identical everywhere, unlike std:: distributions).
  I uniform(I lo, I hi) { return lo + static_cast<I>(engine() % static_cast<std::uint64_t>(hi - lo + 1)); }
};

// Adds vertices and triangles of one object; equal positions within the object share one vertex index.
struct ObjectBuilder {
  Scene& scene;
  int object;
  std::map<std::array<I, 3>, int> index;

  ObjectBuilder(Scene& s, const std::string& name) : scene(s), object(static_cast<int>(s.objects.size())) {
    s.objects.push_back({name});
  }
  int vertex(I x, I y, I z) {
    auto [it, inserted] = index.emplace(std::array<I, 3>{x, y, z}, static_cast<int>(scene.vertices.size()));
    if (inserted) scene.vertices.push_back({x * kUnit, y * kUnit, z * kUnit});
    return it->second;
  }
  int vertex(const std::array<I, 3>& p) { return vertex(p[0], p[1], p[2]); }
  void triangle(int a, int b, int c) {
    const std::int64_t id = static_cast<std::int64_t>(scene.triangles.size());
    scene.triangles.push_back({id, {a, b, c}, object});
  }
};

// Axis-aligned rectangle split at the given cut positions (offsets from `origin` along axes u and v, first 0,
// last the side length); cells with skip(i, j) are holes. Triangles face u x v.
template <class Skip>
void grid_rectangle(ObjectBuilder& b, std::array<I, 3> origin, int u, const std::vector<I>& cu, int v,
                    const std::vector<I>& cv, Skip skip) {
  auto at = [&](size_t i, size_t j) {
    auto p = origin;
    p[u] += cu[i];
    p[v] += cv[j];
    return b.vertex(p);
  };
  for (size_t i = 0; i + 1 < cu.size(); ++i)
    for (size_t j = 0; j + 1 < cv.size(); ++j) {
      if (skip(i, j)) continue;
      const int p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
      b.triangle(p00, p10, p11);
      b.triangle(p00, p11, p01);
    }
}

std::vector<I> uniform_cuts(I length, I segments) {
  std::vector<I> c;
  for (I i = 0; i <= segments; ++i) c.push_back(length * i / segments);
  return c;
}

// Closed box [lo, hi] with each face split k x k; outward-facing unless `inward`. 12 k^2 triangles.
void subdivided_box(ObjectBuilder& b, std::array<I, 3> lo, std::array<I, 3> hi, I k, bool inward = false) {
  const std::array<I, 3> len{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  auto none = [](size_t, size_t) { return false; };
  // Each face as (origin, u, v) with u x v pointing outward.
  struct Face {
    std::array<I, 3> origin;
    int u, v;
  };
  const Face faces[6] = {
      {lo, 1, 0},                      // z = lo, normal -z
      {{lo[0], lo[1], hi[2]}, 0, 1},   // z = hi, normal +z
      {lo, 0, 2},                      // y = lo, normal -y
      {{lo[0], hi[1], lo[2]}, 2, 0},   // y = hi, normal +y
      {lo, 2, 1},                      // x = lo, normal -x
      {{hi[0], lo[1], lo[2]}, 1, 2},   // x = hi, normal +x
  };
  for (const Face& f : faces) {
    const int u = inward ? f.v : f.u, v = inward ? f.u : f.v;
    grid_rectangle(b, f.origin, u, uniform_cuts(len[u], k), v, uniform_cuts(len[v], k), none);
  }
}

// A strip of exactly n triangles (zigzag between two rows) in the plane z, starting at (x, y), width w.
void triangle_strip(ObjectBuilder& b, I x, I y, I z, I w, I n) {
  const I step = std::max<I>(1, 4096 / (n / 2 + 1));
  auto bot = [&](I i) { return b.vertex(x + i * step, y, z); };
  auto top = [&](I i) { return b.vertex(x + i * step, y + w, z); };
  for (I k = 0; k < n; ++k) {
    if (k % 2 == 0) b.triangle(bot(k / 2), bot(k / 2 + 1), top(k / 2));
    else b.triangle(bot((k + 1) / 2), top((k + 1) / 2), top((k - 1) / 2));
  }
}
I strip_length(I n) { return std::max<I>(1, 4096 / (n / 2 + 1)) * (n / 2 + 1); }

I isqrt(I n) {
  I r = static_cast<I>(std::sqrt(static_cast<double>(n)));
  while (r * r > n) --r;
  while ((r + 1) * (r + 1) <= n) ++r;
  return r;
}
// floor(n^(1/4) / d), at least 1.
I scale_param(I n, I d) { return std::max<I>(1, isqrt(isqrt(n)) / d); }

// ---------------------------------------------------------------------------------------------------------
Scene random_scene(I n, Rng& rng) {
  Scene s;
  const I box = 64 * 64;  // 64 world units
  const I size = std::max<I>(16, static_cast<I>(2.0 * box / std::cbrt(static_cast<double>(n))));
  while (static_cast<I>(s.triangles.size()) < n) {
    const I cx = rng.uniform(0, box), cy = rng.uniform(0, box), cz = rng.uniform(0, box);
    std::array<std::array<I, 3>, 3> p;
    for (auto& q : p) q = {cx + rng.uniform(-size, size), cy + rng.uniform(-size, size), cz + rng.uniform(-size, size)};
    auto pt = [&](int k) { return Point3{p[k][0] * kUnit, p[k][1] * kUnit, p[k][2] * kUnit}; };
    if (collinear(pt(0), pt(1), pt(2))) continue;  // exact test; redraw
    ObjectBuilder b(s, "triangle" + std::to_string(s.triangles.size()));
    b.triangle(b.vertex(p[0]), b.vertex(p[1]), b.vertex(p[2]));
  }
  return s;
}

// ---------------------------------------------------------------------------------------------------------
struct Building {
  I nx, ny, nz;     // windows along x walls, along y walls, floors
  I cell, floor_h;  // window-grid cell width and floor height
};
I building_triangles(const Building& b) {
  auto wall = [&](I n) { return 2 * ((2 * n + 1) * (2 * b.nz + 1) - n * b.nz); };
  return 2 * wall(b.nx) + 2 * wall(b.ny) + 2 * (2 * b.nx + 1) + 2 * (2 * b.ny + 1);
}

void emit_building(ObjectBuilder& ob, const Building& b, I x0, I y0) {
  const I w = (2 * b.nx + 1) * b.cell, d = (2 * b.ny + 1) * b.cell, h = (2 * b.nz + 1) * b.floor_h;
  const auto cx = uniform_cuts(w, 2 * b.nx + 1), cy = uniform_cuts(d, 2 * b.ny + 1),
             cz = uniform_cuts(h, 2 * b.nz + 1);
  auto window = [](size_t i, size_t j) { return i % 2 == 1 && j % 2 == 1; };
  auto window_t = [](size_t j, size_t i) { return i % 2 == 1 && j % 2 == 1; };
  grid_rectangle(ob, {x0, y0, 0}, 0, cx, 2, cz, window);          // y = y0, normal -y
  grid_rectangle(ob, {x0, y0 + d, 0}, 2, cz, 0, cx, window_t);    // y = y1, normal +y
  grid_rectangle(ob, {x0, y0, 0}, 2, cz, 1, cy, window_t);        // x = x0, normal -x
  grid_rectangle(ob, {x0 + w, y0, 0}, 1, cy, 2, cz, window);      // x = x1, normal +x
  // Roof: fan from the centre over every boundary point (the walls' top vertices), counterclockwise from above.
  std::vector<int> ring;
  for (size_t i = 0; i + 1 < cx.size(); ++i) ring.push_back(ob.vertex(x0 + cx[i], y0, h));
  for (size_t j = 0; j + 1 < cy.size(); ++j) ring.push_back(ob.vertex(x0 + w, y0 + cy[j], h));
  for (size_t i = cx.size() - 1; i > 0; --i) ring.push_back(ob.vertex(x0 + cx[i], y0 + d, h));
  for (size_t j = cy.size() - 1; j > 0; --j) ring.push_back(ob.vertex(x0, y0 + cy[j], h));
  // The centre must be a grid point: w and d are odd multiples of `cell`, which is even.
  const int centre = ob.vertex(x0 + w / 2, y0 + d / 2, h);
  for (size_t i = 0; i < ring.size(); ++i) ob.triangle(centre, ring[i], ring[(i + 1) % ring.size()]);
}

// Ground rectangle (2 triangles) at z = 0 and a filler strip below its lower edge.
void ground_and_filler(Scene& s, I x0, I y0, I x1, I y1, I filler, const char* filler_name) {
  ObjectBuilder g(s, "ground");
  grid_rectangle(g, {x0, y0, 0}, 0, {0, x1 - x0}, 1, {0, y1 - y0}, [](size_t, size_t) { return false; });
  if (filler > 0) {
    ObjectBuilder f(s, filler_name);
    triangle_strip(f, x0, y0 - 128, 0, 64, filler);
  }
}

Scene town_scene(I n, Rng& rng) {
  const I K = scale_param(n, 5);
  std::vector<Building> buildings;
  I remaining = n - 2;  // ground
  for (;;) {
    Building b{rng.uniform(1, K), rng.uniform(1, K), rng.uniform(1, K), 2 * rng.uniform(24, 48), rng.uniform(64, 128)};
    if (buildings.empty() && building_triangles(b) > remaining) b = {0, 0, 0, b.cell, b.floor_h};
    if (building_triangles(b) > remaining && !buildings.empty()) break;
    buildings.push_back(b);
    remaining -= building_triangles(b);
  }
  const I cols = std::max<I>(1, isqrt(static_cast<I>(buildings.size()) - 1) + 1);
  const I lot = (2 * K + 1) * 96 + 256;  // largest footprint plus a street
  Scene s;
  for (size_t i = 0; i < buildings.size(); ++i) {
    ObjectBuilder ob(s, "building" + std::to_string(i));
    emit_building(ob, buildings[i], static_cast<I>(i) % cols * lot, static_cast<I>(i) / cols * lot);
  }
  const I rows = (static_cast<I>(buildings.size()) + cols - 1) / cols;
  const I filler = std::max<I>(0, remaining);
  ground_and_filler(s, -128, -128, std::max(cols * lot, strip_length(filler) - 128), rows * lot, filler, "curb");
  return s;
}

// ---------------------------------------------------------------------------------------------------------
struct Tree {
  I half_width, height, f, step;  // trunk; crown octahedron split f times, radius f * step
};
I tree_triangles(const Tree& t) { return 14 + 8 * t.f * t.f; }

void emit_tree(ObjectBuilder& ob, const Tree& t, I cx, I cy) {
  const I a = t.half_width, h = t.height;
  // Trunk: a box open at the top, closed by a fan to the top centre, which is also the crown's lowest vertex.
  const std::array<I, 3> lo{cx - a, cy - a, 0};
  auto none = [](size_t, size_t) { return false; };
  grid_rectangle(ob, lo, 1, {0, 2 * a}, 0, {0, 2 * a}, none);           // bottom, normal -z
  grid_rectangle(ob, lo, 0, {0, 2 * a}, 2, {0, h}, none);               // y = lo, normal -y
  grid_rectangle(ob, {cx - a, cy + a, 0}, 2, {0, h}, 0, {0, 2 * a}, none);  // y = hi
  grid_rectangle(ob, lo, 2, {0, h}, 1, {0, 2 * a}, none);               // x = lo
  grid_rectangle(ob, {cx + a, cy - a, 0}, 1, {0, 2 * a}, 2, {0, h}, none);  // x = hi
  const int top = ob.vertex(cx, cy, h);
  const int c00 = ob.vertex(cx - a, cy - a, h), c10 = ob.vertex(cx + a, cy - a, h), c11 = ob.vertex(cx + a, cy + a, h),
            c01 = ob.vertex(cx - a, cy + a, h);
  ob.triangle(top, c00, c10);
  ob.triangle(top, c10, c11);
  ob.triangle(top, c11, c01);
  ob.triangle(top, c01, c00);
  // Crown: octahedron |x|+|y|+|z| = R around (cx, cy, h + R), each face split into f^2 triangles.
  const I R = t.f * t.step;
  const std::array<I, 3> centre{cx, cy, h + R};
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) {
        std::array<I, 3> A = centre, B = centre, C = centre;
        A[0] += sx * R;
        B[1] += sy * R;
        C[2] += sz * R;
        if (sx * sy * sz < 0) std::swap(B, C);  // keep the outward orientation
        auto P = [&](I i, I j) {
          std::array<I, 3> p;
          for (int k = 0; k < 3; ++k) p[k] = A[k] + (B[k] - A[k]) / t.f * i + (C[k] - A[k]) / t.f * j;
          return ob.vertex(p);
        };
        for (I i = 0; i < t.f; ++i)
          for (I j = 0; i + j < t.f; ++j) {
            ob.triangle(P(i, j), P(i + 1, j), P(i, j + 1));
            if (i + j + 2 <= t.f) ob.triangle(P(i + 1, j), P(i + 1, j + 1), P(i, j + 1));
          }
      }
}

Scene forest_scene(I n, Rng& rng) {
  const I F = scale_param(n, 4);
  std::vector<Tree> trees;
  I remaining = n - 2;
  for (;;) {
    const I f = rng.uniform(1, F);
    Tree t{rng.uniform(8, 16), rng.uniform(64, 192), f, std::max<I>(1, rng.uniform(64, 160) / f)};
    if (tree_triangles(t) > remaining && !trees.empty()) break;
    if (tree_triangles(t) > remaining) t.f = 1, t.step = rng.uniform(64, 160);
    trees.push_back(t);
    remaining -= tree_triangles(t);
  }
  const I cols = std::max<I>(1, isqrt(static_cast<I>(trees.size()) - 1) + 1);
  const I lot = 2 * 160 + 96;
  Scene s;
  for (size_t i = 0; i < trees.size(); ++i) {
    ObjectBuilder ob(s, "tree" + std::to_string(i));
    const I jx = rng.uniform(-32, 32), jy = rng.uniform(-32, 32);  // jitter: not a perfect grid
    emit_tree(ob, trees[i], static_cast<I>(i) % cols * lot + lot / 2 + jx, static_cast<I>(i) / cols * lot + lot / 2 + jy);
  }
  const I rows = (static_cast<I>(trees.size()) + cols - 1) / cols;
  const I filler = std::max<I>(0, remaining);
  ground_and_filler(s, 0, 0, std::max(cols * lot, strip_length(filler)), rows * lot, filler, "path");
  return s;
}

// ---------------------------------------------------------------------------------------------------------
struct Furniture {
  I w, d, h, k;
};

Scene room_scene(I n, Rng& rng) {
  const I K = scale_param(n, 4);
  std::vector<Furniture> pieces;
  I budget = std::max<I>(12, n / 2), used = 0;
  for (;;) {
    Furniture p{rng.uniform(64, 256), rng.uniform(64, 256), rng.uniform(32, 192), rng.uniform(1, K)};
    if (used + 12 * p.k * p.k > budget && !pieces.empty()) break;
    if (used + 12 * p.k * p.k > budget) p.k = 1;
    pieces.push_back(p);
    used += 12 * p.k * p.k;
  }
  const I shell_budget = std::max<I>(12, n - used);
  const I g = std::max<I>(1, isqrt(shell_budget / 12));
  const I filler = std::max<I>(0, n - used - 12 * g * g);
  const I cols = std::max<I>(1, isqrt(static_cast<I>(pieces.size()) - 1) + 1);
  const I rows = (static_cast<I>(pieces.size()) + cols - 1) / cols;
  const I cell = 320, band = 256;  // furniture grid cell; rug band along the y = 0 wall
  const I W = std::max(cols * cell + 128, strip_length(filler) + 128);
  const I D = band + rows * cell + 64, H = 384;
  Scene s;
  {
    ObjectBuilder shell(s, "room");
    subdivided_box(shell, {0, 0, 0}, {W, D, H}, g, /*inward=*/true);
  }
  for (size_t i = 0; i < pieces.size(); ++i) {
    ObjectBuilder ob(s, "furniture" + std::to_string(i));
    const Furniture& p = pieces[i];
    const I x0 = 64 + static_cast<I>(i) % cols * cell + rng.uniform(0, cell - 32 - p.w);
    const I y0 = band + static_cast<I>(i) / cols * cell + rng.uniform(0, cell - 32 - p.d);
    subdivided_box(ob, {x0, y0, 0}, {x0 + p.w, y0 + p.d, p.h}, p.k);
  }
  if (filler > 0) {
    ObjectBuilder rug(s, "rug");
    triangle_strip(rug, 64, 64, 1, 128, filler);
  }
  return s;
}

}  // namespace

const std::vector<std::string>& scene_generator_kinds() {
  static const std::vector<std::string> kinds{"random", "town", "forest", "room"};
  return kinds;
}

Scene generate_scene(const std::string& kind, std::int64_t triangles, std::uint64_t seed) {
  if (triangles < 10 || triangles > 10'000'000)
    throw std::invalid_argument("triangle count " + std::to_string(triangles) + " out of range [10, 10^7]");
  Rng rng(seed);
  Scene s;
  if (kind == "random") s = random_scene(triangles, rng);
  else if (kind == "town") s = town_scene(triangles, rng);
  else if (kind == "forest") s = forest_scene(triangles, rng);
  else if (kind == "room") s = room_scene(triangles, rng);
  else throw std::invalid_argument("unknown scene kind '" + kind + "' (expected random, town, forest or room)");
  s.faces_read = static_cast<std::int64_t>(s.triangles.size());
  return s;
}

}  // namespace exactvis
