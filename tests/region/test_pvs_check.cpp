// Exact check of another tool's PVS (region/pvs_check.hpp): errors planted in a PVS (visible ids removed,
// hidden ids added) are found exactly, no more and no fewer; every false invisible witness is re-checked by
// the independent oracle and every triangle the check calls hidden is attacked by its refutation sampling;
// hand-built adversarial scenes (coplanar ground, closed box, a 1e-9 slit, touching slit) with known answers.
#include "region/pvs_check.hpp"

#include "kernel/scene_generators.hpp"
#include "oracles/visibility_oracle.hpp"
#include "tests/region/region_scene_builder.hpp"
#include "tests/region/oracle_input.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

using namespace exactvis;
using namespace exactvis::region;

namespace {

using region_test::qv;

using region_test::SceneBuilder;

std::vector<std::int64_t> indices_where(const std::vector<bool>& v, bool value) {
  std::vector<std::int64_t> out;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] == value) out.push_back(static_cast<std::int64_t>(i));
  return out;
}

// The exact answer (region/exact_pvs through the check) verified by the oracle: witnesses of the visible triangles (from a check of an empty PVS,
// where every visible triangle is false invisible) valid, hidden ones not refuted by sampling.
std::vector<bool> oracle_checked_answer(const Scene& scene, const RationalBox3& cell) {
  const PvsCheck c = check_reported_pvs(PvsContext(scene), cell, {});
  EXPECT_TRUE(c.false_visible.empty());
  EXPECT_EQ(c.reported, 0);
  EXPECT_EQ(c.exact, static_cast<std::int64_t>(c.false_invisible.size()));
  const auto os = region_test::oracle_scene(scene);
  const oracle::Source src = region_test::oracle_box(cell.lo, cell.hi);
  for (std::size_t i = 0; i < c.false_invisible.size(); ++i) {
    std::string why;
    EXPECT_TRUE(oracle::witness_is_valid(os, static_cast<std::size_t>(c.false_invisible[i]), src,
                                         qv(c.false_invisible_witness[i].p), qv(c.false_invisible_witness[i].q), &why))
        << "triangle " << c.false_invisible[i] << ": " << why;
  }
  for (const std::int64_t h : indices_where(c.exactly_visible, false))
    EXPECT_FALSE(oracle::find_robust_free_segment(os, static_cast<std::size_t>(h), src, 150, 11))
        << "triangle " << h << " called hidden, but the oracle found a free segment";
  return c.exactly_visible;
}

// Plants errors into the exact PVS and checks that exactly those are found.
void expect_planted_errors_found(const Scene& scene, const RationalBox3& cell, std::uint64_t seed) {
  const std::vector<bool> exact = oracle_checked_answer(scene, cell);
  std::vector<std::int64_t> visible = indices_where(exact, true), hidden = indices_where(exact, false);
  ASSERT_FALSE(visible.empty());
  std::mt19937_64 rng(seed);
  std::shuffle(visible.begin(), visible.end(), rng);
  std::shuffle(hidden.begin(), hidden.end(), rng);
  const std::size_t n_removed = std::max<std::size_t>(1, visible.size() / 4);
  const std::size_t n_added = std::min<std::size_t>(hidden.size(), 5);
  std::vector<std::int64_t> removed(visible.begin(), visible.begin() + static_cast<std::ptrdiff_t>(n_removed));
  std::vector<std::int64_t> added(hidden.begin(), hidden.begin() + static_cast<std::ptrdiff_t>(n_added));
  std::vector<std::int64_t> reported(visible.begin() + static_cast<std::ptrdiff_t>(n_removed), visible.end());
  reported.insert(reported.end(), added.begin(), added.end());
  if (!reported.empty()) reported.push_back(reported.front());  // repeats count once
  std::shuffle(reported.begin(), reported.end(), rng);
  std::sort(removed.begin(), removed.end());
  std::sort(added.begin(), added.end());

  PvsOptions options;
  options.threads = 2;
  const PvsCheck c = check_reported_pvs(PvsContext(scene), cell, reported, options);
  EXPECT_EQ(c.false_invisible, removed);
  EXPECT_EQ(c.false_visible, added);
  EXPECT_EQ(c.exact, static_cast<std::int64_t>(visible.size()));
  EXPECT_EQ(c.reported, static_cast<std::int64_t>(visible.size() - n_removed + n_added));
  EXPECT_EQ(c.false_invisible_witness.size(), c.false_invisible.size());
  EXPECT_EQ(c.exactly_visible, exact);
}

