// `exactvis pvs` and `exactvis pvs-merge` run as users run them: the JSON shape of issue #11, every cell
// equal to `exactvis visible --cell ... --triangles all`, witnesses parsed back from JSON and re-checked by
// the independent oracle, the JSON-lines form (--no-witnesses, --resume after an interruption), shards
// merged == the unsharded file, --vtp, and one-line errors for bad cells files and options.
#include "oracles/json_rational.hpp"
#include "oracles/visibility_oracle.hpp"
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using cli_test::CliRun;
using cli_test::slurp;

using oracle::json_point;
using oracle::json_rational;

// The triangles of an OBJ written by `exactvis generate` (triangles only, "v" and "f" lines), in id order.
std::vector<oracle::Triangle> read_obj(const std::string& path) {
  std::ifstream in(path);
  std::vector<oracle::QVec> v;
  std::vector<oracle::Triangle> t;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      double x, y, z;
      s >> x >> y >> z;
      v.push_back(oracle::qvec(x, y, z));
    } else if (tag == "f") {
      std::vector<int> idx;
      std::string w;
      while (s >> w) idx.push_back(std::stoi(w.substr(0, w.find('/'))) - 1);
      for (std::size_t k = 1; k + 1 < idx.size(); ++k) t.push_back({v[idx[0]], v[idx[k]], v[idx[k + 1]]});
    }
  }
  return t;
}

std::string cell_text(const json& box) {
  std::string s;
  for (std::size_t k = 0; k < 6; ++k) s += (k ? "," : "") + (box[k].is_string() ? box[k].get<std::string>() : box[k].dump());
  return s;
}

class PvsCli : public cli_test::CliTest {
 protected:
  PvsCli() : CliTest("pvs-cli") {}
  void SetUp() override { ASSERT_EQ(run("generate town -n 120 -s 3 -o " + path("town.obj")).status, 0); }
};

TEST_F(PvsCli, JsonShapeEqualsVisibleAndWitnessesCheckByOracle) {
  const CliRun r = run("pvs " + path("town.obj") + " --grid 2,2,1 --box 0,0,0.5,20,12,3 --json -o " + path("pvs.json") + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const json doc = json::parse(slurp(path("pvs.json")));
  ASSERT_TRUE(doc.contains("scene"));
  EXPECT_EQ(doc["triangles"], 120);
  ASSERT_TRUE(doc["cells"].is_array());
  ASSERT_EQ(doc["cells"].size(), 4u);
  ASSERT_TRUE(doc["stats"].is_object());
  const auto os = read_obj(path("town.obj"));
  ASSERT_EQ(os.size(), 120u);
  std::int64_t total_visible = 0, hidden_somewhere = 0;
  for (const auto& cell : doc["cells"]) {
    for (const char* key : {"box", "visible", "objects", "witnesses", "stats"}) ASSERT_TRUE(cell.contains(key)) << key;
    ASSERT_EQ(cell["box"].size(), 6u);
    const CliRun v = run("visible " + path("town.obj") + " --cell " + cell_text(cell["box"]) + " --json -q");
    ASSERT_EQ(v.status, 0) << v.err;
    std::vector<std::int64_t> expected;
    const json answer = json::parse(v.out);
    for (const auto& e : answer["results"])
      if (e["visible"].get<bool>()) expected.push_back(e["triangle"]);
    EXPECT_EQ(cell["visible"].get<std::vector<std::int64_t>>(), expected) << cell["box"].dump();
    EXPECT_EQ(cell["witnesses"].size(), cell["visible"].size());
    total_visible += static_cast<std::int64_t>(expected.size());
    hidden_somewhere += 120 - static_cast<std::int64_t>(expected.size());
    oracle::Source src;
    src.is_box = true;
    src.lo = {json_rational(cell["box"][0]), json_rational(cell["box"][1]), json_rational(cell["box"][2])};
    src.hi = {json_rational(cell["box"][3]), json_rational(cell["box"][4]), json_rational(cell["box"][5])};
    for (const auto& [id, w] : cell["witnesses"].items()) {
      std::string why;
      EXPECT_TRUE(oracle::witness_is_valid(os, std::stoul(id), src, json_point(w[0]), json_point(w[1]), &why)) << id << ": " << why;
    }
    EXPECT_FALSE(cell["objects"].empty());
  }
  EXPECT_EQ(doc["stats"]["visible"], total_visible);
  EXPECT_GT(hidden_somewhere, 0);
  // --json alone prints the same document.
  const CliRun s = run("pvs " + path("town.obj") + " --grid 2,2,1 --box 0,0,0.5,20,12,3 --json -q");
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_EQ(s.out, slurp(path("pvs.json")));
}

TEST_F(PvsCli, CoherenceKeepsTheVisibleSetsAndItsWitnessesCheckByOracle) {
  // --coherence: each cell tries the previous neighbouring cell's witnesses first. Same visible sets as
  // without; every witness (many now come from the cell before) re-checked by the oracle against its cell.
  const std::string base = "pvs " + path("town.obj") + " --grid 3,2,1 --box 0,0,0.5,20,12,3 --json -o ";
  ASSERT_EQ(run(base + path("plain.json") + " -q").status, 0);
  const CliRun c = run(base + path("coh.json") + " --coherence");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.err.find("accepted through the previous cell's witnesses"), std::string::npos) << c.err;
  const json plain = json::parse(slurp(path("plain.json"))), coh = json::parse(slurp(path("coh.json")));
  ASSERT_EQ(coh["cells"].size(), 6u);
  const auto os = read_obj(path("town.obj"));
  for (std::size_t k = 0; k < 6; ++k) {
    const json& cell = coh["cells"][k];
    EXPECT_EQ(cell["visible"], plain["cells"][k]["visible"]) << "cell " << k;
    oracle::Source src;
    src.is_box = true;
    src.lo = {json_rational(cell["box"][0]), json_rational(cell["box"][1]), json_rational(cell["box"][2])};
    src.hi = {json_rational(cell["box"][3]), json_rational(cell["box"][4]), json_rational(cell["box"][5])};
    EXPECT_EQ(cell["witnesses"].size(), cell["visible"].size());
    for (const auto& [id, w] : cell["witnesses"].items()) {
      std::string why;
      EXPECT_TRUE(oracle::witness_is_valid(os, std::stoul(id), src, json_point(w[0]), json_point(w[1]), &why))
          << "cell " << k << " triangle " << id << ": " << why;
    }
  }
  const CliRun bad = run("pvs " + path("town.obj") + " --grid 2,1,1 --coherence --method sampled -q");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("--coherence"), std::string::npos) << bad.err;
}

