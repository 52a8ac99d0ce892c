// The Quake 3 BSP reader: round trip of a map written by the tests' own writer (every field back as written,
// the visdata bits as chosen), .pk3 archives (exact and short member names, one or several maps, a bad
// checksum), every kind of bad file (one-line "FILE: problem" errors), and random corruptions of a valid
// file (an InputError or a valid map, never a crash). On Debian's openarena-data, when installed: every map
// reads.
#include "io/quake3_bsp.hpp"

#include "bsp_test_writer.hpp"
#include "io/load_scene.hpp"
#include "io_test_util.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <random>

using namespace exactvis;
using namespace exactvis::quake3;
using iotest::TempDir;
using iotest::write_file;

namespace {

// Reading must fail with one line "BLAME: ..." containing `words`; returns the message.
std::string expect_bad(const std::string& source, const std::string& blame, const std::string& words) {
  try {
    read_bsp(source);
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(blame + ": ", 0), 0u) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_NE(msg.find(words), std::string::npos) << "expected \"" << words << "\" in: " << msg;
    return msg;
  } catch (const std::exception& e) {
    ADD_FAILURE() << source << ": wrong exception type: " << e.what();
    return "";
  }
  ADD_FAILURE() << source << ": read without error (expected \"" << words << "\")";
  return "";
}

// Writes the doorway map changed by `edit` and expects the error.
void expect_bad_map(const TempDir& dir, const std::string& name, const std::function<void(bsptest::Bsp&)>& edit,
                    const std::string& words) {
  bsptest::Bsp b = bsptest::doorway_map().bsp;
  edit(b);
  const std::string path = write_file(dir.file(name + ".bsp"), b.bytes());
  SCOPED_TRACE(name);
  expect_bad(path, path, words);
}

const char* kOpenArena = "/usr/share/games/openarena";

}  // namespace

TEST(Quake3Bsp, RoundTripOfTheDoorwayMap) {
  TempDir dir;
  const bsptest::Bsp b = bsptest::doorway_map().bsp;
  const std::string path = write_file(dir.file("doorway.bsp"), b.bytes());
  const BspMap map = read_bsp(path);
  EXPECT_EQ(map.source, path);
  EXPECT_EQ(map.version, 46);
  EXPECT_EQ(map.entities, b.entities);
  ASSERT_EQ(map.shaders.size(), b.shaders.size());
  for (std::size_t i = 0; i < b.shaders.size(); ++i) {
    EXPECT_EQ(map.shaders[i].name, b.shaders[i].name);
    EXPECT_EQ(map.shaders[i].surface_flags, b.shaders[i].surface);
    EXPECT_EQ(map.shaders[i].content_flags, b.shaders[i].contents);
  }
  ASSERT_EQ(map.planes.size(), b.planes.size());
  for (std::size_t i = 0; i < b.planes.size(); ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(map.planes[i].normal[k], b.planes[i].n[k]);
    EXPECT_EQ(map.planes[i].dist, b.planes[i].d);
  }
  ASSERT_EQ(map.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < b.nodes.size(); ++i) {
    EXPECT_EQ(map.nodes[i].plane, b.nodes[i].plane);
    EXPECT_EQ(map.nodes[i].children[0], b.nodes[i].front);
    EXPECT_EQ(map.nodes[i].children[1], b.nodes[i].back);
  }
  ASSERT_EQ(map.leaves.size(), b.leaves.size());
  for (std::size_t i = 0; i < b.leaves.size(); ++i) {
    EXPECT_EQ(map.leaves[i].cluster, b.leaves[i].cluster);
    EXPECT_EQ(map.leaves[i].first_leaf_brush, b.leaves[i].first_brush);
    EXPECT_EQ(map.leaves[i].n_leaf_brushes, b.leaves[i].n_brushes);
    EXPECT_EQ(map.leaves[i].first_leaf_face, b.leaves[i].first_face);
    EXPECT_EQ(map.leaves[i].n_leaf_faces, b.leaves[i].n_faces);
  }
  EXPECT_EQ(map.leaf_brushes, b.leaf_brushes);
  EXPECT_EQ(map.leaf_faces, b.leaf_faces);
  EXPECT_EQ(map.mesh_vertices, b.mesh_vertices);
  ASSERT_EQ(map.models.size(), 2u);
  EXPECT_EQ(map.models[0].maxs[0], 256.0f);
  EXPECT_EQ(map.models[1].first_brush, 4);
  ASSERT_EQ(map.brushes.size(), b.brushes.size());
  ASSERT_EQ(map.brush_sides.size(), b.sides.size());
  for (std::size_t i = 0; i < b.sides.size(); ++i) EXPECT_EQ(map.brush_sides[i].plane, b.sides[i].plane);
  ASSERT_EQ(map.vertices.size(), b.vertices.size());
  EXPECT_EQ(map.vertices[6].position[2], 10.5f);
  ASSERT_EQ(map.faces.size(), b.faces.size());
  EXPECT_EQ(map.faces[2].type, kFacePatch);
  EXPECT_EQ(map.faces[2].patch_size[0], 3);
  // World leaves: 1-7; leaf 0 (unused) and 8 (a brush model's) are outside the tree.
  const std::vector<bool> world{false, true, true, true, true, true, true, true, false};
  EXPECT_EQ(map.world_leaf, world);
  EXPECT_EQ(map.cluster_count(), 4);
  EXPECT_EQ(map.vis.sz_vecs, 8);
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(map.cluster_visible(a, c), bsptest::DoorwayMap::visible(a, c)) << a << " " << c;
  EXPECT_THROW(map.cluster_visible(4, 0), std::out_of_range);
  EXPECT_THROW(map.cluster_visible(0, -1), std::out_of_range);
}

