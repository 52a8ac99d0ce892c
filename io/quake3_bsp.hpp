#pragma once
// Reading Quake 3 BSP maps (IBSP version 46, as compiled by q3map2) into plain structs, every read checked.
//
// Sources (read_bsp, bsp_sources):
//   PATH.bsp                     a map file;
//   PATH.pk3                     a zip archive (read with libzip) holding exactly one map `*.bsp`;
//   PATH.pk3:MEMBER              the map MEMBER inside the archive: an exact member name such as
//                                `maps/oa_dm1.bsp`, or the short form `oa_dm1` / `oa_dm1.bsp` for `maps/oa_dm1.bsp`
//                                (member names compare case-insensitively, as the game does).
// A path that names an existing file is always taken whole (so a ':' in a file name is fine); otherwise it
// is split at its last ".pk3:" (any case). A file is read as a zip archive when it starts with "PK\3\4",
// else as a BSP.
//
// Format (docs/theory.md, "Quake 3 maps"): little-endian; header "IBSP", version 46, 17 lumps (offset,
// length). Entry sizes: shaders 72, planes 16, nodes 36, leaves 48, leaf faces 4, leaf brushes 4, models 40,
// brushes 12, brush sides 8, vertices 44, mesh vertices 4, effects 72, faces 104, lightmaps 49152, light
// volumes 8; entities and visdata are byte blobs.
//
// Checks: every lump lies inside the file and is a whole number of entries; every index is in range (node
// plane and children, leaf face/brush ranges and their entries, model face/brush ranges, brush side ranges
// and shaders, side planes and shaders, face shaders/effects (not of billboards, whose effect q3map2 leaves
// at 0 in maps without effects)/vertex and mesh-vertex ranges, mesh vertex offsets, patch sizes); the node tree reached from node 0 is a tree (no node or leaf reached twice, which also rules out
// cycles); plane and vertex numbers are finite and plane normals non-zero; the visdata header (n_vecs,
// sz_vecs) matches the lump length and covers every cluster (without visdata, clusters must be fewer than
// the leaves). Any failure throws InputError
// "SOURCE: problem" (one line). Memory is bounded by the input: the whole file (or archive member, at most
// kMaxBspBytes, checked before it is read) is held, and every table is sized by its lump's entry count, so
// the map takes a small multiple of the file's size.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace exactvis::quake3 {

// Content flags of shaders (the ones the geometry code and its documentation refer to).
inline constexpr std::int32_t kContentsSolid = 0x1;
inline constexpr std::int32_t kContentsLava = 0x8;
inline constexpr std::int32_t kContentsSlime = 0x10;
inline constexpr std::int32_t kContentsWater = 0x20;
inline constexpr std::int32_t kContentsFog = 0x40;
inline constexpr std::int32_t kContentsPlayerClip = 0x10000;
inline constexpr std::int32_t kContentsMonsterClip = 0x20000;
inline constexpr std::int32_t kContentsDetail = 0x8000000;
inline constexpr std::int32_t kContentsStructural = 0x10000000;
inline constexpr std::int32_t kContentsTranslucent = 0x20000000;

// Face types.
inline constexpr std::int32_t kFacePolygon = 1, kFacePatch = 2, kFaceMesh = 3, kFaceBillboard = 4;

// Largest BSP accepted (the biggest openarena-data map is about 10 MB).
inline constexpr std::int64_t kMaxBspBytes = std::int64_t(1) << 30;

struct BspShader {
  std::string name;              // up to 64 characters
  std::int32_t surface_flags = 0;
  std::int32_t content_flags = 0;
};

// The plane {p : normal . p = dist}; the float32 numbers are taken exactly by the geometry code.
struct BspPlane {
  std::array<float, 3> normal{};
  float dist = 0;
};

// children[k] >= 0: a node index; children[k] < 0: the leaf -(children[k] + 1). children[0] is the front
// (normal . p > dist), children[1] the back. mins/maxs: the compiler's integer bounds (not used for geometry).
struct BspNode {
  std::int32_t plane = 0;
  std::array<std::int32_t, 2> children{};
  std::array<std::int32_t, 3> mins{}, maxs{};
};

// cluster -1: no cluster (solid or outside). Leaf faces/brushes: ranges into leaf_faces / leaf_brushes.
struct BspLeaf {
  std::int32_t cluster = -1, area = -1;
  std::array<std::int32_t, 3> mins{}, maxs{};
  std::int32_t first_leaf_face = 0, n_leaf_faces = 0;
  std::int32_t first_leaf_brush = 0, n_leaf_brushes = 0;
};

