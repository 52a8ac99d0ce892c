// PVS JSON (io/pvs_json.hpp): the CELL shape with exact boxes and stable ids, run stats as sums, documents
// sorted by cell, and JSON-lines files read back with an interrupted last line ignored.
#include "io/load_scene.hpp"
#include "io/pvs_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace exactvis;
namespace fs = std::filesystem;

namespace {

Scene two_triangles() {
  Scene s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  s.objects = {{"a"}, {"b"}};
  s.triangles = {{3, {0, 1, 2}, 0}, {7, {0, 1, 3}, 1}};  // ids 3 and 7
  return s;
}

TEST(PvsJson, CellShapeAndDocument) {
  const Scene scene = two_triangles();
  region::CellPvs pvs;
  pvs.cell = {{Exact(1, 3), Exact(0), Exact(0)}, {Exact(1), Exact(1), Exact(1)}};
  pvs.visible.push_back({1, region::Witness{{Exact(1), Exact(1, 2), Exact(0)}, {Exact(1, 4), Exact(0), Exact(1, 3)}}});
  pvs.stats.triangles = 2;
  pvs.stats.visible = 1;
  pvs.stats.accepted_by_rays = 1;
  const OrderedJson c = pvs_cell_json(scene, 4, pvs, true);
  EXPECT_EQ(c.dump(),
            R"({"cell":4,"box":["1/3",0.0,0.0,1.0,1.0,1.0],"visible":[7],"objects":["b"],)"
            R"("witnesses":{"7":[[1.0,0.5,0.0],[0.25,0.0,"1/3"]]},"stats":{"triangles":2,"visible":1,)"
            R"("accepted_by_rays":1,"exact_queries":0,"culled":0,"stabbing_pairs":0,"occluders_considered":0,)"
            R"("splits":0,"cones_created":0,"real_line_tests":0}})");
  EXPECT_FALSE(pvs_cell_json(scene, 4, pvs, false).contains("witnesses"));
  OrderedJson c0 = pvs_cell_json(scene, 0, pvs, false);
  const OrderedJson doc = pvs_document("s.obj", 2, {c, c0});
  EXPECT_EQ(doc["cells"][0]["cell"], 0);
  EXPECT_EQ(doc["cells"][1]["cell"], 4);
  EXPECT_EQ(doc["stats"]["cells"], 2);
  EXPECT_EQ(doc["stats"]["visible"], 2);
  EXPECT_EQ(doc.begin().key(), "scene");
  EXPECT_FALSE(doc.contains("shard"));
}

TEST(PvsJson, LinesReadBackIgnoringAnInterruptedLastLine) {
  const fs::path p = fs::temp_directory_path() / ("exactvis_pvs_lines_" + std::to_string(::getpid()) + ".jsonl");
  const std::string header = pvs_lines_header("s.obj", 2, 3, "exact", true).dump();
  {
    std::ofstream out(p);
    out << header << "\n" << R"({"cell":2,"box":[0,0,0,1,1,1],"visible":[]})" << "\n" << R"({"cell":0,"box":[0,0)";
  }
  const PvsLines lines = read_pvs_lines(p.string());
  EXPECT_EQ(lines.header.dump(), header);
  ASSERT_EQ(lines.cells.size(), 1u);
  EXPECT_TRUE(lines.cells.count(2));
  EXPECT_EQ(lines.valid_bytes, header.size() + 1 + std::string(R"({"cell":2,"box":[0,0,0,1,1,1],"visible":[]})").size() + 1);
  {
    std::ofstream out(p);
    out << header << "\n" << "garbage\n" << R"({"cell":0,"visible":[]})" << "\n";
  }
  EXPECT_THROW(read_pvs_lines(p.string()), InputError);
  {
    std::ofstream out(p);
    out << header << "\n" << R"({"cell":3,"visible":[]})" << "\n";  // out of range
  }
  EXPECT_THROW(read_pvs_lines(p.string()), InputError);
  {
    std::ofstream out(p);
    out << R"({"cell":0,"visible":[]})" << "\n";  // no header
  }
  EXPECT_THROW(read_pvs_lines(p.string()), InputError);
  fs::remove(p);
}

}  // namespace
