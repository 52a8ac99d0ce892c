// Event surfaces (.vtp): written, read back with VTK's own reader, cell counts and arrays checked; the
// umbra/penumbra wedges of a cube under a light reach the floor (clipped at the first blocker).
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"
#include "events/event_surfaces.hpp"
#include "io/write_event_surfaces.hpp"
#include "tests/scene_test_util.hpp"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>
#include <cmath>
#include <map>

namespace exactvis {
namespace {

Scene cube_floor_light() {
  std::vector<Point3> v;
  for (int i = 0; i < 8; ++i) v.push_back({2.0 * (i & 1), 2.0 * ((i >> 1) & 1), 2.0 * ((i >> 2) & 1)});
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<std::array<int, 3>> t;
  for (const auto& f : faces) {
    t.push_back({f[0], f[1], f[2]});
    t.push_back({f[0], f[2], f[3]});
  }
  v.insert(v.end(), {{-10, -10, -1}, {10, -10, -1}, {10, 10, -1}, {-10, 10, -1}});
  t.push_back({8, 9, 10});
  t.push_back({8, 10, 11});
  v.insert(v.end(), {{0.5, 0.5, 6}, {1.5, 0.5, 6}, {1.5, 1.5, 6}, {0.5, 1.5, 6}});
  t.push_back({12, 13, 14});
  t.push_back({12, 14, 15});
  return scene_test::make_scene(v, t);
}

TEST(EventSurfaces, WrittenAndReadBackWithArrays) {
  const Scene s = cube_floor_light();
  EvOptions ev_opt;
  ev_opt.light_triangles = {14, 15};
  EeeOptions eee_opt;
  eee_opt.light_triangles = {14, 15};
  const EvResult ev = enumerate_ev_events(s, ev_opt);
  const EeeResult eee = enumerate_eee_events(s, eee_opt);
  ASSERT_EQ(ev.events.size(), 64u);
  const auto path = std::filesystem::temp_directory_path() / "exactvis_test_event_surfaces.vtp";
  const int n = 4;
  write_event_surfaces_vtp(path.string(), s, ev, eee, n);

  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  std::size_t ev_intervals = 0, eee_intervals = 0;
  for (const auto& e : ev.events) ev_intervals += e.intervals.size();
  for (const auto& e : eee.events) eee_intervals += e.intervals.size();
  ASSERT_EQ(static_cast<std::size_t>(poly->GetNumberOfCells()), 2 * n * (ev_intervals + eee_intervals));
  for (const char* name : {"kind", "event", "vertex", "edge0", "edge1", "edge2", "edge3", "edge4", "edge5", "interval",
                           "t0", "t1"})
    ASSERT_NE(poly->GetCellData()->GetArray(name), nullptr) << name;
  vtkDataArray* kind = poly->GetCellData()->GetArray("kind");
  vtkDataArray* event = poly->GetCellData()->GetArray("event");
  vtkDataArray* vertex = poly->GetCellData()->GetArray("vertex");
  std::size_t ev_cells = 0;
  // Lowest z reached by each EV event's surface.
  std::map<int, double> min_z;
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
    if (kind->GetTuple1(c) != 0) continue;
    ++ev_cells;
    const int ei = static_cast<int>(event->GetTuple1(c));
    EXPECT_EQ(vertex->GetTuple1(c), ev.events[ei].vertex);
    vtkIdType npts;
    const vtkIdType* pts;
    poly->GetCellPoints(c, npts, pts);
    for (vtkIdType k = 0; k < npts; ++k) {
      double p[3];
      poly->GetPoint(pts[k], p);
      // Inside the scene box [-10, 10]^2 x [-1, 6] (display coordinates).
      EXPECT_GE(p[2], -1 - 1e-9);
      EXPECT_LE(p[2], 6 + 1e-9);
      auto [it, inserted] = min_z.emplace(ei, p[2]);
      if (!inserted) it->second = std::min(it->second, p[2]);
    }
  }
  EXPECT_EQ(ev_cells, 2 * n * ev_intervals);
  // Penumbra/umbra wedges (light vertex, cube top edge): the free segments pass the top edge and end on the
  // floor (z = -1), not earlier and not below it.
  int wedges = 0;
  for (std::size_t ei = 0; ei < ev.events.size(); ++ei) {
    const auto& e = ev.events[ei];
    if (e.vertex < 12 || e.edge[0] < 4 || e.edge[1] > 7) continue;
    ++wedges;
    EXPECT_DOUBLE_EQ(min_z.at(static_cast<int>(ei)), -1.0) << e.vertex;
  }
  EXPECT_EQ(wedges, 16);
  std::filesystem::remove(path);
}

// The geometry itself (events/event_surfaces.hpp): one surface per interval, samples in increasing t inside
// the interval, and the wedges of the light's vertices over the cube's top edges hit the floor (triangles 12,
// 13) at z = -1; segments that leave the scene end on its box.
TEST(EventSurfaces, SweptSegmentsEndOnTheTrianglesHit) {
  const Scene s = cube_floor_light();
  EvOptions ev_opt;
  ev_opt.light_triangles = {14, 15};
  const EvResult ev = enumerate_ev_events(s, ev_opt);
  const std::vector<EventSurface> surfaces = event_surfaces(s, ev, EeeResult{}, 4);
  std::size_t intervals = 0;
  for (const auto& e : ev.events) intervals += e.intervals.size();
  ASSERT_EQ(surfaces.size(), intervals);
  int floor_hits = 0;
  for (const EventSurface& surface : surfaces) {
    ASSERT_EQ(surface.kind, EventSurface::Kind::EV);
    const auto& e = ev.events[surface.event];
    const auto& iv = e.intervals[surface.interval];
    ASSERT_EQ(surface.samples.size(), 5u);
    for (std::size_t k = 0; k < surface.samples.size(); ++k) {
      const SurfaceSample& smp = surface.samples[k];
      EXPECT_TRUE(iv.t0 <= RootNumber(smp.t) && RootNumber(smp.t) <= iv.t1);
      if (k > 0) {
        EXPECT_LT(surface.samples[k - 1].t, smp.t);
      }
      if (smp.front_triangle == 12 || smp.front_triangle == 13) {
        ++floor_hits;
        EXPECT_EQ(smp.front.z, -1.0);  // the exact hit point on the floor, rounded: exactly -1
      }
      if (smp.front_triangle < 0) {  // left the box: on its boundary
        const bool on_box = std::abs(smp.front.x) == 10 || std::abs(smp.front.y) == 10 || smp.front.z == -1 ||
                            smp.front.z == 6;
        EXPECT_TRUE(on_box) << smp.front.x << " " << smp.front.y << " " << smp.front.z;
      }
    }
  }
  EXPECT_GT(floor_hits, 16 * 5 - 1);
}

// EEE ruled strips: three skew bars (as in test_events_cli.cpp); every EEE interval gives 2 n triangles of
// kind 1 carrying the event's edges, and all points stay in the scene box.
TEST(EventSurfaces, EeeStripsReadBack) {
  Scene s;
  s.vertices = {{-4, 0, 0}, {4, 0, 0}, {0, -1, -3}, {0, -4, 4}, {0, 4, 4}, {-3, 0, 5}, {-4, -4, 8}, {4, 4, 8}, {3, -3, 11}};
  for (int i = 0; i < 3; ++i) s.triangles.push_back({i, {3 * i, 3 * i + 1, 3 * i + 2}, 0});
  s.objects.push_back({"bars"});
  s.faces_read = 3;
  const EeeResult eee = enumerate_eee_events(s);
  ASSERT_GT(eee.events.size(), 0u);
  std::size_t intervals = 0;
  for (const auto& e : eee.events) intervals += e.intervals.size();
  const auto path = std::filesystem::temp_directory_path() / "exactvis_test_eee_surfaces.vtp";
  const int n = 3;
  write_event_surfaces_vtp(path.string(), s, EvResult{}, eee, n);
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  ASSERT_EQ(static_cast<std::size_t>(poly->GetNumberOfCells()), 2 * n * intervals);
  vtkDataArray* kind = poly->GetCellData()->GetArray("kind");
  vtkDataArray* event = poly->GetCellData()->GetArray("event");
  vtkDataArray* e2 = poly->GetCellData()->GetArray("edge2");
  ASSERT_NE(kind, nullptr);
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
    EXPECT_EQ(kind->GetTuple1(c), 1);
    EXPECT_EQ(e2->GetTuple1(c), eee.events[static_cast<std::size_t>(event->GetTuple1(c))].edges[1][0]);
  }
  for (vtkIdType p = 0; p < poly->GetNumberOfPoints(); ++p) {
    double x[3];
    poly->GetPoint(p, x);
    EXPECT_GE(x[0], -4 - 1e-9);
    EXPECT_LE(x[0], 4 + 1e-9);
    EXPECT_GE(x[2], -3 - 1e-9);
    EXPECT_LE(x[2], 11 + 1e-9);
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace exactvis
