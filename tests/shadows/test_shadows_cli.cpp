// `exactvis shadows` and `exactvis lightcheck` from outside: the JSON shape of issue #15, the mesh files, the
// textbook classification of given points, and one-line errors without partial output.
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <vector>

namespace {

namespace fs = std::filesystem;

fs::path test_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("exactvis_shadows_cli_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// A JSON exact number (a double, or "num/den" where not a double) as a double.
double number(const nlohmann::json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string t = j.get<std::string>();
  const auto slash = t.find('/');
  return slash == std::string::npos ? std::stod(t) : std::stod(t.substr(0, slash)) / std::stod(t.substr(slash + 1));
}

const char* kTextbook =
    "o floor\nv -4 -4 0\nv 12 -4 0\nv 12 12 0\nv -4 12 0\nf 1 2 3\nf 1 3 4\n"
    "o blocker\nv 3 3 2\nv 5 3 2\nv 5 5 2\nv 3 5 2\nf 5 6 7\nf 5 7 8\n"
    "o lamp\nv 3 3 4\nv 5 3 4\nv 5 5 4\nv 3 5 4\nf 9 10 11\nf 9 11 12\n";

TEST(ShadowsCli, JsonHasTheShapeOfTheIssue) {
  const fs::path d = test_dir("json");
  write(d / "s.obj", kTextbook);
  const auto r = cli_test::run_exactvis(d, "shadows " + (d / "s.obj").string() + " --light lamp --receivers 0,1 --json -o " +
                                               (d / "m.vtp").string() + " --ply " + (d / "m.ply").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["receivers"].size(), 2u);
  double umbra = 0, penumbra = 0, lit = 0;
  for (const auto& rec : j["receivers"]) {
    EXPECT_TRUE(rec["triangle"] == 0 || rec["triangle"] == 1);
    for (const auto& c : rec["curves"]) {
      EXPECT_TRUE(c["kind"] == "EV" || c["kind"] == "EEE");
      EXPECT_TRUE(c["order"] == 0 || c["order"] == 1 || c["order"] == 2);
      EXPECT_TRUE(c["generators"].is_object());
      ASSERT_EQ(c["ends"].size(), 2u);
      EXPECT_EQ(c["ends"][0].size(), 3u);
    }
    for (const auto& f : rec["faces"]) {
      const std::string cls = f["class"];
      ASSERT_TRUE(f["area"].is_number());
      ASSERT_EQ(f["sample"].size(), 3u);
      ASSERT_TRUE(f["light_fraction"].is_number());
      ASSERT_TRUE(f["irradiance"].is_number());
      (cls == "umbra" ? umbra : cls == "penumbra" ? penumbra : lit) += f["area"].get<double>();
      if (cls == "umbra") {
        EXPECT_EQ(f["light_fraction"].get<double>(), 0.0);
      }
      if (cls == "lit") {
        EXPECT_EQ(f["light_fraction"].get<double>(), 1.0);
      }
    }
  }
  EXPECT_NEAR(umbra, 4, 1e-12);
  EXPECT_NEAR(penumbra, 32, 1e-12);
  EXPECT_NEAR(lit, 220, 1e-12);
  EXPECT_TRUE(j["counts"].is_object());
  EXPECT_TRUE(j["stats"].is_object());
  EXPECT_GT(fs::file_size(d / "m.vtp"), 100u);
  std::ifstream ply(d / "m.ply");
  std::string first;
  std::getline(ply, first);
  EXPECT_EQ(first, "ply");
}

TEST(ShadowsCli, LightcheckClassifiesPointsWithWitnessOrProof) {
  const fs::path d = test_dir("lightcheck");
  write(d / "s.obj", kTextbook);
  write(d / "p.txt", "# x y z\n4 4 0\n9/2 7/4 0\n10 10 0\n");
  const auto r = cli_test::run_exactvis(d, "lightcheck " + (d / "s.obj").string() + " --light lamp --points " +
                                               (d / "p.txt").string() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["points"].size(), 3u);
  EXPECT_EQ(j["points"][0]["status"], "umbra");
  EXPECT_EQ(j["points"][0]["proof"]["backprojection"], "empty");
  EXPECT_EQ(j["points"][1]["status"], "partly_lit");
  // 1 - hx * hy: hx = |[1.5, 5.5] ∩ [3, 5]| / 2 = 1, hy = |[4.25, 8.25] ∩ [3, 5]| / 2 = 3/8.
  EXPECT_EQ(j["points"][1]["light_fraction_exact"], 0.625);
  EXPECT_TRUE(j["points"][1].contains("witness"));
  EXPECT_EQ(j["points"][2]["status"], "fully_lit");
  EXPECT_EQ(j["points"][2]["light_fraction"], 1.0);
  // The witnesses, re-checked by hand: a light point of the lamp [3, 5]^2 x {4} whose segment to the point
  // passes the blocker plane z = 2 at (q + p) / 2 outside the blocker square [3, 5]^2 (the only occluder).
  for (int k : {1, 2}) {
    const auto& w = j["points"][k]["witness"]["light_point"];
    ASSERT_EQ(w.size(), 3u);
    const double qx = number(w[0]), qy = number(w[1]);
    EXPECT_EQ(number(w[2]), 4.0);
    EXPECT_TRUE(qx > 3 && qx < 5 && qy > 3 && qy < 5) << w.dump();
    const double px = number(j["points"][k]["point"][0]), py = number(j["points"][k]["point"][1]);
    const double mx = (qx + px) / 2, my = (qy + py) / 2;
    EXPECT_FALSE(mx >= 3 && mx <= 5 && my >= 3 && my <= 5) << w.dump();
  }
}

// The radiosity mesh file: per-vertex irradiance against the closed form of a parallel rectangle's form
// factor (the lamp minus the blocker's shadow rectangle, derived by hand as in the textbook test), per-face
// class against the hand classification at the cell's centroid. The ASCII .ply is parsed here.
namespace {
// Form factor from a point at height h under the corner of the rectangle [0, a] x [0, b] (signed a, b: odd in
// each), parallel to it: the classical closed form.
double corner_form_factor(double a, double b, double h) {
  const double ra = std::sqrt(a * a + h * h), rb = std::sqrt(b * b + h * h);
  return (a / ra * std::atan(b / ra) + b / rb * std::atan(a / rb)) / (2 * std::numbers::pi);
}
double rectangle_form_factor(double x0, double x1, double y0, double y1, double h) {
  if (x1 <= x0 || y1 <= y0) return 0;
  return corner_form_factor(x1, y1, h) - corner_form_factor(x0, y1, h) - corner_form_factor(x1, y0, h) +
         corner_form_factor(x0, y0, h);
}
// Floor point (px, py): the lamp [3, 5]^2 at height 4 minus the light points q with (q + p) / 2 in [3, 5]^2.
double textbook_irradiance(double px, double py) {
  const double lit = rectangle_form_factor(3 - px, 5 - px, 3 - py, 5 - py, 4);
  const double hx0 = std::max(3.0, 6 - px), hx1 = std::min(5.0, 10 - px);
  const double hy0 = std::max(3.0, 6 - py), hy1 = std::min(5.0, 10 - py);
  return lit - rectangle_form_factor(hx0 - px, hx1 - px, hy0 - py, hy1 - py, 4);
}
}  // namespace

TEST(ShadowsCli, PlyMeshHasHandDerivedVertexIrradianceAndFaceClasses) {
  const fs::path d = test_dir("ply");
  // The textbook scene with the floor cut into three triangles: the side from (-4, -4) to (12, 10) crosses the
  // penumbra curve x = 3 at y = 17/8, where the mesh gets a vertex of fractional visibility (all the grid
  // crossings of the textbook curves are fully lit or umbra).
  write(d / "s.obj",
        "o floor\nv -4 -4 0\nv 12 -4 0\nv 12 10 0\nv 12 12 0\nv -4 12 0\nf 1 2 3\nf 1 3 4\nf 1 4 5\n"
        "o blocker\nv 3 3 2\nv 5 3 2\nv 5 5 2\nv 3 5 2\nf 6 7 8\nf 6 8 9\n"
        "o lamp\nv 3 3 4\nv 5 3 4\nv 5 5 4\nv 3 5 4\nf 10 11 12\nf 10 12 13\n");
  const auto r = cli_test::run_exactvis(d, "shadows " + (d / "s.obj").string() + " --light lamp --receivers 0,1,2 -q -o " +
                                               (d / "m.vtp").string() + " --ply " + (d / "m.ply").string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(d / "m.ply");
  std::string line;
  std::size_t nv = 0, nf = 0;
  std::vector<std::string> vertex_props, face_props;
  for (std::vector<std::string>* props = nullptr; std::getline(in, line) && line != "end_header";) {
    std::istringstream ss(line);
    std::string w, name;
    ss >> w;
    if (w == "element") {
      ss >> name;
      if (name == "vertex") ss >> nv, props = &vertex_props;
      if (name == "face") ss >> nf, props = &face_props;
    } else if (w == "property" && props) {
      std::string last;
      while (ss >> name) last = name;
      props->push_back(last);
    }
  }
  ASSERT_EQ(vertex_props, (std::vector<std::string>{"x", "y", "z", "irradiance"}));
  ASSERT_GE(face_props.size(), 2u);
  EXPECT_EQ(face_props[0], "vertex_indices");
  EXPECT_EQ(face_props[1], "class");
  ASSERT_GT(nv, 8u);
  ASSERT_GT(nf, 8u);
  std::vector<std::array<double, 3>> xyz(nv);
  int umbra_vertices = 0, penumbra_vertices = 0;
  for (std::size_t k = 0; k < nv; ++k) {
    double irr = 0;
    in >> xyz[k][0] >> xyz[k][1] >> xyz[k][2] >> irr;
    ASSERT_TRUE(in.good());
    EXPECT_EQ(xyz[k][2], 0.0);
    const double want = textbook_irradiance(xyz[k][0], xyz[k][1]);
    EXPECT_NEAR(irr, want, 1e-9) << "vertex " << k << " at " << xyz[k][0] << ", " << xyz[k][1];
    umbra_vertices += want == 0;
    penumbra_vertices += want > 0 && xyz[k][0] > 1 && xyz[k][0] < 7 && xyz[k][1] > 1 && xyz[k][1] < 7;
  }
  EXPECT_GE(umbra_vertices, 4);  // the umbra square's corners at least
  EXPECT_GE(penumbra_vertices, 1);
  std::map<int, int> classes;
  for (std::size_t f = 0; f < nf; ++f) {
    std::getline(in >> std::ws, line);
    std::istringstream ss(line);
    int n = 0, cls = -1;
    std::array<std::size_t, 3> v{};
    ss >> n >> v[0] >> v[1] >> v[2] >> cls;
    ASSERT_EQ(n, 3);
    double cx = 0, cy = 0;
    for (std::size_t k : v) {
      ASSERT_LT(k, nv);
      cx += xyz[k][0] / 3, cy += xyz[k][1] / 3;
    }
    // Hand classes (the textbook test): umbra [3, 5]^2, penumbra [1, 7]^2 minus it, lit elsewhere; the
    // centroid of a cell lies strictly inside its face.
    const int want = (cx > 3 && cx < 5 && cy > 3 && cy < 5) ? 0 : (cx > 1 && cx < 7 && cy > 1 && cy < 7) ? 1 : 2;
    EXPECT_EQ(cls, want) << "cell " << f << " centroid " << cx << ", " << cy;
    ++classes[cls];
  }
  EXPECT_GT(classes[0], 0);
  EXPECT_GT(classes[1], 0);
  EXPECT_GT(classes[2], 0);
  // The .vtp carries the same arrays (VTK XML: the array names are in the text header).
  const std::string vtp = cli_test::slurp((d / "m.vtp").string());
  EXPECT_NE(vtp.find("Name=\"irradiance\""), std::string::npos);
  EXPECT_NE(vtp.find("Name=\"class\""), std::string::npos);
}

TEST(ShadowsCli, BadInputGivesOneLineErrorsAndNoOutputFiles) {
  const fs::path d = test_dir("bad");
  write(d / "s.obj", kTextbook);
  write(d / "bad.txt", "1 2 3\n1 2\n");
  const std::string scene = (d / "s.obj").string(), vtp = (d / "out.vtp").string();
  struct Case {
    std::string args, needle;
  };
  const std::vector<Case> cases{
      {"shadows " + (d / "missing.obj").string() + " --light lamp -o " + vtp, "missing.obj"},
      {"shadows " + scene + " --light nosuch -o " + vtp, "--light 'nosuch'"},
      {"shadows " + scene + " --light lamp --receivers 0,99 -o " + vtp, "--receivers"},
      {"shadows " + scene + " --light lamp --receivers 4 -o " + vtp, "part of the light"},
      {"shadows " + scene + " --light lamp --receivers x -o " + vtp, "--receivers"},
      {"lightcheck " + scene + " --light lamp --points " + (d / "bad.txt").string(), "bad.txt:2"},
      {"lightcheck " + scene + " --light lamp --points " + (d / "none.txt").string(), "none.txt"},
  };
  for (const auto& c : cases) {
    const auto r = cli_test::run_exactvis(d, c.args);
    EXPECT_NE(r.status, 0) << c.args;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(vtp)) << c.args;
  }
}

}  // namespace

namespace {

TEST(ShadowsCli, PngIsRenderedHeadless) {
  const fs::path d = test_dir("png");
  write(d / "s.obj", kTextbook);
  // No DISPLAY: the renderer starts (and stops) its own Xvfb.
  unsetenv("DISPLAY");
  const auto r = cli_test::run_exactvis(d, "shadows " + (d / "s.obj").string() + " --light lamp -q --png " +
                                               (d / "s.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(d / "s.png", std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  EXPECT_EQ(std::string(sig + 1, 3), "PNG");
  EXPECT_GT(fs::file_size(d / "s.png"), 1000u);
}

}  // namespace