// Model 0 is the world; the others are brush entities (doors, platforms).
struct BspModel {
  std::array<float, 3> mins{}, maxs{};
  std::int32_t first_face = 0, n_faces = 0;
  std::int32_t first_brush = 0, n_brushes = 0;
};

struct BspBrush {
  std::int32_t first_side = 0, n_sides = 0, shader = 0;
};

// A brush is the intersection of {p : normal . p <= dist} over its sides' planes.
struct BspBrushSide {
  std::int32_t plane = 0, shader = 0;
};

struct BspVertex {
  std::array<float, 3> position{};
  std::array<float, 2> texcoord{}, lightmap_coord{};
  std::array<float, 3> normal{};
  std::array<std::uint8_t, 4> color{};
};

struct BspEffect {
  std::string name;
  std::int32_t brush = 0, unknown = 0;
};

// Polygon and mesh faces are triangle lists: triangle k has the vertices
// first_vertex + mesh_vertices[first_mesh_vertex + 3k + j], j = 0, 1, 2. Patches (type 2) are
// patch_size[0] x patch_size[1] Bezier control points starting at first_vertex.
struct BspFace {
  std::int32_t shader = 0, effect = -1, type = 0;
  std::int32_t first_vertex = 0, n_vertices = 0;
  std::int32_t first_mesh_vertex = 0, n_mesh_vertices = 0;
  std::int32_t lightmap = -1;
  std::array<float, 3> normal{};
  std::array<std::int32_t, 2> patch_size{};
};

// Potentially visible sets: row x (n_vecs rows of sz_vecs bytes) has bit y % 8 of byte y / 8 set iff
// cluster y is potentially visible from cluster x. Empty (n_vecs == 0) when the map was compiled without vis.
struct BspVisData {
  std::int32_t n_vecs = 0, sz_vecs = 0;
  std::vector<std::uint8_t> bits;
};

struct BspMap {
  std::string source;            // the name used in error messages ("FILE" or "ARCHIVE:MEMBER")
  std::int32_t version = 0;
  std::string entities;          // the entity text, without its trailing NUL
  std::vector<BspShader> shaders;
  std::vector<BspPlane> planes;
  std::vector<BspNode> nodes;
  std::vector<BspLeaf> leaves;
  std::vector<std::int32_t> leaf_faces;   // face indices
  std::vector<std::int32_t> leaf_brushes; // brush indices
  std::vector<BspModel> models;
  std::vector<BspBrush> brushes;
  std::vector<BspBrushSide> brush_sides;
  std::vector<BspVertex> vertices;
  std::vector<std::int32_t> mesh_vertices;
  std::vector<BspEffect> effects;
  std::vector<BspFace> faces;
  BspVisData vis;
  // world_leaf[i]: leaf i is reached from node 0 (the world tree). q3map2 also writes an unused leaf 0 and
  // one leaf per brush model outside the tree; those are not part of the world's partition.
  std::vector<bool> world_leaf;

  // Number of clusters: vis.n_vecs when the map has visdata, else 1 + the largest cluster of a world leaf.
  int cluster_count() const;
  // True iff cluster b is potentially visible from cluster a (always true without visdata).
  // Requires 0 <= a, b < cluster_count(); throws std::out_of_range otherwise. Cost O(1).
  bool cluster_visible(int a, int b) const;
  // The root of the world tree as a child code: 0 (node 0), or -1 (leaf 0) for a map without nodes.
  std::int32_t root() const { return nodes.empty() ? -1 : 0; }
};

// Reads a map from a source (see the top of this file). Throws InputError "SOURCE: problem".
// Cost: linear in the file's size (plus the archive's decompression).
BspMap read_bsp(const std::string& source);

// Parses a BSP held in memory; `name` is used in error messages and as BspMap::source.
// Throws InputError "NAME: problem". Cost: linear in bytes.size().
BspMap parse_bsp(std::string_view bytes, const std::string& name);

// The map sources a path stands for, each readable by read_bsp: a .bsp file or "ARCHIVE:MEMBER" itself, or
// for an archive every member ending in ".bsp" (any case), as "ARCHIVE:MEMBER", in the archive's order.
// Throws InputError when the path cannot be read or an archive holds no map.
std::vector<std::string> bsp_sources(const std::string& path);

}  // namespace exactvis::quake3
