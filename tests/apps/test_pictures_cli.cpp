// `--png` of visible, pvs, events and export, run as a user would: each picture is a PNG of the requested
// size (header parsed by hand, pixels read by VTK) showing the result's colours exactly where the JSON of
// the same run says they must be (visible green, hidden red, EV surfaces orange); bad paths and sizes are
// one-line errors with no file left.
#include "png_test_util.hpp"
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <set>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using cli_test::CliRun;
using nlohmann::json;

// The colours of io/result_pictures.cpp, as documented in docs/cli.md "Pictures".
const std::array<int, 3> kGreen{80, 175, 90}, kRed{205, 85, 75}, kOrange{240, 150, 30}, kBlue{30, 90, 210};

class PicturesCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    unsetenv("DISPLAY");  // every picture starts its own Xvfb
    dir_ = fs::temp_directory_path() / ("exactvis_pictures_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    ASSERT_EQ(cli_test::run_exactvis(dir_, "generate town -n 200 -s 5 -o " + path("town.obj")).status, 0);
    ASSERT_EQ(cli_test::run_exactvis(dir_, "generate room -n 40 -s 2 -o " + path("room.obj")).status, 0);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static std::string path(const std::string& name) { return (dir_ / name).string(); }
  static CliRun run(const std::string& args) { return cli_test::run_exactvis(dir_, args); }
  static fs::path dir_;
};
fs::path PicturesCli::dir_;

std::string ids(const std::vector<std::int64_t>& v) {
  std::string s;
  for (auto i : v) s += (s.empty() ? "" : ",") + std::to_string(i);
  return s;
}

TEST_F(PicturesCli, PvsAndVisiblePicturesColourWhatTheJsonSays) {
  const CliRun p = run("pvs " + path("town.obj") + " --grid 2,1,1 --json -q --png " + path("pvs.png") +
                       " --png-cell 1 --png-size 400x300");
  ASSERT_EQ(p.status, 0) << p.err;
  const json doc = json::parse(p.out);
  const json& cell = doc["cells"][1];
  const auto img = png_test::read_png(path("pvs.png"));
  ASSERT_TRUE(img.valid);
  EXPECT_EQ(img.width, 400);
  EXPECT_EQ(img.height, 300);
  std::set<std::int64_t> visible(cell["visible"].begin(), cell["visible"].end());
  std::vector<std::int64_t> seen, hidden;
  for (std::int64_t id = 0; id < doc["triangles"].get<std::int64_t>(); ++id) (visible.count(id) ? seen : hidden).push_back(id);
  ASSERT_FALSE(hidden.empty());  // the scene and cell are chosen so that cell 1 hides something
  EXPECT_GT(png_test::pixels_like(img, kGreen), 200);
  EXPECT_GT(png_test::pixels_like(img, kRed), 0);
  EXPECT_GT(png_test::pixels_like(img, kBlue, 0.9), 20);  // the cell's wire box

  // visible from the same cell, asked about the hidden triangles only: red and grey, no green.
  std::string box;
  for (const auto& v : cell["box"]) box += (box.empty() ? "" : ",") + v.dump();
  const CliRun h = run("visible " + path("town.obj") + " --cell " + box + " -q --triangles " + ids(hidden) +
                       " --png " + path("hidden.png") + " --png-size 320x240 --witnesses");
  ASSERT_EQ(h.status, 0) << h.err;
  const auto himg = png_test::read_png(path("hidden.png"));
  ASSERT_TRUE(himg.valid);
  EXPECT_EQ(himg.width, 320);
  EXPECT_EQ(himg.height, 240);
  EXPECT_GT(png_test::pixels_like(himg, kRed), 0);
  EXPECT_EQ(png_test::pixels_like(himg, kGreen), 0);
  // ... and about the visible ones only: green, no red.
  const CliRun s = run("visible " + path("town.obj") + " --cell " + box + " -q --triangles " + ids(seen) + " --png " +
                       path("seen.png") + " --png-size 320x240");
  ASSERT_EQ(s.status, 0) << s.err;
  const auto simg = png_test::read_png(path("seen.png"));
  ASSERT_TRUE(simg.valid);
  EXPECT_GT(png_test::pixels_like(simg, kGreen), 200);
  EXPECT_EQ(png_test::pixels_like(simg, kRed), 0);
}

TEST_F(PicturesCli, EventsPictureShowsTheSurfaces) {
  const CliRun e = run("events " + path("room.obj") + " --kinds EV -q --png " + path("ev.png") + " --png-size 320x240");
  ASSERT_EQ(e.status, 0) << e.err;
  const auto img = png_test::read_png(path("ev.png"));
  ASSERT_TRUE(img.valid);
  EXPECT_EQ(img.width, 320);
  EXPECT_EQ(img.height, 240);
  // The surfaces are drawn under a translucent grey scene: orange mixed with grey still leans orange.
  std::int64_t orange = 0;
  for (const auto& [c, n] : img.colours)
    if (c[0] > c[2] + 40 && c[1] > c[2] + 10) orange += n;
  EXPECT_GT(orange, 50);
  // No events computed (EEE only; the box room has none): nothing orange.
  const CliRun none = run("events " + path("room.obj") + " --kinds EEE -q --png " + path("none.png") +
                          " --png-size 320x240");
  ASSERT_EQ(none.status, 0) << none.err;
  const auto nimg = png_test::read_png(path("none.png"));
  ASSERT_TRUE(nimg.valid);
  std::int64_t orange_none = 0;
  for (const auto& [c, n] : nimg.colours)
    if (c[0] > c[2] + 40 && c[1] > c[2] + 10) orange_none += n;
  EXPECT_EQ(orange_none, 0);
}

TEST_F(PicturesCli, ExportPictureHasTheSceneOnABackground) {
  const CliRun x = run("export " + path("town.obj") + " --png " + path("x.png") + " --png-size 200x160 -q");
  ASSERT_EQ(x.status, 0) << x.err;
  EXPECT_EQ(x.err, "");
  const auto img = png_test::read_png(path("x.png"));
  ASSERT_TRUE(img.valid);
  EXPECT_EQ(img.width, 200);
  EXPECT_EQ(img.height, 160);
  const std::int64_t white = img.colours.count({255, 255, 255}) ? img.colours.at({255, 255, 255}) : 0;
  EXPECT_GT(white, 0);
  EXPECT_LT(white, 200 * 160 * 9 / 10);  // the scene covers a good part of the picture
  EXPECT_GT(img.colours.size(), 10u);
}

TEST_F(PicturesCli, BadPathsAndSizesAreOneLineErrorsWithoutFiles) {
  const std::string town = path("town.obj");
  const std::string missing = path("no/such/dir/p.png");
  for (const std::string& args :
       {"visible " + town + " --cell 1,1,1,2,2,2 --png " + missing, "pvs " + town + " --grid 1,1,1 --png " + missing,
        "events " + path("room.obj") + " --kinds EV --png " + missing, "export " + town + " --png " + missing,
        "visible " + town + " --cell 1,1,1,2,2,2 --png " + path("a.png") + " --png-size 10x10",
        "export " + town + " --png " + path("a.png") + " --png-size 640",
        "pvs " + town + " --grid 2,1,1 --png " + path("a.png") + " --png-cell 2",
        "pvs " + town + " --grid 2,1,1 --shard 0/2 --png " + path("a.png") + " --png-cell 1"}) {
    const CliRun r = run(args + " -q");
    EXPECT_EQ(r.status, 1) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("exactvis ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(missing));
    EXPECT_FALSE(fs::exists(path("a.png"))) << args;
  }
}

}  // namespace