TEST(Quake3Bsp, WithoutVisdataEverythingIsVisible) {
  TempDir dir;
  bsptest::Bsp b = bsptest::doorway_map().bsp;
  b.has_vis = false;
  const BspMap map = read_bsp(write_file(dir.file("novis.bsp"), b.bytes()));
  EXPECT_EQ(map.vis.n_vecs, 0);
  EXPECT_EQ(map.cluster_count(), 4);  // from the world leaves' clusters
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) EXPECT_TRUE(map.cluster_visible(a, c));
}

TEST(Quake3Bsp, Pk3Archives) {
  TempDir dir;
  const std::string bytes = bsptest::doorway_map().bsp.bytes();
  const std::string one = write_file(dir.file("one.pk3"), bsptest::zip_stored({{"maps/", ""}, {"maps/Doorway.bsp", bytes}}));
  const std::string two = write_file(
      dir.file("two.pk3"),
      bsptest::zip_stored({{"levelshots/a.tga", "xx"}, {"maps/a.bsp", bytes}, {"maps/b.BSP", bytes}}));
  // One map: the archive alone, the exact member, the short forms (any case).
  EXPECT_EQ(read_bsp(one).source, one + ":maps/Doorway.bsp");
  EXPECT_EQ(read_bsp(one + ":maps/Doorway.bsp").cluster_count(), 4);
  EXPECT_EQ(read_bsp(one + ":doorway").source, one + ":maps/Doorway.bsp");
  EXPECT_EQ(read_bsp(one + ":DOORWAY.bsp").source, one + ":maps/Doorway.bsp");
  EXPECT_EQ(bsp_sources(one), std::vector<std::string>{one + ":maps/Doorway.bsp"});
  // Several maps: bsp_sources lists them; the archive alone is ambiguous.
  EXPECT_EQ(bsp_sources(two), (std::vector<std::string>{two + ":maps/a.bsp", two + ":maps/b.BSP"}));
  EXPECT_EQ(read_bsp(two + ":b").source, two + ":maps/b.BSP");
  expect_bad(two, two, "holds 2 maps");
  expect_bad(two + ":c", two + ":c", "no such map");
  expect_bad(dir.file("missing.pk3") + ":a", dir.file("missing.pk3"), "no such file");
  // A member's error names the member.
  const std::string broken = write_file(dir.file("broken.pk3"), bsptest::zip_stored({{"maps/x.bsp", bytes.substr(0, 100)}}));
  expect_bad(broken, broken + ":maps/x.bsp", "truncated");
  // A bad checksum, a truncated archive, an archive without maps.
  const std::string crc = write_file(dir.file("crc.pk3"), bsptest::zip_stored({{"maps/x.bsp", bytes}}, 0));
  expect_bad(crc, crc + ":maps/x.bsp", "decompress");
  const std::string full = bsptest::zip_stored({{"maps/x.bsp", bytes}});
  const std::string cut = write_file(dir.file("cut.pk3"), full.substr(0, full.size() / 2));
  expect_bad(cut + ":x", cut, "zip archive");
  const std::string none = write_file(dir.file("none.pk3"), bsptest::zip_stored({{"readme.txt", "hi"}}));
  expect_bad(none, none, "holds no map");
  EXPECT_THROW(bsp_sources(none), InputError);
  // A plain BSP named .pk3 is read by its content.
  const std::string plain = write_file(dir.file("plain.pk3"), bytes);
  EXPECT_EQ(read_bsp(plain).source, plain);
}

