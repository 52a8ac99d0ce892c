#include "io/load_scene.hpp"

#include "kernel/predicates.hpp"
#include "util/union_find.hpp"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>
#include <string_view>

namespace exactvis {
namespace {

// ---------------------------------------------------------------------------------------------------------
// What one file contributes, in file order.
struct RawMesh {
  std::vector<Point3> vertices;
  std::vector<std::vector<int>> faces;     // local vertex indices, as in the file
  std::vector<int> face_group;             // OBJ only: group per face (empty: use components)
  std::vector<std::string> group_names;
};

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw InputError(path + ": " + problem);
}

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

// Exact double from text (correctly rounded by from_chars); nullopt if `tok` is not a number.
std::optional<double> parse_double(std::string_view tok) {
  if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
  double v = 0;
  auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ptr != tok.data() + tok.size()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) {
    // Overflow is a non-finite coordinate; underflow rounds to a (sub)normal or zero, which strtod does exactly.
    v = std::strtod(std::string(tok).c_str(), nullptr);
  } else if (ec != std::errc()) {
    return std::nullopt;
  }
  return v;
}

std::optional<long long> parse_int(std::string_view tok) {
  if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
  long long v = 0;
  auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec != std::errc() || ptr != tok.data() + tok.size()) return std::nullopt;
  return v;
}

// Whitespace-separated tokens of a line.
std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

// Calls f(line_number, line) for each line of `text` (without the end-of-line characters).
template <class F>
void for_each_line(const std::string& text, F&& f) {
  size_t start = 0;
  long line_no = 1;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!f(line_no, line)) return;
    start = end + 1;
    ++line_no;
  }
}

// ---------------------------------------------------------------------------------------------------------
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
    std::vector<int> f;
    f.reserve(hs.size());
    for (auto h : hs)
      f.push_back(h.idx() >= 0 && static_cast<size_t>(h.idx()) < file_index.size() ? file_index[h.idx()] : -1);
    faces.push_back(std::move(f));
    return Base::add_face(hs);
  }
};

// OpenMesh reports problems on its own streams; our errors say it better, and a non-manifold mesh would
// print one line per face. Silence them while reading.
struct QuietOpenMesh {
  QuietOpenMesh() { ::omerr().disable(); ::omlog().disable(); ::omout().disable(); }
  ~QuietOpenMesh() { ::omerr().enable(); ::omlog().enable(); ::omout().enable(); }
};

struct OpenMeshResult {
  std::vector<OpenMesh::Vec3f> points;
  std::vector<std::vector<int>> faces;
};