TEST_F(PvsCli, CellsFileJsonLinesAndResume) {
  std::ofstream(path("cells.json")) << R"({"cells": [[1,1,1,2,2,2], ["1/3",5,0.5,"7/3",6,"3/2"], [10,3,0,12,5,4]]})";
  const std::string base = "pvs " + path("town.obj") + " --cells " + path("cells.json") + " -q ";
  ASSERT_EQ(run(base + "--json -o " + path("doc.json")).status, 0);
  const CliRun full = run(base + "-o " + path("full.jsonl") + " --no-witnesses");
  ASSERT_EQ(full.status, 0) << full.err;
  const std::string text = slurp(path("full.jsonl"));
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 4u);
  const json header = json::parse(lines[0]);
  EXPECT_EQ(header["cell_count"], 3);
  EXPECT_EQ(header["witnesses"], false);
  const json doc = json::parse(slurp(path("doc.json")));
  for (int c = 0; c < 3; ++c) {
    const json cell = json::parse(lines[c + 1]);
    EXPECT_EQ(cell["cell"], c);
    EXPECT_FALSE(cell.contains("witnesses"));
    EXPECT_EQ(cell["visible"], doc["cells"][c]["visible"]);
    EXPECT_EQ(cell["box"], doc["cells"][c]["box"]);
  }
  EXPECT_EQ(json::parse(lines[2])["box"][0], "1/3");

  // An interrupted run: the header, one finished cell and half a line. --resume completes it.
  std::ofstream(path("part.jsonl")) << lines[0] << "\n" << lines[1] << "\n" << lines[2].substr(0, lines[2].size() / 2);
  const CliRun resumed = run(base + "-o " + path("part.jsonl") + " --no-witnesses --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_EQ(slurp(path("part.jsonl")), text);
  // Resuming a finished file changes nothing; resuming with other settings is refused.
  ASSERT_EQ(run(base + "-o " + path("part.jsonl") + " --no-witnesses --resume").status, 0);
  EXPECT_EQ(slurp(path("part.jsonl")), text);
  const CliRun other = run(base + "-o " + path("part.jsonl") + " --resume");
  EXPECT_EQ(other.status, 1);
  EXPECT_NE(other.err.find("different run"), std::string::npos) << other.err;
  EXPECT_EQ(slurp(path("part.jsonl")), text);
  // JSON lines on stdout.
  const CliRun out = run(base + "--jsonl --no-witnesses");
  ASSERT_EQ(out.status, 0);
  EXPECT_EQ(out.out, text);
}

