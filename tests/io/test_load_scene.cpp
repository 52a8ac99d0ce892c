// Loader tests: fan rule and ids, degenerate dropping, objects (groups and components), exact coordinates,
// all four formats, multi-file scenes, non-manifold input. Expected values are written out by hand from the
// file text (or come from the generator that wrote the file), not from the loader's code.
#include "io/load_scene.hpp"
#include "io/write_mesh.hpp"
#include "kernel/scene_generators.hpp"
#include "io_test_util.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>

using namespace exactvis;
using iotest::TempDir;
using iotest::write_file;

namespace {

using Tri = std::array<int, 3>;

std::vector<Tri> corners(const Scene& s) {
  std::vector<Tri> out;
  for (const auto& t : s.triangles) out.push_back(t.v);
  return out;
}
std::vector<std::int64_t> ids(const Scene& s) {
  std::vector<std::int64_t> out;
  for (const auto& t : s.triangles) out.push_back(t.id);
  return out;
}
std::vector<std::string> object_names_per_triangle(const Scene& s) {
  std::vector<std::string> out;
  for (const auto& t : s.triangles) out.push_back(s.objects.at(t.object).name);
  return out;
}

using iotest::put_f32;
using iotest::put_u32;

}  // namespace

TEST(LoadScene, FanRuleAndIdsObj) {
  TempDir dir;
  const auto path = write_file(dir.file("fan.obj"),
                               "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 0\nv 0 0 1\n"
                               "f 1 2 3 4\n"        // quad -> (0,1,2) (0,2,3)
                               "f 6/1 1/2 2/3\n"    // v/vt form -> (5,0,1)
                               "f 1//1 2//1 3//1 5//1 4//1\n"  // pentagon -> (0,1,2) (0,2,4) (0,4,3)
                               "f -6 -5 -1\n");     // relative -> (0,1,5)
  const Scene s = load_scene(path);
  EXPECT_EQ(s.faces_read, 7);
  EXPECT_EQ(s.degenerate_dropped, 0);
  EXPECT_EQ(ids(s), (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(corners(s), (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {5, 0, 1}, {0, 1, 2}, {0, 2, 4}, {0, 4, 3}, {0, 1, 5}}));
  ASSERT_EQ(s.vertices.size(), 6u);
  EXPECT_EQ(s.vertices[4].x, 0.5);
  EXPECT_EQ(s.vertices[4].y, 1.5);
  EXPECT_EQ(s.index_of_id(6), 6);
}

TEST(LoadScene, DegenerateTrianglesDroppedAfterIdsAreFixed) {
  TempDir dir;
  // Face 1 (quad with a repeated vertex): fan (0,1,1) is degenerate, (0,1,2) is fine.
  // Face 2: three distinct collinear points (exactly: 1/3 steps are not representable, use 0, 2^-40, 1).
  const auto path = write_file(dir.file("deg.obj"),
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 9.094947017729282e-13 0 0\nv 1 1 1\n"
                               "f 1 2 2 3\n"
                               "f 1 4 2\n"
                               "f 1 2 5\n");
  testing::internal::CaptureStderr();
  const Scene s = load_scene(path);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(s.faces_read, 4);
  EXPECT_EQ(s.degenerate_dropped, 2);
  EXPECT_EQ(ids(s), (std::vector<std::int64_t>{1, 3}));
  EXPECT_EQ(corners(s), (std::vector<Tri>{{0, 1, 2}, {0, 1, 4}}));
  EXPECT_EQ(s.index_of_id(0), -1);
  EXPECT_EQ(s.index_of_id(2), -1);
  EXPECT_EQ(s.index_of_id(3), 1);
  EXPECT_NE(err.find(path + ": dropped 2 degenerate triangles"), std::string::npos) << err;
}

TEST(LoadScene, NearlyCollinearTriangleIsKept) {
  TempDir dir;
  // The third point is off the line by one unit in the last place: exact test keeps it.
  const auto path = write_file(dir.file("thin.obj"), "v 0 0 0\nv 1 1 1\nv 0.5 0.5 0.50000000000000011\nf 1 2 3\n");
  const Scene s = load_scene(path);
  EXPECT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.degenerate_dropped, 0);
}

TEST(LoadScene, ObjGroupsAreObjects) {
  TempDir dir;
  const auto path = write_file(dir.file("groups.obj"),
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                               "f 1 2 3\n"            // before any group: "default"
                               "g wall one\nf 1 2 4\n"
                               "o chair\nf 1 3 4\nf 2 3 4\n"
                               "g wall one\nf 1 2 3\n");  // same name again: same object
  const Scene s = load_scene(path);
  ASSERT_EQ(s.triangles.size(), 5u);
  EXPECT_EQ(object_names_per_triangle(s),
            (std::vector<std::string>{"default", "wall one", "chair", "chair", "wall one"}));
  EXPECT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.triangles[1].object, s.triangles[4].object);
}

