#pragma once
// Reading 2D scenes: JSON files, or the section of a 3D scene by an axis-parallel plane.
//
// JSON: {"polygons": [P, ...]} where P is either a ring [[x,y], ...] (a polygon without holes) or a list of
// rings [[[x,y],...], [[x,y],...], ...] (outer boundary first, then holes). Coordinates are JSON numbers
// (taken as the exact doubles they are) or strings "num/den". Rings are not closed (no repeated vertex).
#include "planar/scene2d.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace exactvis {

// Parses the polygons of a 2D scene JSON document. Throws InputError("FILE: problem").
std::vector<PolygonInput2D> read_polygons2d_json(const std::string& path);

// The polygons of an already parsed 2D scene document `doc` ({"polygons": [...]}, as above); `name` stands
// for the file in messages. Throws InputError("NAME: problem") with the messages read_polygons2d_json gives.
std::vector<PolygonInput2D> polygons2d_from_json(const nlohmann::json& doc, const std::string& name);

// Section of a 3D scene file (any format load_scenes reads) by the plane `spec`, "x=V", "y=V" or "z=V"
// (V exact, e.g. 1.5 or 3/2): planar/slice_scene.hpp (plane coordinates, loops, holes). Throws InputError
// ("FILE: reason") when the file cannot be read or the slice cannot be made.
std::vector<PolygonInput2D> slice_scene_file(const std::string& path, const std::string& spec);

// Either of the above (slice when `slice_spec` is non-empty), validated into a Scene2D.
// Throws InputError("FILE: problem") for unreadable files and invalid scenes.
Scene2D load_scene2d(const std::string& path, const std::string& slice_spec = "");

}  // namespace exactvis
