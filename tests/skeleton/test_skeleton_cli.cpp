// `exactvis skeleton`: the JSON shape of issue 14, the text summary, --pair, -o, --vtp, and one-line errors
// with a non-zero exit on bad input. Needs the `exactvis` binary.
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

using cli_test::TempDir;

// Three triangles in general position, one object each.
const char* kScene =
    "o A\nv 0 0 0\nv 4 0 1\nv 1 3 0\nf 1 2 3\n"
    "o B\nv 1 1 5\nv 5 2 6\nv 2 5 4\nf 4 5 6\n"
    "o C\nv 6 -1 2\nv 7 3 3\nv 5 1 -2\nf 7 8 9\n";

std::string write_scene(const TempDir& d, const std::string& text = kScene) {
  const auto p = d.path / "scene.obj";
  std::ofstream(p) << text;
  return p.string();
}

TEST(SkeletonCli, JsonShape) {
  TempDir d;
  const auto r = cli_test::run_exactvis(d.path, "skeleton " + write_scene(d) + " --json -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* k : {"VV", "VEE", "EEEE", "FVE", "FEE"}) ASSERT_TRUE(j["counts"]["nodes"].contains(k)) << k;
  ASSERT_TRUE(j["counts"]["arcs"].contains("EV"));
  ASSERT_TRUE(j["counts"]["arcs"].contains("EEE"));
  const auto& nodes = j["nodes"];
  const auto& arcs = j["arcs"];
  ASSERT_GT(nodes.size(), 0u);
  ASSERT_GT(arcs.size(), 0u);
  std::size_t valid = 0;
  for (const auto& [k, c] : j["counts"]["nodes"].items()) valid += c.get<std::size_t>();
  EXPECT_EQ(valid, nodes.size());  // valid by kind + degenerate = all listed nodes
  std::size_t ev = 0, eee = 0;
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    const auto& a = arcs[i];
    (a["kind"] == "EV" ? ev : eee) += 1;
    if (a["kind"] == "EV") {
      EXPECT_TRUE(a["vertex"].is_number_integer());
      EXPECT_EQ(a["edge"].size(), 2u);
    } else {
      EXPECT_EQ(a["edges"].size(), 3u);
    }
    EXPECT_EQ(a["t"].size(), 2u);
    ASSERT_EQ(a["nodes"].size(), 2u);
    ASSERT_EQ(a["ends"].size(), 2u);
    for (const auto& n : a["nodes"]) {
      ASSERT_LT(n.get<std::size_t>(), nodes.size());
      const auto& list = nodes[n.get<std::size_t>()]["arcs"];
      EXPECT_NE(std::find(list.begin(), list.end(), i), list.end());
    }
  }
  EXPECT_EQ(j["counts"]["arcs"]["EV"], ev);
  EXPECT_EQ(j["counts"]["arcs"]["EEE"], eee);
  for (const auto& n : nodes) {
    for (const char* k : {"kind", "vertices", "edges", "line", "ends", "arcs"}) ASSERT_TRUE(n.contains(k)) << k;
    EXPECT_EQ(n["line"]["through"].size(), 2u);
    ASSERT_EQ(n["ends"].size(), 2u);
    for (const auto& e : n["ends"])
      if (!e.is_null()) {
        EXPECT_TRUE(e["triangle"].is_number_integer());
        EXPECT_TRUE(e["object"] == "A" || e["object"] == "B" || e["object"] == "C");
      }
  }
}

TEST(SkeletonCli, TextPairOutputFileAndVtp) {
  TempDir d;
  const std::string scene = write_scene(d);
  const auto text = cli_test::run_exactvis(d.path, "skeleton " + scene + " -q");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("nodes: "), std::string::npos);
  EXPECT_NE(text.out.find("arcs: "), std::string::npos);
  EXPECT_NE(text.out.find("time: "), std::string::npos);
  // --pair: exactly the nodes and arcs whose ends are on A and B (plus those arcs' end nodes).
  const auto out = (d.path / "pair.json").string(), vtp = (d.path / "pair.vtp").string();
  const auto r = cli_test::run_exactvis(d.path, "skeleton " + scene + " --pair A,B --json -q -o " + out + " --vtp " + vtp);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_TRUE(fs::exists(vtp));
  const auto j = nlohmann::json::parse(cli_test::slurp(out));
  const std::set<std::string> ab{"A", "B"};
  auto on_ab = [&](const nlohmann::json& ends) {
    std::set<std::string> o;
    for (const auto& e : ends) o.insert(e.is_null() ? "" : e["object"].get<std::string>());
    return o == ab;
  };
  for (const auto& a : j["arcs"]) EXPECT_TRUE(on_ab(a["ends"]));
  std::set<std::size_t> arc_nodes;
  for (const auto& a : j["arcs"])
    for (const auto& n : a["nodes"]) arc_nodes.insert(n.get<std::size_t>());
  for (std::size_t i = 0; i < j["nodes"].size(); ++i)
    EXPECT_TRUE(on_ab(j["nodes"][i]["ends"]) || arc_nodes.count(i)) << i;
}

TEST(SkeletonCli, BadInput) {
  TempDir d;
  const std::string scene = write_scene(d);
  const auto missing = cli_test::run_exactvis(d.path, "skeleton " + (d.path / "nope.obj").string());
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.err.find("nope.obj"), std::string::npos) << missing.err;
  const auto pair = cli_test::run_exactvis(d.path, "skeleton " + scene + " --pair A,Z");
  EXPECT_NE(pair.status, 0);
  EXPECT_NE(pair.err.find("--pair"), std::string::npos) << pair.err;
  const auto one = cli_test::run_exactvis(d.path, "skeleton " + scene + " --pair A");
  EXPECT_NE(one.status, 0);
  EXPECT_NE(one.err.find("--pair"), std::string::npos) << one.err;
  const auto out = cli_test::run_exactvis(d.path, "skeleton " + scene + " -o " + (d.path / "no_dir" / "x.json").string());
  EXPECT_NE(out.status, 0);
  EXPECT_FALSE(fs::exists(d.path / "no_dir" / "x.json"));
  EXPECT_EQ(std::count(out.err.begin(), out.err.end(), '\n'), 1) << out.err;
}

}  // namespace
