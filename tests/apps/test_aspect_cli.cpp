// `exactvis aspect`: the command line and JSON shape of issue 16, and its errors.
#include "cli_test_util.hpp"
#include "oracles/aspect_oracle.hpp"
#include "oracles/json_rational.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using cli_test::run_exactvis;

// Three tetrahedra with pairwise skew edges (vertex coordinates) and the faces of one tetrahedron (0-based).
const double kSkewVertices[12][3] = {{-1, 0, 0}, {1, 0, 0},   {0, -3, 0}, {0, -1, -1}, {0, -1, 1}, {0, 1, 1},
                                     {3, 0, 1},  {1, 0, 1.5}, {-1, -1, 2}, {1, 1, 2},   {2, -2, 2}, {1, -1, 3}};
const std::array<std::array<int, 3>, 4> kTetrahedronFaces = {{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}}};

fs::path test_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("exactvis_aspect_cli_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write_cube(const fs::path& file) {
  std::ofstream f(file);
  f << "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
       "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
}

// Two unit boxes side by side with a gap: closed, not convex.
void write_two_boxes(const fs::path& file) {
  std::ofstream f(file);
  for (int b = 0; b < 2; ++b)
    for (int k = 0; k < 8; ++k) f << "v " << (k & 1) + 3 * b << " " << ((k >> 1) & 1) << " " << ((k >> 2) & 1) << "\n";
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int b = 0; b < 2; ++b)
    for (const auto& x : q) {
      const int o = 1 + 8 * b;
      f << "f " << x[0] + o << " " << x[1] + o << " " << x[2] + o << "\n";
      f << "f " << x[0] + o << " " << x[2] + o << " " << x[3] + o << "\n";
    }
}

TEST(AspectCli, CubeJsonHasTheIssueShape) {
  const fs::path d = test_dir("cube");
  write_cube(d / "cube.obj");
  for (const std::string view : {"--orthographic", "--perspective"}) {
    const auto r = run_exactvis(d, "aspect " + (d / "cube.obj").string() + " " + view + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j.size(), 3u);
    EXPECT_EQ(j["counts"]["regions"], 26);
    EXPECT_EQ(j["counts"]["edges"], j["adjacency"].size());
    ASSERT_EQ(j["regions"].size(), 26u);
    for (std::size_t i = 0; i < j["regions"].size(); ++i) {
      const auto& reg = j["regions"][i];
      EXPECT_EQ(reg["id"], i);
      EXPECT_TRUE(reg["dimension"].is_number_integer());
      EXPECT_TRUE(reg["aspect"].is_array());
      EXPECT_EQ(reg["sample"].size(), 3u);
    }
    for (const auto& a : j["adjacency"]) {
      ASSERT_EQ(a.size(), 3u);
      EXPECT_LT(a[0].get<int>(), a[1].get<int>());
      EXPECT_EQ(a[2]["type"], "EV");
    }
  }
}

