#include "io/view_cells_json.hpp"

#include "io/json_number.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace exactvis {

std::vector<region::RationalBox3> read_view_cells(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the cells file");
  std::stringstream text;
  text << in.rdbuf();
  return view_cells_from_json_text(text.str(), path);
}

std::vector<region::RationalBox3> view_cells_from_json_text(const std::string& text, const std::string& name) {
  auto fail = [&](const std::string& problem) { return InputError(name + ": " + problem); };
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception&) {
    throw fail("not valid JSON (expected {\"cells\": [[x0,y0,z0,x1,y1,z1], ...]})");
  }
  if (!j.is_object() || !j.contains("cells") || !j["cells"].is_array())
    throw fail("expected {\"cells\": [[x0,y0,z0,x1,y1,z1], ...]}");
  const nlohmann::json& cells = j["cells"];
  if (cells.empty()) throw fail("no cells (\"cells\" is an empty list)");
  std::vector<region::RationalBox3> out;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::string where = "cell " + std::to_string(c);
    const nlohmann::json& cell = cells[c];
    if (!cell.is_array() || cell.size() != 6) throw fail(where + " is not a list of 6 numbers [x0,y0,z0,x1,y1,z1]");
    std::array<Exact, 6> v;
    for (int k = 0; k < 6; ++k) {
      const nlohmann::json& x = cell[k];
      if (x.is_number_float() && !std::isfinite(x.get<double>()))
        throw fail(where + ": coordinate " + x.dump() + " is not finite");
      if (!x.is_number() && !x.is_string()) throw fail(where + ": " + x.dump() + " is not a number");
      try {
        v[k] = exact_from_json(x);
      } catch (const std::exception&) {
        throw fail(where + ": " + x.dump() + " is not a finite number");
      }
    }
    region::RationalBox3 b{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    for (int k = 0; k < 3; ++k)
      if (!(b.lo[k] < b.hi[k]))
        throw fail(where + " is empty or inverted in " + "xyz"[k] + " (need x0 < x1, y0 < y1, z0 < z1)");
    out.push_back(b);
  }
  return out;
}

}  // namespace exactvis
