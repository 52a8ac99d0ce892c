// Side-by-side harness: the same cell-to-triangle queries as `exactvis visible --cell C --triangles IDS`,
// answered by visilib (github.com/dhaumont/visilib, header-only, GPL; NOT a dependency of exactvis: this file
// is built only by bench/visilib/run.sh against a checkout the user names). Answers are printed so that
// run.sh can compare them with exactvis's exact ones; timings are the CPU time of the areVisible calls only.
//
// Query per target triangle T: the occluders are all other triangles (one occluder set per target, one mesh per
// OBJ object, built outside the timer); the cell is a box, so T is visible iff some face F of the cell whose outer side T
// reaches sees T (a segment from the cell to T leaves the cell through such a face); each such face is a
// polygon-to-polygon query, in visilib's default configuration (double precision, stop at the first
// visible line).
#include <visilib.h>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Mesh {
  std::vector<float> xyz;     // vertex coordinates
  std::vector<int> tri;       // 3 indices per triangle, ids = position (fan-triangulated in load order)
  std::vector<int> object;    // per triangle: its OBJ group/object (a new one at each g/o line)
};

Mesh read_obj(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    std::cerr << path << ": cannot open\n";
    std::exit(2);
  }
  Mesh m;
  int group = 0;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      double x, y, z;
      s >> x >> y >> z;
      m.xyz.insert(m.xyz.end(), {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
    } else if (tag == "g" || tag == "o") {
      ++group;
    } else if (tag == "f") {
      std::vector<int> f;
      std::string w;
      while (s >> w) f.push_back(std::stoi(w.substr(0, w.find('/'))) - 1);
      for (std::size_t k = 1; k + 1 < f.size(); ++k) {
        m.tri.insert(m.tri.end(), {f[0], f[k], f[k + 1]});
        m.object.push_back(group);
      }
    }
  }
  return m;
}

// The triangles of one object but `skip`, with their own vertex array (visilib selects occluders by the
// bounding boxes of these meshes, so one mesh per object as in its demos). The occluder set owns it.
struct ObjectMesh : visilib::GeometryTriangleMeshDescription {
  std::vector<float> xyz;
  std::vector<int> indices;
  ObjectMesh(const Mesh& m, int object, int skip) {
    std::vector<int> local(m.xyz.size() / 3, -1);
    for (std::size_t t = 0; t < m.object.size(); ++t) {
      if (m.object[t] != object || static_cast<int>(t) == skip) continue;
      for (int k = 0; k < 3; ++k) {
        const int v = m.tri[3 * t + k];
        if (local[v] < 0) {
          local[v] = static_cast<int>(xyz.size() / 3);
          xyz.insert(xyz.end(), m.xyz.begin() + 3 * v, m.xyz.begin() + 3 * v + 3);
        }
        indices.push_back(local[v]);
      }
    }
    vertexCount = xyz.size() / 3;
    faceCount = indices.size() / 3;
    vertexArray = xyz.data();
    indexArray = indices.data();
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: visilib_side_by_side SCENE.obj X0,Y0,Z0,X1,Y1,Z1 ID[,ID...]|all [double|gmp]\n";
    return 2;
  }
  const Mesh mesh = read_obj(argv[1]);
  double c[6];
  if (std::sscanf(argv[2], "%lf,%lf,%lf,%lf,%lf,%lf", &c[0], &c[1], &c[2], &c[3], &c[4], &c[5]) != 6) {
    std::cerr << "bad cell\n";
    return 2;
  }
  std::vector<int> ids;
  if (std::string(argv[3]) == "all") {
    for (std::size_t t = 0; t * 3 < mesh.tri.size(); ++t) ids.push_back(static_cast<int>(t));
  } else {
    std::stringstream s(argv[3]);
    std::string w;
    while (std::getline(s, w, ',')) ids.push_back(std::stoi(w));
  }
  // The six faces of the cell as quads, with the axis and side of each.
  struct Face {
    int axis;
    bool high;
    std::vector<float> quad;
  };
  std::vector<Face> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (bool high : {false, true}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Face f{axis, high, {}};
      // Counterclockwise seen from outside: the face's normal points away from the cell (visilib clips each
      // polygon to the positive side of the other's plane, so the two must face each other).
      const bool flip = !high;
      const double uv[4][2] = {{c[u], c[v]}, {c[u + 3], c[v]}, {c[u + 3], c[v + 3]}, {c[u], c[v + 3]}};
      for (int i = 0; i < 4; ++i) {
        const auto& p = uv[flip ? 3 - i : i];
        float q[3];
        q[axis] = static_cast<float>(high ? c[axis + 3] : c[axis]);
        q[u] = static_cast<float>(p[0]);
        q[v] = static_cast<float>(p[1]);
        f.quad.insert(f.quad.end(), q, q + 3);
      }
      faces.push_back(f);
    }
  visilib::VisibilityExactQueryConfiguration config;  // defaults: DOUBLE, detectApertureOnly
#ifdef ENABLE_GMP
  if (argc > 4 && std::string(argv[4]) == "gmp") config.precision = visilib::VisibilityExactQueryConfiguration::GMP_RATIONAL;
#endif
  double query_seconds = 0;
  int visible = 0, failures = 0;
  for (const int id : ids) {
    visilib::GeometryOccluderSet set;
    const int objects = mesh.object.empty() ? 0 : *std::max_element(mesh.object.begin(), mesh.object.end()) + 1;
    for (int o = 0; o < objects; ++o) {
      auto* part = new ObjectMesh(mesh, o, id);
      if (part->faceCount == 0) delete part;
      else set.addOccluder(part);
    }
    set.prepare();
    float t[9];
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) t[3 * k + a] = mesh.xyz[3 * mesh.tri[3 * id + k] + a];
    bool seen = false;
    const std::clock_t start = std::clock();
    for (const Face& f : faces) {
      const double plane = f.high ? c[f.axis + 3] : c[f.axis];
      bool outer = false;  // some corner of T strictly on the face's outer side
      for (int k = 0; k < 3; ++k) outer |= f.high ? t[3 * k + f.axis] > plane : t[3 * k + f.axis] < plane;
      if (!outer) continue;
      // T facing the face: once per side of T's plane on which a corner of the face lies.
      const double e1[3] = {t[3] - t[0], t[4] - t[1], t[5] - t[2]}, e2[3] = {t[6] - t[0], t[7] - t[1], t[8] - t[2]};
      const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      for (const int side : {1, -1}) {
        bool in_front = false;
        for (int k = 0; k < 4; ++k) {
          double d = 0;
          for (int a = 0; a < 3; ++a) d += n[a] * (f.quad[3 * k + a] - t[a]);
          in_front |= side * d > 0;
        }
        if (!in_front) continue;
        float oriented[9];
        std::copy(t, t + 9, oriented);
        if (side < 0) std::swap_ranges(oriented + 3, oriented + 6, oriented + 6);
        const visilib::VisibilityResult r = visilib::areVisible(&set, f.quad.data(), 4, oriented, 3, config);
        if (r == visilib::FAILURE) ++failures;
        if (r == visilib::VISIBLE) {
          seen = true;
          break;
        }
      }
      if (seen) break;
    }
    query_seconds += static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    visible += seen;
    std::cout << id << " " << (seen ? "visible" : "hidden") << "\n";
  }
  std::cerr << "visilib: " << ids.size() << " queries, " << visible << " visible, " << failures
            << " failures, query CPU time " << query_seconds << " s\n";
  return 0;
}
