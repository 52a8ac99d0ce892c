#pragma once
// Test-side writer of Quake 3 BSP files (IBSP 46) and of stored (uncompressed) zip archives, plus the small
// maps with known answers the BSP tests use and an independent exact point-location descent.
//
// Written from the format description, sharing no code with io/quake3_bsp: its own structs, its own byte
// layout. Fields are raw so that tests can break any of them; the lump directory can be overridden.
#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace bsptest {

struct Shader {
  std::string name;
  std::int32_t surface = 0, contents = 0;
};
struct Plane {
  float n[3];
  float d;
};
struct Node {
  std::int32_t plane, front, back;  // children: >= 0 node, < 0 leaf -(c + 1)
  std::int32_t mins[3] = {0, 0, 0}, maxs[3] = {0, 0, 0};
};
struct Leaf {
  std::int32_t cluster = -1, area = 0;
  std::int32_t mins[3] = {0, 0, 0}, maxs[3] = {0, 0, 0};
  std::int32_t first_face = 0, n_faces = 0, first_brush = 0, n_brushes = 0;
};
struct Model {
  float mins[3], maxs[3];
  std::int32_t first_face = 0, n_faces = 0, first_brush = 0, n_brushes = 0;
};
struct Brush {
  std::int32_t first_side, n_sides, shader;
};
struct Side {
  std::int32_t plane, shader;
};
struct Vertex {
  float p[3];
};
struct Face {
  std::int32_t shader = 0, effect = -1, type = 1, first_vertex = 0, n_vertices = 0, first_mesh = 0, n_mesh = 0;
  std::int32_t size[2] = {0, 0};
};

struct Bsp {
  std::string magic = "IBSP";
  std::int32_t version = 46;
  std::string entities = "{\n\"classname\" \"worldspawn\"\n}\n";
  std::vector<Shader> shaders;
  std::vector<Plane> planes;
  std::vector<Node> nodes;
  std::vector<Leaf> leaves;
  std::vector<std::int32_t> leaf_faces, leaf_brushes;
  std::vector<Model> models;
  std::vector<Brush> brushes;
  std::vector<Side> sides;
  std::vector<Vertex> vertices;
  std::vector<std::int32_t> mesh_vertices;
  std::vector<std::string> effects;  // names; brush -1
  std::vector<Face> faces;
  bool has_vis = true;
  std::int32_t n_vecs = 0, sz_vecs = 0;
  std::vector<std::uint8_t> vis;  // n_vecs * sz_vecs bytes
  // Directory overrides: lump index -> (offset, length) written instead of the real ones.
  std::vector<std::pair<int, std::pair<std::int32_t, std::int32_t>>> directory_override;

  int add_plane(float nx, float ny, float nz, float d) {
    planes.push_back({{nx, ny, nz}, d});
    return static_cast<int>(planes.size()) - 1;
  }
  // Visdata with sz bytes per row and every bit from visible(a, b).
  template <class F>
  void set_vis(int clusters, int sz, F visible) {
    n_vecs = clusters;
    sz_vecs = sz;
    vis.assign(static_cast<std::size_t>(clusters) * sz, 0);
    for (int a = 0; a < clusters; ++a)
      for (int b = 0; b < clusters; ++b)
        if (b / 8 < sz && visible(a, b)) vis[a * sz + b / 8] |= std::uint8_t(1u << (b % 8));
  }

  std::string bytes() const;
};

inline void put_i32(std::string& s, std::int32_t v) {
  const std::uint32_t u = static_cast<std::uint32_t>(v);
  for (int k = 0; k < 4; ++k) s.push_back(static_cast<char>((u >> (8 * k)) & 0xff));
}
inline void put_f32(std::string& s, float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  put_i32(s, static_cast<std::int32_t>(u));
}
inline void put_name(std::string& s, const std::string& name) {
  std::string field(64, '\0');
  field.replace(0, std::min<std::size_t>(name.size(), 64), name.substr(0, 64));
  s += field;
}
inline void set_i32(std::string& s, std::size_t at, std::int32_t v) {
  std::string b;
  put_i32(b, v);
  s.replace(at, 4, b);
}

