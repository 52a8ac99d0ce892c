#pragma once
// Checks of an orthographic aspect graph against the independent slab oracle (oracle::direction_aspect, no
// aspect code), shared by the general (closed and open model) suites: every cell's sample gives its region's
// aspect, adjacent regions' samples give different aspects, and random directions off every circle give the
// aspect of the face whose sign vector they have (a refuting sampler: a missing boundary would show as a face
// with two aspects).
#include "aspect/aspect_graph_3d.hpp"
#include "tests/aspect/aspect_test_models.hpp"
#include "tests/exact_to_mpq.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>
#include <vector>

namespace exactvis::aspect_test {

// The stable ids of the triangles the oracle sees from direction d.
inline std::vector<std::int64_t> oracle_ids(const Scene& s, const Vec3<Exact>& d) {
  std::vector<std::int64_t> ids;
  for (int i : oracle::direction_aspect(oracle_model(s), exact_to_mpq::qv(d))) ids.push_back(s.triangles[i].id);
  return ids;
}

// g must keep its sampled cells (with_cells). `random_directions` integer directions in [-40, 40]^3 off every
// circle, from `seed`.
inline void check_against_oracle(const Scene& s, const AspectGraph3& g, unsigned seed, int random_directions) {
  ASSERT_FALSE(g.sampled_cells.empty());
  for (const auto& c : g.sampled_cells)
    EXPECT_EQ(oracle_ids(s, c.direction), g.regions[c.region].aspect)
        << "cell of dimension " << c.dimension << " in region " << c.region;
  for (const auto& a : g.adjacency) {
    EXPECT_NE(oracle_ids(s, g.regions[a.a].sample), oracle_ids(s, g.regions[a.b].sample));
    EXPECT_FALSE(a.events.empty());
  }
  std::map<std::string, int> face_region;
  for (const auto& c : g.sampled_cells)
    if (c.dimension == 2) face_region[c.signs] = c.region;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-40, 40);
  int checked = 0;
  while (checked < random_directions) {
    const Vec3<Exact> d(Exact(coord(rng)), Exact(coord(rng)), Exact(coord(rng)));
    std::string signs;
    bool on_circle = false;
    for (const auto& n : g.circles) {
      const int sg = CGAL::sign(dot(n, d));
      on_circle |= sg == 0;
      signs += sg > 0 ? '+' : '-';
    }
    if (on_circle) continue;
    ++checked;
    const auto it = face_region.find(signs);
    ASSERT_NE(it, face_region.end());
    EXPECT_EQ(oracle_ids(s, d), g.regions[it->second].aspect) << "d = " << d.x << " " << d.y << " " << d.z;
  }
}

}  // namespace exactvis::aspect_test