TEST(LoadScene, ConnectedComponentsWithoutGroups) {
  TempDir dir;
  // Components: {t0, t2} share vertex 3 (index 2); t1 alone; t3 shares vertices with t1 -> {t1, t3}.
  const auto path = write_file(dir.file("cc.off"),
                               "OFF\n9 4 0\n"
                               "0 0 0\n1 0 0\n0 1 0\n"
                               "5 0 0\n6 0 0\n5 1 0\n"
                               "0 1 1\n1 1 1\n6 1 1\n"
                               "3 0 1 2\n3 3 4 5\n3 2 6 7\n3 4 5 8\n");
  const Scene s = load_scene(path);
  ASSERT_EQ(s.triangles.size(), 4u);
  EXPECT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.triangles[0].object, 0);
  EXPECT_EQ(s.triangles[1].object, 1);
  EXPECT_EQ(s.triangles[2].object, 0);
  EXPECT_EQ(s.triangles[3].object, 1);
  EXPECT_EQ(s.objects[0].name, "cc.off#component0");
}

TEST(LoadScene, CoordinatesAreExactDoubles) {
  TempDir dir;
  // OpenMesh parses float32; the scene must hold the doubles the text denotes.
  const auto obj = write_file(dir.file("c.obj"), "v 0.1 0.2 0.3\nv 1e-300 1 0\nv 0 0 123456789.123456789\nf 1 2 3\n");
  const auto off = write_file(dir.file("c.off"), "OFF\n# comment\n3 1 0\n0.1 0.2 0.3\n1e-300 1 0\n0 0 123456789.123456789\n3 0 1 2\n");
  for (const auto& path : {obj, off}) {
    const Scene s = load_scene(path);
    ASSERT_EQ(s.vertices.size(), 3u) << path;
    EXPECT_EQ(s.vertices[0].x, 0.1) << path;
    EXPECT_EQ(s.vertices[0].y, 0.2) << path;
    EXPECT_EQ(s.vertices[0].z, 0.3) << path;
    EXPECT_EQ(s.vertices[1].x, 1e-300) << path;
    EXPECT_EQ(s.vertices[2].z, 123456789.123456789) << path;
  }
}

TEST(LoadScene, NonManifoldFacesKeepFileVertexIds) {
  TempDir dir;
  // Three triangles on one edge (0,1): OpenMesh duplicates vertices for the third ("complex edge");
  // the scene must still refer to the file's vertices 0..5, and no face may be lost.
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n2 2 2\n";
  const auto off = write_file(dir.file("nm.off"),
                              "OFF\n6 5 0\n" + body + "3 0 1 2\n3 1 0 3\n3 0 1 4\n3 1 0 4\n3 2 5 4\n");
  std::string objtext;
  for (const char* l : {"0 0 0", "1 0 0", "0 1 0", "0 -1 0", "0 0 1", "2 2 2"}) objtext += std::string("v ") + l + "\n";
  objtext += "f 1 2 3\nf 2 1 4\nf 1 2 5\nf 2 1 5\nf 3 6 5\n";
  const auto obj = write_file(dir.file("nm.obj"), objtext);
  for (const auto& path : {off, obj}) {
    const Scene s = load_scene(path);
    EXPECT_EQ(s.vertices.size(), 6u) << path;
    EXPECT_EQ(corners(s), (std::vector<Tri>{{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {1, 0, 4}, {2, 5, 4}})) << path;
  }
}

TEST(LoadScene, BinaryPlyAndStl) {
  TempDir dir;
  // Binary PLY: 4 vertices, a quad and a triangle.
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const float pts[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.25f}};
  for (const auto& p : pts)
    for (float c : p) put_f32(ply, c);
  ply += static_cast<char>(4);
  for (std::uint32_t v : {0u, 1u, 2u, 3u}) put_u32(ply, v);
  ply += static_cast<char>(3);
  for (std::uint32_t v : {3u, 2u, 1u}) put_u32(ply, v);
  const Scene sp = load_scene(write_file(dir.file("b.ply"), ply));
  EXPECT_EQ(corners(sp), (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {3, 2, 1}}));
  EXPECT_EQ(sp.vertices[3].z, 0.25);

  // Binary STL: 3 facets, the middle one degenerate (repeated corner) -> id 1 absent.
  std::string stl(80, ' ');
  put_u32(stl, 3);
  const float facets[3][3][3] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                 {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}},
                                 {{1, 0, 0}, {0, 1, 0}, {0, 0, 2}}};
  for (const auto& f : facets) {
    for (int k = 0; k < 3; ++k) put_f32(stl, 0);  // normal
    for (const auto& c : f)
      for (float x : c) put_f32(stl, x);
    stl += std::string(2, '\0');
  }
  testing::internal::CaptureStderr();
  const Scene ss = load_scene(write_file(dir.file("b.stl"), stl));
  testing::internal::GetCapturedStderr();
  EXPECT_EQ(ss.faces_read, 3);
  EXPECT_EQ(ss.degenerate_dropped, 1);
  EXPECT_EQ(ids(ss), (std::vector<std::int64_t>{0, 2}));
  // STL vertices: equal positions merged in order of first appearance: (0,0,0) (1,0,0) (0,1,0) (0,0,2).
  EXPECT_EQ(corners(ss), (std::vector<Tri>{{0, 1, 2}, {1, 2, 3}}));
  EXPECT_EQ(ss.vertices.size(), 4u);
  EXPECT_EQ(ss.objects.size(), 1u);
}

