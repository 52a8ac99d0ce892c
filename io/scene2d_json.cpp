#include "io/scene2d_json.hpp"

#include "io/json_number.hpp"
#include "io/load_scene.hpp"
#include "planar/slice_scene.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace exactvis {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw InputError(path + ": " + what); }

std::vector<Point2> read_ring(const std::string& path, const nlohmann::json& r, const std::string& name) {
  if (!r.is_array()) fail(path, name + " is not an array of [x, y] points");
  std::vector<Point2> ring;
  for (const auto& p : r) {
    if (!p.is_array() || p.size() != 2) fail(path, name + " has a vertex that is not [x, y]");
    try {
      ring.emplace_back(exact_from_json(p[0]), exact_from_json(p[1]));
    } catch (const std::exception& e) {
      fail(path, name + ": bad coordinate (" + std::string(e.what()) + ")");
    }
  }
  return ring;
}

}  // namespace

std::vector<PolygonInput2D> read_polygons2d_json(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a 2D scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open (") + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) fail(path, "read error");
  nlohmann::json doc;
  try {
    // The whole file must be one JSON value: parse() refuses trailing characters (operator>> would stop
    // after the first value and ignore the rest).
    doc = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    // e.what(): "[json.exception.parse_error.101] parse error at line L, column C: ..."
    std::string why = e.what();
    const auto at = why.find("parse error");
    why = at == std::string::npos ? why : why.substr(at + std::string("parse error").size());
    for (char& c : why)
      if (c == '\n' || c == '\r') c = ' ';
    fail(path, "not valid JSON:" + why);
  }
  return polygons2d_from_json(doc, path);
}

std::vector<PolygonInput2D> polygons2d_from_json(const nlohmann::json& doc, const std::string& path) {
  if (!doc.is_object() || !doc.contains("polygons") || !doc["polygons"].is_array())
    fail(path, "expected {\"polygons\": [...]}");
  std::vector<PolygonInput2D> polys;
  int k = 0;
  for (const auto& p : doc["polygons"]) {
    const std::string name = "polygon " + std::to_string(k++);
    PolygonInput2D poly;
    if (!p.is_array() || p.empty()) fail(path, name + " is empty or not an array");
    const bool with_holes = p[0].is_array() && !p[0].empty() && p[0][0].is_array();
    if (with_holes) {
      for (std::size_t r = 0; r < p.size(); ++r)
        poly.rings.push_back(read_ring(path, p[r], name + (r ? " hole " + std::to_string(r - 1) : "")));
    } else {
      poly.rings.push_back(read_ring(path, p, name));
    }
    polys.push_back(std::move(poly));
  }
  if (polys.empty()) fail(path, "no polygons");
  return polys;
}

std::vector<PolygonInput2D> slice_scene_file(const std::string& path, const std::string& spec) {
  try {
    const SlicePlane plane = parse_slice_plane(spec);
    return slice_scene(load_scenes({path}), plane);
  } catch (const SliceError& e) {
    fail(path, e.what());
  }
}

Scene2D load_scene2d(const std::string& path, const std::string& slice_spec) {
  const auto polys = slice_spec.empty() ? read_polygons2d_json(path) : slice_scene_file(path, slice_spec);
  try {
    return make_scene2d(polys);
  } catch (const Scene2DError& e) {
    throw InputError(path + (slice_spec.empty() ? "" : " (slice " + slice_spec + ")") + ": " + e.what());
  }
}

}  // namespace exactvis
