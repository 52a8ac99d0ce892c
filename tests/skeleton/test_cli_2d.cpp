// The complex2d / visibility2d / aspect2d subcommands: documented JSON shape, and one-line errors with a
// non-zero exit on bad input. Needs the `exactvis` binary (built with the tests by `ninja`).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

struct CliRun {
  int status;
  std::string out, err;
};

CliRun run(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string out = (dir / "exactvis_plane2d_cli.out").string(), err = (dir / "exactvis_plane2d_cli.err").string();
  const int raw = std::system((std::string(EXACTVIS_BINARY) + " " + args + " >" + out + " 2>" + err).c_str());
  auto slurp = [](const std::string& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  return {WEXITSTATUS(raw), slurp(out), slurp(err)};
}

std::string write(const std::string& name, const std::string& text) {
  const auto path = (std::filesystem::temp_directory_path() / ("exactvis_plane2d_" + name)).string();
  std::ofstream(path) << text;
  return path;
}

const char* kTwoSquares = R"({"polygons": [[[0,0],[1,0],[1,1],[0,1]], [[3,0.5],[4,0.5],[4,2],[3,2]]]})";

}  // namespace

TEST(Cli2D, Complex2dJsonHasTheDocumentedShape) {
  ASSERT_TRUE(std::filesystem::exists(EXACTVIS_BINARY)) << "build the exactvis target first";
  const CliRun r = run("complex2d " + write("two.json", kTwoSquares) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(j.begin().key(), "counts");
  EXPECT_EQ(j["counts"]["bitangents"], 4);
  EXPECT_EQ(j["counts"]["edges"], 8);
  EXPECT_EQ(j["counts"]["faces"], 4);
  ASSERT_EQ(j["bitangents"].size(), 4u);
  for (const auto& b : j["bitangents"]) {
    EXPECT_EQ(b["objects"].size(), 2u);
    EXPECT_TRUE(b["kind"] == "LL" || b["kind"] == "LR" || b["kind"] == "RL" || b["kind"] == "RR");
    EXPECT_EQ(b["a"].size(), 2u);
    EXPECT_EQ(b["b"].size(), 2u);
  }
}

TEST(Cli2D, Visibility2dAndAspect2d) {
  ASSERT_TRUE(std::filesystem::exists(EXACTVIS_BINARY));
  const std::string scene = write("two2.json", kTwoSquares);
  const CliRun v = run("visibility2d " + scene + " --from 2,0.25");
  ASSERT_EQ(v.status, 0) << v.err;
  const auto j = nlohmann::json::parse(v.out);
  EXPECT_GE(j["polygon"].size(), 6u);
  const CliRun a = run("aspect2d " + scene + " --json");
  ASSERT_EQ(a.status, 0) << a.err;
  const auto k = nlohmann::json::parse(a.out);
  EXPECT_GE(k["regions"].size(), 2u);
  EXPECT_EQ(k["counts"]["regions"], k["regions"].size());
  const CliRun s = run("visibility2d " + scene + " --from-segment -1,0.5,-1,1.5 --to-segment 6,3,6,5");
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_TRUE(nlohmann::json::parse(s.out)["visible"].get<bool>());
  // blocked: every line from S to T' crosses one of the squares
  const CliRun b = run("visibility2d " + scene + " --from-segment -1,0.5,-1,1.5 --to-segment 6,0,6,2");
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_FALSE(nlohmann::json::parse(b.out)["visible"].get<bool>());
}

TEST(Cli2D, Visibility2dMethodsGiveTheSameJson) {
  ASSERT_TRUE(std::filesystem::exists(EXACTVIS_BINARY));
  // a non-convex object with a hole, a triangle, and viewpoints on lines through several vertices
  const std::string scene = write("m.json", R"({"polygons": [[[[0,0],[6,0],[6,6],[0,6]], [[2,2],[2,4],[4,4],[4,2]]],
      [[8,0],[12,0],[12,4],[10,2],[8,4]], [[1,8],[3,8],[2,10]]]})");
  for (const char* from : {"2.5,3.5", "7,2", "10,3", "2,7", "13,5", "-1,-1", "3,3", "6,8"}) {
    const CliRun a = run("visibility2d " + scene + " --from " + from);
    const CliRun b = run("visibility2d " + scene + " --from " + from + " --method sweep");
    ASSERT_EQ(a.status, 0) << from << ": " << a.err;
    ASSERT_EQ(b.status, 0) << from << ": " << b.err;
    EXPECT_EQ(a.out, b.out) << from;
    EXPECT_GE(nlohmann::json::parse(a.out)["polygon"].size(), 4u) << from;
  }
  for (const char* seg : {"--from-segment 7,1,7,3 --to-segment 13,1,13,3", "--from-segment 2.5,2.5,2.5,3 --to-segment 3.5,3.5,3,3.5",
                          "--from-segment -1,1,-1,5 --to-segment 13,5,14,6"}) {
    const CliRun a = run("visibility2d " + scene + " " + seg);
    const CliRun b = run("visibility2d " + scene + " " + seg + " --method sweep");
    ASSERT_EQ(a.status, 0) << seg << ": " << a.err;
    EXPECT_EQ(nlohmann::json::parse(a.out)["visible"], nlohmann::json::parse(b.out)["visible"]) << seg;
  }
}

TEST(Cli2D, BadInputGivesOneLineErrorAndNonZeroExit) {
  ASSERT_TRUE(std::filesystem::exists(EXACTVIS_BINARY));
  const std::vector<std::string> bad = {
      "complex2d " + write("overlap.json", R"({"polygons": [[[0,0],[2,0],[2,2],[0,2]], [[1,1],[3,1],[3,3],[1,3]]]})"),
      "complex2d " + write("dup.json", R"({"polygons": [[[0,0],[1,0],[1,0],[0,1]]]})"),
      "complex2d " + write("notjson.json", "{polygons"),
      "complex2d " + write("shape.json", R"({"polygons": [[[0,0],[1]]]})"),
      "complex2d /nonexistent/scene.json",
      "visibility2d " + write("v.json", kTwoSquares) + " --from 0.5,0.5",
      "visibility2d " + write("v2.json", kTwoSquares) + " --from 1,0.5",
      "visibility2d " + write("v3.json", kTwoSquares) + " --from x",
      "visibility2d " + write("v4.json", kTwoSquares) + " --from 2,0.25 --method fast",
      "visibility2d " + write("v5.json", kTwoSquares) + " --from 0.5,0.5 --method sweep",
      "aspect2d " + write("a.json", kTwoSquares) + " --margin -1",
      "complex2d " + write("s.json", kTwoSquares) + " --slice z=1",
  };
  for (const auto& args : bad) {
    const CliRun r = run(args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}