TEST(Quake3Bsp, BadHeaders) {
  TempDir dir;
  const std::string good = bsptest::doorway_map().bsp.bytes();
  auto bad = [&](const std::string& name, const std::string& bytes, const std::string& words) {
    const std::string path = write_file(dir.file(name), bytes);
    SCOPED_TRACE(name);
    expect_bad(path, path, words);
  };
  bad("empty.bsp", "", "truncated");
  bad("header.bsp", good.substr(0, 100), "truncated");
  bad("half.bsp", good.substr(0, good.size() / 2), "runs past the end");
  bad("lastbyte.bsp", good.substr(0, good.size() - 1), "runs past the end");
  std::string magic = good;
  magic[0] = 'V';
  bad("magic.bsp", magic, "magic");
  std::string version = good;
  bsptest::set_i32(version, 4, 47);
  bad("version.bsp", version, "version 47");
  bad("missing.bsp", "", "truncated");
  expect_bad(dir.file("absent.bsp"), dir.file("absent.bsp"), "no such file");
  expect_bad_map(dir, "negative_offset", [](bsptest::Bsp& b) { b.directory_override.push_back({2, {-8, 16}}); },
                 "negative offset");
  expect_bad_map(dir, "offset_past_end", [](bsptest::Bsp& b) { b.directory_override.push_back({3, {1 << 30, 36}}); },
                 "runs past the end");
  expect_bad_map(dir, "length_past_end", [](bsptest::Bsp& b) { b.directory_override.push_back({0, {144, 1 << 30}}); },
                 "runs past the end");
  expect_bad_map(dir, "negative_length", [](bsptest::Bsp& b) { b.directory_override.push_back({5, {144, -4}}); },
                 "negative");
  expect_bad_map(dir, "planes_not_multiple", [](bsptest::Bsp& b) { b.directory_override.push_back({2, {144, 17}}); },
                 "not a multiple of its entry size 16");
  expect_bad_map(dir, "faces_not_multiple", [](bsptest::Bsp& b) { b.directory_override.push_back({13, {144, 100}}); },
                 "not a multiple of its entry size 104");
}

