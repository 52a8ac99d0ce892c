#pragma once
// The JSON forms of a PVS run (`exactvis pvs`, `exactvis pvs-merge`; docs/cli.md "pvs"):
//
// - the document (--json, -o pvs.json):
//     {"scene": ..., "triangles": N, "cells": [CELL, ...], "stats": {...}}
// - the compact JSON-lines form (--jsonl, -o pvs.jsonl): a header line
//     {"scene": ..., "triangles": N, "cell_count": C, "method": "exact", "witnesses": true}
//   then one CELL per line in the order cells finish;
// with CELL = {"cell": i, "box": [x0,y0,z0,x1,y1,z1], "visible": [ids...], "objects": [names...],
//              "witnesses": {"id": [[p],[q]], ...}, "stats": {...}}  ("witnesses" left out by --no-witnesses).
// Ids are the scene's stable ids; coordinates are exact (a JSON number when exactly a double, else "num/den").
// A shard's document (--shard K/N) also carries "shard": {"index": K, "count": N, "cell_count": C}.
#include "kernel/scene.hpp"
#include "region/cell_pvs.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace exactvis {

using OrderedJson = nlohmann::ordered_json;

// The cell's box as 6 exact JSON values.
OrderedJson box_json(const region::RationalBox3& box);

// CELL for cell number `cell_index` (see above). Deterministic (no timings).
OrderedJson pvs_cell_json(const Scene& scene, std::int64_t cell_index, const region::CellPvs& pvs, bool witnesses);

// The run's "stats": {"cells": number of CELLs, then the sums of the cells' integer counters}.
OrderedJson pvs_run_stats(const std::vector<OrderedJson>& cells);

// The document: `scene` (the file name, or a list of names), the triangle count, the CELLs sorted by "cell",
// pvs_run_stats, and the shard record when `shard` is set.
OrderedJson pvs_document(const OrderedJson& scene, std::int64_t triangles, std::vector<OrderedJson> cells,
                         const std::optional<OrderedJson>& shard = std::nullopt);

// The JSON-lines header (see above).
OrderedJson pvs_lines_header(const OrderedJson& scene, std::int64_t triangles, std::int64_t cell_count,
                             const std::string& method, bool witnesses);

// A JSON-lines file read back: its header, its complete CELL lines by cell number, and the byte length of
// the well-formed prefix (an interrupted run may leave a partial last line, which is not counted).
struct PvsLines {
  OrderedJson header;
  std::map<std::int64_t, OrderedJson> cells;
  std::uint64_t valid_bytes = 0;
};

// Reads a JSON-lines PVS file. Throws InputError "FILE: problem" for an unreadable file, a bad or missing
// header, a malformed line before the last, or a cell line without a valid "cell" number (or given twice
// with different content). A last line without its newline is ignored (a run killed mid-write).
PvsLines read_pvs_lines(const std::string& path);

}  // namespace exactvis
