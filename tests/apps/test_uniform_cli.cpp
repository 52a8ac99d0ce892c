// One command line (issue 17): every subcommand listed by `exactvis --help` takes --json and -q, prints JSON
// that parses with the same indentation (2 spaces), and long results are summarised in text (a bounded
// number of lines, "N more, use --json") rather than printed a line per item.
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using cli_test::CliRun;

class UniformCli : public cli_test::CliTest {
 protected:
  UniformCli() : CliTest("uniform-cli") {}
  static std::string scene(const std::string& name) { return std::string(EXACTVIS_SOURCE_DIR) + "/scenes/" + name; }
};

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST_F(UniformCli, EverySubcommandPrintsJsonWithTwoSpaceIndentation) {
  const std::string lamp = scene("lamp_room.obj"), cells = scene("lamp_cells.json"), plan = scene("plan2d.json");
  // pvs-merge reads a shard written first; validate reads the merged document.
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"info", "info " + lamp},
      {"generate", "generate room -n 40 -s 2 -o " + path("g.obj")},
      {"export", "export " + lamp + " -o " + path("e.vtp")},
      {"visible", "visible " + lamp + " --cell 0.25,0.25,1,1.25,1.25,1.5"},
      {"events", "events " + lamp + " --light lamp"},
      {"exterior", "exterior " + lamp},
      {"pvs", "pvs " + lamp + " --cells " + cells},
      {"pvs-merge", "pvs-merge " + path("pvs.json") + " -o " + path("merged.json")},
      {"validate", "validate " + lamp + " --cells " + cells + " --pvs " + path("merged.json")},
      {"skeleton", "skeleton " + lamp + " --pair floor,ceiling"},
      {"shadows", "shadows " + lamp + " --light lamp"},
      {"lightcheck", "lightcheck " + lamp + " --light lamp --points " + scene("lamp_points.txt")},
      {"complex2d", "complex2d " + plan},
      {"visibility2d", "visibility2d " + plan + " --from 5,2"},
      {"aspect2d", "aspect2d " + plan},
      {"aspect", "aspect " + scene("cube.obj") + " --orthographic"},
  };
  ASSERT_EQ(run("pvs " + lamp + " --cells " + cells + " --shard 0/1 -q -o " + path("pvs.json")).status, 0);
  std::set<std::string> tried;
  for (const auto& [name, args] : runs) {
    tried.insert(name);
    const CliRun r = run(args + " --json -q");
    ASSERT_EQ(r.status, 0) << args << ": " << r.err;
    nlohmann::ordered_json j;  // keeps the printed key order, so dump(2) reproduces the 2-space form
    ASSERT_NO_THROW(j = nlohmann::ordered_json::parse(r.out)) << args << ": " << r.out.substr(0, 200);
    ASSERT_TRUE(j.is_object()) << args;
    EXPECT_EQ(r.out, j.dump(2) + "\n") << args << ": not the 2-space form";
  }
  // Every subcommand of --help was tried.
  const CliRun help = run("--help");
  std::istringstream in(help.out.substr(help.out.find("Subcommands:")));
  std::set<std::string> listed;
  const std::regex row("^  ([a-z0-9-]+) .*");
  for (std::string l; std::getline(in, l);) {
    std::smatch m;
    if (std::regex_match(l, m, row)) listed.insert(m[1]);
  }
  EXPECT_FALSE(listed.empty());
  EXPECT_EQ(listed, tried);
}

TEST_F(UniformCli, LongResultsAreSummarised) {
  ASSERT_EQ(run("generate room -n 40 -s 2 -o " + path("room.obj")).status, 0);
  const CliRun e = run("events " + path("room.obj") + " --kinds EV -q");
  ASSERT_EQ(e.status, 0) << e.err;
  const CliRun ej = run("events " + path("room.obj") + " --kinds EV --json -q");
  const auto n = nlohmann::json::parse(ej.out)["counts"]["EV"].get<int>();
  ASSERT_GT(n, 100);  // many events, yet a short text
  EXPECT_LE(lines(e.out), 20) << e.out;
  EXPECT_NE(e.out.find(std::to_string(n - 10) + " more, use --json"), std::string::npos) << e.out;

  ASSERT_EQ(run("generate town -n 200 -s 5 -o " + path("town.obj")).status, 0);
  const CliRun v = run("visible " + path("town.obj") + " --cell 1,1,1,2,2,2 --triangles all -q");
  ASSERT_EQ(v.status, 0) << v.err;
  EXPECT_LE(lines(v.out), 16) << v.out;
  EXPECT_NE(v.out.find("190 more, use --json"), std::string::npos) << v.out;
  EXPECT_TRUE(std::regex_search(v.out, std::regex("\n[0-9]+ of 200 triangles visible\n$"))) << v.out;
}

}  // namespace