TEST(AspectCli, PlaneOfViewpoints) {
  const fs::path d = test_dir("plane");
  write_cube(d / "cube.obj");
  const auto r = run_exactvis(d, "aspect " + (d / "cube.obj").string() + " --plane z=2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["counts"]["regions"], 9);
  for (const auto& reg : j["regions"]) EXPECT_EQ(reg["sample"][2], 2);
}

TEST(AspectCli, VtpPictures) {
  const fs::path d = test_dir("vtp");
  write_cube(d / "cube.obj");
  const std::string c = (d / "cube.obj").string();
  EXPECT_EQ(run_exactvis(d, "aspect " + c + " --orthographic --vtp " + (d / "s.vtp").string()).status, 0);
  EXPECT_GT(fs::file_size(d / "s.vtp"), 1000u);
  EXPECT_EQ(run_exactvis(d, "aspect " + c + " --plane z=0 --vtp " + (d / "p.vtp").string()).status, 0);
  EXPECT_GT(fs::file_size(d / "p.vtp"), 1000u);
  const auto r = run_exactvis(d, "aspect " + c + " --perspective --vtp " + (d / "q.vtp").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_FALSE(fs::exists(d / "q.vtp"));
}

// --png renders offscreen (a private Xvfb when DISPLAY is unset): a PNG file appears.
TEST(AspectCli, PngPicture) {
  const fs::path d = test_dir("png");
  write_cube(d / "cube.obj");
  const auto r = run_exactvis(d, "aspect " + (d / "cube.obj").string() + " --orthographic -q --png " +
                                     (d / "a.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string png = cli_test::slurp((d / "a.png").string());
  ASSERT_GT(png.size(), 1000u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST(AspectCli, OutputFileHoldsTheSameJson) {
  const fs::path d = test_dir("output");
  write_cube(d / "cube.obj");
  const auto r = run_exactvis(d, "aspect " + (d / "cube.obj").string() + " --orthographic --json -o " +
                                     (d / "out.json").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out), nlohmann::json::parse(cli_test::slurp((d / "out.json").string())));
}

TEST(AspectCli, PerspectiveOnANonConvexModelPointsToPlane) {
  const fs::path d = test_dir("nonconvex");
  write_two_boxes(d / "two.obj");
  const auto r = run_exactvis(d, "aspect " + (d / "two.obj").string() + " --perspective -o " + (d / "o.json").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("two.obj: not a closed convex model"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--plane"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_FALSE(fs::exists(d / "o.json"));
  // --plane on this closed solid with convex front parts (docs/theory.md 10.8): the facing faces are hidden
  // only on the strips behind the other box, 13 regions at mid-height (as tests/aspect's hand count).
  const auto o = run_exactvis(d, "aspect " + (d / "two.obj").string() + " --plane z=1/2 --json -q");
  ASSERT_EQ(o.status, 0) << o.err;
  const auto j = nlohmann::json::parse(o.out);
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j["counts"]["regions"], 13);
  EXPECT_EQ(j["counts"]["edges"], j["adjacency"].size());
  for (const auto& reg : j["regions"]) EXPECT_EQ(reg["sample"][2], 0.5);
  EXPECT_EQ(j["adjacency"][0][2]["type"], "EV");
  const auto t = run_exactvis(d, "aspect " + (d / "two.obj").string() + " --plane z=1/2");
  EXPECT_NE(t.out.find("plane aspect graph of a non-convex closed model with 24 triangles"), std::string::npos) << t.out;
  const auto v = run_exactvis(d, "aspect " + (d / "two.obj").string() + " --plane z=1/2 -q --vtp " + (d / "p.vtp").string());
  EXPECT_EQ(v.status, 0) << v.err;
  EXPECT_GT(fs::file_size(d / "p.vtp"), 1000u);
}

// Two boxes with a gap of 2: orthographic works (docs/theory.md 10.5), the issue's JSON shape, 26 regions;
// a third box in a row makes a front part of two boxes (EEE events possible): one-line error, no output.
TEST(AspectCli, OrthographicNonConvexModels) {
  const fs::path d = test_dir("nonconvex_ortho");
  write_two_boxes(d / "two.obj");
  const auto r = run_exactvis(d, "aspect " + (d / "two.obj").string() + " --orthographic --json -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["counts"]["regions"], 26);
  EXPECT_EQ(j["regions"].size(), 26u);
  EXPECT_EQ(j["adjacency"][0][2]["type"], "EV");
  const auto t = run_exactvis(d, "aspect " + (d / "two.obj").string() + " --orthographic");
  EXPECT_NE(t.out.find("non-convex closed model with 24 triangles"), std::string::npos) << t.out;
  const auto v = run_exactvis(d, "aspect " + (d / "two.obj").string() + " --orthographic -q --vtp " + (d / "s.vtp").string());
  EXPECT_EQ(v.status, 0) << v.err;
  EXPECT_GT(fs::file_size(d / "s.vtp"), 1000u);
  {
    std::ifstream in(d / "two.obj");
    std::ofstream out(d / "three.obj");
    std::string line;
    std::vector<std::string> faces;
    while (std::getline(in, line)) (line[0] == 'v' ? out << line << "\n" : (faces.push_back(line), out));
    for (int k = 0; k < 8; ++k) out << "v " << (k & 1) + 6 << " " << ((k >> 1) & 1) << " " << ((k >> 2) & 1) << "\n";
    for (const auto& f : faces) out << f << "\n";
    for (std::size_t i = 0; i < 12; ++i) {  // the first box's faces shifted to the third box's vertices
      std::istringstream fs(faces[i].substr(2));
      int a, b, c;
      fs >> a >> b >> c;
      out << "f " << a + 16 << " " << b + 16 << " " << c + 16 << "\n";
    }
  }
  // Three boxes in a row are outside the class of 10.5; orthographic, their free event arcs are EV arcs only
  // (docs/theory.md 10.10): the graph of aspect/general_orthographic_aspect_graph, in the same JSON shape.
  const auto e = run_exactvis(d, "aspect " + (d / "three.obj").string() + " --orthographic -q -o " + (d / "o.json").string());
  EXPECT_EQ(e.status, 0) << e.err;
  EXPECT_NE(e.out.find("outside the convex-front class with 36 triangles"), std::string::npos) << e.out;
  {
    std::ifstream in(d / "o.json");
    const auto g = nlohmann::json::parse(in);
    EXPECT_EQ(g["counts"]["regions"], g["regions"].size());
    EXPECT_EQ(g["regions"].size(), 26u);  // as two boxes: a facing face is hidden only from +-x (theory 10.5)
    EXPECT_EQ(g["adjacency"][0][2]["type"], "EV");
  }
  fs::remove(d / "o.json");
  const auto pv = run_exactvis(d, "aspect " + (d / "three.obj").string() + " --orthographic -q --vtp " + (d / "t.vtp").string());
  EXPECT_EQ(pv.status, 0) << pv.err;
  EXPECT_GT(fs::file_size(d / "t.vtp"), 1000u);
  {
    // Three disjoint tetrahedra with pairwise skew edges met by the line x = y = 0: a free EEE family whose
    // arcs cross (docs/theory.md 10.11, "EEE x EEE crossings"; refused before session 11).
    std::ofstream out(d / "skew.obj");
    for (const auto& p : kSkewVertices) out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    for (int b : {1, 5, 9})
      for (const auto& f : kTetrahedronFaces) out << "f " << b + f[0] << " " << b + f[1] << " " << b + f[2] << "\n";
  }
  const auto k = run_exactvis(d, "aspect " + (d / "skew.obj").string() + " --orthographic -q -o " + (d / "o.json").string());
  EXPECT_EQ(k.status, 0) << k.err;
  {
    // Every region's sample direction sees exactly the region's aspect, by the independent slab oracle
    // (oracle::direction_aspect shares no code with aspect/); some adjacency names an EEE event.
    std::vector<oracle::OTriangle> model;
    for (int b : {0, 4, 8})
      for (const auto& f : kTetrahedronFaces) {
        oracle::OTriangle t;
        for (int c = 0; c < 3; ++c) {
          const double* v = kSkewVertices[b + f[c]];
          t[c] = oracle::qvec(v[0], v[1], v[2]);
        }
        model.push_back(t);
      }
    std::ifstream in(d / "o.json");
    const auto g = nlohmann::json::parse(in);
    ASSERT_EQ(g["counts"]["regions"], g["regions"].size());
    ASSERT_GT(g["regions"].size(), 26u);
    for (const auto& r : g["regions"]) {
      std::vector<int> aspect = r["aspect"].get<std::vector<int>>();
      std::sort(aspect.begin(), aspect.end());
      auto seen = oracle::direction_aspect(model, oracle::json_point(r["sample"]));
      std::sort(seen.begin(), seen.end());
      EXPECT_EQ(aspect, seen) << "region " << r["id"];
    }
    bool eee = false;
    for (const auto& a : g["adjacency"]) eee = eee || a[2]["type"].get<std::string>().find("EEE") != std::string::npos;
    EXPECT_TRUE(eee);
  }
  fs::remove(d / "o.json");
  // The same one-line error for a plane of viewpoints (the class of 10.5 is required there too).
  const auto p = run_exactvis(d, "aspect " + (d / "three.obj").string() + " --plane z=1/2 -o " + (d / "o.json").string());
  EXPECT_EQ(p.status, 1);
  EXPECT_NE(p.err.find("three.obj: the part of the model in front of triangle"), std::string::npos) << p.err;
  EXPECT_EQ(std::count(p.err.begin(), p.err.end(), '\n'), 1);
  EXPECT_FALSE(fs::exists(d / "o.json"));
}

// Models that are not closed solids (issue 16's general polyhedral scenes): --orthographic takes every
// triangle as a two-sided occluder (docs/theory.md 10.10). Two parallel triangles, the lower one hidden only
// from a closed 2D region of directions above (tests/aspect's hand count): 4 regions, the issue's JSON shape.
TEST(AspectCli, OrthographicOpenModels) {
  const fs::path d = test_dir("open");
  {
    std::ofstream f(d / "open.off");
    f << "OFF\n6 2 0\n0 0 0\n3 0 0\n0 3 0\n-2 -2 1\n7 -2 1\n-2 7 1\n3 0 1 2\n3 3 4 5\n";
  }
  const std::string m = (d / "open.off").string();
  const auto r = run_exactvis(d, "aspect " + m + " --orthographic --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j["counts"]["regions"], 4);
  EXPECT_EQ(j["counts"]["edges"], 3);
  ASSERT_EQ(j["regions"].size(), 4u);
  for (const auto& reg : j["regions"]) {
    EXPECT_TRUE(reg["aspect"].is_array());
    EXPECT_EQ(reg["sample"].size(), 3u);
  }
  for (const auto& a : j["adjacency"]) EXPECT_EQ(a[2]["type"], "EV");
  const auto t = run_exactvis(d, "aspect " + m + " --orthographic -q");
  EXPECT_NE(t.out.find("a model that is not a closed solid (two-sided triangles) with 2 triangles"), std::string::npos)
      << t.out;
  // Triangles that cross: a one-line error naming them, no output.
  {
    std::ofstream f(d / "crossing.off");
    f << "OFF\n6 2 0\n0 0 0\n2 0 0\n0 2 0\n0.5 0.5 -1\n0.5 0.5 1\n3 3 0\n3 0 1 2\n3 3 4 5\n";
  }
  const auto c = run_exactvis(d, "aspect " + (d / "crossing.off").string() + " --orthographic -q -o " +
                                     (d / "o.json").string());
  EXPECT_EQ(c.status, 1);
  EXPECT_NE(c.err.find("crossing.off: triangles 0 and 1 cross"), std::string::npos) << c.err;
  EXPECT_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1);
  EXPECT_FALSE(fs::exists(d / "o.json"));
  // A plane of viewpoints still needs a closed solid (docs/theory.md 10.8): the one-line error.
  const auto p = run_exactvis(d, "aspect " + m + " --plane z=2 -q");
  EXPECT_EQ(p.status, 1);
  EXPECT_NE(p.err.find("open.off: the model is not closed"), std::string::npos) << p.err;
  EXPECT_NE(p.err.find("--orthographic takes such models"), std::string::npos) << p.err;
  EXPECT_EQ(std::count(p.err.begin(), p.err.end(), '\n'), 1);
}

TEST(AspectCli, BadOptions) {
  const fs::path d = test_dir("bad");
  write_cube(d / "cube.obj");
  const std::string c = (d / "cube.obj").string();
  EXPECT_EQ(run_exactvis(d, "aspect " + c).status, 1);  // no view given
  EXPECT_NE(run_exactvis(d, "aspect " + c + " --orthographic --perspective").status, 0);
  const auto p = run_exactvis(d, "aspect " + c + " --plane y=3");  // only z=H
  EXPECT_EQ(p.status, 1);
  EXPECT_NE(p.err.find("--plane"), std::string::npos);
  const auto m = run_exactvis(d, "aspect " + (d / "missing.obj").string() + " --orthographic");
  EXPECT_EQ(m.status, 1);
  EXPECT_NE(m.err.find("missing.obj"), std::string::npos);
}

}  // namespace
