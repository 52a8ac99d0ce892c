#include "io/view_cells.hpp"

#include "io/json_number.hpp"
#include "io/load_scene.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace exactvis {

std::vector<region::RationalBox3> read_view_cells(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": not a JSON document (" + std::string(e.what()) + ")");
  }
  if (!j.is_object() || !j.contains("cells") || !j["cells"].is_array())
    throw InputError(path + ": expected {\"cells\": [[x0,y0,z0,x1,y1,z1], ...]}");
  if (j["cells"].empty()) throw InputError(path + ": no cells");
  std::vector<region::RationalBox3> cells;
  for (std::size_t k = 0; k < j["cells"].size(); ++k) {
    const nlohmann::json& c = j["cells"][k];
    const std::string where = path + ": cell " + std::to_string(k);
    if (!c.is_array() || c.size() != 6) throw InputError(where + ": expected an array of 6 numbers, got " + c.dump());
    Exact v[6];
    for (int i = 0; i < 6; ++i) {
      if (c[i].is_number_float() && !std::isfinite(c[i].get<double>()))
        throw InputError(where + ": " + c[i].dump() + " is not finite");
      try {
        v[i] = exact_from_json(c[i]);
      } catch (const std::exception&) {
        throw InputError(where + ": " + c[i].dump() + " is not a number");
      }
    }
    for (int i = 0; i < 3; ++i)
      if (!(v[i] < v[i + 3]))
        throw InputError(where + ": empty or inverted (needs x0 < x1, y0 < y1, z0 < z1)");
    cells.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}});
  }
  return cells;
}

}  // namespace exactvis
