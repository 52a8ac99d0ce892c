#include "io/load_scene.hpp"

#include "kernel/predicates.hpp"
#include "io/load_ply.hpp"
#include "io/mesh_text.hpp"
#include "io/openmesh_reader.hpp"
#include "util/union_find.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <string_view>

namespace exactvis {
namespace {

using namespace mesh_io;

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string read_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a mesh file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open (") + std::strerror(errno) + ")");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) fail(path, "read error");
  return ss.str();
}

// Text formats (OBJ, OFF) must be ASCII or UTF-8: name the encoding of a UTF-16/32 or binary file.
void check_text_encoding(const std::string& path, std::string_view text) {
  if (auto enc = unreadable_encoding(text)) fail(path, *enc + "; save it as ASCII or UTF-8 text");
}

// ---------------------------------------------------------------------------------------------------------
// Checks shared by all formats.

void check_faces_valid(const std::string& path, const RawMesh& m) {
  const long long nv = static_cast<long long>(m.vertices.size());
  for (size_t f = 0; f < m.faces.size(); ++f) {
    if (m.faces[f].size() < 3)
      fail(path, "face " + std::to_string(f) + " has " + std::to_string(m.faces[f].size()) +
                     " vertices (at least 3 needed)");
    for (int v : m.faces[f])
      if (v < 0 || v >= nv)
        fail(path, "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", out of range [0, " +
                       std::to_string(nv) + ")");
  }
}

void check_finite(const std::string& path, const std::vector<Point3>& vs) {
  for (size_t i = 0; i < vs.size(); ++i)
    if (!std::isfinite(vs[i].x) || !std::isfinite(vs[i].y) || !std::isfinite(vs[i].z))
      fail(path, "vertex " + std::to_string(i) + " has a non-finite coordinate");
}

// ---------------------------------------------------------------------------------------------------------
// OBJ: OpenMesh parses floats, drops repeated vertices within a face and does not keep groups, so the
// vertices (exact doubles), faces (as written) and groups come from our line scan; OpenMesh's reading must
// agree with it (same vertex and face counts, same coordinates up to float rounding, same vertex sets).
// Values beyond float32 in v/vn/vt/vp lines reach OpenMesh as float32 stand-ins (io/mesh_text.hpp).
RawMesh load_obj(const std::string& path, const std::string& text, bool altered) {
  check_text_encoding(path, text);
  RawMesh m;
  std::vector<TokenReplacement> stand_ins;
  std::map<std::string, int> group_of_name;
  int current_group = -1;
  bool has_groups = false;
  // First pass: count vertices so forward references can be range-checked.
  for_each_line(text, [&](long line_no, std::string_view line) {
    auto t = tokens(line);
    if (t.empty()) return true;
    if (t[0] == "vn" || t[0] == "vt" || t[0] == "vp") {  // not ours to read, but OpenMesh must get through them
      for (std::size_t k = 1; k < t.size(); ++k)
        if (auto v = parse_double(t[k]); v && beyond_float32(*v)) stand_ins.push_back(float32_stand_in(text, t[k], *v));
      return true;
    }
    if (t[0] != "v") return true;
    if (t.size() < 4) fail(path, "line " + std::to_string(line_no) + ": vertex needs 3 coordinates");
    Point3 p;
    for (int k = 0; k < 3; ++k) {
      p[k] = text_coordinate(path, line_no, t[k + 1]);
      if (beyond_float32(p[k])) stand_ins.push_back(float32_stand_in(text, t[k + 1], p[k]));
    }
    m.vertices.push_back(p);
    return true;
  });
  long long seen_vertices = 0;
  for_each_line(text, [&](long line_no, std::string_view line) {
    auto t = tokens(line);
    if (t.empty()) return true;
    const std::string where = "line " + std::to_string(line_no) + ": ";
    if (t[0] == "v") {
      ++seen_vertices;
    } else if (t[0] == "g" || t[0] == "o") {
      std::string name;
      for (size_t i = 1; i < t.size(); ++i) name += (i > 1 ? " " : "") + std::string(t[i]);
      if (name.empty()) name = "default";
      has_groups = true;
      auto [it, inserted] = group_of_name.emplace(name, static_cast<int>(m.group_names.size()));
      if (inserted) m.group_names.push_back(name);
      current_group = it->second;
    } else if (t[0] == "f") {
      if (t.size() < 4) fail(path, where + "face with " + std::to_string(t.size() - 1) + " vertices (at least 3 needed)");
      std::vector<int> face;
      for (size_t i = 1; i < t.size(); ++i) {
        auto slash = t[i].find('/');
        auto idx = parse_int(t[i].substr(0, slash));
        if (!idx) fail(path, where + "bad face vertex '" + std::string(t[i]) + "'");
        long long v = *idx;
        if (v < 0) v = seen_vertices + v;  // relative index: -1 is the last vertex so far
        else v = v - 1;
        if (*idx == 0 || v < 0 || v >= static_cast<long long>(m.vertices.size()))
          fail(path, where + "vertex index " + std::to_string(*idx) + " out of range (file has " +
                         std::to_string(m.vertices.size()) + " vertices)");
        face.push_back(static_cast<int>(v));
      }
      m.faces.push_back(std::move(face));
      m.face_group.push_back(current_group);
    }
    return true;
  });
  if (has_groups) {
    // Faces before the first g/o line belong to OBJ's "default" group.
    for (auto& g : m.face_group)
      if (g < 0) {
        auto [it, inserted] = group_of_name.emplace("default", static_cast<int>(m.group_names.size()));
        if (inserted) m.group_names.push_back("default");
        g = it->second;
      }
  } else {
    m.face_group.clear();
  }
  if (m.faces.empty()) fail(path, "no faces");

  std::string copy;
  if (altered || !stand_ins.empty()) copy = with_replacements(text, stand_ins);
  const OpenMeshResult om = copy.empty() ? read_with_openmesh(path) : read_with_openmesh(path, &copy, "obj");
  check_same_points(path, m.vertices, om.points);
  if (om.faces.size() != m.faces.size())
    fail(path, "OpenMesh read " + std::to_string(om.faces.size()) + " faces, the file has " +
                   std::to_string(m.faces.size()));
  for (size_t f = 0; f < m.faces.size(); ++f) {
    std::vector<int> a = m.faces[f], b = om.faces[f];
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    std::sort(b.begin(), b.end());
    b.erase(std::unique(b.begin(), b.end()), b.end());
    if (a != b) fail(path, "face " + std::to_string(f) + ": OpenMesh read different vertices than the file lists");
  }
  return m;
}

// ---------------------------------------------------------------------------------------------------------
// OFF (ASCII only): header counts are checked against the file size before OpenMesh allocates for them;
// vertices (exact doubles) and face lists are read here too and must agree with OpenMesh's reading.
// OpenMesh reads a normalized copy: plain "OFF", comments and blank lines removed, each vertex line cut to
// its x y z (values beyond float32 as stand-ins) and each face line to its count and indices. (Its reader
// misreads '#' comments, and per-face colours derail it: it reads them as integers and then loses every
// face after the first.)
RawMesh load_off(const std::string& path, const std::string& text) {
  // Binary OFF ("OFF BINARY") holds NUL bytes legitimately; it is refused below, by name.
  if (text.substr(0, text.find('\n')).find("BINARY") == std::string::npos) check_text_encoding(path, text);
  // Header: keyword, then nV nF nE (possibly on following lines), '#' comments allowed.
  std::vector<std::string_view> head;
  bool binary = false;
  std::vector<std::pair<long, std::string_view>> lines;  // (line number, content) after the header
  for_each_line(text, [&](long n, std::string_view line) {
    auto hash = line.find('#');
    std::string_view content = hash == std::string::npos ? line : line.substr(0, hash);
    if (head.size() < 4) {
      for (auto t : tokens(content)) {
        if (head.size() < 4) {
          head.push_back(t);
          // "OFF BINARY" (the spec's form) or a keyword with BINARY in it
          if ((head.size() == 1 && t.find("BINARY") != std::string_view::npos) || (head.size() == 2 && t == "BINARY"))
            binary = true;
        }
        if (binary) break;
      }
      if (binary) return false;  // binary body: refused below
      return true;
    }
    if (!tokens(content).empty()) lines.emplace_back(n, content);
    return true;
  });
  if (head.empty() || head[0].size() < 3 || head[0].substr(head[0].size() - 3) != "OFF")
    fail(path, "not an OFF file (first keyword must end in OFF)");
  if (head[0] != "OFF" && head[0] != "COFF" && head[0] != "NOFF" && head[0] != "CNOFF" && head[0] != "STOFF" &&
      head[0] != "STCOFF" && head[0] != "STNOFF" && head[0] != "STCNOFF" && head[0] != "NCOFF" && !binary)
    fail(path, "unsupported OFF variant '" + std::string(head[0]) + "'");
  RawMesh m;
  if (!binary) {
    if (head.size() < 4) fail(path, "truncated header (needs vertex, face and edge counts)");
    auto nv = parse_int(head[1]), nf = parse_int(head[2]);
    if (!nv || !nf || *nv < 0 || *nf < 0) fail(path, "bad vertex/face counts in the header");
    // Each vertex line needs at least 6 bytes ("0 0 0\n"), each face line at least 8 ("3 0 1 2\n").
    if (static_cast<long double>(*nv) * 6 + static_cast<long double>(*nf) * 8 > text.size())
      fail(path, "header declares " + std::to_string(*nv) + " vertices and " + std::to_string(*nf) +
                     " faces, more than the file can hold (truncated or corrupt)");
    if (*nf == 0) fail(path, "no faces");
    if (static_cast<long long>(lines.size()) < *nv)
      fail(path, "truncated: header declares " + std::to_string(*nv) + " vertices, file has fewer lines");
    for (long long i = 0; i < *nv; ++i) {
      auto t = tokens(lines[i].second);
      if (t.size() < 3) fail(path, "line " + std::to_string(lines[i].first) + ": vertex needs 3 coordinates");
      Point3 p;
      for (int k = 0; k < 3; ++k) p[k] = text_coordinate(path, lines[i].first, t[k]);
      m.vertices.push_back(p);
    }
    if (static_cast<long long>(lines.size()) < *nv + *nf)
      fail(path, "truncated: header declares " + std::to_string(*nf) + " faces, file has only " +
                     std::to_string(lines.size() - *nv));
    // Face lines: "n i1 ... in [colour]"; OpenMesh must read the same lists.
    std::vector<std::vector<int>> faces;
    for (long long i = *nv; i < *nv + *nf; ++i) {
      auto t = tokens(lines[i].second);
      const std::string where = "line " + std::to_string(lines[i].first) + ": ";
      auto n = parse_int(t[0]);
      if (!n || *n < 3) fail(path, where + "bad face (needs a vertex count of at least 3)");
      if (static_cast<long long>(t.size()) < 1 + *n) fail(path, where + "face lists fewer vertices than its count");
      std::vector<int> face;
      for (long long k = 1; k <= *n; ++k) {
        auto v = parse_int(t[k]);
        if (!v) fail(path, where + "bad vertex index '" + std::string(t[k]) + "'");
        if (*v < 0 || *v >= *nv)
          fail(path, where + "vertex index " + std::to_string(*v) + " out of range [0, " + std::to_string(*nv) + ")");
        face.push_back(static_cast<int>(*v));
      }
      faces.push_back(std::move(face));
    }
    // OpenMesh's copy (see above).
    std::string clean = "OFF\n" + std::string(head[1]) + " " + std::string(head[2]) + " " + std::string(head[3]) + "\n";
    clean.reserve(text.size());
    for (long long i = 0; i < *nv; ++i) {
      const auto t = tokens(lines[i].second);
      for (int k = 0; k < 3; ++k) {
        if (k) clean += ' ';
        if (beyond_float32(m.vertices[i][k])) clean += float32_stand_in(text, t[k], m.vertices[i][k]).text;
        else clean.append(t[k]);
      }
      clean += '\n';
    }
    char digits[24];
    const auto put = [&](long long v) { clean.append(digits, std::to_chars(digits, digits + sizeof digits, v).ptr); };
    for (const auto& face : faces) {
      put(static_cast<long long>(face.size()));
      for (int v : face) clean += ' ', put(v);
      clean += '\n';
    }
    const OpenMeshResult om = read_with_openmesh(path, &clean, "off", &faces);
    check_same_points(path, m.vertices, om.points);
    if (static_cast<long long>(om.face_count) != *nf)
      fail(path, "OpenMesh read " + std::to_string(om.face_count) + " faces, the header declares " +
                     std::to_string(*nf));
    if (!om.faces_match) fail(path, "OpenMesh read different face lists than the file has");
    m.faces = std::move(faces);
  } else {
    // Its counts cannot be checked against the file size before OpenMesh allocates for them.
    fail(path, "binary OFF is not supported (convert it to ASCII OFF, PLY or OBJ)");
  }
  return m;
}

// ---------------------------------------------------------------------------------------------------------
// STL: OpenMesh merges equal positions and silently skips facets whose merged corners repeat, which would
// shift ids; so facets are read here (binary: the float32 values; ASCII: exact doubles), merged by exact
// position in order of first appearance as OpenMesh does, and OpenMesh's face count must match the
// facets with three distinct corners.
RawMesh load_stl(const std::string& path, const std::string& file_text) {
  // An ASCII STL may start with a UTF-8 byte-order mark (a binary one may too, in its free-form header).
  const std::size_t bom = utf8_bom_length(file_text);
  const std::string text_without_bom = bom ? file_text.substr(bom) : std::string();
  const std::string& text = bom ? text_without_bom : file_text;
  std::vector<Point3> corners;
  bool is_ascii = false;
  {
    auto t = tokens(std::string_view(text).substr(0, std::min<size_t>(text.size(), 512)));
    is_ascii = !t.empty() && t[0] == "solid" && text.find("facet") != std::string::npos &&
               text.find("vertex") != std::string::npos;
  }
  // A binary file's size is exactly 84 + 50 n; prefer binary when that holds (binary headers may say "solid").
  bool binary_size = false;
  if (file_text.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, file_text.data() + 80, 4);
    binary_size = file_text.size() == 84 + 50ull * n;
  }
  if (binary_size) is_ascii = false;
  if (!is_ascii && !binary_size)
    if (auto enc = unreadable_encoding(file_text); enc && enc->find("UTF") != std::string::npos)
      fail(path, *enc + "; save it as ASCII or UTF-8 text");
  if (is_ascii) {
    for_each_line(text, [&](long n, std::string_view line) {
      auto t = tokens(line);
      if (t.empty() || t[0] != "vertex") return true;
      if (t.size() < 4) fail(path, "line " + std::to_string(n) + ": vertex needs 3 coordinates");
      Point3 p;
      for (int k = 0; k < 3; ++k) p[k] = text_coordinate(path, n, t[k + 1]);
      corners.push_back(p);
      return true;
    });
    if (corners.size() % 3 != 0) fail(path, "a facet does not have 3 vertices (truncated?)");
    // Without counts, a cut-off file is recognised by its missing last line.
    const auto last = text.find_last_not_of(" \t\r\n");
    const auto line_start = text.find_last_of('\n', last);
    auto t = tokens(std::string_view(text).substr(line_start == std::string::npos ? 0 : line_start + 1));
    if (t.empty() || t[0] != "endsolid") fail(path, "truncated ASCII STL (does not end with 'endsolid')");
  } else {
    const std::string& bin = file_text;
    if (bin.size() < 84) fail(path, "truncated binary STL (shorter than its 84-byte header)");
    std::uint32_t n = 0;
    std::memcpy(&n, bin.data() + 80, 4);
    if (bin.size() < 84 + 50ull * n)
      fail(path, "truncated binary STL: header declares " + std::to_string(n) + " facets, file holds " +
                     std::to_string((bin.size() - 84) / 50));
    for (std::uint32_t f = 0; f < n; ++f)
      for (int c = 0; c < 3; ++c) {
        float xyz[3];
        std::memcpy(xyz, bin.data() + 84 + 50ull * f + 12 + 12 * c, 12);
        corners.push_back({xyz[0], xyz[1], xyz[2]});
      }
  }
  RawMesh m;
  check_finite(path, corners);
  if (corners.empty()) fail(path, "no faces");
  std::map<std::array<double, 3>, int> index;
  size_t nondegenerate = 0;
  for (size_t f = 0; f < corners.size() / 3; ++f) {
    std::vector<int> face;
    for (int c = 0; c < 3; ++c) {
      const Point3& p = corners[3 * f + c];
      auto [it, inserted] = index.emplace(std::array<double, 3>{p.x, p.y, p.z}, static_cast<int>(m.vertices.size()));
      if (inserted) m.vertices.push_back(p);
      face.push_back(it->second);
    }
    if (face[0] != face[1] && face[1] != face[2] && face[0] != face[2]) ++nondegenerate;
    m.faces.push_back(std::move(face));
  }
  // OpenMesh's STL reader takes values beyond float32 (as +-FLT_MAX) and counts facets only.
  const OpenMeshResult om = is_ascii && bom ? read_with_openmesh(path, &text, "stl") : read_with_openmesh(path);
  if (om.faces.size() != nondegenerate)
    fail(path, "OpenMesh read " + std::to_string(om.faces.size()) + " facets, the file has " +
                   std::to_string(nondegenerate) + " with three distinct corners");
  return m;
}

// ---------------------------------------------------------------------------------------------------------
RawMesh load_raw(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a mesh file");
  const auto dot = path.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : lower(path.substr(dot));
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    fail(path, "unknown extension '" + ext + "' (expected .obj, .ply, .off or .stl)");
  std::string text = read_file(path);
  if (text.empty()) fail(path, "empty file");
  // A UTF-8 byte-order mark is skipped (then OpenMesh reads our copy without it); STL decides for itself.
  const bool altered = ext != ".stl" && utf8_bom_length(text) > 0;
  if (altered) text.erase(0, utf8_bom_length(text));
  if (text.empty()) fail(path, "empty file");
  RawMesh m = ext == ".obj" ? load_obj(path, text, altered)
              : ext == ".off" ? load_off(path, text)
              : ext == ".ply" ? load_ply(path, text, altered)
                              : load_stl(path, text);
  check_finite(path, m.vertices);
  check_faces_valid(path, m);
  return m;
}

// Appends the mesh `m` read from `path` (or named `path`) to `scene`: fan triangulation, ids, the exact
// zero-area drop, objects (groups, else connected components named "<file>#component<k>").
void append_mesh(Scene& scene, const std::string& path, const RawMesh& m, bool report_drops) {
  if (scene.vertices.size() + m.vertices.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
    fail(path, "too many vertices");
  const int base = static_cast<int>(scene.vertices.size());
  scene.vertices.insert(scene.vertices.end(), m.vertices.begin(), m.vertices.end());

  // Fan triangulation and ids (before dropping), then the exact zero-area test.
  struct Tri {
    std::int64_t id;
    std::array<int, 3> v;
    int face;
  };
  std::vector<Tri> kept;
  std::int64_t dropped = 0;
  for (size_t f = 0; f < m.faces.size(); ++f) {
    const auto& face = m.faces[f];
    for (size_t k = 1; k + 1 < face.size(); ++k) {
      const std::int64_t id = scene.faces_read++;
      const std::array<int, 3> v{base + face[0], base + face[k], base + face[k + 1]};
      if (collinear(scene.vertices[v[0]], scene.vertices[v[1]], scene.vertices[v[2]])) {
        ++dropped;
        continue;
      }
      kept.push_back({id, v, static_cast<int>(f)});
    }
  }
  scene.degenerate_dropped += dropped;
  if (dropped > 0 && report_drops) std::cerr << path << ": dropped " << dropped << " degenerate triangles\n";

  // Objects: OBJ groups when present, else connected components (over kept triangles' shared vertices).
  std::vector<int> key(kept.size());
  std::vector<std::string> names;
  if (!m.face_group.empty()) {
    for (size_t i = 0; i < kept.size(); ++i) key[i] = m.face_group[kept[i].face];
    names = m.group_names;
  } else {
    UnionFind uf(m.vertices.size());
    for (const auto& t : kept) {
      uf.unite(t.v[0] - base, t.v[1] - base);
      uf.unite(t.v[0] - base, t.v[2] - base);
    }
    for (size_t i = 0; i < kept.size(); ++i) key[i] = uf.find(kept[i].v[0] - base);
  }
  // Number objects in order of their first triangle; groups/components without triangles are not objects.
  std::map<int, int> object_of_key;
  const std::string file_name = std::filesystem::path(path).filename().string();
  for (size_t i = 0; i < kept.size(); ++i) {
    auto [it, inserted] = object_of_key.emplace(key[i], static_cast<int>(scene.objects.size()));
    if (inserted) {
      const std::string name = names.empty()
                                   ? file_name + "#component" + std::to_string(object_of_key.size() - 1)
                                   : names[key[i]];
      scene.objects.push_back({name});
    }
    scene.triangles.push_back({kept[i].id, kept[i].v, it->second});
  }
}

}  // namespace

Scene load_scenes(const std::vector<std::string>& paths) {
  if (paths.empty()) throw InputError("no scene files given");
  Scene scene;
  for (const std::string& path : paths) append_mesh(scene, path, load_raw(path), true);
  return scene;
}

Scene scene_from_arrays(const std::vector<Point3>& vertices, const std::vector<std::array<std::int64_t, 3>>& faces,
                        const std::string& name) {
  RawMesh m;
  m.vertices = vertices;
  const auto nv = static_cast<std::int64_t>(vertices.size());
  if (nv > std::numeric_limits<int>::max()) fail("V", "too many vertices");
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (!std::isfinite(vertices[i].x) || !std::isfinite(vertices[i].y) || !std::isfinite(vertices[i].z))
      fail("V", "vertex " + std::to_string(i) + " has a non-finite coordinate");
  m.faces.reserve(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (const std::int64_t v : faces[f])
      if (v < 0 || v >= nv)
        fail("F", "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", out of range [0, " +
                      std::to_string(nv) + ")");
    m.faces.push_back({static_cast<int>(faces[f][0]), static_cast<int>(faces[f][1]), static_cast<int>(faces[f][2])});
  }
  Scene scene;
  append_mesh(scene, name, m, false);
  return scene;
}

Scene load_scene(const std::string& path) { return load_scenes({path}); }

}  // namespace exactvis
