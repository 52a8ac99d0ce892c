#include "io/quake3_bsp.hpp"

#include "io/load_scene.hpp"
#include "io/zip_archive.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace exactvis::quake3 {

namespace {

constexpr int kLumpCount = 17;
enum Lump {
  kEntities = 0, kShaders, kPlanes, kNodes, kLeaves, kLeafFaces, kLeafBrushes, kModels, kBrushes,
  kBrushSides, kVertices, kMeshVertices, kEffects, kFaces, kLightmaps, kLightVolumes, kVisData
};
constexpr const char* kLumpNames[kLumpCount] = {
    "entities", "shaders", "planes", "nodes", "leaves", "leaf faces", "leaf brushes", "models", "brushes",
    "brush sides", "vertices", "mesh vertices", "effects", "faces", "lightmaps", "light volumes", "visdata"};
constexpr std::int64_t kEntrySize[kLumpCount] = {1, 72, 16, 36, 48, 4, 4, 40, 12, 8, 44, 4, 72, 104, 49152, 8, 1};
constexpr std::int64_t kHeaderBytes = 8 + 8 * kLumpCount;

// Bounds-checked little-endian reads from the file's bytes, with the file's name for errors.
class Reader {
 public:
  Reader(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(name_ + ": " + problem); }

  std::uint32_t u32(std::int64_t at) const {
    check(at, 4);
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + at);
    return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) |
           (std::uint32_t(p[3]) << 24);
  }
  std::int32_t i32(std::int64_t at) const { return static_cast<std::int32_t>(u32(at)); }
  float f32(std::int64_t at) const {
    const std::uint32_t bits = u32(at);
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
  }
  std::uint8_t u8(std::int64_t at) const {
    check(at, 1);
    return static_cast<std::uint8_t>(bytes_[static_cast<std::size_t>(at)]);
  }
  // A NUL-padded string of at most n bytes.
  std::string text(std::int64_t at, std::int64_t n) const {
    check(at, n);
    const char* p = bytes_.data() + at;
    return std::string(p, strnlen(p, static_cast<std::size_t>(n)));
  }
  std::string_view bytes(std::int64_t at, std::int64_t n) const {
    check(at, n);
    return bytes_.substr(static_cast<std::size_t>(at), static_cast<std::size_t>(n));
  }
  std::int64_t size() const { return static_cast<std::int64_t>(bytes_.size()); }

 private:
  void check(std::int64_t at, std::int64_t n) const {
    if (at < 0 || n < 0 || at + n > size()) fail("read past the end of the file");  // lumps are checked first
  }
  std::string_view bytes_;
  const std::string& name_;
};

struct LumpRange {
  std::int64_t offset = 0, count = 0;
};

std::array<LumpRange, kLumpCount> read_directory(const Reader& in) {
  if (in.size() < kHeaderBytes)
    in.fail("truncated: " + std::to_string(in.size()) + " bytes, shorter than the " +
            std::to_string(kHeaderBytes) + "-byte BSP header");
  if (in.text(0, 4) != "IBSP") in.fail("not a Quake 3 BSP (magic is not \"IBSP\")");
  const std::int32_t version = in.i32(4);
  if (version != 46) in.fail("BSP version " + std::to_string(version) + " is not 46 (Quake 3)");
  std::array<LumpRange, kLumpCount> lumps;
  for (int i = 0; i < kLumpCount; ++i) {
    const std::int64_t offset = in.i32(8 + 8 * i), length = in.i32(12 + 8 * i);
    const std::string what = std::string("lump ") + std::to_string(i) + " (" + kLumpNames[i] + ")";
    if (offset < 0 || length < 0)
      in.fail(what + " has negative offset or length (" + std::to_string(offset) + ", " + std::to_string(length) +
              ")");
    if (offset + length > in.size())
      in.fail(what + " at " + std::to_string(offset) + " with " + std::to_string(length) +
              " bytes runs past the end of the file (" + std::to_string(in.size()) + " bytes; truncated?)");
    if (length % kEntrySize[i] != 0)
      in.fail(what + " length " + std::to_string(length) + " is not a multiple of its entry size " +
              std::to_string(kEntrySize[i]));
    lumps[i] = {offset, length / kEntrySize[i]};
  }
  return lumps;
}