TEST(Quake3Bsp, BadIndices) {
  TempDir dir;
  using B = bsptest::Bsp;
  expect_bad_map(dir, "node_plane", [](B& b) { b.nodes[2].plane = 999; }, "node 2: plane 999 out of range");
  expect_bad_map(dir, "node_plane_negative", [](B& b) { b.nodes[0].plane = -1; }, "node 0: plane -1 out of range");
  expect_bad_map(dir, "child_node", [](B& b) { b.nodes[1].front = 6; }, "node 1: front child node 6 out of range");
  expect_bad_map(dir, "child_leaf", [](B& b) { b.nodes[4].back = -(9 + 1); }, "node 4: back child leaf 9 out of range");
  expect_bad_map(dir, "cycle", [](B& b) { b.nodes[5].front = 1; }, "child node 1 is reached twice");
  expect_bad_map(dir, "root_cycle", [](B& b) { b.nodes[3].front = 0; }, "child node 0 is reached twice");
  expect_bad_map(dir, "shared_node", [](B& b) { b.nodes[1].front = 2; }, "child node 2 is reached twice");
  expect_bad_map(dir, "shared_leaf", [](B& b) { b.nodes[5].front = -(5 + 1); }, "leaf 5 is reached twice");
  expect_bad_map(dir, "leaf_faces", [](B& b) { b.leaves[1].n_faces = 3; }, "leaf 1: leaf faces");
  expect_bad_map(dir, "leaf_brushes", [](B& b) { b.leaves[4].first_brush = 3, b.leaves[4].n_brushes = 2; },
                 "leaf 4: leaf brushes");
  expect_bad_map(dir, "leaf_brush_negative", [](B& b) { b.leaves[4].n_brushes = -1; }, "leaf 4: leaf brushes");
  expect_bad_map(dir, "leaf_face_index", [](B& b) { b.leaf_faces[1] = 4; }, "leaf face 1: face 4 out of range");
  expect_bad_map(dir, "leaf_brush_index", [](B& b) { b.leaf_brushes[3] = -2; }, "leaf brush 3: brush -2 out of range");
  expect_bad_map(dir, "cluster", [](B& b) { b.leaves[7].cluster = -2; }, "leaf 7: cluster -2");
  expect_bad_map(dir, "no_leaves", [](B& b) { b.leaves.clear(), b.nodes.clear(); }, "no leaves");
  expect_bad_map(dir, "no_models", [](B& b) { b.models.clear(); }, "no models");
  expect_bad_map(dir, "model_brushes", [](B& b) { b.models[1].n_brushes = 2; }, "model 1: brushes");
  expect_bad_map(dir, "model_faces", [](B& b) { b.models[0].first_face = -1; }, "model 0: faces");
  expect_bad_map(dir, "model_bounds", [](B& b) { b.models[0].mins[2] = 500; }, "model 0: bounds");
  expect_bad_map(dir, "brush_sides", [](B& b) { b.brushes[4].n_sides = 7; }, "brush 4: sides");
  expect_bad_map(dir, "brush_shader", [](B& b) { b.brushes[0].shader = 4; }, "brush 0: shader 4 out of range");
  expect_bad_map(dir, "side_plane", [](B& b) { b.sides[5].plane = 1000; }, "brush side 5: plane 1000 out of range");
  expect_bad_map(dir, "side_shader", [](B& b) { b.sides[0].shader = -1; }, "brush side 0: shader -1 out of range");
  expect_bad_map(dir, "face_shader", [](B& b) { b.faces[0].shader = 9; }, "face 0: shader 9 out of range");
  expect_bad_map(dir, "face_effect", [](B& b) { b.faces[1].effect = 0; }, "face 1: effect 0 out of range");
  expect_bad_map(dir, "face_type", [](B& b) { b.faces[1].type = 5; }, "face 1: unknown type 5");
  expect_bad_map(dir, "face_vertices", [](B& b) { b.faces[0].n_vertices = 100; }, "face 0: vertices");
  expect_bad_map(dir, "face_mesh", [](B& b) { b.faces[1].first_mesh = 7; }, "face 1: mesh vertices");
  expect_bad_map(dir, "face_mesh_partial", [](B& b) { b.faces[0].n_mesh = 5; }, "not whole triangles");
  expect_bad_map(dir, "mesh_offset", [](B& b) { b.mesh_vertices[2] = 4; }, "face 0: mesh vertex offset 4 out of range");
  expect_bad_map(dir, "patch_size", [](B& b) { b.faces[2].size[1] = 4; }, "face 2: patch of 3 x 4");
  expect_bad_map(dir, "plane_nan", [](B& b) { b.planes[3].d = std::nanf(""); }, "plane 3: non-finite");
  expect_bad_map(dir, "plane_inf", [](B& b) { b.planes[0].n[1] = INFINITY; }, "plane 0: non-finite");
  expect_bad_map(dir, "plane_zero", [](B& b) { b.planes[2] = {{0, 0, 0}, 1}; }, "plane 2: zero normal");
  expect_bad_map(dir, "vertex_nan", [](B& b) { b.vertices[3].p[0] = std::nanf(""); }, "vertex 3: non-finite");
  expect_bad_map(dir, "model_nan", [](B& b) { b.models[0].maxs[0] = INFINITY; }, "model 0: non-finite");
}

