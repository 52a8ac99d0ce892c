#pragma once
// The summarising text output of the subcommands (docs/cli.md "Text output"): a table of the first rows of
// a long result, then one line "N more, use --json" instead of a line per triangle, event or cell.
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace exactvis {

// The number of rows a summary table shows unless told otherwise.
inline constexpr std::size_t kSummaryRows = 10;

// Input: the column headers, the rows to show (each as many cells as headers; at most `shown` of them are
// printed), the total number of rows the full result has (>= rows.size()). Output on `out`: a header line,
// the rows with columns left-aligned and padded to their widest cell, two spaces apart, each line indented
// by two spaces; then, when total exceeds the rows printed, "  N more, use --json". No rows and total 0:
// nothing at all. Cost: linear in the printed cells.
void print_table(std::ostream& out, const std::vector<std::string>& headers,
                 const std::vector<std::vector<std::string>>& rows, std::int64_t total,
                 std::size_t shown = kSummaryRows);

}  // namespace exactvis