inline std::string Bsp::bytes() const {
  std::array<std::string, 17> lump;
  lump[0] = entities + std::string(1, '\0');
  for (const auto& sh : shaders) put_name(lump[1], sh.name), put_i32(lump[1], sh.surface), put_i32(lump[1], sh.contents);
  for (const auto& p : planes) {
    for (float c : p.n) put_f32(lump[2], c);
    put_f32(lump[2], p.d);
  }
  for (const auto& n : nodes) {
    put_i32(lump[3], n.plane), put_i32(lump[3], n.front), put_i32(lump[3], n.back);
    for (auto c : n.mins) put_i32(lump[3], c);
    for (auto c : n.maxs) put_i32(lump[3], c);
  }
  for (const auto& l : leaves) {
    put_i32(lump[4], l.cluster), put_i32(lump[4], l.area);
    for (auto c : l.mins) put_i32(lump[4], c);
    for (auto c : l.maxs) put_i32(lump[4], c);
    put_i32(lump[4], l.first_face), put_i32(lump[4], l.n_faces);
    put_i32(lump[4], l.first_brush), put_i32(lump[4], l.n_brushes);
  }
  for (auto i : leaf_faces) put_i32(lump[5], i);
  for (auto i : leaf_brushes) put_i32(lump[6], i);
  for (const auto& m : models) {
    for (float c : m.mins) put_f32(lump[7], c);
    for (float c : m.maxs) put_f32(lump[7], c);
    put_i32(lump[7], m.first_face), put_i32(lump[7], m.n_faces);
    put_i32(lump[7], m.first_brush), put_i32(lump[7], m.n_brushes);
  }
  for (const auto& b : brushes) put_i32(lump[8], b.first_side), put_i32(lump[8], b.n_sides), put_i32(lump[8], b.shader);
  for (const auto& s : sides) put_i32(lump[9], s.plane), put_i32(lump[9], s.shader);
  for (const auto& v : vertices) {
    for (float c : v.p) put_f32(lump[10], c);
    for (int k = 0; k < 7; ++k) put_f32(lump[10], 0.5f);  // texture, lightmap coordinates, normal
    lump[10] += std::string("\xff\xff\xff\xff", 4);        // colour
  }
  for (auto i : mesh_vertices) put_i32(lump[11], i);
  for (const auto& e : effects) put_name(lump[12], e), put_i32(lump[12], -1), put_i32(lump[12], 0);
  for (const auto& f : faces) {
    std::string& o = lump[13];
    put_i32(o, f.shader), put_i32(o, f.effect), put_i32(o, f.type), put_i32(o, f.first_vertex);
    put_i32(o, f.n_vertices), put_i32(o, f.first_mesh), put_i32(o, f.n_mesh);
    put_i32(o, -1);                                  // lightmap
    for (int k = 0; k < 4; ++k) put_i32(o, 0);       // lightmap start, size
    for (int k = 0; k < 12; ++k) put_f32(o, 0.0f);   // lightmap origin, vectors, normal
    put_i32(o, f.size[0]), put_i32(o, f.size[1]);
  }
  if (has_vis) {
    put_i32(lump[16], n_vecs), put_i32(lump[16], sz_vecs);
    lump[16].append(reinterpret_cast<const char*>(vis.data()), vis.size());
  }
  std::string out = magic.substr(0, 4);
  out.resize(4, '\0');
  put_i32(out, version);
  std::string body;
  std::array<std::pair<std::int32_t, std::int32_t>, 17> dir;
  const std::int32_t header = 8 + 17 * 8;
  for (int i = 0; i < 17; ++i) {
    while (body.size() % 4) body.push_back('\0');
    dir[i] = {header + static_cast<std::int32_t>(body.size()), static_cast<std::int32_t>(lump[i].size())};
    body += lump[i];
  }
  for (const auto& [i, entry] : directory_override) dir[i] = entry;
  for (const auto& [offset, length] : dir) put_i32(out, offset), put_i32(out, length);
  return out + body;
}

