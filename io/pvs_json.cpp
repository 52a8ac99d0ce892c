#include "io/pvs_json.hpp"

#include "io/json_number.hpp"
#include "io/load_scene.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace exactvis {
namespace {

OrderedJson point_json(const RationalPoint3& p) {
  return OrderedJson::array({OrderedJson(exact_to_json(p.x)), OrderedJson(exact_to_json(p.y)),
                             OrderedJson(exact_to_json(p.z))});
}

}  // namespace

OrderedJson box_json(const region::RationalBox3& b) {
  OrderedJson j = OrderedJson::array();
  for (const auto* p : {&b.lo, &b.hi})
    for (int k = 0; k < 3; ++k) j.push_back(OrderedJson(exact_to_json((*p)[k])));
  return j;
}

OrderedJson pvs_cell_json(const Scene& scene, std::int64_t cell_index, const region::CellPvs& pvs, bool witnesses) {
  OrderedJson j;
  j["cell"] = cell_index;
  j["box"] = box_json(pvs.cell);
  OrderedJson ids = OrderedJson::array();
  for (const auto& v : pvs.visible) ids.push_back(scene.triangles[v.index].id);
  j["visible"] = ids;
  j["objects"] = region::visible_objects(scene, pvs);
  if (witnesses) {
    OrderedJson w = OrderedJson::object();
    for (const auto& v : pvs.visible)
      if (v.witness)
        w[std::to_string(scene.triangles[v.index].id)] = OrderedJson::array({point_json(v.witness->p), point_json(v.witness->q)});
    j["witnesses"] = w;
  }
  const region::CellPvsStats& s = pvs.stats;
  j["stats"] = {{"triangles", s.triangles},
                {"visible", s.visible},
                {"accepted_by_rays", s.accepted_by_rays},
                {"exact_queries", s.exact_queries},
                {"culled", s.culled},
                {"boxes_tested", s.boxes_tested},
                {"boxes_culled", s.boxes_culled},
                {"stabbing_pairs", s.query.stabbing_pairs},
                {"occluders_considered", s.query.occluders_considered},
                {"splits", s.query.splits},
                {"cones_created", s.query.cones_created},
                {"real_line_tests", s.query.real_line_tests}};
  if (s.rays_cast > 0) j["stats"]["rays_cast"] = s.rays_cast;  // method `sampled` only
  return j;
}

OrderedJson pvs_run_stats(const std::vector<OrderedJson>& cells) {
  OrderedJson s;
  s["cells"] = cells.size();
  for (const auto& c : cells) {
    if (!c.contains("stats") || !c["stats"].is_object()) continue;
    for (const auto& [key, value] : c["stats"].items())
      if (value.is_number_integer()) s[key] = (s.contains(key) ? s[key].get<std::int64_t>() : 0) + value.get<std::int64_t>();
  }
  return s;
}

OrderedJson pvs_document(const OrderedJson& scene, std::int64_t triangles, std::vector<OrderedJson> cells,
                         const std::optional<OrderedJson>& shard) {
  std::stable_sort(cells.begin(), cells.end(), [](const OrderedJson& a, const OrderedJson& b) {
    return a["cell"].get<std::int64_t>() < b["cell"].get<std::int64_t>();
  });
  OrderedJson stats = pvs_run_stats(cells);
  OrderedJson out;
  out["scene"] = scene;
  out["triangles"] = triangles;
  if (shard) out["shard"] = *shard;
  out["cells"] = std::move(cells);
  out["stats"] = std::move(stats);
  return out;
}

OrderedJson pvs_lines_header(const OrderedJson& scene, std::int64_t triangles, std::int64_t cell_count,
                             const std::string& method, bool witnesses) {
  OrderedJson h;
  h["scene"] = scene;
  h["triangles"] = triangles;
  h["cell_count"] = cell_count;
  h["method"] = method;
  h["witnesses"] = witnesses;
  return h;
}

PvsLines read_pvs_lines(const std::string& path) {
  auto fail = [&](const std::string& problem) { return InputError(path + ": " + problem); };
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail("cannot open the PVS lines file");
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  PvsLines out;
  std::size_t pos = 0;
  std::int64_t line_no = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) break;  // a partial last line: the run was interrupted while writing it
    ++line_no;
    OrderedJson j;
    try {
      j = OrderedJson::parse(text.substr(pos, nl - pos));
    } catch (const nlohmann::json::exception&) {
      throw fail("line " + std::to_string(line_no) + " is not valid JSON");
    }
    if (line_no == 1) {
      if (!j.is_object() || !j.contains("cell_count") || !j["cell_count"].is_number_integer() ||
          !j.contains("triangles"))
        throw fail("line 1 is not a PVS lines header {\"scene\", \"triangles\", \"cell_count\", ...}");
      out.header = std::move(j);
    } else {
      if (!j.is_object() || !j.contains("cell") || !j["cell"].is_number_integer() || !j.contains("visible"))
        throw fail("line " + std::to_string(line_no) + " is not a PVS cell {\"cell\": i, \"box\", \"visible\", ...}");
      const std::int64_t c = j["cell"].get<std::int64_t>();
      if (c < 0 || c >= out.header["cell_count"].get<std::int64_t>())
        throw fail("line " + std::to_string(line_no) + ": cell " + std::to_string(c) + " is out of range");
      auto [it, fresh] = out.cells.emplace(c, j);
      if (!fresh && it->second != j)
        throw fail("cell " + std::to_string(c) + " is given twice with different content");
    }
    pos = nl + 1;
    out.valid_bytes = pos;
  }
  if (line_no == 0) throw fail("no PVS lines header (empty or interrupted before the first line)");
  return out;
}

}  // namespace exactvis
