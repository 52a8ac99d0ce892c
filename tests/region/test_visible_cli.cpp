// `exactvis visible` run as a user would: the JSON shape of the issue, exact witnesses re-checked by the
// independent oracle after parsing them back from JSON, the .vtp output, and bad parameters.
#include "oracles/json_rational.hpp"
#include "oracles/visibility_oracle.hpp"
#include "tests/cli_test_util.hpp"
#include "tests/region/slit_scene.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

using cli_test::CliRun;
using cli_test::slurp;

class VisibleCli : public cli_test::CliTest {
 protected:
  VisibleCli() : CliTest("visible-cli") {}
  void SetUp() override { write("slit.obj", region_test_slit::kSlitObj); }  // tests/region/slit_scene.hpp
};

using oracle::json_point;
using region_test_slit::slit_scene;

}  // namespace

TEST_F(VisibleCli, PolygonSourceJsonShapeAndWitnesses) {
  const CliRun r = run("visible " + path("slit.obj") + " --source-polygon \"0,-1,-1;0,1,-1;0,1,1;0,-1,1\" --triangles 0,1 --json -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("source"));
  ASSERT_TRUE(j["source"].contains("polygon"));
  ASSERT_TRUE(j.contains("stats"));
  ASSERT_EQ(j["results"].size(), 2u);
  EXPECT_EQ(j["results"][0]["triangle"], 0);
  EXPECT_EQ(j["results"][0]["visible"], true);
  EXPECT_EQ(j["results"][1]["triangle"], 1);
  EXPECT_EQ(j["results"][1]["visible"], false);
  EXPECT_FALSE(j["results"][1].contains("witness"));
  oracle::Source src;
  for (auto [x, y, z] : {std::array<double, 3>{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}})
    src.polygon.push_back(oracle::qvec(x, y, z));
  const auto& w = j["results"][0]["witness"];
  ASSERT_EQ(w.size(), 2u);
  std::string why;
  EXPECT_TRUE(oracle::witness_is_valid(slit_scene(), 0, src, json_point(w[0]), json_point(w[1]), &why)) << why;
}

TEST_F(VisibleCli, CellSourceWritesJsonFileAndVtp) {
  const std::string json = path("out.json"), vtp = path("out.vtp");
  const CliRun r = run("visible " + path("slit.obj") + " --cell -2,-1,-1,-1,1,1 -o " + json + " --vtp " + vtp + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(json));
  ASSERT_EQ(j["results"].size(), 6u);  // --triangles defaults to all
  EXPECT_EQ(j["source"]["cell"].size(), 6u);
  oracle::Source src;
  src.is_box = true;
  src.lo = oracle::qvec(-2, -1, -1);
  src.hi = oracle::qvec(-1, 1, 1);
  int visible = 0;
  for (const auto& e : j["results"]) {
    if (!e["visible"].get<bool>()) continue;
    ++visible;
    std::string why;
    EXPECT_TRUE(oracle::witness_is_valid(slit_scene(), e["triangle"].get<std::size_t>(), src, json_point(e["witness"][0]),
                                         json_point(e["witness"][1]), &why))
        << why;
  }
  EXPECT_EQ(j["results"][0]["visible"], true);
  EXPECT_EQ(j["results"][1]["visible"], false);
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(vtp.c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  EXPECT_EQ(poly->GetNumberOfPolys(), 6 + 6);  // the scene's triangles and the cell's faces
  EXPECT_EQ(poly->GetNumberOfLines(), visible);
  vtkDataArray* vis = poly->GetCellData()->GetArray("visible");
  vtkDataArray* kind = poly->GetCellData()->GetArray("kind");
  ASSERT_NE(vis, nullptr);
  ASSERT_NE(kind, nullptr);
  // Cell order: witness lines, scene triangles, cell faces. Only scene triangles carry a `visible` value.
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
    const int k = static_cast<int>(kind->GetTuple1(c));
    EXPECT_EQ(k, c < visible ? 1 : c < visible + 6 ? 0 : 2) << c;
    EXPECT_EQ(std::isnan(vis->GetTuple1(c)), k != 0) << c;
  }
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (vtkIdType c = visible + 6; c < poly->GetNumberOfCells(); ++c) {
    vtkCell* face = poly->GetCell(c);
    EXPECT_EQ(face->GetNumberOfPoints(), 4);
    for (vtkIdType k = 0; k < face->GetNumberOfPoints(); ++k) {
      double p[3];
      poly->GetPoint(face->GetPointId(k), p);
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
    }
  }
  EXPECT_EQ(lo[0], -2.0);  // the cell -2,-1,-1,-1,1,1
  EXPECT_EQ(hi[0], -1.0);
  EXPECT_EQ(lo[1], -1.0);
  EXPECT_EQ(hi[2], 1.0);
}

TEST_F(VisibleCli, BadParametersFailCleanly) {
  const std::string json = path("bad.json");
  const std::string scene = path("slit.obj");
  const std::vector<std::string> bad{
      "visible " + scene + " --cell 0,0,0,1,1 -o " + json,                       // 5 numbers
      "visible " + scene + " --cell 0,0,0,0,1,1 -o " + json,                     // empty extent
      "visible " + scene + " --cell 0,0,nan,1,1,1 -o " + json,                   // not finite
      "visible " + scene + " --cell 0,0,x,1,1,1 -o " + json,                     // not a number
      "visible " + scene + " -o " + json,                                        // no source
      "visible " + scene + " --source-polygon \"0,0,0;1,0,0;2,0,0\" -o " + json,  // collinear
      "visible " + scene + " --source-polygon \"0,0,0;2,0,0;0,2,0;2,2,0\" -o " + json,  // self-crossing
      "visible " + scene + " --source-polygon \"0,0,0;1,0,0;0,1,1;0,0,2\" -o " + json,  // not planar
      "visible " + scene + " --cell -2,-1,-1,-1,1,1 --triangles 99 -o " + json,  // unknown id
      "visible " + scene + " --cell -2,-1,-1,-1,1,1 --triangles 1,a -o " + json,  // malformed id
      "visible " + path("missing.obj") + " --cell -2,-1,-1,-1,1,1 -o " + json,    // missing file
  };
  for (const auto& args : bad) {
    const CliRun r = run(args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_FALSE(r.err.empty()) << args;
    EXPECT_FALSE(fs::exists(json)) << args;
  }
}
