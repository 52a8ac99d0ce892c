// The skeleton façade (api/skeleton.hpp): --pair parsing (names, triangle ids, the command line's
// messages), the lazy pair build against the slice of the full skeleton (two different computations), and
// the JSON of `skeleton --json`.
#include "api/skeleton.hpp"
#include "io/load_scene.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace exactvis;

namespace {

// Two unit-square plates, one above the other and shifted, between a floor and a ceiling (so that critical
// lines end on objects at both ends).
Scene plates() {
  const std::vector<Point3> V{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {0.5, 0.25, 2}, {1.5, 0.25, 2},
                              {1.5, 1.25, 2}, {0.5, 1.25, 2}, {-2, -2, 0}, {3, -2, 0}, {3, 3, 0}, {-2, 3, 0},
                              {-2, -2, 3}, {3, -2, 3}, {3, 3, 3}, {-2, 3, 3}};
  return scene_from_arrays(V, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}, {8, 9, 10}, {8, 10, 11}, {12, 14, 13},
                               {12, 15, 14}});
}

std::string message(const Scene& scene, const std::string& spec) {
  try {
    api::parse_skeleton_pair(scene, spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(ApiSkeleton, PairParsingAndMessages) {
  const Scene scene = plates();
  const auto p = api::parse_skeleton_pair(scene, "0,4");
  EXPECT_EQ(p.first.triangle, 0);
  EXPECT_EQ(p.second.triangle, 4);
  ASSERT_FALSE(scene.objects.empty());
  const auto named = api::parse_skeleton_pair(scene, scene.objects[0].name + ",5");
  EXPECT_EQ(named.first.object, 0);
  EXPECT_EQ(named.first.triangle, -1);
  EXPECT_EQ(message(scene, "0,99"), "--pair '0,99': '99' is neither an object name nor a triangle id of the scene");
  EXPECT_EQ(message(scene, "0"), "--pair '0': expected two objects A,B (object names or triangle ids)");
  EXPECT_EQ(message(scene, "0,"), "--pair '0,': expected two objects A,B (object names or triangle ids)");
  EXPECT_EQ(message(scene, "a,b,c"), "--pair 'a,b,c': expected two objects A,B (object names or triangle ids)");
}

TEST(ApiSkeleton, PairBuildEqualsSliceOfFullAndJson) {
  const Scene scene = plates();
  const Skeleton3D full = api::skeleton(scene, {});
  const nlohmann::ordered_json j = api::skeleton_json(scene, full);
  EXPECT_EQ(j["arcs"].size(), full.arcs.size());
  EXPECT_EQ(j["nodes"].size(), full.nodes.size());
  ASSERT_GT(full.arcs.size(), 0u);
  api::SkeletonRequest request;
  // the pair of distinct objects with the most arcs between them (Durand's table of the full skeleton)
  std::array<int, 2> best{-1, -1};
  std::size_t most = 0;
  for (const auto& [objects, sl] : full.by_objects)
    if (objects[0] >= 0 && objects[0] != objects[1] && sl.arcs.size() > most) {
      most = sl.arcs.size();
      best = objects;
    }
  ASSERT_GE(best[0], 0);
  request.pair = api::parse_skeleton_pair(scene, scene.objects[best[0]].name + "," + scene.objects[best[1]].name);
  const Skeleton3D lazy = api::skeleton(scene, request);
  const SkeletonPairSlice slice = pair_slice(scene, full, request.pair->first, request.pair->second);
  EXPECT_EQ(lazy.arcs.size(), slice.arcs.size());
  ASSERT_GT(lazy.arcs.size(), 0u);
  EXPECT_LT(lazy.arcs.size(), full.arcs.size());
  const nlohmann::ordered_json lj = api::skeleton_json(scene, lazy);
  for (std::size_t k = 0; k < slice.arcs.size(); ++k) {
    nlohmann::ordered_json a = j["arcs"][slice.arcs[k]], b = lj["arcs"][k];
    a.erase("nodes");  // node indices are renumbered within the slice
    b.erase("nodes");
    EXPECT_EQ(a, b) << k;
  }
}

}  // namespace
