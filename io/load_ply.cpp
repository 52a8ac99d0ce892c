#include "io/load_ply.hpp"

#include "io/openmesh_reader.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>

namespace exactvis::mesh_io {
namespace {

// PLY: the header, the vertex coordinates and the faces are read here, exactly (ASCII: the doubles nearest
// to the decimals, whatever the declared type; binary: float32 and integers widen exactly, float64 as
// stored), because OpenMesh reads coordinates as float32 and cannot be asked to stop before it allocates.
// Element and list counts are checked against the bytes left before any loop or allocation; an ASCII integer
// must fit its declared type. OpenMesh then reads the (valid) file too and must find the same vertex count,
// coordinates (up to float rounding) and face lists.

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

const char* ply_name(PlyScalar t) {
  switch (t) {
    case PlyScalar::I8: return "char";
    case PlyScalar::U8: return "uchar";
    case PlyScalar::I16: return "short";
    case PlyScalar::U16: return "ushort";
    case PlyScalar::I32: return "int";
    case PlyScalar::U32: return "uint";
    case PlyScalar::F32: return "float";
    case PlyScalar::F64: return "double";
  }
  return "?";
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

// Range of an integer type.
std::pair<long long, long long> ply_range(PlyScalar t) {
  switch (t) {
    case PlyScalar::I8: return {INT8_MIN, INT8_MAX};
    case PlyScalar::U8: return {0, UINT8_MAX};
    case PlyScalar::I16: return {INT16_MIN, INT16_MAX};
    case PlyScalar::U16: return {0, UINT16_MAX};
    case PlyScalar::I32: return {INT32_MIN, INT32_MAX};
    case PlyScalar::U32: return {0, UINT32_MAX};
    default: return {0, 0};
  }
}

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
  std::size_t data_offset = 0;  // first byte after the end_header line
  long data_line = 1;           // line number of that byte
};

PlyHeader read_ply_header(const std::string& path, const std::string& text) {
  PlyHeader h;
  bool have_format = false, ended = false;
  std::size_t start = 0;
  long line_no = 0;
  while (start < text.size() && !ended) {
    std::size_t end = text.find('\n', start);
    const std::size_t next = end == std::string::npos ? text.size() : end + 1;
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++line_no;
    start = next;
    const std::string where = "header line " + std::to_string(line_no) + ": ";
    auto t = tokens(line);
    if (line_no == 1) {
      if (t.empty() || t[0] != "ply") {
        if (auto enc = unreadable_encoding(text)) fail(path, *enc + "; save it as ASCII or UTF-8 text");
        fail(path, "not a PLY file (must start with 'ply')");
      }
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
      h.data_line = line_no + 1;
    }
    // Other lines are ignored, as OpenMesh does (some exporters write free text, e.g. "Created by ...").
  }
  if (line_no == 0) fail(path, "empty file");
  if (!ended) fail(path, "truncated header (no end_header)");
  if (!have_format) fail(path, "header lacks a format line");
  return h;
}

// The name of a value in messages, "face 12 index 3", built only when a message needs it (reading
// millions of values must not build millions of strings).
struct ValueName {
  const std::string& element;  // "vertex", "face", "element 'NAME'"
  long long index;
  const char* part = "";       // e.g. " index", " (list count)"
  long long item = -1;         // with part " index": the item
  std::string str() const {
    return element + " " + std::to_string(index) + part + (item >= 0 ? " " + std::to_string(item) : "");
  }
  ValueName with(const char* p, long long i = -1) const { return {element, index, p, i}; }
};

// Reads the data section value by value (ASCII tokens or binary scalars), failing on truncation, on ASCII
// integers outside their declared type, and on list counts larger than the bytes left can hold.
struct PlyDataReader {
  const std::string& path;
  const std::string& text;
  PlyFormat format;
  std::size_t pos;
  long line;                                   // ASCII: line of the next byte
  std::vector<TokenReplacement> replacements;  // ASCII values beyond float32, for OpenMesh's copy
  std::string hint;                            // ASCII: the first list that ran past the end of its line

  [[noreturn]] void fail_data(const std::string& problem) const {
    fail(path, problem + (hint.empty() ? "" : "; " + hint));
  }

  bool ascii() const { return format == PlyFormat::Ascii; }
  std::size_t left() const { return text.size() - pos; }

  // ASCII: the next token (skipping whitespace, counting lines); empty at the end of the data.
  std::string_view token() {
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) {
      if (text[pos] == '\n') ++line;
      ++pos;
    }
    std::size_t e = pos;
    while (e < text.size() && !std::isspace(static_cast<unsigned char>(text[e]))) ++e;
    std::string_view tok(text.data() + pos, e - pos);
    pos = e;
    return tok;
  }