TEST(PvsCheck, PlantedErrorsFoundOnGeneratedTown) {
  const Scene scene = generate_scene("town", 120, 5);
  const RationalBox3 cell{{Exact(1, 3), Exact(1, 3), Exact(1, 2)}, {Exact(7, 3), Exact(5, 3), Exact(3, 2)}};
  expect_planted_errors_found(scene, cell, 1);
}

TEST(PvsCheck, PlantedErrorsFoundOnGeneratedForest) {
  const Scene scene = generate_scene("forest", 60, 2);
  const Box3 box = bounding_box(scene);
  const Exact cx = (Exact(box.lo.x) + Exact(box.hi.x)) / 2, cy = (Exact(box.lo.y) + Exact(box.hi.y)) / 2;
  const RationalBox3 cell{{cx - 1, cy - 1, Exact(box.lo.z) + Exact(1, 4)}, {cx + 1, cy + 1, Exact(box.lo.z) + 1}};
  expect_planted_errors_found(scene, cell, 2);
}

TEST(PvsCheck, PlantedErrorsFoundOnAdversarialScenes) {
  {  // Ground coplanar with a building's bottom: the bottom (triangles 10, 11) is hidden, the rest visible.
    SceneBuilder b;
    b.box({0, 0, 0}, {2, 2, 2});
    b.quad({-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0});
    const RationalBox3 cell = exact_box({{-5, -5, 8}, {7, 7, 9}});
    const std::vector<bool> exact = oracle_checked_answer(b.scene, cell);
    for (std::int64_t t = 0; t < 14; ++t) EXPECT_EQ(exact[static_cast<std::size_t>(t)], t != 10 && t != 11) << t;
    expect_planted_errors_found(b.scene, cell, 3);
  }
  {  // A slit 1e-9 wide: the target behind it (0) is visible, the one behind the wall (1) hidden; a second
     // wall with a touching (zero-width) slit hides target 2.
    SceneBuilder b;
    b.triangle({10, -1, -1}, {10, 1, -1}, {10, 0, 1});
    b.triangle({10, 5, -1}, {10, 7, -1}, {10, 6, 1});
    b.triangle({10, -1, 21}, {10, 1, 21}, {10, 0, 23});
    b.quad({5, -10, -10}, {5, -5e-10, -10}, {5, -5e-10, 10}, {5, -10, 10});
    b.quad({5, 5e-10, -10}, {5, 10, -10}, {5, 10, 10}, {5, 5e-10, 10});
    b.quad({5, -10, 12}, {5, 0, 12}, {5, 0, 32}, {5, -10, 32});
    b.quad({5, 0, 12}, {5, 10, 12}, {5, 10, 32}, {5, 0, 32});
    const RationalBox3 cell = exact_box({{-1, -1, -1}, {0, 1, 1}});
    const RationalBox3 cell_up = exact_box({{-1, -1, 21}, {0, 1, 23}});
    const std::vector<bool> exact = oracle_checked_answer(b.scene, cell);
    EXPECT_TRUE(exact[0]);
    EXPECT_FALSE(exact[1]);
    EXPECT_FALSE(oracle_checked_answer(b.scene, cell_up)[2]);
    expect_planted_errors_found(b.scene, cell, 4);
  }
}

TEST(PvsCheck, RefusesIndicesOutOfRange) {
  SceneBuilder b;
  b.triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const RationalBox3 cell = exact_box({{0, 0, 1}, {1, 1, 2}});
  const PvsContext context(b.scene);
  EXPECT_THROW(check_reported_pvs(context, cell, {1}), std::invalid_argument);
  EXPECT_THROW(check_reported_pvs(context, cell, {-1}), std::invalid_argument);
}

}  // namespace