// ---- Stored zip archives (no compression), enough for .pk3 tests. ----
inline std::uint32_t crc32(const std::string& data) {
  std::uint32_t c = 0xffffffffu;
  for (unsigned char b : data) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return ~c;
}
inline void put_u16(std::string& s, unsigned v) {
  s.push_back(static_cast<char>(v & 0xff));
  s.push_back(static_cast<char>((v >> 8) & 0xff));
}
// entries: (name, content); corrupt_crc_of: index of an entry whose stored CRC is wrong (-1: none).
inline std::string zip_stored(const std::vector<std::pair<std::string, std::string>>& entries,
                              int corrupt_crc_of = -1) {
  std::string out, central;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto& [name, data] = entries[i];
    const std::uint32_t crc = crc32(data) ^ (static_cast<int>(i) == corrupt_crc_of ? 1u : 0u);
    const std::uint32_t offset = static_cast<std::uint32_t>(out.size());
    out += std::string("PK\x03\x04", 4);
    put_u16(out, 20), put_u16(out, 0), put_u16(out, 0), put_u16(out, 0), put_u16(out, 0);
    put_i32(out, static_cast<std::int32_t>(crc));
    put_i32(out, static_cast<std::int32_t>(data.size())), put_i32(out, static_cast<std::int32_t>(data.size()));
    put_u16(out, static_cast<unsigned>(name.size())), put_u16(out, 0);
    out += name + data;
    central += std::string("PK\x01\x02", 4);
    put_u16(central, 20), put_u16(central, 20), put_u16(central, 0), put_u16(central, 0), put_u16(central, 0),
        put_u16(central, 0);
    put_i32(central, static_cast<std::int32_t>(crc));
    put_i32(central, static_cast<std::int32_t>(data.size())), put_i32(central, static_cast<std::int32_t>(data.size()));
    put_u16(central, static_cast<unsigned>(name.size())), put_u16(central, 0), put_u16(central, 0);
    put_u16(central, 0), put_u16(central, 0), put_i32(central, 0), put_i32(central, static_cast<std::int32_t>(offset));
    central += name;
  }
  const std::uint32_t cd_offset = static_cast<std::uint32_t>(out.size());
  out += central;
  out += std::string("PK\x05\x06", 4);
  put_u16(out, 0), put_u16(out, 0), put_u16(out, static_cast<unsigned>(entries.size())),
      put_u16(out, static_cast<unsigned>(entries.size()));
  put_i32(out, static_cast<std::int32_t>(central.size())), put_i32(out, static_cast<std::int32_t>(cd_offset));
  put_u16(out, 0);
  return out;
}

// ---- Maps with known answers. ----
//
// The doorway map: world box [0, 256] x [0, 128] x [0, 128]; a wall 120 <= x <= 136 with a doorway
// 48 < y <= 80, z <= 96; room A (x <= 120, cluster 0); room B (x > 136) split by a slanted plane
// 0.6f x + 0.8f y = 170.3f into cluster 1 (front) and cluster 3 (back); the doorway is cluster 2.
// Leaves: 0 unused (all zero, cluster 0, as q3map2 writes it), 1 room A, 2 wall below the doorway
// (y <= 48), 3 wall above (y > 80), 4 lintel (z > 96), 5 doorway, 6 B front, 7 B back, 8 a brush model's
// leaf outside the tree (cluster 0, as q3map2 writes them).
// Brushes (world model 0: brushes 0-3; model 1: brush 4):
//   0 wall part y <= 48 (solid), 1 wall part y >= 80 (solid), 2 lintel 48 <= y <= 80, z >= 96 (shader
//   "textures/common/nodrawnonsolid", contents 0: a vis blocker that is not solid), 3 a detail pillar
//   [32, 48] x [32, 48] x [0, 64] inside room A (solid, not in the tree), 4 a door brush of model 1.
// Visdata: 4 clusters, rows of 8 bytes, every pair visible except 0 <-> 3 both ways and 1 -> 0.
struct DoorwayMap {
  Bsp bsp;
  static bool visible(int a, int b) { return !((a == 0 && b == 3) || (a == 3 && b == 0) || (a == 1 && b == 0)); }
};