  // Exact value of the next scalar of type t (every PLY scalar is exactly a double), named `name` in messages.
  double scalar(PlyScalar t, const ValueName& name) {
    if (ascii()) {
      const std::string_view tok = token();
      if (tok.empty()) fail_data("truncated data: " + name.str() + " is missing");
      if (ply_is_float(t)) {
        auto v = parse_double(tok);
        if (!v) fail_data(name.str() + ": bad number '" + std::string(tok) + "'");
        if (beyond_float32(*v)) replacements.push_back(float32_stand_in(text, tok, *v));
        return *v;
      }
      auto v = parse_int(tok);
      if (!v) fail_data(name.str() + ": bad integer '" + std::string(tok) + "'");
      const auto [lo, hi] = ply_range(t);
      if (*v < lo || *v > hi)
        fail_data(name.str() + ": value " + std::string(tok) + " does not fit its type " + ply_name(t) + " [" +
                  std::to_string(lo) + ", " + std::to_string(hi) + "]");
      return static_cast<double>(*v);
    }
    const int n = ply_size(t);
    if (left() < static_cast<std::size_t>(n)) fail_data("truncated data: " + name.str() + " is missing");
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

  // A vertex coordinate: ASCII floats by the coordinate rule of text formats (text_coordinate), other
  // values as scalar(); non-finite values fail.
  double coordinate(PlyScalar t, const ValueName& name) {
    if (ascii() && ply_is_float(t)) {
      const std::string_view tok = token();
      if (tok.empty()) fail_data("truncated data: " + name.str() + " is missing");
      const auto v = parse_double(tok);
      if (!v || !std::isfinite(*v)) return text_coordinate(path, name.str() + ": ", tok);  // fails, with the message
      if (beyond_float32(*v)) replacements.push_back(float32_stand_in(text, tok, *v));
      return *v;
    }
    const double v = scalar(t, name);
    if (!std::isfinite(v)) fail(path, name.str() + " has a non-finite coordinate");
    return v;
  }

  // A list's item count, checked against the bytes left (an ASCII item takes at least 2 bytes but the last).
  long long list_count(const PlyProperty& p, const ValueName& name) {
    const double n = scalar(p.count_type, name.with(" (list count)"));
    if (n < 0) fail_data(name.str() + ": negative list count");
    const long double need = ascii() ? 2.0L * n - 1 : static_cast<long double>(n) * ply_size(p.type);
    if (need > static_cast<long double>(left()))
      fail_data(name.str() + ": list count " + std::to_string(static_cast<long long>(n)) +
                " is more than the rest of the file can hold");
    return static_cast<long long>(n);
  }

  // ASCII: called after each list item; remembers (once) the first list whose items run past the line
  // holding its count (legal, but the likely cause of a later error: a count larger than its list).
  void note_list_item(const ValueName& name, long count_line, long long n, long long& on_its_line) {
    if (!ascii()) return;
    if (line == count_line) {
      ++on_its_line;
    } else if (hint.empty()) {
      hint = name.str() + " (line " + std::to_string(count_line) + ") has list count " + std::to_string(n) +
             " but its line holds " + std::to_string(on_its_line) + " items";
    }
  }

  // Skips one property value (a list: its count, then that many items).
  void skip(const PlyProperty& p, const ValueName& name) {
    if (!p.is_list) {
      scalar(p.type, name);
      return;
    }
    const long long n = list_count(p, name);
    const long count_line = line;
    long long on_line = 0;
    for (long long k = 0; k < n; ++k) {
      scalar(p.type, name);
      note_list_item(name, count_line, n, on_line);
    }
  }

  // Fails unless `count` instances of element e can fit in the bytes left (each value takes at least one
  // byte in binary, two in ASCII but the last), so no loop or allocation runs on a corrupt count.
  void check_fits(const PlyElement& e) const {
    if (e.props.empty() || e.count == 0) return;
    long double per = 0;
    for (const auto& p : e.props) per += ascii() ? 2 : ply_size(p.is_list ? p.count_type : p.type);
    if (static_cast<long double>(e.count) * per > static_cast<long double>(left()) + 1)
      fail(path, "header declares " + std::to_string(e.count) + " '" + e.name +
                     "' elements, more than the file can hold (truncated or corrupt)");
  }
};

}  // namespace

RawMesh load_ply(const std::string& path, const std::string& text, bool altered) {
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
  int ix[3] = {-1, -1, -1};
  for (std::size_t i = 0; i < vertex->props.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (ix[k] < 0 && vertex->props[i].name == std::string(1, "xyz"[k])) {
        if (vertex->props[i].is_list) fail(path, std::string("vertex property ") + "xyz"[k] + " is a list");
        ix[k] = static_cast<int>(i);
      }
  for (int k = 0; k < 3; ++k)
    if (ix[k] < 0) fail(path, std::string("vertex element lacks property ") + "xyz"[k]);
  int indices = -1;  // the face property holding the vertex index list (OpenMesh's names)
  for (std::size_t i = 0; i < face->props.size(); ++i)
    if (indices < 0 && (face->props[i].name == "vertex_indices" || face->props[i].name == "vertex_index"))
      indices = static_cast<int>(i);
  if (indices < 0) fail(path, "face element lacks the list property vertex_indices");
  const PlyProperty& index_list = face->props[indices];
  if (!index_list.is_list) fail(path, "face property " + index_list.name + " is not a list");
  if (ply_is_float(index_list.type)) fail(path, "face property " + index_list.name + " must hold integers");

  PlyDataReader in{path, text, h.format, h.data_offset, h.data_line, {}, {}};
  const std::string vertex_label = "vertex", face_label = "face";
  RawMesh m;
  for (const auto& e : h.elements) {
    in.check_fits(e);
    if (e.props.empty()) continue;  // nothing to read (and no loop over a huge empty count)
    if (&e == vertex) {
      m.vertices.reserve(static_cast<std::size_t>(nv));
      for (long long i = 0; i < nv; ++i) {
        const ValueName what{vertex_label, i};
        Point3 p;
        for (std::size_t j = 0; j < vertex->props.size(); ++j) {
          const PlyProperty& prop = vertex->props[j];
          const int k = static_cast<int>(j) == ix[0] ? 0 : static_cast<int>(j) == ix[1] ? 1 : static_cast<int>(j) == ix[2] ? 2 : -1;
          if (k < 0) {
            in.skip(prop, what);
            continue;
          }
          p[k] = in.coordinate(prop.type, what);
        }
        m.vertices.push_back(p);
      }
    } else if (&e == face) {
      m.faces.reserve(static_cast<std::size_t>(nf));
      for (long long f = 0; f < nf; ++f) {
        const ValueName what{face_label, f};
        for (std::size_t j = 0; j < face->props.size(); ++j) {
          if (static_cast<int>(j) != indices) {
            in.skip(face->props[j], what);
            continue;
          }
          const long long n = in.list_count(index_list, what);
          const long count_line = in.line;
          std::vector<int> list;
          list.reserve(static_cast<std::size_t>(n));
          long long on_line = 0;
          for (long long k = 0; k < n; ++k) {
            const double v = in.scalar(index_list.type, what.with(" index", k));
            in.note_list_item(what, count_line, n, on_line);
            if (v < 0 || v >= static_cast<double>(nv))
              in.fail_data(what.str() + " refers to vertex " + std::to_string(static_cast<long long>(v)) +
                           ", out of range [0, " + std::to_string(nv) + ")");
            list.push_back(static_cast<int>(v));
          }
          m.faces.push_back(std::move(list));
        }
      }
    } else {
      const std::string label = "element '" + e.name + "'";
      for (long long i = 0; i < e.count; ++i)
        for (const auto& p : e.props) in.skip(p, ValueName{label, i});
    }
  }
  if (in.ascii() && !in.token().empty())
    in.fail_data("data continues after the last element the header declares (line " + std::to_string(in.line) +
                 "; wrong element or list counts?)");

  std::string copy;
  if (altered || !in.replacements.empty()) copy = with_replacements(text, in.replacements);
  const OpenMeshResult om = copy.empty() ? read_with_openmesh(path, nullptr, "", &m.faces)
                                          : read_with_openmesh(path, &copy, "ply", &m.faces);
  if (static_cast<long long>(om.points.size()) != nv)
    fail(path, "OpenMesh read " + std::to_string(om.points.size()) + " vertices, the header declares " +
                   std::to_string(nv) + " (truncated?)");
  if (static_cast<long long>(om.face_count) != nf)
    fail(path, "OpenMesh read " + std::to_string(om.face_count) + " faces, the header declares " +
                   std::to_string(nf) + " (truncated?)");
  check_same_points(path, m.vertices, om.points);
  if (!om.faces_match) fail(path, "OpenMesh read different face lists than the file has");
  return m;
}

}  // namespace exactvis::mesh_io
