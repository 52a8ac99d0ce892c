// The `exactvis events` subcommand end to end: JSON shape, light selection, .vtp output, bad input.
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

// The suite's scene files and outputs, in one directory of this test process (removed at its end).
const std::filesystem::path& scratch() {
  static const cli_test::TempDir dir("events-cli");
  return dir.path;
}

cli_test::CliRun run(const std::string& args) { return cli_test::run_exactvis(scratch(), args); }

std::filesystem::path scene_file() {
  const auto path = scratch() / "cube_floor_lamp.obj";
  std::ofstream f(path);
  f << "o cube\n";
  for (int i = 0; i < 8; ++i) f << "v " << 2 * (i & 1) << " " << 2 * ((i >> 1) & 1) << " " << 2 * ((i >> 2) & 1) << "\n";
  f << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
    << "o floor\nv -10 -10 -1\nv 10 -10 -1\nv 10 10 -1\nv -10 10 -1\nf 9 10 11 12\n"
    << "o lamp\nv 0.5 0.5 6\nv 1.5 0.5 6\nv 1.5 1.5 6\nv 0.5 1.5 6\nf 13 14 15 16\n";
  return path;
}

TEST(EventsCli, LightRestrictedJson) {
  const auto r = run("events " + scene_file().string() + " --light lamp --json");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["counts"]["EV"], 64);  // see tests/events/test_ev_events.cpp, CubeAboveFloorWithLight
  ASSERT_TRUE(j["counts"]["EEE"].is_number_integer());
  EXPECT_FALSE(j.contains("not_computed"));
  ASSERT_EQ(j["events"].size(), 64u + j["counts"]["EEE"].get<std::size_t>());
  for (const auto& e : j["events"]) {
    if (e["kind"] == "EEE") continue;  // checked in EeeEventsJsonShape
    EXPECT_EQ(e["kind"], "EV");
    EXPECT_LT(e["edge"][0].get<int>(), e["edge"][1].get<int>());
    // One free interval [0, 1]; its pieces (split where the end objects change: the floor's two triangles)
    // are listed in segment_ends, contiguous, with different end objects on neighbouring pieces.
    const auto& iv = e["intervals"];
    ASSERT_EQ(iv.size(), 1u);
    EXPECT_EQ(iv[0][0], 0);
    EXPECT_EQ(iv[0][1], 1);
    EXPECT_EQ(e["ends"][0][0]["cause"], "edge_endpoint");
    EXPECT_NE(e["ends"][0][1]["cause"], "end_object_change");
    // The key of the t = 0 end: the VV line through V and the edge's first vertex.
    EXPECT_EQ(e["ends"][0][0]["key"],
              (nlohmann::json{{"kind", "VV"}, {"vertices", {std::min(e["vertex"].get<int>(), e["edge"][0].get<int>()),
                                                            std::max(e["vertex"].get<int>(), e["edge"][0].get<int>())}},
                              {"edges", nlohmann::json::array()}, {"faces", nlohmann::json::array()}}));
    const auto& pieces = e["segment_ends"];
    ASSERT_GE(pieces.size(), 1u);
    EXPECT_EQ(pieces[0]["t0"], 0);
    EXPECT_EQ(pieces[pieces.size() - 1]["t1"], 1);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      EXPECT_EQ(pieces[i]["interval"], 0);
      if (i + 1 == pieces.size()) continue;
      EXPECT_EQ(pieces[i]["t1"], pieces[i + 1]["t0"]);
      EXPECT_TRUE(pieces[i]["beyond_edge"] != pieces[i + 1]["beyond_edge"] ||
                  pieces[i]["behind_vertex"] != pieces[i + 1]["behind_vertex"]);
    }
  }
}

// --no-split: one entry per free interval (here [0, 1] for every light event), no end_object_change ends.
TEST(EventsCli, NoSplitReportsFreeIntervalsOnce) {
  const auto r = run("events " + scene_file().string() + " --light lamp --kinds EV --no-split --json");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["counts"]["EV"], 64);
  for (const auto& e : j["events"]) {
    ASSERT_EQ(e["intervals"].size(), 1u);
    EXPECT_EQ(e["intervals"][0][0], 0);
    EXPECT_EQ(e["intervals"][0][1], 1);
  }
}

TEST(EventsCli, PolygonLightAndVtp) {
  const auto vtp = scratch() / "surfaces.vtp";
  std::filesystem::remove(vtp);
  const auto r = run("events " + scene_file().string() + " --light '0.5,0.5,6;1.5,0.5,6;1.5,1.5,6' --json --vtp " +
                     vtp.string());
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["light"]["appended"], true);
  EXPECT_GT(j["counts"]["EV"].get<int>(), 0);
  EXPECT_TRUE(j["counts"]["EEE"].is_number_integer());
  EXPECT_TRUE(std::filesystem::exists(vtp));
  EXPECT_GT(std::filesystem::file_size(vtp), 100u);
}

