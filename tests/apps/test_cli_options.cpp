// Shared options of the subcommands, run as a user would (the hardening items of the house issue): exact
// --cell text (subnormals, num/den), thread counts, empty --triangles, seeds beyond 64 bits. Each bad value
// gives one line on stderr naming the option, a non-zero exit and no output file.
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using cli_test::CliRun;

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

class CliOptions : public cli_test::CliTest {
 protected:
  CliOptions() : CliTest("cli-options") {}
  void SetUp() override {
    // A target triangle (id 0) at x = 10 and a wall (id 1, 2) at x = 5 covering y in [-10, 0] only.
    write("scene.obj",
          "v 10 -1 -1\nv 10 1 -1\nv 10 0 1\n"
          "v 5 -10 -10\nv 5 0 -10\nv 5 0 10\nv 5 -10 10\n"
          "f 1 2 3\nf 4 5 6 7\n");
  }
};

TEST_F(CliOptions, CellIsExact) {
  // A subnormal coordinate is a number.
  CliRun r = run("visible " + path("scene.obj") + " --cell 0,1e-320,-1,1,1,1 --triangles 0 --json -q");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["source"]["cell"][1].get<double>(), std::strtod("1e-320", nullptr));
  EXPECT_TRUE(j["results"][0]["visible"].get<bool>());
  // num/den is read exactly, as --source-polygon reads it, and written back exactly.
  r = run("visible " + path("scene.obj") + " --cell 0,1/3,-1,1,2/3,1 --triangles 0 --json -q");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["source"]["cell"][1], "1/3");
  EXPECT_EQ(j["source"]["cell"][4], "2/3");
  EXPECT_TRUE(j["results"][0]["visible"].get<bool>());
  r = run("visible " + path("scene.obj") + " --cell 0,1/0,-1,1,2/3,1 --triangles 0");
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--cell"), std::string::npos) << r.err;
}

TEST_F(CliOptions, ThreadCounts) {
  // 0 means all cores (the default); 1 .. 1024 that many; anything else is refused.
  for (const std::string ok : {"0", "1", "3"}) {
    const CliRun r = run("visible " + path("scene.obj") + " --cell 0,-1,-1,1,1,1 --json -q --threads " + ok);
    ASSERT_EQ(r.status, 0) << ok << ": " << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["stats"]["queries"], 3);
  }
  for (const std::string bad : {"-3", "100000", "1025"}) {
    const CliRun r = run("visible " + path("scene.obj") + " --cell 0,-1,-1,1,1,1 -o " + path("out.json") +
                         " --threads " + bad);
    EXPECT_NE(r.status, 0) << bad;
    EXPECT_EQ(r.out, "") << bad;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--threads: " + bad + " is not a thread count"), std::string::npos) << bad << ": " << r.err;
    EXPECT_FALSE(fs::exists(path("out.json"))) << bad;
  }
}

TEST_F(CliOptions, EmptyTriangleListIsAnError) {
  for (const std::string bad : {"\"\"", "\" \""}) {
    const CliRun r = run("visible " + path("scene.obj") + " --cell 0,-1,-1,1,1,1 -o " + path("out.json") +
                         " --triangles " + bad);
    EXPECT_NE(r.status, 0) << bad;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--triangles: no triangle ids given"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("out.json")));
  }
}

TEST_F(CliOptions, SeedsBeyond64BitsAreErrors) {
  const CliRun big = run("generate random -n 10 -s 18446744073709551616 -o " + path("g.obj"));
  EXPECT_NE(big.status, 0);
  EXPECT_EQ(lines(big.err), 1) << big.err;
  EXPECT_NE(big.err.find("--seed: '18446744073709551616' is out of range"), std::string::npos) << big.err;
  EXPECT_FALSE(fs::exists(path("g.obj")));
  const CliRun max = run("generate random -n 10 -s 18446744073709551615 -o " + path("g.obj"));
  EXPECT_EQ(max.status, 0) << max.err;
  EXPECT_TRUE(fs::exists(path("g.obj")));
  const CliRun vis = run("visible " + path("scene.obj") + " --cell 0,-1,-1,1,1,1 --seed 99999999999999999999999");
  EXPECT_NE(vis.status, 0);
  EXPECT_EQ(lines(vis.err), 1) << vis.err;
  EXPECT_NE(vis.err.find("--seed"), std::string::npos) << vis.err;
}

}  // namespace
