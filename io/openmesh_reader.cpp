#include "io/openmesh_reader.hpp"

#include "io/mesh_text.hpp"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <cmath>
#include <limits>
#include <new>
#include <sstream>

namespace exactvis::mesh_io {
namespace {

// OpenMesh side: an importer that records the vertices and faces the reader delivers, in the reader's order.
// It still builds the mesh (the readers use the returned handles), but the mesh is never used: OpenMesh
// duplicates vertices of non-manifold ("complex edge") faces, so the recorded handles are mapped back to
// the file's vertex order through `file_index`.
struct OmTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
};
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<OmTraits>;

struct RecordingImporter : OpenMesh::IO::ImporterT<OmMesh> {
  using Base = OpenMesh::IO::ImporterT<OmMesh>;
  explicit RecordingImporter(OmMesh& m) : Base(m) {}

  std::vector<OpenMesh::Vec3f> points;       // in the reader's add order (= file order)
  std::vector<int> file_index;               // mesh handle idx -> file vertex index, -1 if none
  std::vector<std::vector<int>> faces;       // file vertex indices, -1 for a handle the file never made
  // When set: faces are compared with these as they arrive instead of being stored.
  const std::vector<std::vector<int>>* expected = nullptr;
  std::size_t face_count = 0;
  bool faces_match = true;
  std::vector<int> scratch;

  OpenMesh::VertexHandle record(OpenMesh::VertexHandle h, const OpenMesh::Vec3f& p) {
    if (h.idx() >= 0) {
      if (static_cast<size_t>(h.idx()) >= file_index.size()) file_index.resize(h.idx() + 1, -1);
      file_index[h.idx()] = static_cast<int>(points.size());
      points.push_back(p);
    }
    return h;
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override { return record(Base::add_vertex(p), p); }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    return record(Base::add_vertex(p), OpenMesh::Vec3f(p));
  }
  OpenMesh::VertexHandle add_vertex() override { return record(Base::add_vertex(), OpenMesh::Vec3f(0, 0, 0)); }
  void set_point(OpenMesh::VertexHandle h, const OpenMesh::Vec3f& p) override {
    if (h.idx() >= 0 && static_cast<size_t>(h.idx()) < file_index.size() && file_index[h.idx()] >= 0)
      points[file_index[h.idx()]] = p;
    Base::set_point(h, p);
  }
  OpenMesh::FaceHandle add_face(const VHandles& hs) override {
    std::vector<int>& f = expected ? scratch : faces.emplace_back();
    f.clear();
    f.reserve(hs.size());
    for (auto h : hs)
      f.push_back(h.idx() >= 0 && static_cast<size_t>(h.idx()) < file_index.size() ? file_index[h.idx()] : -1);
    if (expected) faces_match = faces_match && face_count < expected->size() && (*expected)[face_count] == f;
    ++face_count;
    return Base::add_face(hs);
  }
};

// OpenMesh reports problems on its own streams; our errors say it better, and a non-manifold mesh would
// print one line per face. Silence them while reading.
struct QuietOpenMesh {
  QuietOpenMesh() { ::omerr().disable(); ::omlog().disable(); ::omout().disable(); }
  ~QuietOpenMesh() { ::omerr().enable(); ::omlog().enable(); ::omout().enable(); }
};

}  // namespace

OpenMeshResult read_with_openmesh(const std::string& path, const std::string* normalized, const std::string& ext,
                                  const std::vector<std::vector<int>>* expected_faces) {
  OmMesh mesh;
  RecordingImporter importer(mesh);
  importer.expected = expected_faces;
  OpenMesh::IO::Options opt;
  bool ok = false;
  try {
    QuietOpenMesh quiet;
    if (normalized) {
      std::istringstream in(*normalized);
      ok = OpenMesh::IO::IOManager().read(in, ext, importer, opt);
    } else {
      ok = OpenMesh::IO::IOManager().read(path, importer, opt);
    }
  } catch (const std::bad_alloc&) {
    fail(path, "OpenMesh ran out of memory reading it (corrupt element counts?)");
  } catch (const std::exception& e) {
    fail(path, std::string("OpenMesh failed: ") + e.what());
  }
  if (!ok) fail(path, "OpenMesh could not read it (malformed or truncated file)");
  const bool match = importer.faces_match && (!expected_faces || importer.face_count == expected_faces->size());
  return {std::move(importer.points), std::move(importer.faces), importer.face_count, match};
}

void check_same_points(const std::string& path, const std::vector<Point3>& exact,
                       const std::vector<OpenMesh::Vec3f>& om) {
  if (exact.size() != om.size())
    fail(path, "OpenMesh read " + std::to_string(om.size()) + " vertices, the file has " +
                   std::to_string(exact.size()));
  // Decimal -> double -> float may differ from decimal -> float by one float ulp (double rounding); outside
  // float's normal range OpenMesh's stream parsing is not comparable at all.
  const double fmax = std::numeric_limits<float>::max(), fmin = std::numeric_limits<float>::min();
  for (size_t i = 0; i < exact.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double d = exact[i][k];
      const float f = static_cast<float>(d);
      const bool comparable = std::fabs(d) <= fmax && std::fabs(d) >= fmin;
      if (comparable && om[i][k] != f && om[i][k] != std::nextafter(f, 2 * f) && om[i][k] != std::nextafter(f, 0.0f))
        fail(path, "vertex " + std::to_string(i) + ": OpenMesh read coordinate " + std::to_string(om[i][k]) +
                       ", the file says " + std::to_string(d));
    }
}

}  // namespace exactvis::mesh_io
