// The `exactvis events` subcommand end to end: JSON shape, light selection, .vtp output, bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

struct Run {
  int status;
  std::string out;
};

Run run(const std::string& args) {
  const std::string cmd = std::string(EXACTVIS_BINARY) + " " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  Run r{-1, ""};
  if (!p) return r;
  std::array<char, 4096> buf;
  while (std::size_t n = fread(buf.data(), 1, buf.size(), p)) r.out.append(buf.data(), n);
  r.status = WEXITSTATUS(pclose(p));
  return r;
}

std::filesystem::path scene_file() {
  const auto dir = std::filesystem::temp_directory_path() / "exactvis_test_events";
  std::filesystem::create_directories(dir);
  const auto path = dir / "cube_floor_lamp.obj";
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
  ASSERT_EQ(j["events"].size(), 64u);
  for (const auto& e : j["events"]) {
    EXPECT_EQ(e["kind"], "EV");
    EXPECT_LT(e["edge"][0].get<int>(), e["edge"][1].get<int>());
    ASSERT_EQ(e["intervals"].size(), 1u);
    EXPECT_EQ(e["intervals"][0][0], 0);
    EXPECT_EQ(e["intervals"][0][1], 1);
    EXPECT_EQ(e["ends"][0][0]["cause"], "edge_endpoint");
  }
}

TEST(EventsCli, PolygonLightAndVtp) {
  const auto vtp = std::filesystem::temp_directory_path() / "exactvis_test_events" / "surfaces.vtp";
  std::filesystem::remove(vtp);
  const auto r = run("events " + scene_file().string() + " --light '0.5,0.5,6;1.5,0.5,6;1.5,1.5,6' --json --vtp " +
                     vtp.string());
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["light"]["appended"], true);
  EXPECT_GT(j["counts"]["EV"].get<int>(), 0);
  EXPECT_TRUE(j["counts"]["EEE"].is_null());  // not computed: reported as such, not as 0
  EXPECT_TRUE(std::filesystem::exists(vtp));
  EXPECT_GT(std::filesystem::file_size(vtp), 100u);
}

TEST(EventsCli, BadInputIsAOneLineErrorAndNonZeroExit) {
  EXPECT_EQ(run("events " + scene_file().string() + " --light nosuchobject").status, 1);
  EXPECT_EQ(run("events " + scene_file().string() + " --light '1,2;3,4,5;6,7,8'").status, 1);
  EXPECT_EQ(run("events " + scene_file().string() + " --light '0,0,0;1,1,1;2,2,2'").status, 1);  // zero area
  EXPECT_EQ(run("events /nonexistent/scene.obj").status, 1);
  EXPECT_NE(run("events " + scene_file().string() + " --vtp /nonexistent/dir/out.vtp").status, 0);
}

}  // namespace
