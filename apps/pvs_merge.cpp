// `exactvis pvs-merge SHARD... -o pvs.json`: joins the outputs of `exactvis pvs --shard K/N` runs (JSON
// documents or JSON lines, in any order) into the document a single unsharded run writes.
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/pvs_json.hpp"

#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace {

using namespace exactvis;

struct MergeOptions {
  std::vector<std::string> inputs;
  std::string output;
  bool json = false, quiet = false;
};

struct ShardFile {
  OrderedJson scene;
  std::int64_t triangles = 0, cell_count = 0;
  std::vector<OrderedJson> cells;
};

// A PVS document or JSON-lines file.
ShardFile read_shard(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  std::string first;
  std::getline(in, first);
  ShardFile s;
  bool is_lines = false;
  try {
    const OrderedJson h = OrderedJson::parse(first);
    is_lines = h.is_object() && h.contains("cell_count");
  } catch (const nlohmann::json::exception&) {
  }
  if (is_lines) {
    PvsLines lines = read_pvs_lines(path);
    s.scene = lines.header["scene"];
    s.triangles = lines.header["triangles"].get<std::int64_t>();
    s.cell_count = lines.header["cell_count"].get<std::int64_t>();
    for (auto& [c, j] : lines.cells) s.cells.push_back(std::move(j));
    return s;
  }
  in.clear();
  in.seekg(0);
  std::stringstream text;
  text << in.rdbuf();
  OrderedJson doc;
  try {
    doc = OrderedJson::parse(text.str());
  } catch (const nlohmann::json::exception&) {
    throw InputError(path + ": not a PVS file (neither a JSON document nor JSON lines)");
  }
  if (!doc.is_object() || !doc.contains("cells") || !doc["cells"].is_array() || !doc.contains("triangles") ||
      !doc["triangles"].is_number_integer() || !doc.contains("scene"))
    throw InputError(path + ": not a PVS document {\"scene\", \"triangles\", \"cells\": [...], ...}");
  s.scene = doc["scene"];
  s.triangles = doc["triangles"].get<std::int64_t>();
  if (doc.contains("shard")) {
    const OrderedJson& sh = doc["shard"];
    if (!sh.is_object() || !sh.contains("cell_count") || !sh["cell_count"].is_number_integer())
      throw InputError(path + ": \"shard\" is not {\"index\", \"count\", \"cell_count\"}");
    s.cell_count = sh["cell_count"].get<std::int64_t>();
  } else {
    s.cell_count = static_cast<std::int64_t>(doc["cells"].size());
  }
  for (auto& c : doc["cells"]) {
    if (!c.is_object() || !c.contains("cell") || !c["cell"].is_number_integer())
      throw InputError(path + ": a cell without its \"cell\" number");
    s.cells.push_back(std::move(c));
  }
  return s;
}

int run_merge(const MergeOptions& o) {
  OutputFiles outputs({o.output});
  std::optional<ShardFile> first;
  std::map<std::int64_t, OrderedJson> cells;
  for (const auto& path : o.inputs) {
    ShardFile s = read_shard(path);
    if (!first) {
      first = ShardFile{s.scene, s.triangles, s.cell_count, {}};
    } else if (s.scene != first->scene || s.triangles != first->triangles || s.cell_count != first->cell_count) {
      throw InputError(path + ": belongs to a different run (scene " + s.scene.dump() + ", " +
                       std::to_string(s.triangles) + " triangles, " + std::to_string(s.cell_count) +
                       " cells; the first input has " + first->scene.dump() + ", " +
                       std::to_string(first->triangles) + ", " + std::to_string(first->cell_count) + ")");
    }
    for (auto& c : s.cells) {
      const std::int64_t i = c["cell"].get<std::int64_t>();
      if (i < 0 || i >= s.cell_count) throw InputError(path + ": cell " + std::to_string(i) + " is out of range");
      auto [it, fresh] = cells.emplace(i, c);
      if (!fresh && it->second != c)
        throw InputError(path + ": cell " + std::to_string(i) + " differs from the same cell in an earlier input");
    }
  }
  if (static_cast<std::int64_t>(cells.size()) != first->cell_count) {
    std::string missing;
    int shown = 0;
    for (std::int64_t i = 0; i < first->cell_count && shown < 8; ++i)
      if (!cells.count(i)) missing += (shown++ ? ", " : "") + std::to_string(i);
    throw std::invalid_argument("the inputs hold " + std::to_string(cells.size()) + " of " +
                                std::to_string(first->cell_count) + " cells (missing: " + missing +
                                (first->cell_count - static_cast<std::int64_t>(cells.size()) > shown ? ", ..." : "") +
                                "): a shard is missing or unfinished");
  }
  std::vector<OrderedJson> all;
  for (auto& [i, c] : cells) all.push_back(std::move(c));
  const OrderedJson doc = pvs_document(first->scene, first->triangles, std::move(all));
  exactvis::app::write_json_output(outputs, o.output, doc);
  outputs.commit();
  if (o.json) std::cout << exactvis::app::json_text(doc);
  else if (!o.quiet)
    std::cout << "merged " << cells.size() << " cells from " << o.inputs.size() << " files into " << o.output << "\n";
  return 0;
}

const exactvis::app::CommandRegistration registration("pvs-merge", 111, [](CLI::App& parent) {
  auto o = std::make_shared<MergeOptions>();
  CLI::App* sub = parent.add_subcommand(
      "pvs-merge", "Join the outputs of `exactvis pvs --shard K/N` runs into the file of one unsharded run");
  sub->add_option("shards", o->inputs, "Shard outputs (JSON documents or JSON lines)")->required();
  exactvis::app::add_output_option(*sub, o->output, "The merged PVS document")->required();
  exactvis::app::add_json_flag(*sub, o->json, "Also print the merged document on stdout");
  exactvis::app::add_quiet_flag(*sub, o->quiet, "No summary line on stdout");
  return [o]() { return run_merge(*o); };
});

}  // namespace