// A scene with EEE events: three pairwise skew bars (thin triangles) crossing a common family of lines, and a
// fourth that blocks part of it. Checks the JSON shape of EEE events and --kinds.
std::filesystem::path skew_bars_file() {
  const auto path = scratch() / "skew_bars.obj";
  std::ofstream f(path);
  // Bar k: triangle with long edge from a_k to b_k and a third vertex off to the side.
  f << "o bars\n"
    << "v -4 0 0\nv 4 0 0\nv 0 -1 -3\n"   // E1 along x at z = 0
    << "v 0 -4 4\nv 0 4 4\nv -3 0 5\n"    // E2 along y at z = 4
    << "v -4 -4 8\nv 4 4 8\nv 3 -3 11\n"  // E3 diagonal at z = 8
    << "f 1 2 3\nf 4 5 6\nf 7 8 9\n";
  return path;
}

TEST(EventsCli, EeeEventsJsonShape) {
  const auto r = run("events " + skew_bars_file().string() + " --json");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["counts"]["EEE"].is_number_integer());
  EXPECT_GT(j["counts"]["EEE"].get<int>(), 0);
  int eee = 0;
  for (const auto& e : j["events"]) {
    if (e["kind"] != "EEE") continue;
    ++eee;
    ASSERT_EQ(e["edges"].size(), 3u);
    for (const auto& edge : e["edges"]) {
      ASSERT_EQ(edge.size(), 2u);
      EXPECT_LT(edge[0].get<int>(), edge[1].get<int>());
    }
    ASSERT_GE(e["intervals"].size(), 1u);
    ASSERT_EQ(e["intervals_approx"].size(), e["intervals"].size());
    ASSERT_EQ(e["ends"].size(), e["intervals"].size());
    ASSERT_EQ(e["segment_ends"].size(), e["intervals"].size());
    for (std::size_t i = 0; i < e["intervals"].size(); ++i) {
      for (int k = 0; k < 2; ++k) {
        const auto& t = e["intervals"][i][k];
        EXPECT_TRUE(t.is_number() || t.is_string());
        EXPECT_TRUE(e["ends"][i][k].contains("cause"));
        ASSERT_TRUE(e["ends"][i][k].contains("key"));
        const auto& key = e["ends"][i][k]["key"];
        // An EEE end meets the family's edges: its key lists edges (and no vertex beyond the one it passes).
        EXPECT_GE(key["edges"].size(), 2u) << key.dump();
        EXPECT_LE(key["vertices"].size(), 1u) << key.dump();
        ASSERT_TRUE(e["ends"][i][k]["line"].contains("through"));
        EXPECT_EQ(e["ends"][i][k]["line"]["through"].size(), 2u);
        EXPECT_EQ(e["ends"][i][k]["line"]["on_generators"].size(), 3u);
      }
      EXPECT_LT(e["intervals_approx"][i][0].get<double>(), e["intervals_approx"][i][1].get<double>());
    }
  }
  EXPECT_EQ(eee, j["counts"]["EEE"].get<int>());
  EXPECT_EQ(j["kinds"], nlohmann::json({"EV", "EEE"}));

  const auto ev_only = nlohmann::json::parse(run("events " + skew_bars_file().string() + " --kinds EV --json").out);
  EXPECT_TRUE(ev_only["counts"]["EEE"].is_null());
  EXPECT_EQ(ev_only["counts"]["EV"], j["counts"]["EV"]);
  for (const auto& e : ev_only["events"]) EXPECT_EQ(e["kind"], "EV");
  const auto eee_only = nlohmann::json::parse(run("events " + skew_bars_file().string() + " --kinds EEE --json").out);
  EXPECT_TRUE(eee_only["counts"]["EV"].is_null());
  EXPECT_EQ(eee_only["counts"]["EEE"], j["counts"]["EEE"]);

  const auto text = run("events " + skew_bars_file().string());
  ASSERT_EQ(text.status, 0);
  EXPECT_NE(text.out.find("EEE events: "), std::string::npos);
}

TEST(EventsCli, BadInputIsAOneLineErrorAndNonZeroExit) {
  EXPECT_EQ(run("events " + scene_file().string() + " --kinds EV,XYZ").status, 1);
  EXPECT_EQ(run("events " + scene_file().string() + " --kinds ,").status, 1);
  EXPECT_EQ(run("events " + scene_file().string() + " --light nosuchobject").status, 1);
  EXPECT_EQ(run("events " + scene_file().string() + " --light '1,2;3,4,5;6,7,8'").status, 1);
  EXPECT_EQ(run("events " + scene_file().string() + " --light '0,0,0;1,1,1;2,2,2'").status, 1);  // zero area
  EXPECT_EQ(run("events /nonexistent/scene.obj").status, 1);
  EXPECT_NE(run("events " + scene_file().string() + " --vtp /nonexistent/dir/out.vtp").status, 0);
}

}  // namespace