// "brush 3", "leaf face 7": one entry of a lump, for error messages.
std::string entry(int lump, std::int64_t i) {
  static constexpr const char* kEntryNames[kLumpCount] = {
      "entities", "shader", "plane", "node", "leaf", "leaf face", "leaf brush", "model", "brush",
      "brush side", "vertex", "mesh vertex", "effect", "face", "lightmap", "light volume", "visdata"};
  return std::string(kEntryNames[lump]) + " " + std::to_string(i);
}

// Index checks: "brush 3: shader 99 out of range [0, 12)".
void check_index(const Reader& in, const std::string& who, const char* field, std::int64_t value,
                 std::int64_t lo, std::int64_t size) {
  if (value < lo || value >= size)
    in.fail(who + ": " + field + " " + std::to_string(value) + " out of range [" + std::to_string(lo) + ", " +
            std::to_string(size) + ")");
}
void check_range(const Reader& in, const std::string& who, const char* field, std::int64_t first,
                 std::int64_t count, std::int64_t size, const char* target) {
  if (first < 0 || count < 0 || first + count > size)
    in.fail(who + ": " + field + " [" + std::to_string(first) + ", " + std::to_string(first) + " + " +
            std::to_string(count) + ") out of range of the " + std::to_string(size) + " " + target);
}
void check_finite(const Reader& in, const std::string& who, std::initializer_list<float> values) {
  for (float v : values)
    if (!std::isfinite(v)) in.fail(who + ": non-finite number");
}

// Fills `out` with one entry per lump entry: parse(entry, byte offset of the entry, index).
template <class T, class Parse>
void read_entries(const std::array<LumpRange, kLumpCount>& L, int lump, std::vector<T>& out, Parse parse) {
  out.resize(static_cast<std::size_t>(L[lump].count));
  for (std::int64_t i = 0; i < L[lump].count; ++i) parse(out[i], L[lump].offset + kEntrySize[lump] * i, i);
}

