// `exactvis shadows` and `exactvis lightcheck` from outside: the JSON shape of issue #15, the mesh files, the
// textbook classification of given points, and one-line errors without partial output.
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;

fs::path test_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("exactvis_shadows_cli_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

const char* kTextbook =
    "o floor\nv -4 -4 0\nv 12 -4 0\nv 12 12 0\nv -4 12 0\nf 1 2 3\nf 1 3 4\n"
    "o blocker\nv 3 3 2\nv 5 3 2\nv 5 5 2\nv 3 5 2\nf 5 6 7\nf 5 7 8\n"
    "o lamp\nv 3 3 4\nv 5 3 4\nv 5 5 4\nv 3 5 4\nf 9 10 11\nf 9 11 12\n";

TEST(ShadowsCli, JsonHasTheShapeOfTheIssue) {
  const fs::path d = test_dir("json");
  write(d / "s.obj", kTextbook);
  const auto r = cli_test::run_exactvis(d, "shadows " + (d / "s.obj").string() + " --light lamp --receivers 0,1 --json -o " +
                                               (d / "m.vtp").string() + " --ply " + (d / "m.ply").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["receivers"].size(), 2u);
  double umbra = 0, penumbra = 0, lit = 0;
  for (const auto& rec : j["receivers"]) {
    EXPECT_TRUE(rec["triangle"] == 0 || rec["triangle"] == 1);
    for (const auto& c : rec["curves"]) {
      EXPECT_TRUE(c["kind"] == "EV" || c["kind"] == "EEE");
      EXPECT_TRUE(c["order"] == 0 || c["order"] == 1 || c["order"] == 2);
      EXPECT_TRUE(c["generators"].is_object());
      ASSERT_EQ(c["ends"].size(), 2u);
      EXPECT_EQ(c["ends"][0].size(), 3u);
    }
    for (const auto& f : rec["faces"]) {
      const std::string cls = f["class"];
      ASSERT_TRUE(f["area"].is_number());
      ASSERT_EQ(f["sample"].size(), 3u);
      ASSERT_TRUE(f["light_fraction"].is_number());
      ASSERT_TRUE(f["irradiance"].is_number());
      (cls == "umbra" ? umbra : cls == "penumbra" ? penumbra : lit) += f["area"].get<double>();
      if (cls == "umbra") EXPECT_EQ(f["light_fraction"].get<double>(), 0.0);
      if (cls == "lit") EXPECT_EQ(f["light_fraction"].get<double>(), 1.0);
    }
  }
  EXPECT_NEAR(umbra, 4, 1e-12);
  EXPECT_NEAR(penumbra, 32, 1e-12);
  EXPECT_NEAR(lit, 220, 1e-12);
  EXPECT_TRUE(j["counts"].is_object());
  EXPECT_TRUE(j["stats"].is_object());
  EXPECT_GT(fs::file_size(d / "m.vtp"), 100u);
  std::ifstream ply(d / "m.ply");
  std::string first;
  std::getline(ply, first);
  EXPECT_EQ(first, "ply");
}

TEST(ShadowsCli, LightcheckClassifiesPointsWithWitnessOrProof) {
  const fs::path d = test_dir("lightcheck");
  write(d / "s.obj", kTextbook);
  write(d / "p.txt", "# x y z\n4 4 0\n9/2 7/4 0\n10 10 0\n");
  const auto r = cli_test::run_exactvis(d, "lightcheck " + (d / "s.obj").string() + " --light lamp --points " +
                                               (d / "p.txt").string() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["points"].size(), 3u);
  EXPECT_EQ(j["points"][0]["status"], "umbra");
  EXPECT_EQ(j["points"][0]["proof"]["backprojection"], "empty");
  EXPECT_EQ(j["points"][1]["status"], "partly_lit");
  // 1 - hx * hy: hx = |[1.5, 5.5] ∩ [3, 5]| / 2 = 1, hy = |[4.25, 8.25] ∩ [3, 5]| / 2 = 3/8.
  EXPECT_EQ(j["points"][1]["light_fraction_exact"], 0.625);
  EXPECT_TRUE(j["points"][1].contains("witness"));
  EXPECT_EQ(j["points"][2]["status"], "fully_lit");
  EXPECT_EQ(j["points"][2]["light_fraction"], 1.0);
}

TEST(ShadowsCli, BadInputGivesOneLineErrorsAndNoOutputFiles) {
  const fs::path d = test_dir("bad");
  write(d / "s.obj", kTextbook);
  write(d / "bad.txt", "1 2 3\n1 2\n");
  const std::string scene = (d / "s.obj").string(), vtp = (d / "out.vtp").string();
  struct Case {
    std::string args, needle;
  };
  const std::vector<Case> cases{
      {"shadows " + (d / "missing.obj").string() + " --light lamp -o " + vtp, "missing.obj"},
      {"shadows " + scene + " --light nosuch -o " + vtp, "--light 'nosuch'"},
      {"shadows " + scene + " --light lamp --receivers 0,99 -o " + vtp, "--receivers"},
      {"shadows " + scene + " --light lamp --receivers 4 -o " + vtp, "part of the light"},
      {"shadows " + scene + " --light lamp --receivers x -o " + vtp, "--receivers"},
      {"lightcheck " + scene + " --light lamp --points " + (d / "bad.txt").string(), "bad.txt:2"},
      {"lightcheck " + scene + " --light lamp --points " + (d / "none.txt").string(), "none.txt"},
  };
  for (const auto& c : cases) {
    const auto r = cli_test::run_exactvis(d, c.args);
    EXPECT_NE(r.status, 0) << c.args;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(vtp)) << c.args;
  }
}

}  // namespace

namespace {

TEST(ShadowsCli, PngIsRenderedHeadless) {
  const fs::path d = test_dir("png");
  write(d / "s.obj", kTextbook);
  // No DISPLAY: the renderer starts (and stops) its own Xvfb.
  unsetenv("DISPLAY");
  const auto r = cli_test::run_exactvis(d, "shadows " + (d / "s.obj").string() + " --light lamp -q --png " +
                                               (d / "s.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(d / "s.png", std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  EXPECT_EQ(std::string(sig + 1, 3), "PNG");
  EXPECT_GT(fs::file_size(d / "s.png"), 1000u);
}

}  // namespace
