// `exactvis validate` run as a user would (issue #12): the JSON shape of the issue on a scene with known
// answers and planted errors, witnesses re-checked by the independent oracle after parsing them back, -o
// equal to --json, the per-cell .vtp files, and bad files (one-line errors, exit 1, no output left behind).
#include "oracles/json_rational.hpp"
#include "oracles/visibility_oracle.hpp"
#include "tests/cli_test_util.hpp"
#include "tests/region/slit_scene.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

using cli_test::CliRun;

class ValidateCli : public cli_test::CliTest {
 protected:
  ValidateCli() : CliTest("validate-cli") {}
  void SetUp() override {
    // Target 0 behind a slit 1e-9 wide in the wall x = 5 (visible from cell 0), target 1 behind the wall
    // (hidden from cell 0); from cell 1, at the wall's far end beyond y = 10, both are visible.
    write("slit.obj", region_test_slit::kSlitObj);  // tests/region/slit_scene.hpp
    write("cells.json", "{\"cells\": [[-1, -1, -1, 0, 1, 1], [6, 11, -1, 7, 12, 1]]}");
  }
};

using oracle::json_point;
using oracle::json_rational;
using region_test_slit::slit_scene;

}  // namespace

TEST_F(ValidateCli, JsonShapePlantedErrorsAndWitnesses) {
  // Cell 0 sees 0 and the wall's near faces (2..5), not 1. Planted: 0 missing, 1 listed.
  // Cell 1 (left out of the file, so reported empty): whatever it sees is false invisible.
  write("other.txt", "0: 1 2 3 4 5 5\n");
  const CliRun r = run("validate " + path("slit.obj") + " --cells " + path("cells.json") + " --pvs " +
                       path("other.txt") + " --json -q -o " + path("report.json") + " --vtp " + path("vtp"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("cell 1 is not listed"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j, nlohmann::json::parse(cli_test::slurp(path("report.json"))));
  ASSERT_EQ(j["cells"].size(), 2u);
  const auto& c0 = j["cells"][0];
  EXPECT_EQ(c0["box"], nlohmann::json::parse("[-1, -1, -1, 0, 1, 1]"));
  EXPECT_EQ(c0["false_visible"], nlohmann::json::parse("[1]"));
  EXPECT_EQ(c0["false_invisible"], nlohmann::json::parse("[0]"));
  EXPECT_EQ(c0["exact"], 5);
  EXPECT_EQ(c0["reported"], 5);
  ASSERT_TRUE(c0["witnesses"].contains("0"));
  EXPECT_EQ(c0["witnesses"].size(), 1u);

  const auto& c1 = j["cells"][1];
  EXPECT_EQ(c1["false_visible"], nlohmann::json::array());
  EXPECT_EQ(c1["reported"], 0);
  EXPECT_EQ(c1["false_invisible"].size(), c1["exact"].get<std::size_t>());
  EXPECT_EQ(c1["witnesses"].size(), c1["exact"].get<std::size_t>());
  const auto& t = j["totals"];
  EXPECT_EQ(t["false_visible"], 1);
  EXPECT_EQ(t["false_invisible"], 1 + c1["exact"].get<int>());
  EXPECT_EQ(t["exact"], 5 + c1["exact"].get<int>());
  EXPECT_EQ(t["reported"], 5);

  // Every witness, parsed back from JSON, re-checked by the oracle.
  const auto scene = slit_scene();
  for (int k = 0; k < 2; ++k) {
    oracle::Source src;
    src.is_box = true;
    const auto& box = j["cells"][k]["box"];
    src.lo = {json_rational(box[0]), json_rational(box[1]), json_rational(box[2])};
    src.hi = {json_rational(box[3]), json_rational(box[4]), json_rational(box[5])};
    for (const auto& [id, w] : j["cells"][k]["witnesses"].items()) {
      std::string why;
      EXPECT_TRUE(oracle::witness_is_valid(scene, std::stoul(id), src, json_point(w[0]), json_point(w[1]), &why))
          << "cell " << k << " triangle " << id << ": " << why;
    }
  }

  // The .vtp of cell 0: status per triangle, one witness line, the six box faces.
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path("vtp/cell_0.vtp").c_str());
  reader->Update();
  vtkPolyData* pd = reader->GetOutput();
  ASSERT_EQ(pd->GetNumberOfCells(), 1 + 6 + 6);
  vtkDataArray* status = pd->GetCellData()->GetArray("status");
  vtkDataArray* kind = pd->GetCellData()->GetArray("kind");
  ASSERT_TRUE(status && kind);
  EXPECT_EQ(kind->GetTuple1(0), 1);     // the witness line first
  EXPECT_EQ(status->GetTuple1(1), 3);   // triangle 0: false invisible
  EXPECT_EQ(status->GetTuple1(2), 2);   // triangle 1: false visible
  for (int i = 3; i < 7; ++i) EXPECT_EQ(status->GetTuple1(i), 1);  // the wall: correctly visible
  EXPECT_EQ(kind->GetTuple1(7), 2);     // box faces
  EXPECT_TRUE(fs::exists(path("vtp/cell_1.vtp")));
}

TEST_F(ValidateCli, HumanSummaryAndCorrectPvs) {
  write("exact.txt", "0: 0 2 3 4 5\n1: 0 1 2 3 4 5\n");
  const CliRun r = run("validate " + path("slit.obj") + " --cells " + path("cells.json") + " --pvs " +
                       path("exact.txt") + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("cell 0: exact 5, reported 5, false visible 0, false invisible 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("total over 2 cells:"), std::string::npos) << r.out;
}

TEST_F(ValidateCli, BadFilesAreOneLineErrorsWithoutOutput) {
  write("unknown.txt", "0: 0 6\n");
  write("range.txt", "2: 0\n");
  write("bad.txt", "zero: 1\n");
  write("bad.json", "{\"cells\": [{\"visible\": [0]}");
  write("badcells.json", "{\"cells\": [[0, 0, 0, 1, 1]]}");
  write("good.txt", "0: 0\n");
  struct Case {
    std::string args, expected;
  };
  const std::string base = "validate " + path("slit.obj") + " -q -o " + path("out.json") + " ";
  const std::vector<Case> cases = {
      {"--cells " + path("cells.json") + " --pvs " + path("unknown.txt"), path("unknown.txt") + ": line 1: triangle id 6 is not in the scene"},
      {"--cells " + path("cells.json") + " --pvs " + path("range.txt"), path("range.txt") + ": line 1: cell 2 is out of range"},
      {"--cells " + path("cells.json") + " --pvs " + path("bad.txt"), path("bad.txt") + ": line 1: 'zero' is not a cell index"},
      {"--cells " + path("cells.json") + " --pvs " + path("bad.json"), path("bad.json") + ": not a JSON document"},
      {"--cells " + path("badcells.json") + " --pvs " + path("good.txt"), path("badcells.json") + ": cell 0 is not a list of 6 numbers"},
      {"--cells " + path("cells.json") + " --pvs " + path("missing.txt"), path("missing.txt") + ": cannot be read"},
      {"--pvs " + path("good.txt"), "--cells: required"},
  };
  for (const auto& c : cases) {
    const CliRun r = run(base + c.args);
    EXPECT_EQ(r.status, 1) << c.args;
    EXPECT_NE(r.err.find("exactvis validate: error: " + c.expected), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(path("out.json"))) << c.args;
  }
}

TEST_F(ValidateCli, ChecksThePvsFilesOfExactvisPvs) {
  // The exact PVS document has no errors; the sampled PVS in JSON lines (header + cells) lists no hidden
  // triangle and misses what it misses.
  const std::string common = path("slit.obj") + " --cells " + path("cells.json") + " -q";
  ASSERT_EQ(run("pvs " + common + " --json -o " + path("exact.json")).status, 0);
  ASSERT_EQ(run("pvs " + common + " --method sampled --rays 3000 --jsonl -o " + path("sampled.jsonl")).status, 0);
  const CliRun e = run("validate " + common + " --pvs " + path("exact.json") + " --json");
  ASSERT_EQ(e.status, 0) << e.err;
  const auto je = nlohmann::json::parse(e.out);
  EXPECT_EQ(je["totals"]["false_visible"], 0);
  EXPECT_EQ(je["totals"]["false_invisible"], 0);
  EXPECT_EQ(je["totals"]["exact"], je["totals"]["reported"]);
  const CliRun s = run("validate " + common + " --pvs " + path("sampled.jsonl") + " --json");
  ASSERT_EQ(s.status, 0) << s.err;
  const auto js = nlohmann::json::parse(s.out);
  EXPECT_EQ(js["totals"]["false_visible"], 0);
  EXPECT_EQ(js["totals"]["exact"], je["totals"]["exact"]);
  EXPECT_GT(js["totals"]["reported"], 0);
  // The conservative PVS misses nothing: validate finds only false visible triangles in it.
  ASSERT_EQ(run("pvs " + common + " --method conservative --json -o " + path("conservative.json")).status, 0);
  const CliRun c = run("validate " + common + " --pvs " + path("conservative.json") + " --json");
  ASSERT_EQ(c.status, 0) << c.err;
  const auto jc = nlohmann::json::parse(c.out);
  EXPECT_EQ(jc["totals"]["false_invisible"], 0);
  EXPECT_EQ(jc["totals"]["exact"], je["totals"]["exact"]);
  EXPECT_EQ(jc["totals"]["reported"].get<int>(), je["totals"]["exact"].get<int>() + jc["totals"]["false_visible"].get<int>());
}