void parse_lumps(const Reader& in, const std::array<LumpRange, kLumpCount>& L, BspMap& map) {
  map.entities = in.text(L[kEntities].offset, L[kEntities].count);
  read_entries(L, kShaders, map.shaders, [&](BspShader& sh, std::int64_t at, std::int64_t) {
    sh = {in.text(at, 64), in.i32(at + 64), in.i32(at + 68)};
  });
  read_entries(L, kPlanes, map.planes, [&](BspPlane& p, std::int64_t at, std::int64_t i) {
    p.normal = {in.f32(at), in.f32(at + 4), in.f32(at + 8)};
    p.dist = in.f32(at + 12);
    check_finite(in, entry(kPlanes, i), {p.normal[0], p.normal[1], p.normal[2], p.dist});
    if (p.normal[0] == 0 && p.normal[1] == 0 && p.normal[2] == 0) in.fail(entry(kPlanes, i) + ": zero normal");
  });
  read_entries(L, kNodes, map.nodes, [&](BspNode& n, std::int64_t at, std::int64_t) {
    n.plane = in.i32(at);
    n.children = {in.i32(at + 4), in.i32(at + 8)};
    for (int k = 0; k < 3; ++k) n.mins[k] = in.i32(at + 12 + 4 * k), n.maxs[k] = in.i32(at + 24 + 4 * k);
  });
  read_entries(L, kLeaves, map.leaves, [&](BspLeaf& l, std::int64_t at, std::int64_t) {
    l.cluster = in.i32(at);
    l.area = in.i32(at + 4);
    for (int k = 0; k < 3; ++k) l.mins[k] = in.i32(at + 8 + 4 * k), l.maxs[k] = in.i32(at + 20 + 4 * k);
    l.first_leaf_face = in.i32(at + 32);
    l.n_leaf_faces = in.i32(at + 36);
    l.first_leaf_brush = in.i32(at + 40);
    l.n_leaf_brushes = in.i32(at + 44);
  });
  const auto index = [&](std::int32_t& v, std::int64_t at, std::int64_t) { v = in.i32(at); };
  read_entries(L, kLeafFaces, map.leaf_faces, index);
  read_entries(L, kLeafBrushes, map.leaf_brushes, index);
  read_entries(L, kMeshVertices, map.mesh_vertices, index);
  read_entries(L, kModels, map.models, [&](BspModel& m, std::int64_t at, std::int64_t i) {
    for (int k = 0; k < 3; ++k) m.mins[k] = in.f32(at + 4 * k), m.maxs[k] = in.f32(at + 12 + 4 * k);
    check_finite(in, entry(kModels, i), {m.mins[0], m.mins[1], m.mins[2], m.maxs[0], m.maxs[1], m.maxs[2]});
    m.first_face = in.i32(at + 24);
    m.n_faces = in.i32(at + 28);
    m.first_brush = in.i32(at + 32);
    m.n_brushes = in.i32(at + 36);
  });
  read_entries(L, kBrushes, map.brushes, [&](BspBrush& b, std::int64_t at, std::int64_t) {
    b = {in.i32(at), in.i32(at + 4), in.i32(at + 8)};
  });
  read_entries(L, kBrushSides, map.brush_sides, [&](BspBrushSide& s, std::int64_t at, std::int64_t) {
    s = {in.i32(at), in.i32(at + 4)};
  });
  read_entries(L, kVertices, map.vertices, [&](BspVertex& v, std::int64_t at, std::int64_t i) {
    for (int k = 0; k < 3; ++k) v.position[k] = in.f32(at + 4 * k), v.normal[k] = in.f32(at + 28 + 4 * k);
    for (int k = 0; k < 2; ++k) v.texcoord[k] = in.f32(at + 12 + 4 * k), v.lightmap_coord[k] = in.f32(at + 20 + 4 * k);
    for (int k = 0; k < 4; ++k) v.color[k] = in.u8(at + 40 + k);
    check_finite(in, entry(kVertices, i), {v.position[0], v.position[1], v.position[2]});
  });
  read_entries(L, kEffects, map.effects, [&](BspEffect& e, std::int64_t at, std::int64_t) {
    e = {in.text(at, 64), in.i32(at + 64), in.i32(at + 68)};
  });
  read_entries(L, kFaces, map.faces, [&](BspFace& f, std::int64_t at, std::int64_t) {
    f.shader = in.i32(at);
    f.effect = in.i32(at + 4);
    f.type = in.i32(at + 8);
    f.first_vertex = in.i32(at + 12);
    f.n_vertices = in.i32(at + 16);
    f.first_mesh_vertex = in.i32(at + 20);
    f.n_mesh_vertices = in.i32(at + 24);
    f.lightmap = in.i32(at + 28);
    for (int k = 0; k < 3; ++k) f.normal[k] = in.f32(at + 88 + 4 * k);
    f.patch_size = {in.i32(at + 96), in.i32(at + 100)};
  });
  const LumpRange& vis = L[kVisData];
  if (vis.count > 0) {
    if (vis.count < 8) in.fail("visdata of " + std::to_string(vis.count) + " bytes is shorter than its 8-byte header");
    map.vis.n_vecs = in.i32(vis.offset);
    map.vis.sz_vecs = in.i32(vis.offset + 4);
    const std::int64_t n = map.vis.n_vecs, sz = map.vis.sz_vecs;
    if (n < 0 || sz < 0)
      in.fail("visdata has negative n_vecs or sz_vecs (" + std::to_string(n) + ", " + std::to_string(sz) + ")");
    if (8 + n * sz != vis.count)  // both < 2^31: the product fits
      in.fail("visdata of " + std::to_string(vis.count) + " bytes does not hold 8 + n_vecs * sz_vecs = 8 + " +
              std::to_string(n) + " * " + std::to_string(sz) + " bytes");
    if (sz * 8 < n)
      in.fail("visdata rows of " + std::to_string(sz) + " bytes are too short for " + std::to_string(n) + " clusters");
    const std::string_view bits = in.bytes(vis.offset + 8, n * sz);
    map.vis.bits.assign(bits.begin(), bits.end());
  }
}