TEST_F(PvsCli, ShardsMergedEqualTheUnshardedRun) {
  const std::string base = "pvs " + path("town.obj") + " --grid 3,2,1 -q ";
  ASSERT_EQ(run(base + "--json -o " + path("all.json")).status, 0);
  ASSERT_EQ(run(base + "--shard 0/3 -o " + path("s0.json")).status, 0);
  ASSERT_EQ(run(base + "--shard 1/3 -o " + path("s1.jsonl")).status, 0);
  ASSERT_EQ(run(base + "--shard 2/3 --json -o " + path("s2.json")).status, 0);
  const json s0 = json::parse(slurp(path("s0.json")));
  ASSERT_EQ(s0["cells"].size(), 2u);
  EXPECT_EQ(s0["cells"][1]["cell"], 3);
  EXPECT_EQ(s0["shard"]["count"], 3);
  const CliRun m = run("pvs-merge " + path("s2.json") + " " + path("s0.json") + " " + path("s1.jsonl") + " -o " + path("merged.json"));
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_EQ(slurp(path("merged.json")), slurp(path("all.json")));
  // A missing shard is an error, and no output is written.
  const CliRun missing = run("pvs-merge " + path("s0.json") + " " + path("s1.jsonl") + " -o " + path("none.json"));
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("missing"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(path("none.json")));
}