TEST(LoadScene, AsciiStl) {
  TempDir dir;
  const auto path = write_file(dir.file("a.stl"),
                               "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
                               "   vertex 0 1 0\n  endloop\n endfacet\n facet normal 0 0 1\n  outer loop\n"
                               "   vertex 5 0 0\n   vertex 6 0 0\n   vertex 5 0.1 0\n  endloop\n endfacet\nendsolid t\n");
  const Scene s = load_scene(path);
  EXPECT_EQ(corners(s), (std::vector<Tri>{{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(s.vertices[5].y, 0.1);  // ASCII STL is re-read as exact doubles
  EXPECT_EQ(s.objects.size(), 2u);
}

// Generated scene -> each format -> load: the same triangles (by corner positions), ids 0..n-1; OBJ also
// keeps vertex indices and objects exactly.
TEST(LoadScene, AllFormatsRoundTrip) {
  TempDir dir;
  for (const std::string kind : {"town", "forest", "room"}) {
    const Scene g = generate_scene(kind, 400, 7);
    for (const std::string ext : {".obj", ".off", ".ply", ".stl"}) {
      const std::string path = dir.file(kind + ext);
      write_scene_mesh(path, g);
      const Scene s = load_scene(path);
      ASSERT_EQ(s.triangles.size(), g.triangles.size()) << kind << ext;
      EXPECT_EQ(s.degenerate_dropped, 0) << kind << ext;
      for (size_t i = 0; i < g.triangles.size(); ++i) {
        ASSERT_EQ(s.triangles[i].id, static_cast<std::int64_t>(i));
        for (int k = 0; k < 3; ++k) ASSERT_EQ(s.corner(s.triangles[i], k), g.corner(g.triangles[i], k)) << kind << ext;
      }
      if (ext == ".obj") {
        EXPECT_EQ(corners(s), corners(g));
        EXPECT_EQ(object_names_per_triangle(s), object_names_per_triangle(g));
        EXPECT_EQ(s.vertices.size(), g.vertices.size());
      }
    }
  }
  // Random triangles: not closed, no duplicated vertices in OpenMesh: every format keeps objects too.
  const Scene g = generate_scene("random", 200, 3);
  for (const std::string ext : {".off", ".ply"}) {
    write_scene_mesh(dir.file("r" + ext), g);
    const Scene s = load_scene(dir.file("r" + ext));
    EXPECT_EQ(corners(s), corners(g)) << ext;
    EXPECT_EQ(s.objects.size(), g.objects.size()) << ext;
  }
}

TEST(LoadScene, MultiFileScene) {
  TempDir dir;
  const auto a = write_file(dir.file("a.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\ng box\nf 1 2 3 4\n");
  const auto b = write_file(dir.file("b.off"), "OFF\n3 1 0\n5 5 5\n6 5 5\n5 6 5\n3 2 1 0\n");
  const Scene s = load_scenes({a, b});
  EXPECT_EQ(s.faces_read, 3);
  EXPECT_EQ(ids(s), (std::vector<std::int64_t>{0, 1, 2}));
  EXPECT_EQ(corners(s), (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {6, 5, 4}}));
  EXPECT_EQ(object_names_per_triangle(s), (std::vector<std::string>{"box", "box", "b.off#component0"}));
  EXPECT_EQ(s.vertices.size(), 7u);
  EXPECT_EQ(s.vertices[4].x, 5.0);
}

// OFF with per-face colours (RGB floats, RGBA, a colour-map index) and a COFF with vertex colours and
// comments, as CGAL's quint_tris.off and mesh_with_colors.off: the colours are not part of the face lists.
// OpenMesh read them as indices and lost every face after the first; its copy now holds only the indices.
TEST(LoadScene, OffFaceColoursAreAccepted) {
  TempDir dir;
  const Scene a = load_scene(write_file(dir.file("rgb.off"), "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                                             "3 0 1 2 .7 0 0 \n3 0 1 3 0.1 0.2 0.3 1.0\n3 1 2 3 4\n"));
  EXPECT_EQ(corners(a), (std::vector<Tri>{{0, 1, 2}, {0, 1, 3}, {1, 2, 3}}));
  const Scene b = load_scene(write_file(dir.file("coff.off"),
                                        "# a comment\nCOFF\n5 2 0\n\n0 0 0 0.9 0 0 #red\n1 0 0 0 0 0.9\n1 1 0 0 0 0.9\n"
                                        "0 1 0 0.9 0 0\n2 2 0 0 0 1\n3 0 1 3     0.9 0 0  #red\n4 1 4 2 3 0 0 0.9\n"));
  EXPECT_EQ(corners(b), (std::vector<Tri>{{0, 1, 3}, {1, 4, 2}, {1, 2, 3}}));
  EXPECT_EQ(b.vertices[4].x, 2.0);
  // CGAL's own files (libcgal-demo ships them in a tarball), when the tarball is there.
  const std::string tarball = "/usr/share/doc/libcgal-demo/data.tar.gz";
  if (!std::filesystem::exists(tarball)) GTEST_SKIP() << "libcgal-demo data not installed";
  const std::string cmd = "tar -xzf " + tarball + " -C " + dir.path.string() +
                          " data/meshes/quint_tris.off data/meshes/mesh_with_colors.off 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const Scene q = load_scene(dir.file("data/meshes/quint_tris.off"));
  EXPECT_EQ(q.faces_read, 20);
  EXPECT_EQ(q.vertices.size(), 12u);
  EXPECT_EQ(q.triangles[0].v, (Tri{0, 1, 10}));
  const Scene m = load_scene(dir.file("data/meshes/mesh_with_colors.off"));
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.faces_read, 3 + 3);  // three triangles and a pentagon (3 fan triangles)
}

// One rule for coordinates beyond float32's range, in every format: accepted, exact (our parsers read them;
// OpenMesh, which reads float32 and stops at such a value, gets stand-ins and only has to agree on the
// connectivity); beyond the double range they are refused with the same message.
TEST(LoadScene, CoordinatesBeyondFloat32InEveryFormat) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> files = {
      {"b.obj", "v 0 0 0\nv 1e39 0 0\nvn 0 0 1e39\nv 0 -1e308 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n"},
      {"b.off", "OFF\n4 2 0\n0 0 0\n1e39 0 0\n0 -1e308 0\n0 0 1\n3 0 1 2\n3 0 2 3\n"},
      {"b.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                "0 0 0\n1e39 0 0\n0 -1e308 0\n0 0 1\n3 0 1 2\n3 0 2 3\n"},
      {"b.stl", "solid b\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1e39 0 0\nvertex 0 -1e308 0\nendloop\n"
                "endfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0 -1e308 0\nvertex 0 0 1\nendloop\n"
                "endfacet\nendsolid b\n"}};
  for (const auto& [name, text] : files) {
    SCOPED_TRACE(name);
    const Scene s = load_scene(write_file(dir.file(name), text));
    ASSERT_EQ(s.vertices.size(), 4u);
    EXPECT_EQ(s.vertices[1].x, 1e39);
    EXPECT_EQ(s.vertices[2].y, -1e308);
    EXPECT_EQ(corners(s), (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}}));
  }
  for (const auto& [name, text] : files) {
    std::string t = text;
    t.replace(t.find("1e39"), 4, "1e400");
    try {
      load_scene(write_file(dir.file("x" + name), t));
      ADD_FAILURE() << name << ": 1e400 accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("non-finite coordinate '1e400' (beyond the range of doubles"),
                std::string::npos)
          << e.what();
    }
  }
}

// A UTF-8 byte-order mark is skipped in every format: the same scene as without it.
TEST(LoadScene, Utf8ByteOrderMarkIsSkipped) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> files = {
      {"m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"m.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
      {"m.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
      {"m.stl", "solid m\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
                "endfacet\nendsolid m\n"}};
  for (const auto& [name, text] : files) {
    SCOPED_TRACE(name);
    const Scene plain = load_scene(write_file(dir.file(name), text));
    const Scene bom = load_scene(write_file(dir.file("bom" + name), "\xEF\xBB\xBF" + text));
    EXPECT_EQ(corners(bom), corners(plain));
    EXPECT_EQ(bom.vertices.size(), 3u);
    EXPECT_EQ(bom.vertices[1].x, 1.0);
  }
}