void check_indices(const Reader& in, BspMap& map) {
  const std::int64_t n_planes = map.planes.size(), n_nodes = map.nodes.size(), n_leaves = map.leaves.size(),
                     n_shaders = map.shaders.size(), n_brushes = map.brushes.size(),
                     n_sides = map.brush_sides.size(), n_faces = map.faces.size(),
                     n_vertices = map.vertices.size(), n_mesh = map.mesh_vertices.size(),
                     n_effects = map.effects.size();
  if (map.models.empty()) in.fail("no models (model 0, the world, is required)");
  if (n_leaves == 0) in.fail("no leaves");
  for (std::int64_t i = 0; i < n_nodes; ++i) {
    const BspNode& n = map.nodes[i];
    const std::string who = entry(kNodes, i);
    check_index(in, who, "plane", n.plane, 0, n_planes);
    for (int k = 0; k < 2; ++k) {
      const std::int64_t c = n.children[k];
      if (c >= 0) check_index(in, who, k == 0 ? "front child node" : "back child node", c, 0, n_nodes);
      else check_index(in, who, k == 0 ? "front child leaf" : "back child leaf", -(c + 1), 0, n_leaves);
    }
  }
  for (std::int64_t i = 0; i < n_leaves; ++i) {
    const BspLeaf& l = map.leaves[i];
    const std::string who = entry(kLeaves, i);
    check_range(in, who, "leaf faces", l.first_leaf_face, l.n_leaf_faces, map.leaf_faces.size(), "leaf faces");
    check_range(in, who, "leaf brushes", l.first_leaf_brush, l.n_leaf_brushes, map.leaf_brushes.size(),
                "leaf brushes");
    if (l.cluster < -1) in.fail(who + ": cluster " + std::to_string(l.cluster) + " is below -1");
  }
  for (std::size_t i = 0; i < map.leaf_faces.size(); ++i)
    check_index(in, entry(kLeafFaces, i), "face", map.leaf_faces[i], 0, n_faces);
  for (std::size_t i = 0; i < map.leaf_brushes.size(); ++i)
    check_index(in, entry(kLeafBrushes, i), "brush", map.leaf_brushes[i], 0, n_brushes);
  for (std::size_t i = 0; i < map.models.size(); ++i) {
    const BspModel& m = map.models[i];
    const std::string who = entry(kModels, i);
    check_range(in, who, "faces", m.first_face, m.n_faces, n_faces, "faces");
    check_range(in, who, "brushes", m.first_brush, m.n_brushes, n_brushes, "brushes");
    for (int k = 0; k < 3; ++k)
      if (m.mins[k] > m.maxs[k]) in.fail(who + ": bounds have mins above maxs");
  }
  for (std::int64_t i = 0; i < n_brushes; ++i) {
    const BspBrush& b = map.brushes[i];
    const std::string who = entry(kBrushes, i);
    check_range(in, who, "sides", b.first_side, b.n_sides, n_sides, "brush sides");
    check_index(in, who, "shader", b.shader, 0, n_shaders);
  }
  for (std::int64_t i = 0; i < n_sides; ++i) {
    const BspBrushSide& s = map.brush_sides[i];
    check_index(in, entry(kBrushSides, i), "plane", s.plane, 0, n_planes);
    check_index(in, entry(kBrushSides, i), "shader", s.shader, 0, n_shaders);
  }
  for (std::int64_t i = 0; i < n_effects; ++i)
    check_index(in, entry(kEffects, i), "brush", map.effects[i].brush, -1, n_brushes);
  for (std::int64_t i = 0; i < n_faces; ++i) {
    const BspFace& f = map.faces[i];
    const std::string who = entry(kFaces, i);
    check_index(in, who, "shader", f.shader, 0, n_shaders);
    // Billboards (flares) are exempt: q3map2 writes effect 0 for them even in maps without effects.
    if (f.type != kFaceBillboard) check_index(in, who, "effect", f.effect, -1, n_effects);
    if (f.type < kFacePolygon || f.type > kFaceBillboard) in.fail(who + ": unknown type " + std::to_string(f.type));
    check_range(in, who, "vertices", f.first_vertex, f.n_vertices, n_vertices, "vertices");
    if (f.type == kFacePolygon || f.type == kFaceMesh) {
      check_range(in, who, "mesh vertices", f.first_mesh_vertex, f.n_mesh_vertices, n_mesh, "mesh vertices");
      if (f.n_mesh_vertices % 3 != 0)
        in.fail(who + ": " + std::to_string(f.n_mesh_vertices) + " mesh vertices are not whole triangles");
      for (std::int32_t k = 0; k < f.n_mesh_vertices; ++k)
        check_index(in, who, "mesh vertex offset", map.mesh_vertices[f.first_mesh_vertex + k], 0, f.n_vertices);
    }
    if (f.type == kFacePatch &&
        (f.patch_size[0] < 0 || f.patch_size[1] < 0 ||
         std::int64_t(f.patch_size[0]) * f.patch_size[1] != f.n_vertices))
      in.fail(who + ": patch of " + std::to_string(f.patch_size[0]) + " x " + std::to_string(f.patch_size[1]) +
              " control points does not have its " + std::to_string(f.n_vertices) + " vertices");
  }
}

