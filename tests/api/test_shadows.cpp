// The shadows façade (api/shadows.hpp): --receivers parsing with the command line's messages, and the JSON
// of `shadows --json` checked against the mesh by independent exact arithmetic: every face's sample lies on
// its receiver's plane, umbra faces see none of the light (fraction 0, no backprojection), lit faces all of
// it (fraction 1), penumbra faces a part strictly between; backprojection vertices lie on the light's plane.
#include "api/shadows.hpp"
#include "events/light_source.hpp"
#include "io/json_number.hpp"
#include "io/load_scene.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace exactvis;

namespace {

// A floor, a square blocker above it and a square light above that (ids: floor 0-1, blocker 2-3, light 4-5).
Scene room() {
  const std::vector<Point3> V{{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}, {-0.5, -0.5, 1}, {0.5, -0.5, 1},
                              {0.5, 0.5, 1}, {-0.5, 0.5, 1}, {-0.25, -0.25, 2}, {0.25, -0.25, 2}, {0.25, 0.25, 2},
                              {-0.25, 0.25, 2}};
  return scene_from_arrays(V, {{0, 1, 2}, {0, 2, 3}, {4, 6, 5}, {4, 7, 6}, {8, 10, 9}, {8, 11, 10}});
}

Exact q(const nlohmann::ordered_json& x) { return exact_from_json(nlohmann::json(x)); }

std::string receivers_error(const Scene& scene, const std::string& text) {
  try {
    api::parse_receivers(scene, text, {4, 5});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(ApiShadows, ReceiversAndMessages) {
  const Scene scene = room();
  EXPECT_TRUE(api::parse_receivers(scene, " all ", {4, 5}).empty());
  EXPECT_EQ(api::parse_receivers(scene, "1, 0,1", {4, 5}), (std::vector<std::int64_t>{1, 0}));
  EXPECT_EQ(receivers_error(scene, "1,x"), "--receivers: 'x' is not a triangle id");
  EXPECT_EQ(receivers_error(scene, "9"), "--receivers: the scene has no triangle 9");
  EXPECT_EQ(receivers_error(scene, "0,4"), "--receivers: triangle 4 is part of the light");
}

TEST(ApiShadows, JsonAgreesWithExactChecks) {
  const Scene scene = room();
  shadows::ShadowOptions options;
  options.light = {4, 5};
  options.receivers = api::parse_receivers(scene, "0,1", options.light);
  options.vertex_irradiance = false;
  const shadows::ShadowResult result = api::shadows(scene, options);
  const nlohmann::ordered_json j = api::shadows_json(scene, result, options.light);
  const api::ShadowCounts n = api::shadow_counts(result);
  EXPECT_EQ(j["counts"]["faces"], n.faces);
  EXPECT_EQ(j["light"]["triangles"], nlohmann::ordered_json::array({4, 5}));
  ASSERT_EQ(j["receivers"].size(), 2u);
  std::uint64_t umbra = 0, penumbra = 0, lit = 0;
  for (const auto& r : j["receivers"])
    for (const auto& f : r["faces"]) {
      EXPECT_EQ(q(f["sample"][2]), Exact(0));  // on the floor z = 0
      const std::string cls = f["class"];
      ASSERT_FALSE(f["light_fraction_exact"].is_null());  // the light is planar
      const Exact frac = q(f["light_fraction_exact"]);
      if (cls == "umbra") {
        ++umbra;
        EXPECT_EQ(frac, Exact(0));
        EXPECT_TRUE(f["backprojection"].empty());
      } else if (cls == "lit") {
        ++lit;
        EXPECT_EQ(frac, Exact(1));
      } else {
        ++penumbra;
        EXPECT_TRUE(Exact(0) < frac && frac < Exact(1)) << f.dump();
      }
      for (const auto& piece : f["backprojection"])
        for (const auto& v : piece["outer"]) EXPECT_EQ(q(v[2]), Exact(2));
    }
  EXPECT_EQ(umbra, n.umbra);
  EXPECT_EQ(penumbra, n.penumbra);
  EXPECT_EQ(lit, n.lit);
  EXPECT_GT(umbra, 0u);  // right under the blocker
  EXPECT_GT(penumbra, 0u);
  EXPECT_GT(lit, 0u);
}

}  // namespace