inline DoorwayMap doorway_map() {
  DoorwayMap m;
  Bsp& b = m.bsp;
  b.shaders = {{"textures/base/wall", 0, 1}, {"textures/common/nodrawnonsolid", 0x80, 0},
               {"textures/base/pillar", 0, 1}, {"textures/base/door", 0, 1}};
  const int x120 = b.add_plane(1, 0, 0, 120), x136 = b.add_plane(1, 0, 0, 136);
  const int y48 = b.add_plane(0, 1, 0, 48), y80 = b.add_plane(0, 1, 0, 80), z96 = b.add_plane(0, 0, 1, 96);
  const int slant = b.add_plane(0.6f, 0.8f, 0, 170.3f);
  // Node tree (children: >= 0 node, < 0 leaf -(c + 1)).
  b.nodes = {{x120, 1, -(1 + 1)},      // 0: x > 120 -> node 1, else room A (leaf 1)
             {x136, 4, 2},             // 1: x > 136 -> node 4 (room B), else node 2 (the wall slab)
             {y48, 3, -(2 + 1)},       // 2: y > 48 -> node 3, else wall below (leaf 2)
             {y80, -(3 + 1), 5},       // 3: y > 80 -> wall above (leaf 3), else node 5
             {slant, -(6 + 1), -(7 + 1)},  // 4: room B front (leaf 6) / back (leaf 7)
             {z96, -(4 + 1), -(5 + 1)}};   // 5: z > 96 -> lintel (leaf 4), else doorway (leaf 5)
  b.leaves.resize(9);
  b.leaves[0].cluster = 0;
  b.leaves[1].cluster = 0;
  b.leaves[2].cluster = -1;
  b.leaves[3].cluster = -1;
  b.leaves[4].cluster = -1;
  b.leaves[5].cluster = 2;
  b.leaves[6].cluster = 1;
  b.leaves[7].cluster = 3;
  b.leaves[8].cluster = 0;
  // Brushes: sides with outward normals (the brush is normal . p <= d on every side).
  auto add_box_brush = [&](float lx, float ly, float lz, float hx, float hy, float hz, int shader) {
    const int first = static_cast<int>(b.sides.size());
    b.sides.push_back({b.add_plane(-1, 0, 0, -lx), shader});
    b.sides.push_back({b.add_plane(1, 0, 0, hx), shader});
    b.sides.push_back({b.add_plane(0, -1, 0, -ly), shader});
    b.sides.push_back({b.add_plane(0, 1, 0, hy), shader});
    b.sides.push_back({b.add_plane(0, 0, -1, -lz), shader});
    b.sides.push_back({b.add_plane(0, 0, 1, hz), shader});
    b.brushes.push_back({first, 6, shader});
  };
  add_box_brush(120, 0, 0, 136, 48, 128, 0);
  add_box_brush(120, 80, 0, 136, 128, 128, 0);
  add_box_brush(120, 48, 96, 136, 80, 128, 1);
  add_box_brush(32, 32, 0, 48, 48, 64, 2);
  add_box_brush(200, 10, 0, 210, 20, 50, 3);
  b.leaf_brushes = {0, 1, 2, 3};
  b.leaves[2].first_brush = 0, b.leaves[2].n_brushes = 1;
  b.leaves[3].first_brush = 1, b.leaves[3].n_brushes = 1;
  b.leaves[4].first_brush = 2, b.leaves[4].n_brushes = 1;
  b.leaves[1].first_brush = 3, b.leaves[1].n_brushes = 1;
  // Drawn geometry: a quad polygon (2 triangles) on the floor of room A, a mesh face (1 triangle), a patch
  // (3 x 3 control points, skipped) and a billboard (skipped).
  b.vertices = {{{0, 0, 0}}, {{120, 0, 0}}, {{120, 128, 0}}, {{0, 128, 0}},   // 0-3 floor quad
                {{10, 10, 10}}, {{20, 10, 10}}, {{10, 20, 10.5f}},             // 4-6 mesh triangle
                {{0, 0, 0}}, {{1, 0, 0}}, {{2, 0, 0}}, {{0, 1, 0}}, {{1, 1, 1}},  // 7-15 patch
                {{2, 1, 0}}, {{0, 2, 0}}, {{1, 2, 0}}, {{2, 2, 0}},
                {{50, 50, 50}}};                                               // 16 billboard
  b.mesh_vertices = {0, 1, 2, 0, 2, 3, 0, 1, 2};
  b.faces = {{0, -1, 1, 0, 4, 0, 6}, {0, -1, 3, 4, 3, 6, 3}, {0, -1, 2, 7, 9, 0, 0, {3, 3}},
             {0, -1, 4, 16, 1, 0, 0}};
  b.leaf_faces = {0, 1};
  b.leaves[1].first_face = 0, b.leaves[1].n_faces = 2;
  b.models = {{{0, 0, 0}, {256, 128, 128}, 0, 4, 0, 4}, {{200, 10, 0}, {210, 20, 50}, 4, 0, 4, 1}};
  b.set_vis(4, 8, DoorwayMap::visible);
  return m;
}

// The tunnels map (exact cluster visibility with known answers): world box [0, 384] x [0, 128] x [0, 128];
// room A (x <= 100, cluster 0), a tunnel D1 (100 <= x <= 200, y <= 16, cluster 1) in a solid slab, room B
// (200 <= x <= 220, cluster 2), a tunnel D2 (220 <= x <= 320, y >= 112, cluster 3) in a second solid slab,
// room C (x >= 320, cluster 4). A segment through a whole tunnel rises less than 16 over 100 in y, so it
// cannot pass both tunnels' ends (a rise of 96 over the 20 of room B): hidden pairs (0, 3), (0, 4), (1, 4) and
// their reverses; every other pair is visible (e.g. D1 -> D2 steeply from D1's exit corner).
// Leaves: 0 unused (cluster 0), 1 A, 2 solid slab 1 (y >= 16), 3 D1, 4 B, 5 C, 6 D2, 7 solid slab 2.
// Visdata: `visible` of the caller (default: the exact answer).
struct TunnelsMap {
  Bsp bsp;
  static bool exact(int a, int b) {
    auto hidden = [](int x, int y) { return (x == 0 && y == 3) || (x == 0 && y == 4) || (x == 1 && y == 4); };
    return !hidden(a, b) && !hidden(b, a);
  }
};