// Walks the world tree from its root without recursion (a hostile file may be deep), marking the leaves it
// reaches; a node or leaf reached twice is an error (a shared child or a cycle).
void check_tree(const Reader& in, BspMap& map) {
  map.world_leaf.assign(map.leaves.size(), false);
  if (map.nodes.empty()) {
    map.world_leaf[0] = true;
    return;
  }
  std::vector<bool> seen(map.nodes.size(), false);
  std::vector<std::int32_t> stack{0};
  seen[0] = true;
  while (!stack.empty()) {
    const std::int32_t node = stack.back();
    stack.pop_back();
    for (std::int32_t c : map.nodes[node].children) {
      if (c >= 0) {
        if (seen[c]) in.fail(entry(kNodes, node) + ": child node " + std::to_string(c) +
                             " is reached twice (the node tree has a cycle or a shared child)");
        seen[c] = true;
        stack.push_back(c);
      } else {
        const std::int32_t leaf = -(c + 1);
        if (map.world_leaf[leaf]) in.fail(entry(kNodes, node) + ": child leaf " + std::to_string(leaf) +
                                          " is reached twice (leaves of the tree must be distinct)");
        map.world_leaf[leaf] = true;
      }
    }
  }
}

void check_clusters(const Reader& in, const BspMap& map) {
  if (map.vis.n_vecs == 0) {
    // Without visdata the cluster count comes from the leaves; bound it so that per-cluster tables stay
    // proportional to the file.
    for (std::size_t i = 0; i < map.leaves.size(); ++i)
      if (map.world_leaf[i] && map.leaves[i].cluster >= static_cast<std::int64_t>(map.leaves.size()))
        in.fail(entry(kLeaves, i) + ": cluster " + std::to_string(map.leaves[i].cluster) +
                " out of range: without visdata a map has fewer clusters than its " +
                std::to_string(map.leaves.size()) + " leaves");
    return;
  }
  for (std::size_t i = 0; i < map.leaves.size(); ++i)
    if (map.world_leaf[i] && map.leaves[i].cluster >= map.vis.n_vecs)
      in.fail(entry(kLeaves, i) + ": cluster " + std::to_string(map.leaves[i].cluster) +
              " out of range of the visdata's " + std::to_string(map.vis.n_vecs) + " clusters");
}

bool ends_with_nocase(const std::string& s, const std::string& tail) {
  if (s.size() < tail.size()) return false;
  return std::equal(tail.begin(), tail.end(), s.end() - tail.size(),
                    [](char a, char b) { return std::tolower(a) == std::tolower(b); });
}

std::string read_file_bytes(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path + ": cannot read (" + ec.message() + ")");
  if (size > static_cast<std::uintmax_t>(kMaxBspBytes))
    throw InputError(path + ": file of " + std::to_string(size) + " bytes is larger than the limit of " +
                     std::to_string(kMaxBspBytes));
  std::ifstream in(path, std::ios::binary);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(size)))
    throw InputError(path + ": cannot read");
  return bytes;
}

