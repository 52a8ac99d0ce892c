// The complex2d / visibility2d / aspect2d subcommands: documented JSON shape, and one-line errors with a
// non-zero exit on bad input. Needs the `exactvis` binary (built with the tests by `ninja`).
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

using cli_test::CliRun;

// Scene files written by write() and the commands' captured output, in one directory of this test process
// (ctest -j runs each test in its own process at the same time), removed when the process ends.
const cli_test::TempDir& scratch() {
  static const cli_test::TempDir dir("plane2d-cli");
  return dir;
}

CliRun run(const std::string& args) { return cli_test::run_exactvis(scratch().path, args); }

std::string write(const std::string& name, const std::string& text) { return scratch().write(name, text); }

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

namespace {

// A run in its own temporary directory (files the command writes land there; nothing else does).
struct CliDir : cli_test::TempDir {
  CliDir() : TempDir("cli2d") {}
  // `command` goes through /bin/sh with stdout and stderr captured (outside the directory's listing).
  CliRun sh(const std::string& command) const { return cli_test::run_shell(path, command); }
  CliRun run(const std::string& args) const { return cli_test::run_exactvis(path, args); }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

// Coordinates whose squares or cubes overflow doubles: aspect2d crashed (SIGSEGV) while complex2d and
// visibility2d answered; margins that overflow the frame crashed with SIGFPE. Now: exact answers, or one
// line naming the problem (docs/theory.md section 7, "Coordinate range").
TEST(Cli2D, HugeCoordinatesAndMargins) {
  ASSERT_TRUE(std::filesystem::exists(EXACTVIS_BINARY));
  const CliDir d;
  for (const char* big : {"1e308", "1e155", "1e103"}) {
    const std::string scene = d.write(std::string("big") + big + ".json",
                                      std::string(R"({"polygons": [[[0,0],[)") + big + R"(,0],[0,1]]]})");
    const CliRun a = d.run("aspect2d " + scene + " --json --svg " + d.file("a.svg"));
    ASSERT_EQ(a.status, 0) << big << ": " << a.err;
    const auto j = nlohmann::json::parse(a.out);
    EXPECT_GE(j["regions"].size(), 2u) << big;
    const CliRun c = d.run("complex2d " + scene + " --json");
    ASSERT_EQ(c.status, 0) << big << ": " << c.err;
    const CliRun v = d.run("visibility2d " + scene + " --from -1,-1");
    ASSERT_EQ(v.status, 0) << big << ": " << v.err;
    // the picture is scaled to finite SVG numbers
    std::ifstream svg(d.file("a.svg"));
    const std::string pic((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
    EXPECT_EQ(pic.find("inf"), std::string::npos) << big;
    EXPECT_EQ(pic.find("nan"), std::string::npos) << big;
  }
  const std::string tri = d.write("tri.json", R"({"polygons": [[[0,0],[1,0],[0,1]]]})");
  EXPECT_EQ(d.run("aspect2d " + tri + " --margin 1e308").status, 0);
  for (const std::string args : {"aspect2d " + tri + " --margin inf", "aspect2d " + tri + " --margin nan",
                                 "visibility2d " + tri + " --from 0.1,0.1 --margin inf",
                                 "aspect2d " + d.file("big1e308.json") + " --margin 1",
                                 "visibility2d " + d.file("big1e308.json") + " --from -1,-1 --margin 1"}) {
    const CliRun r = d.run(args);
    EXPECT_EQ(r.status, 1) << args;
    EXPECT_EQ(lines(r.err), 1) << args << ": " << r.err;
  }
  EXPECT_NE(d.run("aspect2d " + d.file("big1e308.json") + " --margin 1").err.find("largest double"), std::string::npos);
  // Segment queries near the double range: both methods answer (the complex method's frame shrinks to
  // margin 0 when margin 0.5 does not fit; any frame containing S and T gives the same answer).
  const std::string b17 = d.write("b17.json", R"({"polygons": [[[0,0],[1.7e308,0],[0,1]]]})");
  for (const char* seg : {"--from-segment -1,-1,-1,-2 --to-segment -3,-1,-3,-2",
                          "--from-segment -1,0.5,-1,0.7 --to-segment 1e300,2,1e300,3"}) {
    const CliRun a = d.run("visibility2d " + b17 + " " + seg), b = d.run("visibility2d " + b17 + " " + seg + " --method sweep");
    ASSERT_EQ(a.status, 0) << seg << ": " << a.err;
    ASSERT_EQ(b.status, 0) << seg << ": " << b.err;
    EXPECT_EQ(nlohmann::json::parse(a.out)["visible"], nlohmann::json::parse(b.out)["visible"]) << seg;
  }
  // The frame widens for far viewpoints (it stopped after 64 doublings: "outside the frame").
  for (const char* from : {"1e300,3", "-1.7e308,0.5"}) {
    const CliRun r = d.run("visibility2d " + tri + " --from " + from);
    ASSERT_EQ(r.status, 0) << from << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const double x = j["from"][0].get<double>();
    EXPECT_LT(j["frame"][0][0].get<double>(), x) << from;
    EXPECT_GT(j["frame"][1][0].get<double>(), x) << from;
  }
}

// 2D scene files: trailing data after the JSON value is refused (it was ignored), a directory is named.
TEST(Cli2D, SceneFileErrorsNameTheProblem) {
  ASSERT_TRUE(std::filesystem::exists(EXACTVIS_BINARY));
  const CliDir d;
  const std::string good = R"({"polygons": [[[0,0],[1,0],[0,1]]]})";
  EXPECT_EQ(d.run("complex2d " + d.write("ws.json", good + "\n \n")).status, 0);
  const std::string trail = d.write("trail.json", good + " xyz");
  const std::string second = d.write("second.json", good + good);
  std::filesystem::create_directory(d.file("dir.json"));
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"complex2d " + trail, "not valid JSON"},          {"aspect2d " + second, "not valid JSON"},
      {"complex2d " + d.file("dir.json"), "is a directory"}, {"visibility2d " + d.file("dir.json") + " --from 0,0", "is a directory"},
      {"complex2d " + d.file("dir.json") + " --slice z=0", "is a directory"}};
  for (const auto& [args, why] : bad) {
    const CliRun r = d.run(args);
    EXPECT_EQ(r.status, 1) << args;
    EXPECT_EQ(lines(r.err), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << args << ": " << r.err;
  }
}

// An output that cannot be written fails the command with one line (no VTK log), and no output of the run
// is left: an unwritable --vtp is found before the work, a write that fails midway (file size limit) removes
// everything the run wrote.
TEST(Cli2D, OutputFailuresLeaveNoFiles) {
  ASSERT_TRUE(std::filesystem::exists(EXACTVIS_BINARY));
  const CliDir d;
  const std::string scene = d.write("two.json", kTwoSquares);
  d.write("plain", "x");
  const auto before = d.entries();
  for (const char* cmd : {"complex2d", "aspect2d"}) {
    for (const std::string vtp : {d.file("missing/out.vtp"), d.file("plain/out.vtp"), d.file("out.svg")}) {
      const std::string args = std::string(cmd) + " " + scene + " --svg " + d.file("out.svg") + " --vtp " + vtp;
      const CliRun r = d.run(args);
      EXPECT_EQ(r.status, 1) << args;
      EXPECT_EQ(lines(r.err), 1) << args << ": " << r.err;
      EXPECT_EQ(d.entries(), before) << args;
    }
    // A file size limit makes the writes fail part-way (SIGXFSZ ignored, so write() reports EFBIG).
    for (const std::string outs : {" --vtp " + d.file("out.vtp"), " --svg " + d.file("out.svg") + " --vtp " + d.file("out.vtp")}) {
      const std::string command = "trap '' XFSZ; ulimit -f 1; " + std::string(EXACTVIS_BINARY) + " " + cmd + " " + scene + outs;
      const CliRun r = d.sh(command);
      EXPECT_EQ(r.status, 1) << command;
      EXPECT_EQ(lines(r.err), 1) << command << ": " << r.err;
      EXPECT_EQ(r.err.find("vtk"), std::string::npos) << r.err;
      EXPECT_EQ(r.err.find("ERROR"), std::string::npos) << r.err;
      EXPECT_EQ(d.entries(), before) << command;
    }
  }
}

// aspect2d's progress bars go to a terminal only (and not with -q); large scenes get a cost warning first.
TEST(Cli2D, Aspect2dProgressAndCostWarning) {
  ASSERT_TRUE(std::filesystem::exists(EXACTVIS_BINARY));
  const CliDir d;
  // A square with 204 vertices (flat ones along its sides): large by count, cheap to compute.
  std::string ring;
  for (int side = 0; side < 4; ++side)
    for (int i = 0; i < 51; ++i) {
      const int x = side == 0 ? i : side == 1 ? 51 : side == 2 ? 51 - i : 0;
      const int y = side == 0 ? 0 : side == 1 ? i : side == 2 ? 51 : 51 - i;
      ring += (ring.empty() ? "" : ",") + std::string("[") + std::to_string(x) + "," + std::to_string(y) + "]";
    }
  const std::string large = d.write("large.json", R"({"polygons": [[)" + ring + "]]}");
  const std::string small = d.write("small.json", kTwoSquares);
  CliRun r = d.run("aspect2d " + small);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");  // not a terminal: no bars
  r = d.run("aspect2d " + large);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("aspect2d: warning: 204 vertices", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("O(n^4)"), std::string::npos) << r.err;
  r = d.run("aspect2d " + large + " -q");
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "");
  // On a terminal (script(1) gives the command one): the bars of the three stages.
  if (!std::filesystem::exists("/usr/bin/script")) GTEST_SKIP() << "script(1) not installed";
  r = d.sh("/usr/bin/script -qec '" + std::string(EXACTVIS_BINARY) + " aspect2d " + small + "' /dev/null");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* stage : {"aspect2d: event segments [", "aspect2d: arrangement [", "aspect2d: faces ["})
    EXPECT_NE(r.out.find(stage), std::string::npos) << stage << ": " << r.out;
  EXPECT_NE(r.out.find("100%"), std::string::npos) << r.out;
  r = d.sh("/usr/bin/script -qec '" + std::string(EXACTVIS_BINARY) + " aspect2d -q " + small + "' /dev/null");
  EXPECT_EQ(r.out.find("aspect2d: faces"), std::string::npos) << r.out;
}

namespace {
std::string slurp_file(const std::string& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
// The texts of the picture's <text> elements, in order.
std::vector<std::string> svg_texts(const std::string& svg) {
  std::vector<std::string> out;
  for (std::size_t i = svg.find("<text"); i != std::string::npos; i = svg.find("<text", i + 1)) {
    const std::size_t a = svg.find('>', i) + 1, b = svg.find("</text>", a);
    out.push_back(svg.substr(a, b - a));
  }
  return out;
}
}  // namespace

// The 2D pictures explain themselves: a legend naming each colour and line style drawn, region ids for
// aspect2d (one per region of the JSON, at a point inside it), and axes with world-unit ticks.
TEST(Cli2D, PicturesHaveLegendsRegionIdsAndAxes) {
  ASSERT_TRUE(std::filesystem::exists(EXACTVIS_BINARY));
  const CliDir d;
  const std::string scene =
      d.write("two.json", R"({"polygons": [[[0,0],[2,0],[2,1],[0,1]], [[4,3],[6,3],[5,5]]]})");
  const CliRun a = d.run("aspect2d " + scene + " --json --svg " + d.file("a.svg"));
  ASSERT_EQ(a.status, 0) << a.err;
  const auto j = nlohmann::json::parse(a.out);
  const std::vector<std::string> at = svg_texts(slurp_file(d.file("a.svg")));
  for (std::size_t r = 0; r < j["regions"].size(); ++r)
    EXPECT_EQ(std::count(at.begin(), at.end(), std::to_string(r)) >= 1, true) << "region id " << r;
  EXPECT_NE(std::find(at.begin(), at.end(), "visual event boundary between regions"), at.end());
  EXPECT_NE(std::find(at.begin(), at.end(), "obstacle"), at.end());
  // Axis ticks: a 1-2-5 step of the box; the x ticks of this scene (x in [0, 6]) include 0, 2 and 4 or 1..5.
  EXPECT_NE(std::find(at.begin(), at.end(), "4"), at.end());

  ASSERT_EQ(d.run("complex2d " + scene + " --svg " + d.file("c.svg")).status, 0);
  const std::vector<std::string> ct = svg_texts(slurp_file(d.file("c.svg")));
  for (const char* label : {"obstacle", "outer bitangent (free segment)", "separating bitangent (free segment)",
                            "maximal free extension (outer)", "maximal free extension (separating)"})
    EXPECT_NE(std::find(ct.begin(), ct.end(), label), ct.end()) << label;

  ASSERT_EQ(d.run("visibility2d " + scene + " --from 3,0.5 --svg " + d.file("v.svg")).status, 0);
  const std::vector<std::string> vt = svg_texts(slurp_file(d.file("v.svg")));
  for (const char* label : {"visibility polygon", "obstacle", "viewpoint"})
    EXPECT_NE(std::find(vt.begin(), vt.end(), label), vt.end()) << label;
}
