#pragma once
// Another tool's PVS, as `exactvis validate --pvs FILE` reads it (issue #12). Three forms, told apart by the
// content:
//   - the PVS JSON of `exactvis pvs` (issue #11): {"cells": [{"box": [...], "visible": [ids...], ...}, ...]};
//     "box", "witnesses", "objects" and "stats" are optional and only "box" is used (it must then equal the
//     cells file's cell of the same index);
//   - its compact form, JSON lines (`exactvis pvs --jsonl`: a header line with "cell_count", then one cell
//     object per line with its "cell" index; read with io/pvs_json.hpp's read_pvs_lines), or plain JSON lines
//     without the header: one cell object per line, with an optional "cell" index (else the line's order);
//   - plain text, one line per cell: `cell_index: id id id ...` (ids separated by spaces or tabs; blank lines
//     and lines starting with '#' are skipped).
// Ids are the scene's stable triangle ids (docs/theory.md §4). A cell of the cells file that the PVS does not
// mention is taken as reported empty.
#include "kernel/scene.hpp"
#include "region/convex_polygon_3.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace exactvis {

struct ReportedCell {
  std::int64_t cell = 0;                      // index into the cells file
  std::optional<std::array<Exact, 6>> box;    // as written, when given (JSON forms)
  std::vector<std::int64_t> ids;              // triangle ids as written (repeats kept)
  std::string where;                          // "FILE: line L" or "FILE: cell K", for messages
};

struct ReportedPvs {
  std::string format;                         // "json", "json-lines" or "text"
  std::vector<ReportedCell> cells;            // in file order
};

// Input: the file's path. Output: its cells. Throws InputError "FILE: problem" (one line) for an unreadable
// or empty file, malformed JSON or text lines (the message names the line or cell), negative or non-integer
// ids or cell indices, and a cell given twice. Cost: linear in the file's size.
ReportedPvs read_reported_pvs(const std::string& path);

// The reported triangles of every cell as indices into scene.triangles (cells not mentioned: empty).
// Throws InputError "FILE: ...: cell K is out of range (the cells file has N cells)", "FILE: ...: triangle id
// X is not in the scene" (absent, out of range or dropped as degenerate) and "FILE: cell K: box differs from
// cell K of the cells file" (each message starts with the cell's `where`).
std::vector<std::vector<std::int64_t>> reported_indices(const ReportedPvs& pvs, const Scene& scene,
                                                        const std::vector<region::RationalBox3>& cells);

}  // namespace exactvis