// Reads `path` with OpenMesh; if `normalized` is given, OpenMesh reads that text instead (as format `ext`).
OpenMeshResult read_with_openmesh(const std::string& path, const std::string* normalized = nullptr,
                                  const std::string& ext = "") {
  OmMesh mesh;
  RecordingImporter importer(mesh);
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
  return {std::move(importer.points), std::move(importer.faces)};
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

// Our exact double must be what OpenMesh's float32 parse saw (a guard against the two parsers disagreeing).
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

// ---------------------------------------------------------------------------------------------------------
// OBJ: OpenMesh parses floats, drops repeated vertices within a face and does not keep groups, so the
// vertices (exact doubles), faces (as written) and groups come from our line scan; OpenMesh's reading must
// agree with it (same vertex and face counts, same coordinates up to float rounding, same vertex sets).
RawMesh load_obj(const std::string& path, const std::string& text) {
  RawMesh m;
  std::map<std::string, int> group_of_name;
  int current_group = -1;
  bool has_groups = false;
  // First pass: count vertices so forward references can be range-checked.
  for_each_line(text, [&](long line_no, std::string_view line) {
    auto t = tokens(line);
    if (t.empty() || t[0] != "v") return true;
    if (t.size() < 4) fail(path, "line " + std::to_string(line_no) + ": vertex needs 3 coordinates");
    Point3 p;
    for (int k = 0; k < 3; ++k) {
      auto v = parse_double(t[k + 1]);
      if (!v) fail(path, "line " + std::to_string(line_no) + ": bad coordinate '" + std::string(t[k + 1]) + "'");
      if (!std::isfinite(*v)) fail(path, "line " + std::to_string(line_no) + ": non-finite coordinate '" +
                                         std::string(t[k + 1]) + "'");
      p[k] = *v;
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

  const OpenMeshResult om = read_with_openmesh(path);
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
RawMesh load_off(const std::string& path, const std::string& text) {
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
          if (head.size() == 1 && t.find("BINARY") != std::string_view::npos) binary = true;
        }
      }
      if (binary && head.size() >= 1) return false;  // binary body: OpenMesh only
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
      const std::string where = "line " + std::to_string(lines[i].first) + ": ";
      if (t.size() < 3) fail(path, where + "vertex needs 3 coordinates");
      Point3 p;
      for (int k = 0; k < 3; ++k) {
        auto v = parse_double(t[k]);
        if (!v) fail(path, where + "bad coordinate '" + std::string(t[k]) + "'");
        if (!std::isfinite(*v)) fail(path, where + "non-finite coordinate '" + std::string(t[k]) + "'");
        p[k] = *v;
      }
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
    // OpenMesh's OFF reader does not skip '#' comments (it misreads counts and may allocate wildly), so it
    // reads the file with comments and blank lines removed.
    std::string clean = std::string(head[0]) + "\n" + std::string(head[1]) + " " + std::string(head[2]) + " " +
                        std::string(head[3]) + "\n";
    for (const auto& l : lines) {
      clean.append(l.second.data(), l.second.size());
      clean += '\n';
    }
    const OpenMeshResult om = read_with_openmesh(path, &clean, "off");
    check_same_points(path, m.vertices, om.points);
    if (static_cast<long long>(om.faces.size()) != *nf)
      fail(path, "OpenMesh read " + std::to_string(om.faces.size()) + " faces, the header declares " +
                     std::to_string(*nf));
    if (om.faces != faces) fail(path, "OpenMesh read different face lists than the file has");
    m.faces = std::move(faces);
  } else {
    // Its counts cannot be checked against the file size before OpenMesh allocates for them.
    fail(path, "binary OFF is not supported (convert it to ASCII OFF, PLY or OBJ)");
  }
  return m;
}

// ---------------------------------------------------------------------------------------------------------
// PLY: the header and the vertex coordinates are read here, exactly (ASCII: correctly rounded doubles from
// the text; binary: float32 and integers widen exactly, float64 as stored), because OpenMesh reads PLY
// coordinates as float32. Faces come from OpenMesh, whose vertex count and coordinates (up to float
// rounding) must agree with ours. Counts are checked against the file size before anything allocates.

enum class PlyScalar { I8, U8, I16, U16, I32, U32, F32, F64 };

std::optional<PlyScalar> ply_scalar(std::string_view name) {
  if (name == "char" || name == "int8") return PlyScalar::I8;
  if (name == "uchar" || name == "uint8") return PlyScalar::U8;
  if (name == "short" || name == "int16") return PlyScalar::I16;
  if (name == "ushort" || name == "uint16") return PlyScalar::U16;
  if (name == "int" || name == "int32") return PlyScalar::I32;
  if (name == "uint" || name == "uint32") return PlyScalar::U32;
  if (name == "float" || name == "float32") return PlyScalar::F32;
  if (name == "double" || name == "float64") return PlyScalar::F64;
  return std::nullopt;
}

int ply_size(PlyScalar t) {
  switch (t) {
    case PlyScalar::I8: case PlyScalar::U8: return 1;
    case PlyScalar::I16: case PlyScalar::U16: return 2;
    case PlyScalar::I32: case PlyScalar::U32: case PlyScalar::F32: return 4;
    case PlyScalar::F64: return 8;
  }
  return 8;
}

bool ply_is_float(PlyScalar t) { return t == PlyScalar::F32 || t == PlyScalar::F64; }

struct PlyProperty {
  std::string name;
  PlyScalar type = PlyScalar::F32;    // the item type for a list
  bool is_list = false;
  PlyScalar count_type = PlyScalar::U8;
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> props;
};

enum class PlyFormat { Ascii, BinaryLE, BinaryBE };

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  size_t data_offset = 0;  // first byte after the end_header line
};

PlyHeader read_ply_header(const std::string& path, const std::string& text) {
  PlyHeader h;
  bool have_format = false, ended = false;
  size_t start = 0;
  long line_no = 0;
  while (start < text.size() && !ended) {
    size_t end = text.find('\n', start);
    const size_t next = end == std::string::npos ? text.size() : end + 1;
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++line_no;
    start = next;
    const std::string where = "header line " + std::to_string(line_no) + ": ";
    auto t = tokens(line);
    if (line_no == 1) {
      if (t.empty() || t[0] != "ply") fail(path, "not a PLY file (must start with 'ply')");
      continue;
    }
    if (t.empty()) continue;
    if (t[0] == "format") {
      if (t.size() != 3 || t[2] != "1.0") fail(path, where + "bad format line (expected 'format TYPE 1.0')");
      if (t[1] == "ascii") h.format = PlyFormat::Ascii;
      else if (t[1] == "binary_little_endian") h.format = PlyFormat::BinaryLE;
      else if (t[1] == "binary_big_endian") h.format = PlyFormat::BinaryBE;
      else fail(path, where + "unknown format '" + std::string(t[1]) + "'");
      have_format = true;
    } else if (t[0] == "element") {
      if (t.size() != 3) fail(path, where + "bad element line (expected 'element NAME COUNT')");
      auto c = parse_int(t[2]);
      if (!c || *c < 0) fail(path, where + "bad element count '" + std::string(t[2]) + "'");
      h.elements.push_back({std::string(t[1]), *c, {}});
    } else if (t[0] == "property") {
      if (h.elements.empty()) fail(path, where + "property before any element");
      PlyProperty p;
      if (t.size() == 5 && t[1] == "list") {
        auto ct = ply_scalar(t[2]), it = ply_scalar(t[3]);
        if (!ct || !it) fail(path, where + "unknown property type");
        if (ply_is_float(*ct)) fail(path, where + "list count type must be an integer type");
        p = {std::string(t[4]), *it, true, *ct};
      } else if (t.size() == 3) {
        auto ty = ply_scalar(t[1]);
        if (!ty) fail(path, where + "unknown property type '" + std::string(t[1]) + "'");
        p = {std::string(t[2]), *ty, false, PlyScalar::U8};
      } else {
        fail(path, where + "bad property line");
      }
      h.elements.back().props.push_back(std::move(p));
    } else if (t[0] == "end_header") {
      ended = true;
      h.data_offset = start;
    }
    // Other lines are ignored, as OpenMesh does (some exporters write free text, e.g. "Created by ...").
  }
  if (line_no == 0) fail(path, "empty file");
  if (!ended) fail(path, "truncated header (no end_header)");
  if (!have_format) fail(path, "header lacks a format line");
  return h;
}

// Reads the data section value by value (ASCII tokens or binary scalars), failing on truncation.
struct PlyDataReader {
  const std::string& path;
  const std::string& text;
  PlyFormat format;
  size_t pos;

  // Exact value of the next scalar of type t (every PLY scalar is exactly a double). `what` names it for errors.
  double scalar(PlyScalar t, const std::string& what) {
    if (format == PlyFormat::Ascii) {
      while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
      size_t e = pos;
      while (e < text.size() && !std::isspace(static_cast<unsigned char>(text[e]))) ++e;
      if (e == pos) fail(path, "truncated data: " + what + " is missing");
      std::string_view tok(text.data() + pos, e - pos);
      pos = e;
      if (ply_is_float(t)) {
        auto v = parse_double(tok);
        if (!v) fail(path, what + ": bad number '" + std::string(tok) + "'");
        // OpenMesh's ASCII reader (which reads the faces) parses floats with a stream that fails for good on
        // a finite value beyond float32's range, so the rest of its reading could not be trusted.
        if (std::isfinite(*v) && std::fabs(*v) > std::numeric_limits<float>::max())
          fail(path, what + ": value '" + std::string(tok) +
                         "' is beyond float32's range, which OpenMesh cannot read in ASCII PLY (use binary PLY)");
        return *v;
      }
      auto v = parse_int(tok);
      if (!v) fail(path, what + ": bad integer '" + std::string(tok) + "'");
      return static_cast<double>(*v);
    }
    const int n = ply_size(t);
    if (text.size() - pos < static_cast<size_t>(n)) fail(path, "truncated data: " + what + " is missing");
    unsigned char b[8];
    std::memcpy(b, text.data() + pos, n);
    pos += n;
    const bool big = format == PlyFormat::BinaryBE;
    if (big != (std::endian::native == std::endian::big)) std::reverse(b, b + n);
    switch (t) {
      case PlyScalar::I8: { std::int8_t v; std::memcpy(&v, b, 1); return v; }
      case PlyScalar::U8: return b[0];
      case PlyScalar::I16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
      case PlyScalar::U16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
      case PlyScalar::I32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
      case PlyScalar::U32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
      case PlyScalar::F32: { float v; std::memcpy(&v, b, 4); return v; }
      case PlyScalar::F64: { double v; std::memcpy(&v, b, 8); return v; }
    }
    return 0;
  }

  // Skips one property value (a list: its count, then that many items).
  void skip(const PlyProperty& p, const std::string& what) {
    if (!p.is_list) {
      scalar(p.type, what);
      return;
    }
    const double n = scalar(p.count_type, what + " (list count)");
    if (n < 0) fail(path, what + ": negative list count");
    for (long long k = 0; k < static_cast<long long>(n); ++k) scalar(p.type, what);
  }
};

RawMesh load_ply(const std::string& path, const std::string& text) {
  const PlyHeader h = read_ply_header(path, text);
  const PlyElement* vertex = nullptr;
  const PlyElement* face = nullptr;
  for (const auto& e : h.elements) {
    if (e.name == "vertex" && !vertex) vertex = &e;
    if (e.name == "face" && !face) face = &e;
  }
  if (!vertex || !face) fail(path, "header lacks a vertex or face element");
  const long long nv = vertex->count, nf = face->count;
  if (nf == 0) fail(path, "no faces");
  const bool ascii = h.format == PlyFormat::Ascii;
  // Minimum bytes per vertex / face: ascii "0 0 0\n" and "3 0 1 2\n"; binary 3 bytes and 4 bytes.
  const long double need = ascii ? nv * 6.0L + nf * 8.0L : nv * 3.0L + nf * 4.0L;
  if (need > text.size())
    fail(path, "header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                   " faces, more than the file can hold (truncated or corrupt)");
  int ix[3] = {-1, -1, -1};
  for (size_t i = 0; i < vertex->props.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (ix[k] < 0 && vertex->props[i].name == std::string(1, "xyz"[k])) {
        if (vertex->props[i].is_list) fail(path, std::string("vertex property ") + "xyz"[k] + " is a list");
        ix[k] = static_cast<int>(i);
      }
  for (int k = 0; k < 3; ++k)
    if (ix[k] < 0) fail(path, std::string("vertex element lacks property ") + "xyz"[k]);

  PlyDataReader in{path, text, h.format, h.data_offset};
  for (const auto& e : h.elements) {
    if (&e == vertex) break;
    if (e.props.empty()) continue;  // nothing to skip (and no loop over a huge empty count)
    // Each value takes at least one byte, so truncation ends this loop within the file's size.
    for (long long i = 0; i < e.count; ++i)
      for (const auto& p : e.props) in.skip(p, "element '" + e.name + "' " + std::to_string(i));
  }
  // Vertex data size check before allocating: binary sizes are known; an ASCII value takes >= 2 bytes.
  long double per_vertex = 0;
  for (const auto& p : vertex->props)
    per_vertex += ascii ? 2 : ply_size(p.is_list ? p.count_type : p.type);
  if (static_cast<long double>(nv) * per_vertex > static_cast<long double>(text.size() - in.pos) + 1)
    fail(path, "header declares " + std::to_string(nv) + " vertices, more than the file can hold (truncated or corrupt)");
  RawMesh m;
  m.vertices.reserve(static_cast<size_t>(nv));
  for (long long i = 0; i < nv; ++i) {
    const std::string what = "vertex " + std::to_string(i);
    Point3 p;
    for (size_t j = 0; j < vertex->props.size(); ++j) {
      const PlyProperty& prop = vertex->props[j];
      const int k = static_cast<int>(j) == ix[0] ? 0 : static_cast<int>(j) == ix[1] ? 1 : static_cast<int>(j) == ix[2] ? 2 : -1;
      if (k < 0) {
        in.skip(prop, what);
        continue;
      }
      const double v = in.scalar(prop.type, what);
      if (!std::isfinite(v)) fail(path, what + " has a non-finite coordinate");
      p[k] = v;
    }
    m.vertices.push_back(p);
  }

  const OpenMeshResult om = read_with_openmesh(path);
  if (static_cast<long long>(om.points.size()) != nv)
    fail(path, "OpenMesh read " + std::to_string(om.points.size()) + " vertices, the header declares " +
                   std::to_string(nv) + " (truncated?)");
  if (static_cast<long long>(om.faces.size()) != nf)
    fail(path, "OpenMesh read " + std::to_string(om.faces.size()) + " faces, the header declares " +
                   std::to_string(nf) + " (truncated?)");
  check_same_points(path, m.vertices, om.points);
  m.faces = om.faces;
  return m;
}

// ---------------------------------------------------------------------------------------------------------
// STL: OpenMesh merges equal positions and silently skips facets whose merged corners repeat, which would
// shift ids; so facets are read here (binary: the float32 values; ASCII: exact doubles), merged by exact
// position in order of first appearance as OpenMesh does, and OpenMesh's face count must match the
// facets with three distinct corners.
RawMesh load_stl(const std::string& path, const std::string& text) {
  std::vector<Point3> corners;
  bool is_ascii = false;
  {
    auto t = tokens(std::string_view(text).substr(0, std::min<size_t>(text.size(), 512)));
    is_ascii = !t.empty() && t[0] == "solid" && text.find("facet") != std::string::npos &&
               text.find("vertex") != std::string::npos;
  }
  // A binary file's size is exactly 84 + 50 n; prefer binary when that holds (binary headers may say "solid").
  if (text.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, text.data() + 80, 4);
    if (text.size() == 84 + 50ull * n) is_ascii = false;
  }
  if (is_ascii) {
    for_each_line(text, [&](long n, std::string_view line) {
      auto t = tokens(line);
      if (t.empty() || t[0] != "vertex") return true;
      if (t.size() < 4) fail(path, "line " + std::to_string(n) + ": vertex needs 3 coordinates");
      Point3 p;
      for (int k = 0; k < 3; ++k) {
        auto v = parse_double(t[k + 1]);
        if (!v) fail(path, "line " + std::to_string(n) + ": bad coordinate '" + std::string(t[k + 1]) + "'");
        if (!std::isfinite(*v)) fail(path, "line " + std::to_string(n) + ": non-finite coordinate");
        p[k] = *v;
      }
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
    if (text.size() < 84) fail(path, "truncated binary STL (shorter than its 84-byte header)");
    std::uint32_t n = 0;
    std::memcpy(&n, text.data() + 80, 4);
    if (text.size() < 84 + 50ull * n)
      fail(path, "truncated binary STL: header declares " + std::to_string(n) + " facets, file holds " +
                     std::to_string((text.size() - 84) / 50));
    for (std::uint32_t f = 0; f < n; ++f)
      for (int c = 0; c < 3; ++c) {
        float xyz[3];
        std::memcpy(xyz, text.data() + 84 + 50ull * f + 12 + 12 * c, 12);
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
  const OpenMeshResult om = read_with_openmesh(path);
  if (om.faces.size() != nondegenerate)
    fail(path, "OpenMesh read " + std::to_string(om.faces.size()) + " facets, the file has " +
                   std::to_string(nondegenerate) + " with three distinct corners");
  return m;
}

// ---------------------------------------------------------------------------------------------------------
RawMesh load_raw(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : lower(path.substr(dot));
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    fail(path, "unknown extension '" + ext + "' (expected .obj, .ply, .off or .stl)");
  const std::string text = read_file(path);
  if (text.empty()) fail(path, "empty file");
  RawMesh m = ext == ".obj" ? load_obj(path, text)
              : ext == ".off" ? load_off(path, text)
              : ext == ".ply" ? load_ply(path, text)
                              : load_stl(path, text);
  check_finite(path, m.vertices);
  check_faces_valid(path, m);
  return m;
}

}  // namespace

Scene load_scenes(const std::vector<std::string>& paths) {
  if (paths.empty()) throw InputError("no scene files given");
  Scene scene;
  for (const std::string& path : paths) {
    const RawMesh m = load_raw(path);
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
    if (dropped > 0) std::cerr << path << ": dropped " << dropped << " degenerate triangles\n";

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
  return scene;
}

Scene load_scene(const std::string& path) { return load_scenes({path}); }

}  // namespace exactvis
