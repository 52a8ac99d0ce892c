#include "io/write_mesh.hpp"

#include "io/atomic_file.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <fstream>

namespace exactvis {
namespace {

struct OmTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
};
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<OmTraits>;

std::string shortest(double x) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

bool write_obj(const std::string& file, const Scene& scene) {
  std::ofstream out(file, std::ios::binary);
  if (!out) return false;
  out << "# exactvis scene: " << scene.vertices.size() << " vertices, " << scene.triangles.size()
      << " triangles, " << scene.objects.size() << " objects\n";
  std::string line;
  for (const auto& p : scene.vertices) {
    line = "v " + shortest(p.x) + " " + shortest(p.y) + " " + shortest(p.z) + "\n";
    out << line;
  }
  int current = -1;
  for (const auto& t : scene.triangles) {
    if (t.object != current) {
      current = t.object;
      std::string name = scene.objects[current].name;
      if (name.empty() || std::all_of(name.begin(), name.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); }))
        name = "object" + std::to_string(current);
      std::replace(name.begin(), name.end(), '\n', ' ');
      out << "g " << name << "\n";
    }
    out << "f " << t.v[0] + 1 << " " << t.v[1] + 1 << " " << t.v[2] + 1 << "\n";
  }
  out.flush();
  return static_cast<bool>(out);
}

bool write_with_openmesh(const std::string& file, const Scene& scene) {
  OmMesh mesh;
  std::vector<OmMesh::VertexHandle> vh;
  vh.reserve(scene.vertices.size());
  for (const auto& p : scene.vertices) vh.push_back(mesh.add_vertex(OmMesh::Point(p.x, p.y, p.z)));
  struct Quiet {
    Quiet() { ::omerr().disable(); ::omlog().disable(); ::omout().disable(); }
    ~Quiet() { ::omerr().enable(); ::omlog().enable(); ::omout().enable(); }
  } quiet;
  for (const auto& t : scene.triangles) {
    std::vector<OmMesh::VertexHandle> f{vh[t.v[0]], vh[t.v[1]], vh[t.v[2]]};
    if (!mesh.add_face(f).is_valid()) {
      // Non-manifold here: give the face its own vertices (as OpenMesh's importer does).
      for (auto& h : f) h = mesh.add_vertex(OmMesh::Point(mesh.point(h)));
      if (!mesh.add_face(f).is_valid()) return false;
    }
  }
  return OpenMesh::IO::write_mesh(mesh, file, OpenMesh::IO::Options::Default, 17);
}

}  // namespace

void write_scene_mesh(const std::string& path, const Scene& scene) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw OutputError(path + ": unknown extension '" + ext + "' (expected .obj, .off, .ply or .stl)");
  write_atomically(path, [&](const std::string& temp) {
    return ext == ".obj" ? write_obj(temp, scene) : write_with_openmesh(temp, scene);
  });
}

}  // namespace exactvis
