// VTK round trip: write with our writers, read back with VTK's own vtkXMLPolyDataReader, compare exactly.
// Failed writes leave no file (and no temporary file) behind.
#include "io/atomic_file.hpp"
#include "io/write_mesh.hpp"
#include "io/write_vtp.hpp"
#include "kernel/scene_generators.hpp"
#include "io_test_util.hpp"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>

using namespace exactvis;
using iotest::TempDir;

namespace {

vtkSmartPointer<vtkPolyData> read_vtp(const std::string& path) {
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> out = reader->GetOutput();
  return out;
}

}  // namespace

TEST(WriteVtp, SceneRoundTrip) {
  TempDir dir;
  const Scene s = generate_scene("town", 1500, 4);
  CellArrays extra;
  IntArray vis{"visible", {}};
  DoubleArray area{"weight", {}};
  for (size_t i = 0; i < s.triangles.size(); ++i) {
    vis.values.push_back(static_cast<std::int64_t>(i % 3) - 1);
    area.values.push_back(static_cast<double>(i) / 7.0);  // not dyadic: checks doubles are stored bit-exactly
  }
  extra.ints.push_back(vis);
  extra.doubles.push_back(area);
  const std::string path = dir.file("town.vtp");
  write_scene_vtp(path, s, extra);
  auto poly = read_vtp(path);
  ASSERT_EQ(poly->GetNumberOfPoints(), static_cast<vtkIdType>(s.vertices.size()));
  ASSERT_EQ(poly->GetNumberOfPolys(), static_cast<vtkIdType>(s.triangles.size()));
  for (size_t i = 0; i < s.vertices.size(); ++i) {
    double p[3];
    poly->GetPoint(static_cast<vtkIdType>(i), p);
    ASSERT_EQ(p[0], s.vertices[i].x);
    ASSERT_EQ(p[1], s.vertices[i].y);
    ASSERT_EQ(p[2], s.vertices[i].z);
  }
  vtkDataArray* id = poly->GetCellData()->GetArray("id");
  vtkDataArray* object = poly->GetCellData()->GetArray("object");
  vtkDataArray* visible = poly->GetCellData()->GetArray("visible");
  vtkDataArray* weight = poly->GetCellData()->GetArray("weight");
  ASSERT_TRUE(id && object && visible && weight);
  vtkCellArray* polys = poly->GetPolys();
  polys->InitTraversal();
  vtkNew<vtkIdList> cell;
  for (size_t i = 0; i < s.triangles.size(); ++i) {
    ASSERT_TRUE(polys->GetNextCell(cell));
    ASSERT_EQ(cell->GetNumberOfIds(), 3);
    for (int k = 0; k < 3; ++k) ASSERT_EQ(cell->GetId(k), s.triangles[i].v[k]);
    ASSERT_EQ(id->GetTuple1(static_cast<vtkIdType>(i)), static_cast<double>(s.triangles[i].id));
    ASSERT_EQ(object->GetTuple1(static_cast<vtkIdType>(i)), static_cast<double>(s.triangles[i].object));
    ASSERT_EQ(visible->GetTuple1(static_cast<vtkIdType>(i)), static_cast<double>(vis.values[i]));
    ASSERT_EQ(weight->GetTuple1(static_cast<vtkIdType>(i)), area.values[i]);
  }
  EXPECT_EQ(iotest::entries(dir.path), 1);  // no temporary file left
}

TEST(WriteVtp, PolylinesAndSegments) {
  TempDir dir;
  const std::vector<std::vector<Point3>> lines = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0.1}}, {{5, 5, 5}, {6, 6, 6}}};
  write_polylines_vtp(dir.file("l.vtp"), lines, {{{"kind", {7, 8}}}, {}});
  auto poly = read_vtp(dir.file("l.vtp"));
  ASSERT_EQ(poly->GetNumberOfLines(), 2);
  ASSERT_EQ(poly->GetNumberOfPoints(), 5);
  vtkNew<vtkIdList> cell;
  poly->GetLines()->InitTraversal();
  for (const auto& line : lines) {
    ASSERT_TRUE(poly->GetLines()->GetNextCell(cell));
    ASSERT_EQ(cell->GetNumberOfIds(), static_cast<vtkIdType>(line.size()));
    for (size_t k = 0; k < line.size(); ++k) {
      double p[3];
      poly->GetPoint(cell->GetId(static_cast<vtkIdType>(k)), p);
      EXPECT_EQ(Point3(p[0], p[1], p[2]), line[k]);
    }
  }
  EXPECT_EQ(poly->GetCellData()->GetArray("kind")->GetTuple1(1), 8.0);

  write_segments_vtp(dir.file("s.vtp"), {{{0, 0, 0}, {0, 0, 1}}}, {});
  EXPECT_EQ(read_vtp(dir.file("s.vtp"))->GetNumberOfLines(), 1);
}

TEST(WriteVtp, FailuresLeaveNoFile) {
  TempDir dir;
  const Scene s = generate_scene("random", 20, 1);
  // Wrong array length, reserved name, bad polyline: OutputError, and nothing in the directory.
  EXPECT_THROW(write_scene_vtp(dir.file("a.vtp"), s, {{{"x", {1, 2, 3}}}, {}}), OutputError);
  EXPECT_THROW(write_scene_vtp(dir.file("b.vtp"), s, {{{"id", std::vector<std::int64_t>(20, 0)}}, {}}), OutputError);
  EXPECT_THROW(write_polylines_vtp(dir.file("c.vtp"), {{{0, 0, 0}}}), OutputError);
  EXPECT_EQ(iotest::entries(dir.path), 0);
  // Unwritable destinations.
  EXPECT_THROW(write_scene_vtp(dir.file("missing/dir/x.vtp"), s), OutputError);
  std::filesystem::create_directory(dir.file("isdir.vtp"));
  EXPECT_THROW(write_scene_vtp(dir.file("isdir.vtp"), s), OutputError);
  EXPECT_THROW(write_scene_mesh(dir.file("x.abc"), s), OutputError);
  EXPECT_EQ(iotest::entries(dir.path), 1);  // only the directory made above
  // An existing file is replaced only on success: a failed write keeps the old content.
  const std::string keep = iotest::write_file(dir.file("keep.vtp"), "old");
  EXPECT_THROW(write_scene_vtp(keep, s, {{{"x", {1}}}, {}}), OutputError);
  EXPECT_EQ(iotest::read_file(keep), "old");
  EXPECT_THROW(write_atomically(dir.file("w.txt"), [](const std::string&) -> bool { throw std::runtime_error("boom"); }),
               OutputError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("w.txt")));
  EXPECT_EQ(iotest::entries(dir.path), 2);
}