TEST_F(PvsCli, VtpPerCell) {
  const CliRun r = run("pvs " + path("town.obj") + " --grid 2,1,1 --vtp " + path("vtp") + " --json -o " + path("p.json") + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const json doc = json::parse(slurp(path("p.json")));
  for (int c = 0; c < 2; ++c) {
    const std::string vtp = path("vtp/cell_" + std::to_string(c) + ".vtp");
    ASSERT_TRUE(fs::exists(vtp)) << vtp;
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(vtp.c_str());
    reader->Update();
    vtkPolyData* poly = reader->GetOutput();
    vtkDataArray* vis = poly->GetCellData()->GetArray("visible");
    vtkDataArray* kind = poly->GetCellData()->GetArray("kind");
    ASSERT_NE(vis, nullptr);
    ASSERT_NE(kind, nullptr);
    std::int64_t visible_triangles = 0, triangles = 0;
    for (vtkIdType i = 0; i < poly->GetNumberOfCells(); ++i) {
      if (kind->GetTuple1(i) != 0) continue;
      ++triangles;
      visible_triangles += vis->GetTuple1(i) == 1 ? 1 : 0;
    }
    EXPECT_EQ(triangles, 120);
    EXPECT_EQ(visible_triangles, static_cast<std::int64_t>(doc["cells"][c]["visible"].size()));
  }
}

TEST_F(PvsCli, BadCellsFilesAndOptionsGiveOneLineErrors) {
  const std::vector<std::pair<std::string, std::string>> files = {
      {"empty", ""},
      {"notjson", "{cells"},
      {"shape", R"({"cells": [[0,0,0,1,1]]})"},
      {"nocells", R"([[0,0,0,1,1,1]])"},
      {"none", R"({"cells": []})"},
      {"inverted", R"({"cells": [[0,0,0,1,1,1],[2,0,0,1,1,1]]})"},
      {"nan", R"({"cells": [[0,0,NaN,1,1,1]]})"},
      {"nanstring", R"({"cells": [[0,0,"nan",1,1,1]]})"},
      {"word", R"({"cells": [[0,0,"zero",1,1,1]]})"},
  };
  for (const auto& [name, text] : files) {
    const std::string cells = path(name + ".json");
    std::ofstream(cells) << text;
    const CliRun r = run("pvs " + path("town.obj") + " --cells " + cells + " --json -o " + path("out.json") + " -q");
    EXPECT_EQ(r.status, 1) << name;
    EXPECT_EQ(r.err.rfind("exactvis pvs: error: " + cells + ": ", 0), 0u) << name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << name << ": " << r.err;
    EXPECT_FALSE(fs::exists(path("out.json"))) << name;
  }
  const std::string scene = path("town.obj");
  const std::vector<std::pair<std::string, std::string>> options = {
      {"--grid 0,1,1", "--grid"},
      {"--grid 2,2", "--grid"},
      {"--grid a,1,1", "--grid"},
      {"--grid 1,1,1 --box 0,0,0,1,1", "--box"},
      {"--grid 1,1,1 --box 0,0,0,1,-1,1", "--box"},
      {"--cells x.json --box 0,0,0,1,1,1", "--box"},
      {"--grid 1,1,1 --cells x.json", "--grid"},
      {"", "--grid"},
      {"--grid 1,1,1 --method fast", "--method"},
      {"--grid 1,1,1 --shard 3/3", "--shard"},
      {"--grid 1,1,1 --shard 1", "--shard"},
      {"--grid 1,1,1 --resume -o " + path("r.json"), "--resume"},
      {"--grid 1,1,1 --threads -2", "--threads"},
  };
  for (const auto& [args, what] : options) {
    const CliRun r = run("pvs " + scene + " " + args + " -q");
    EXPECT_EQ(r.status, 1) << args;
    EXPECT_NE(r.err.find(what), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

TEST_F(PvsCli, ResumeAfterAKillEqualsAnUninterruptedRun) {
  const std::string base = "pvs " + path("town.obj") + " --grid 6,1,1 --threads 1 --rays 0 -q -o ";
  ASSERT_EQ(run(base + path("whole.jsonl")).status, 0);
  const std::string whole = slurp(path("whole.jsonl"));
  // Start the same run, SIGKILL it once it has written a cell, then resume.
  const std::string log = path("killed.log");
  const std::string cmd = std::string(EXACTVIS_BINARY) + " " + base + path("killed.jsonl") + " >" + log + " 2>&1 & echo $! >" +
                          path("pid");
  ASSERT_EQ(std::system(("sh -c '" + cmd + "'").c_str()), 0);
  std::string pid;
  for (int i = 0; i < 500 && pid.empty(); ++i) {
    pid = slurp(path("pid"));
    if (pid.empty()) ::usleep(10000);
  }
  ASSERT_FALSE(pid.empty());
  bool killed = false;
  for (int i = 0; i < 3000; ++i) {
    const std::string part = slurp(path("killed.jsonl"));
    if (std::count(part.begin(), part.end(), '\n') >= 2) {
      killed = std::system(("kill -9 " + pid + " 2>/dev/null").c_str()) == 0;
      break;
    }
    ::usleep(5000);
  }
  ::usleep(100000);
  const std::string partial = slurp(path("killed.jsonl"));
  if (killed) {
    EXPECT_LT(partial.size(), whole.size()) << "the kill came after the run had finished";
  }
  const CliRun resumed = run(base + path("killed.jsonl") + " --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_EQ(slurp(path("killed.jsonl")), whole);
}

#ifdef EXACTVIS_MPIEXEC
TEST_F(PvsCli, MpiRunEqualsTheSerialRun) {
  const std::string args = "pvs " + path("town.obj") + " --grid 3,2,1 --threads 1 -q ";
  ASSERT_EQ(run(args + "--json -o " + path("serial.json")).status, 0);
  const std::string mpirun = std::string(EXACTVIS_MPIEXEC) + " --oversubscribe --allow-run-as-root -np 3 ";
  const std::string cmd = mpirun + EXACTVIS_BINARY + " " + args + "--json -o " + path("mpi.json") + " >" +
                          path("mpi.log") + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(path("mpi.log"));
  EXPECT_EQ(slurp(path("mpi.json")), slurp(path("serial.json")));
  // JSON lines under MPI: the same cells (in finishing order).
  const std::string lines = mpirun + EXACTVIS_BINARY + " " + args + "-o " + path("mpi.jsonl") + " >" + path("mpi.log") + " 2>&1";
  ASSERT_EQ(std::system(lines.c_str()), 0) << slurp(path("mpi.log"));
  ASSERT_EQ(run("pvs-merge " + path("mpi.jsonl") + " -o " + path("mpi_merged.json")).status, 0);
  EXPECT_EQ(slurp(path("mpi_merged.json")), slurp(path("serial.json")));
}
#endif

}  // namespace
