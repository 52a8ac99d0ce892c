#include "io/reported_pvs.hpp"

#include "io/json_number.hpp"
#include "io/load_scene.hpp"
#include "io/pvs_json.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <fstream>
#include <set>
#include <sstream>

namespace exactvis {
namespace {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// A non-negative decimal integer (at most 18 digits), or std::nullopt.
std::optional<std::int64_t> whole_number(const std::string& t) {
  if (t.empty() || t.size() > 18 || t.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  return std::stoll(t);
}

std::int64_t json_id(const nlohmann::json& j, const std::string& where) {
  // nlohmann reads non-negative integers as unsigned.
  if (!j.is_number_unsigned() || j.get<std::uint64_t>() > std::uint64_t(INT64_MAX))
    throw InputError(where + ": " + j.dump() + " is not a triangle id (a whole number >= 0)");
  return j.get<std::int64_t>();
}

ReportedCell json_cell(const nlohmann::json& c, std::int64_t default_index, const std::string& where) {
  if (!c.is_object()) throw InputError(where + ": expected a cell object {\"visible\": [ids...], ...}");
  ReportedCell rc;
  rc.cell = default_index;
  rc.where = where;
  if (c.contains("cell")) {
    const nlohmann::json& k = c["cell"];
    if (!k.is_number_unsigned() || k.get<std::uint64_t>() > std::uint64_t(INT64_MAX))
      throw InputError(where + ": \"cell\" " + k.dump() + " is not a cell index (a whole number >= 0)");
    rc.cell = k.get<std::int64_t>();
  }
  if (!c.contains("visible") || !c["visible"].is_array())
    throw InputError(where + ": no \"visible\" array of triangle ids");
  for (const auto& id : c["visible"]) rc.ids.push_back(json_id(id, where));
  if (c.contains("box")) {
    const nlohmann::json& b = c["box"];
    if (!b.is_array() || b.size() != 6) throw InputError(where + ": \"box\" is not an array of 6 numbers");
    std::array<Exact, 6> box;
    for (int i = 0; i < 6; ++i) {
      try {
        box[static_cast<std::size_t>(i)] = exact_from_json(b[i]);
      } catch (const std::exception&) {
        throw InputError(where + ": \"box\" entry " + b[i].dump() + " is not a number");
      }
    }
    rc.box = box;
  }
  return rc;
}

ReportedPvs parse_text(const std::string& path, const std::string& text) {
  ReportedPvs out;
  out.format = "text";
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string t = trimmed(line);
    if (t.empty() || t[0] == '#') continue;
    const std::string where = "line " + std::to_string(number);
    const auto colon = t.find(':');
    if (colon == std::string::npos)
      throw InputError(path + ": " + where + ": expected 'cell_index: id id ...', got '" + t + "'");
    const std::string head = trimmed(t.substr(0, colon));
    const auto k = whole_number(head);
    if (!k) throw InputError(path + ": " + where + ": '" + head + "' is not a cell index (a whole number >= 0)");
    ReportedCell rc;
    rc.cell = *k;
    rc.where = path + ": " + where;
    std::istringstream ids(t.substr(colon + 1));
    std::string tok;
    while (ids >> tok) {
      const auto id = whole_number(tok);
      if (!id) throw InputError(path + ": " + where + ": '" + tok + "' is not a triangle id (a whole number >= 0)");
      rc.ids.push_back(*id);
    }
    out.cells.push_back(std::move(rc));
  }
  return out;
}

// Whether the first line is the header of `exactvis pvs --jsonl` (an object with "cell_count").
bool is_pvs_lines_header(const std::string& text) {
  try {
    const nlohmann::json first = nlohmann::json::parse(text.substr(0, text.find('\n')));
    return first.is_object() && first.contains("cell_count") && !first.contains("visible");
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

}  // namespace

ReportedPvs read_reported_pvs(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot be read");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::string start = trimmed(text);
  if (start.empty()) throw InputError(path + ": empty file (no cells)");
  ReportedPvs out;
  if (start[0] != '{') {
    out = parse_text(path, text);
    if (out.cells.empty()) throw InputError(path + ": no cell lines ('cell_index: id id ...')");
  } else {
    nlohmann::json whole;
    bool is_whole = true;
    std::string whole_error;
    try {
      whole = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
      is_whole = false;
      whole_error = e.what();
    }
    if (is_whole && whole.contains("cells")) {
      out.format = "json";
      if (!whole["cells"].is_array()) throw InputError(path + ": \"cells\" is not an array");
      for (std::size_t k = 0; k < whole["cells"].size(); ++k)
        out.cells.push_back(json_cell(whole["cells"][k], static_cast<std::int64_t>(k), path + ": cell " + std::to_string(k)));
    } else if (is_pvs_lines_header(text)) {
      // The JSON-lines file of `exactvis pvs` (a header line, then one cell per line): its own reader.
      out.format = "json-lines";
      const PvsLines lines = read_pvs_lines(path);
      for (const auto& [index, cell] : lines.cells)
        out.cells.push_back(json_cell(nlohmann::json::parse(cell.dump()), index, path + ": cell " + std::to_string(index)));
    } else {
      // JSON lines: every non-blank line one cell object (a single-line file without "cells" too).
      out.format = "json-lines";
      std::istringstream lines(text);
      std::string line;
      std::int64_t order = 0;
      for (int number = 1; std::getline(lines, line); ++number) {
        if (trimmed(line).empty()) continue;
        const std::string where = path + ": line " + std::to_string(number);
        nlohmann::json c;
        try {
          c = nlohmann::json::parse(line);
        } catch (const nlohmann::json::exception& e) {
          throw InputError(is_whole || number > 1 ? where + ": not a JSON cell object"
                                                  : path + ": not a JSON document (" + whole_error + ")");
        }
        out.cells.push_back(json_cell(c, order++, where));
      }
    }
    if (out.cells.empty()) throw InputError(path + ": no cells");
  }
  std::set<std::int64_t> seen;
  for (const auto& c : out.cells)
    if (!seen.insert(c.cell).second)
      throw InputError(c.where + ": cell " + std::to_string(c.cell) + " is given twice");
  return out;
}

std::vector<std::vector<std::int64_t>> reported_indices(const ReportedPvs& pvs, const Scene& scene,
                                                        const std::vector<region::RationalBox3>& cells) {
  std::vector<std::vector<std::int64_t>> out(cells.size());
  for (const ReportedCell& c : pvs.cells) {
    if (c.cell >= static_cast<std::int64_t>(cells.size()))
      throw InputError(c.where + ": cell " + std::to_string(c.cell) + " is out of range (the cells file has " +
                       std::to_string(cells.size()) + " cells)");
    const region::RationalBox3& b = cells[static_cast<std::size_t>(c.cell)];
    if (c.box) {
      const std::array<Exact, 6> want{b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z};
      if (*c.box != want)
        throw InputError(c.where + ": box differs from cell " + std::to_string(c.cell) + " of the cells file");
    }
    auto& list = out[static_cast<std::size_t>(c.cell)];
    for (const std::int64_t id : c.ids) {
      const std::int64_t index = scene.index_of_id(id);
      if (index < 0)
        throw InputError(c.where + ": triangle id " + std::to_string(id) +
                         " is not in the scene (out of range, or dropped as degenerate)");
      list.push_back(index);
    }
  }
  return out;
}

}  // namespace exactvis