TEST(Quake3Bsp, BadVisdata) {
  TempDir dir;
  using B = bsptest::Bsp;
  expect_bad_map(dir, "vis_short", [](B& b) { b.directory_override.push_back({16, {144, 4}}); }, "shorter than its 8-byte header");
  expect_bad_map(dir, "vis_size", [](B& b) { b.n_vecs = 5; }, "does not hold 8 + n_vecs * sz_vecs = 8 + 5 * 8");
  expect_bad_map(dir, "vis_huge", [](B& b) { b.n_vecs = 1 << 30, b.sz_vecs = 1 << 30; }, "does not hold");
  expect_bad_map(dir, "vis_negative", [](B& b) { b.n_vecs = -4, b.sz_vecs = -8; }, "negative n_vecs");
  expect_bad_map(dir, "vis_rows", [](B& b) { b.set_vis(20, 2, [](int, int) { return true; }); },
                 "rows of 2 bytes are too short for 20 clusters");
  expect_bad_map(dir, "novis_cluster", [](B& b) { b.has_vis = false, b.leaves[6].cluster = 1 << 30; },
                 "leaf 6: cluster 1073741824 out of range: without visdata");
  expect_bad_map(dir, "vis_clusters", [](B& b) { b.set_vis(3, 1, [](int, int) { return true; }); },
                 "leaf 7: cluster 3 out of range of the visdata's 3 clusters");
}

// Random corruptions (fixed seed): a flipped byte, a random 32-bit word, or a truncation. The reader must
// give a valid map or an InputError, nothing else.
TEST(Quake3Bsp, CorruptionsGiveInputErrorsOrValidMaps) {
  TempDir dir;
  const std::string good = bsptest::doorway_map().bsp.bytes();
  std::mt19937_64 rng(2024);
  int errors = 0, valid = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    std::string bytes = good;
    const int kind = static_cast<int>(rng() % 3);
    const std::size_t at = rng() % bytes.size();
    if (kind == 0) bytes[at] = static_cast<char>(bytes[at] ^ (1 << (rng() % 8)));
    else if (kind == 1 && at + 4 <= bytes.size()) bsptest::set_i32(bytes, at & ~std::size_t(3), static_cast<std::int32_t>(rng()));
    else bytes.resize(at);
    try {
      const BspMap map = parse_bsp(bytes, "corrupt.bsp");
      ++valid;
      // What the reader accepts is safe to use: visdata queries in range.
      for (int a = 0; a < map.cluster_count() && a < 8; ++a) map.cluster_visible(a, map.cluster_count() - 1);
    } catch (const InputError& e) {
      ++errors;
      EXPECT_EQ(std::string(e.what()).rfind("corrupt.bsp: ", 0), 0u) << e.what();
    }
  }
  EXPECT_GT(errors, 300);
  EXPECT_GT(valid, 300);  // most flipped bytes land in coordinates, names and bounds
}

TEST(Quake3Bsp, OpenArenaMapsRead) {
  std::error_code ec;
  if (!std::filesystem::is_directory(kOpenArena, ec)) GTEST_SKIP() << "openarena-data is not installed";
  int maps = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(kOpenArena, ec)) {
    if (e.path().extension() != ".pk3") continue;
    std::vector<std::string> sources;
    try {
      sources = bsp_sources(e.path().string());
    } catch (const InputError&) {
      continue;  // an archive without maps
    }
    for (const std::string& s : sources) {
      SCOPED_TRACE(s);
      const BspMap map = read_bsp(s);
      ++maps;
      EXPECT_GT(map.cluster_count(), 0);
      EXPECT_FALSE(map.world_leaf[0]);  // q3map2's unused leaf 0
      for (int c = 0; c < map.cluster_count(); ++c) EXPECT_TRUE(map.cluster_visible(c, c));
    }
  }
  EXPECT_GT(maps, 50);
}
