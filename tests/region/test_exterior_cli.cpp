// `exactvis exterior` run as a user would: the counts on stdout, the JSON shape of issue 13 with every witness
// parsed back and re-checked by the independent oracle, the reduced mesh (-o) read back, the .vtp, the
// sampler comparison, and bad input (one-line errors, non-zero exit, no output files).
#include "io/load_scene.hpp"
#include "oracles/exterior_oracle.hpp"
#include "oracles/json_rational.hpp"
#include "tests/cli_test_util.hpp"
#include "tests/region/exterior_test_scenes.hpp"
#include "tests/region/oracle_input.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

namespace fs = std::filesystem;
using namespace exactvis;

namespace {

using cli_test::CliRun;

class ExteriorCli : public cli_test::CliTest {
 protected:
  ExteriorCli() : CliTest("exterior-cli") {}
  void SetUp() override {
    // The slit model (a box whose lid has a slit 2^-20 wide, a target inside: everything visible) and a
    // box inside a box (the inner 12 triangles hidden).
    scene_ = exterior_test::slit_box(std::ldexp(1.0, -21));
    exterior_test::ModelBuilder outer;
    outer.box({-2, -2, -2}, {3, 3, 3});
    outer.box({0, 0, 0}, {1, 1, 1});
    write_obj(path("slit.obj"), scene_);
    write_obj(path("boxes.obj"), outer.scene);
    boxes_ = outer.scene;
  }
  static void write_obj(const std::string& file, const Scene& s) {
    std::ofstream out(file);
    char buf[128];
    for (const Point3& p : s.vertices) {
      std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
      out << buf;
    }
    for (const auto& t : s.triangles) out << "f " << t.v[0] + 1 << " " << t.v[1] + 1 << " " << t.v[2] + 1 << "\n";
  }
  Scene scene_, boxes_;
};

using oracle::json_point;

TEST_F(ExteriorCli, CountsOnStdout) {
  const CliRun r = run("exterior " + path("boxes.obj") + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "kept 12\nremoved 12\n");
}

TEST_F(ExteriorCli, JsonShapeAndWitnessesRecheckedByOracle) {
  const CliRun r = run("exterior " + path("slit.obj") + " --json -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 3u);
  ASSERT_TRUE(j["kept"].is_array() && j["removed"].is_array() && j["witnesses"].is_object());
  EXPECT_EQ(j["kept"].size(), scene_.triangles.size());  // the slit shows the inside
  EXPECT_EQ(j["removed"].size(), 0u);
  EXPECT_EQ(j["witnesses"].size(), j["kept"].size());
  const auto os = region_test::oracle_scene(scene_);
  for (const auto& id : j["kept"]) {
    const auto& w = j["witnesses"][std::to_string(id.get<int>())];
    ASSERT_EQ(w.size(), 2u);
    std::string why;
    EXPECT_TRUE(oracle::exterior_witness_is_valid(os, id.get<std::size_t>(), json_point(w[0]), json_point(w[1]), &why))
        << "triangle " << id << ": " << why;
  }
}

TEST_F(ExteriorCli, ReducedMeshKeepsExactlyTheVisibleTriangles) {
  for (const std::string ext : {".ply", ".obj"}) {
    const std::string out = path("reduced" + ext);
    const CliRun r = run("exterior " + path("boxes.obj") + " -o " + out + " -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const Scene reduced = load_scenes({out});
    ASSERT_EQ(reduced.triangles.size(), 12u);
    std::multiset<std::tuple<double, double, double>> got, want;
    for (const auto& t : reduced.triangles)
      for (int k = 0; k < 3; ++k) got.insert({reduced.corner(t, k).x, reduced.corner(t, k).y, reduced.corner(t, k).z});
    for (int i = 0; i < 12; ++i)
      for (int k = 0; k < 3; ++k) {
        const Point3& p = boxes_.corner(boxes_.triangles[i], k);
        want.insert({p.x, p.y, p.z});
      }
    EXPECT_EQ(got, want) << ext;
  }
}

TEST_F(ExteriorCli, VtpColoursKeptAndRemovedWithWitnessRays) {
  const CliRun r = run("exterior " + path("boxes.obj") + " --vtp " + path("e.vtp") + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path("e.vtp").c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  EXPECT_EQ(poly->GetNumberOfPolys(), 24);
  EXPECT_EQ(poly->GetNumberOfLines(), 12);
  ASSERT_NE(poly->GetCellData()->GetArray("visible"), nullptr);
}

TEST_F(ExteriorCli, CompareSampledReportsTheSlitMiss) {
  const CliRun r = run("exterior " + path("slit.obj") + " --compare sampled --views 16 --resolution 32 --json -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("compare"));
  const auto& missed = j["compare"]["removed_but_visible"];
  const std::int64_t target = scene_.triangles.back().id;
  EXPECT_NE(std::find(missed.begin(), missed.end(), target), missed.end());
  EXPECT_EQ(j["compare"]["kept_but_hidden"].size(), 0u);
  const CliRun s = run("exterior " + path("boxes.obj") + " --method sampled --views 16 --resolution 32 -q");
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_EQ(s.out, "kept 12\nremoved 12\n");
}

TEST_F(ExteriorCli, BadInputOneLineErrorsAndNoOutputFiles) {
  std::ofstream(path("empty.obj")).close();
  std::ofstream(path("bad.obj")) << "v 0 0 0\nv 1 0 0\nf 1 2 9\n";
  const std::string out = path("never.ply"), vtp = path("never.vtp");
  for (const std::string& args :
       {"exterior " + path("missing.obj"), "exterior " + path("empty.obj"), "exterior " + path("bad.obj"),
        "exterior " + path("boxes.obj") + " --method magic", "exterior " + path("boxes.obj") + " --compare exact",
        "exterior " + path("boxes.obj") + " --threads -3", "exterior " + path("boxes.obj") + " --seed x",
        "exterior " + path("boxes.obj") + " --views 0", "exterior " + path("boxes.obj") + " --rays -1",
        "exterior " + path("boxes.obj") + " --resolution 9000"}) {
    const CliRun r = run(args + " -o " + out + " --vtp " + vtp + " -q");
    EXPECT_NE(r.status, 0) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
    EXPECT_FALSE(fs::exists(vtp)) << args;
  }
  // An output that cannot be written: the error names it, and the other output is not left either.
  const CliRun r = run("exterior " + path("boxes.obj") + " --vtp " + vtp + " -o " + path("nodir/x.ply") + " -q");
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("nodir"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(vtp));
}

}  // namespace