// The map members of an archive.
std::vector<std::string> archive_maps(const std::string& archive) {
  std::vector<std::string> maps;
  for (const std::string& name : zip_member_names(archive))
    if (ends_with_nocase(name, ".bsp")) maps.push_back(name);
  return maps;
}

// An archive member named exactly, or by the short form NAME / NAME.bsp for maps/NAME.bsp.
std::string resolve_member(const std::string& archive, const std::string& member) {
  const std::vector<std::string> names = zip_member_names(archive);
  auto find = [&](const std::string& want) -> const std::string* {
    for (const std::string& n : names)
      if (n.size() == want.size() && ends_with_nocase(n, want)) return &n;
    return nullptr;
  };
  if (const std::string* n = find(member)) return *n;
  const std::string with_ext = ends_with_nocase(member, ".bsp") ? member : member + ".bsp";
  if (const std::string* n = find("maps/" + with_ext)) return *n;
  throw InputError(archive + ":" + member + ": no such map in the archive");
}

struct SplitSource {
  std::string file, member;  // member empty: the file itself
};

SplitSource split_source(const std::string& source) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(source, ec)) return {source, ""};
  std::string lower = source;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  const std::size_t at = lower.rfind(".pk3:");
  if (at == std::string::npos) return {source, ""};
  return {source.substr(0, at + 4), source.substr(at + 5)};
}

}  // namespace

int BspMap::cluster_count() const {
  if (vis.n_vecs > 0) return vis.n_vecs;
  int n = 0;
  for (std::size_t i = 0; i < leaves.size(); ++i)
    if (i < world_leaf.size() && world_leaf[i]) n = std::max(n, leaves[i].cluster + 1);
  return n;
}

bool BspMap::cluster_visible(int a, int b) const {
  const int n = cluster_count();
  if (a < 0 || b < 0 || a >= n || b >= n)
    throw std::out_of_range("cluster_visible(" + std::to_string(a) + ", " + std::to_string(b) + "): " +
                            std::to_string(n) + " clusters");
  if (vis.n_vecs == 0) return true;
  return (vis.bits[static_cast<std::size_t>(a) * vis.sz_vecs + b / 8] >> (b % 8)) & 1;
}

BspMap parse_bsp(std::string_view bytes, const std::string& name) {
  const Reader in(bytes, name);
  const auto lumps = read_directory(in);
  BspMap map;
  map.source = name;
  map.version = in.i32(4);
  parse_lumps(in, lumps, map);
  check_indices(in, map);
  check_tree(in, map);
  check_clusters(in, map);
  return map;
}

BspMap read_bsp(const std::string& source) {
  const SplitSource s = split_source(source);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(s.file, ec)) throw InputError(s.file + ": no such file");
  if (!s.member.empty()) {
    const std::string member = resolve_member(s.file, s.member);
    const std::string name = s.file + ":" + member;
    return parse_bsp(read_zip_member(s.file, member, kMaxBspBytes), name);
  }
  if (looks_like_zip(s.file)) {
    const std::vector<std::string> maps = archive_maps(s.file);
    if (maps.empty()) throw InputError(s.file + ": archive holds no map (*.bsp)");
    if (maps.size() > 1)
      throw InputError(s.file + ": archive holds " + std::to_string(maps.size()) + " maps (" + maps[0] + ", " +
                       maps[1] + ", ...); name one as " + s.file + ":MEMBER");
    return parse_bsp(read_zip_member(s.file, maps[0], kMaxBspBytes), s.file + ":" + maps[0]);
  }
  return parse_bsp(read_file_bytes(s.file), s.file);
}

std::vector<std::string> bsp_sources(const std::string& path) {
  const SplitSource s = split_source(path);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(s.file, ec)) throw InputError(s.file + ": no such file");
  if (!s.member.empty()) return {s.file + ":" + resolve_member(s.file, s.member)};
  if (!looks_like_zip(s.file)) return {s.file};
  std::vector<std::string> out;
  for (const std::string& m : archive_maps(s.file)) out.push_back(s.file + ":" + m);
  if (out.empty()) throw InputError(s.file + ": archive holds no map (*.bsp)");
  return out;
}

}  // namespace exactvis::quake3
