// `exactvis validate --bsp` run as a user would (issue #12): the JSON shape of the issue on the tunnels map
// written by the test with planted visdata errors (found exactly: a hidden pair marked visible, a visible
// pair marked invisible), --pairs sampling the invisible pairs first, --obj, and bad maps and options
// (one-line errors, exit 1, no output left behind).
#include "bsp_test_writer.hpp"
#include "io_test_util.hpp"
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace fs = std::filesystem;

namespace {

// Planted: (0, 3) hidden but marked visible; (1, 3) visible but marked invisible; the rest exact.
bool planted(int a, int b) {
  if (a == 0 && b == 3) return true;
  if (a == 1 && b == 3) return false;
  return bsptest::TunnelsMap::exact(a, b);
}

}  // namespace

TEST(ValidateBspCli, JsonShapeAndPlantedVisdataErrors) {
  iotest::TempDir dir;
  const std::string map = iotest::write_file(dir.file("tunnels.bsp"), bsptest::tunnels_map(planted).bsp.bytes());
  const auto r = cli_test::run_exactvis(dir.path, "validate --bsp " + map + " --clusters 0,1,2,3,4 --json -q -o " +
                                                      dir.file("r.json") + " --obj " + dir.file("solid.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j, nlohmann::json::parse(iotest::read_file(dir.file("r.json"))));
  EXPECT_EQ(j["map"], map);
  EXPECT_EQ(j["clusters"], 5);
  EXPECT_EQ(j["occluders"], "leaves");
  ASSERT_EQ(j["pairs"].size(), 20u);
  for (const auto& p : j["pairs"]) {
    const int a = p["from"], b = p["to"];
    EXPECT_EQ(p["visdata"], planted(a, b)) << a << " " << b;
    EXPECT_EQ(p["exact"], bsptest::TunnelsMap::exact(a, b)) << a << " " << b;
    EXPECT_EQ(p["witness"].is_null(), !bsptest::TunnelsMap::exact(a, b));
    if (!p["witness"].is_null()) EXPECT_EQ(p["witness"].size(), 2u);
  }
  EXPECT_EQ(j["totals"], nlohmann::json::parse(R"({"pairs": 20, "false_invisible": 1, "false_visible": 1})"));
  EXPECT_NE(iotest::read_file(dir.file("solid.obj")).find("g leaf_2"), std::string::npos);

  // Human summary names the two errors.
  const auto h = cli_test::run_exactvis(dir.path, "validate --bsp " + map + " --clusters 0,1,3 -q");
  ASSERT_EQ(h.status, 0) << h.err;
  EXPECT_NE(h.out.find("cluster 0 -> 3: false visible"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("cluster 1 -> 3: false invisible"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("false invisible 1, false visible 1"), std::string::npos) << h.out;
}

TEST(ValidateBspCli, PairsSampleTheInvisibleFirst) {
  iotest::TempDir dir;
  const std::string map = iotest::write_file(dir.file("tunnels.bsp"), bsptest::tunnels_map(planted).bsp.bytes());
  // 6 pairs marked invisible: (0,4) (4,0) (1,4) (4,1) (3,0) (1,3); 7 pairs asked: all 6 first, then one more.
  const auto r = cli_test::run_exactvis(dir.path, "validate --bsp " + map + " --pairs 7 --seed 3 --json -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["pairs"].size(), 7u);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(j["pairs"][i]["visdata"], false) << i;
  EXPECT_EQ(j["pairs"][6]["visdata"], true);
  EXPECT_EQ(j["totals"]["false_invisible"], 1);
}

TEST(ValidateBspCli, BadMapsAndOptions) {
  iotest::TempDir dir;
  const std::string good = iotest::write_file(dir.file("good.bsp"), bsptest::tunnels_map().bsp.bytes());
  std::string truncated = bsptest::tunnels_map().bsp.bytes();
  truncated.resize(100);
  iotest::write_file(dir.file("short.bsp"), truncated);
  bsptest::Bsp wrong = bsptest::tunnels_map().bsp;
  wrong.magic = "XBSP";
  iotest::write_file(dir.file("magic.bsp"), wrong.bytes());
  struct Case {
    std::string args, expected;
  };
  const std::vector<Case> cases = {
      {"--bsp " + dir.file("short.bsp"), dir.file("short.bsp") + ": "},
      {"--bsp " + dir.file("magic.bsp"), dir.file("magic.bsp") + ": "},
      {"--bsp " + dir.file("missing.bsp"), dir.file("missing.bsp") + ": "},
      {"--bsp " + good + " --clusters 0,9", "--clusters: '9' is not a cluster of the map (0 .. 4)"},
      {"--bsp " + good + " --clusters 0", "--clusters: give at least two different clusters"},
      {"--bsp " + good + " --pairs 3 --clusters 0,1", "--pairs: give either --pairs or --clusters"},
      {"--bsp " + good + " --occluders walls", "--occluders: 'walls' is not leaves or brushes"},
      {"--pairs 3", "--pairs, --clusters, --occluders and --obj need --bsp MAP"},
  };
  for (const auto& c : cases) {
    const auto r = cli_test::run_exactvis(dir.path, "validate " + c.args + " -q -o " + dir.file("out.json"));
    EXPECT_EQ(r.status, 1) << c.args;
    EXPECT_NE(r.err.find("exactvis validate: error: " + c.expected), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("out.json"))) << c.args;
  }
}

TEST(ValidateBspCli, BrushesJsonOnADetailDoorway) {
  // The doorway map with its lintel made solid and a detail brush (solid bit only, as in real maps) filling
  // the doorway: with brushes only rooms B front and back see each other; the visdata marks every pair but
  // (0, 3), (3, 0), (1, 0) visible: 7 false visible, no false invisible. Leaves see through the doorway.
  bsptest::Bsp b = bsptest::doorway_map().bsp;
  b.shaders.push_back({"textures/base/lintel", 0, 1});
  b.brushes[2].shader = static_cast<int>(b.shaders.size()) - 1;
  const int detail = bsptest::add_world_box_brush(b, {120, 48, 0}, {136, 80, 96}, 2);
  iotest::TempDir dir;
  const std::string map = iotest::write_file(dir.file("detail.bsp"), b.bytes());
  const auto r = cli_test::run_exactvis(dir.path, "validate --bsp " + map + " --clusters 0,1,2,3 --occluders brushes --json -q --obj " +
                                                      dir.file("brushes.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["occluders"], "brushes");
  ASSERT_EQ(j["pairs"].size(), 12u);
  for (const auto& p : j["pairs"]) {
    const int from = p["from"], to = p["to"];
    EXPECT_EQ(p["exact"], (from == 1 && to == 3) || (from == 3 && to == 1)) << from << " " << to;
    EXPECT_EQ(p["witness"].is_null(), !p["exact"].get<bool>());
  }
  EXPECT_EQ(j["totals"], nlohmann::json::parse(R"({"pairs": 12, "false_invisible": 0, "false_visible": 7})"));
  const std::string obj = iotest::read_file(dir.file("brushes.obj"));
  EXPECT_NE(obj.find("g brush_" + std::to_string(detail)), std::string::npos);
  EXPECT_EQ(obj.find("g leaf_"), std::string::npos);
  EXPECT_NE(obj.find("g brush_2\n"), std::string::npos);                          // the lintel, now solid
  EXPECT_EQ(obj.find("g brush_" + std::to_string(detail + 1)), std::string::npos);  // model 1's door
  const auto leaves = cli_test::run_exactvis(dir.path, "validate --bsp " + map + " --clusters 0,1 --json -q");
  ASSERT_EQ(leaves.status, 0) << leaves.err;
  EXPECT_EQ(nlohmann::json::parse(leaves.out)["pairs"][0]["exact"], true);
}
