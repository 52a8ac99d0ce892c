// The `info`, `generate` and `export` subcommands, run as a user would: exit codes, output, and no output
// file after an error.
#include "io/load_scene.hpp"
#include "kernel/scene_generators.hpp"
#include "io_test_util.hpp"
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>

using iotest::TempDir;

namespace {

using cli_test::CliRun;

CliRun run(const TempDir& dir, const std::string& args) { return cli_test::run_exactvis(dir.path, args); }

bool exists(const std::string& p) { return std::filesystem::exists(p); }

}  // namespace

TEST(Cli, GenerateInfoExport) {
  TempDir dir;
  const std::string obj = dir.file("town.obj"), vtp = dir.file("town.vtp");
  CliRun g = run(dir, "generate town --triangles 500 --seed 3 -o " + obj);
  ASSERT_EQ(g.status, 0) << g.err;
  // Independent of the CLI: the file loads to the generator's scene.
  const exactvis::Scene expected = exactvis::generate_scene("town", 500, 3);
  const exactvis::Scene loaded = exactvis::load_scene(obj);
  EXPECT_EQ(loaded.triangles.size(), expected.triangles.size());
  EXPECT_EQ(loaded.objects.size(), expected.objects.size());

  CliRun i = run(dir, "info " + obj + " --json");
  ASSERT_EQ(i.status, 0) << i.err;
  const auto j = nlohmann::json::parse(i.out);
  EXPECT_EQ(j["triangles"], 500);
  EXPECT_EQ(j["objects"], expected.objects.size());
  EXPECT_EQ(j["vertices"], expected.vertices.size());
  EXPECT_EQ(j["faces_read"], 500);
  EXPECT_EQ(j["degenerate_dropped"], 0);
  const exactvis::Box3 box = exactvis::bounding_box(expected);
  EXPECT_EQ(j["bounding_box"]["min"][0].get<double>(), box.lo.x);
  EXPECT_EQ(j["bounding_box"]["max"][2].get<double>(), box.hi.z);

  CliRun t = run(dir, "info " + obj);
  ASSERT_EQ(t.status, 0);
  EXPECT_NE(t.out.find("triangles:          500"), std::string::npos) << t.out;

  CliRun e = run(dir, "export " + obj + " " + obj + " -o " + vtp);  // two files -> one scene of 1000
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_TRUE(exists(vtp));
  EXPECT_NE(e.err.find("1000 triangles"), std::string::npos) << e.err;

  for (const char* ext : {".off", ".ply", ".stl"}) {
    const std::string p = dir.file(std::string("forest") + ext);
    ASSERT_EQ(run(dir, "generate forest -n 300 -s 1 -o " + p).status, 0) << ext;
    CliRun r = run(dir, "info --json " + p);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], 300) << ext;
  }
  for (const char* sub : {"", "info", "generate", "export"}) {
    CliRun h = run(dir, std::string(sub) + " --help");
    EXPECT_EQ(h.status, 0) << sub;
    EXPECT_FALSE(h.out.empty()) << sub;
  }
}

TEST(Cli, BadParametersFailCleanlyWithoutOutput) {
  TempDir dir;
  const std::string out = dir.file("x.obj");
  const std::vector<std::string> bad = {
      "generate town --triangles 0 -o " + out,
      "generate town --triangles -5 -o " + out,
      "generate town --triangles 5 -o " + out,
      "generate town --triangles abc -o " + out,
      "generate castle --triangles 100 -o " + out,
      "generate town --triangles 100",  // no output
      "generate town --triangles 100 -o " + dir.file("x.xyz"),
      "generate town --triangles 100 -o " + dir.file("no/such/dir/x.obj"),
      "generate town --triangles 100 --seed -3 -o " + out,
  };
  for (const auto& args : bad) {
    CliRun r = run(dir, args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_FALSE(r.err.empty()) << args;
    EXPECT_EQ(iotest::entries(dir.path), 0) << args << ": left a file";
  }
}

TEST(Cli, BadScenesFailCleanlyWithoutOutput) {
  TempDir dir;
  const std::string vtp = dir.file("out.vtp");
  const std::string broken = iotest::write_file(dir.file("broken.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
  const std::string good = iotest::write_file(dir.file("good.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  for (const std::string& args : std::vector<std::string>{"info " + broken, "info " + dir.file("missing.obj"), "info --json " + broken,
                                  "export " + broken + " -o " + vtp, "export " + good + " " + broken + " -o " + vtp,
                                  "export " + good + " -o " + dir.file("out.txt"),
                                  "export " + good + " -o " + dir.file("nodir/out.vtp"), "info", "nonsense"}) {
    CliRun r = run(dir, args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_FALSE(exists(vtp)) << args;
    EXPECT_FALSE(exists(dir.file("out.txt"))) << args;
    EXPECT_EQ(iotest::entries(dir.path), 2) << args;
  }
  CliRun r = run(dir, "info " + broken);
  // One line: "exactvis info: error: FILE: problem".
  EXPECT_EQ(r.err, "exactvis info: error: " + broken + ": line 3: vertex index 3 out of range (file has 2 vertices)\n")
      << r.err;
}

// Broken files as a user meets them, through `exactvis info`: assimp's invalid models and the inputs that
// crashed, hung or misled before (huge PLY list counts, UTF-16 text). One line "exactvis info: error: FILE:
// problem", exit status 1 (not a signal).
TEST(Cli, BrokenFilesThroughInfo) {
  TempDir dir;
  std::vector<std::string> files;
  const std::filesystem::path assimp = "/usr/share/assimp/models/invalid";
  if (std::filesystem::exists(assimp))
    for (const auto& e : std::filesystem::directory_iterator(assimp))
      if (e.path().extension() != ".txt") files.push_back(e.path().string());
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n";
  files.push_back(iotest::write_file(dir.file("huge.ply"), head + "property list uchar int vertex_indices\nend_header\n"
                                                                  "0 0 0\n1 0 0\n0 1 0\n4294967296 0 1 2\n"));
  files.push_back(iotest::write_file(dir.file("c256.ply"), head + "property list uchar int vertex_indices\nend_header\n"
                                                                  "0 0 0\n1 0 0\n0 1 0\n256 0 1 2\n"));
  files.push_back(iotest::write_file(dir.file("u16.obj"), std::string("\xFF\xFEv\0 \0" "0\0", 8)));
  for (const std::string& f : files) {
    const CliRun r = run(dir, "info " + f);
    EXPECT_EQ(r.status, 1) << f << ": " << r.err;
    EXPECT_EQ(r.err.rfind("exactvis info: error: " + f + ": ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_GE(files.size(), 3u);
}