template <class F>
inline TunnelsMap tunnels_map(F visible) {
  TunnelsMap m;
  Bsp& b = m.bsp;
  b.shaders = {{"textures/base/wall", 0, 1}};
  const int x100 = b.add_plane(1, 0, 0, 100), x200 = b.add_plane(1, 0, 0, 200);
  const int x220 = b.add_plane(1, 0, 0, 220), x320 = b.add_plane(1, 0, 0, 320);
  const int y16 = b.add_plane(0, 1, 0, 16), y112 = b.add_plane(0, 1, 0, 112);
  b.nodes = {{x100, 1, -(1 + 1)},          // 0: x > 100 -> node 1, else A
             {x200, 2, 3},                 // 1: x > 200 -> node 2, else the first slab
             {x220, 4, -(4 + 1)},          // 2: x > 220 -> node 4, else B
             {y16, -(2 + 1), -(3 + 1)},    // 3: y > 16 -> solid, else D1
             {x320, -(5 + 1), 5},          // 4: x > 320 -> C, else the second slab
             {y112, -(6 + 1), -(7 + 1)}};  // 5: y > 112 -> D2, else solid
  b.leaves.resize(8);
  const int cluster[8] = {0, 0, -1, 1, 2, 4, 3, -1};
  for (int i = 0; i < 8; ++i) b.leaves[i].cluster = cluster[i];
  b.models = {{{0, 0, 0}, {384, 128, 128}, 0, 0, 0, 0}};
  b.set_vis(5, 1, visible);
  return m;
}
inline TunnelsMap tunnels_map() { return tunnels_map(TunnelsMap::exact); }

// Adds the box brush [lo, hi] (six axis-aligned sides, outward normals) with `shader` to the world model
// (model 0): inserted after model 0's last brush, the later models' brush ranges shifted. Returns its index.
inline int add_world_box_brush(Bsp& b, std::array<float, 3> lo, std::array<float, 3> hi, int shader) {
  const int first = static_cast<int>(b.sides.size());
  b.sides.push_back({b.add_plane(-1, 0, 0, -lo[0]), shader});
  b.sides.push_back({b.add_plane(1, 0, 0, hi[0]), shader});
  b.sides.push_back({b.add_plane(0, -1, 0, -lo[1]), shader});
  b.sides.push_back({b.add_plane(0, 1, 0, hi[1]), shader});
  b.sides.push_back({b.add_plane(0, 0, -1, -lo[2]), shader});
  b.sides.push_back({b.add_plane(0, 0, 1, hi[2]), shader});
  const int at = b.models[0].first_brush + b.models[0].n_brushes;
  b.brushes.insert(b.brushes.begin() + at, Brush{first, 6, shader});
  ++b.models[0].n_brushes;
  for (std::size_t m = 1; m < b.models.size(); ++m)
    if (b.models[m].first_brush >= at) ++b.models[m].first_brush;
  for (auto& i : b.leaf_brushes)
    if (i >= at) ++i;
  return at;
}

// ---- Independent exact point location (oracle): descend the writer's own tree with GMP rationals. ----
// Returns the leaf, or nullopt when x lies exactly on a plane met on the way (the tests skip such points).
inline std::optional<int> oracle_leaf_of(const Bsp& b, const std::array<mpq_class, 3>& x) {
  if (b.nodes.empty()) return 0;
  int c = 0;
  for (std::size_t steps = 0; c >= 0 && steps <= b.nodes.size(); ++steps) {
    const Node& n = b.nodes[c];
    const Plane& p = b.planes[n.plane];
    const mpq_class v = mpq_class(double(p.n[0])) * x[0] + mpq_class(double(p.n[1])) * x[1] +
                        mpq_class(double(p.n[2])) * x[2] - mpq_class(double(p.d));
    if (v == 0) return std::nullopt;
    c = v > 0 ? n.front : n.back;
  }
  return -(c + 1);
}

}  // namespace bsptest
