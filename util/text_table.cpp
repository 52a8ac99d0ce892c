#include "util/text_table.hpp"

#include <algorithm>

namespace exactvis {

void print_table(std::ostream& out, const std::vector<std::string>& headers,
                 const std::vector<std::vector<std::string>>& rows, std::int64_t total, std::size_t shown) {
  const std::size_t n = std::min(shown, rows.size());
  if (n == 0 && total <= 0) return;
  std::vector<std::size_t> width(headers.size(), 0);
  for (std::size_t c = 0; c < headers.size(); ++c) width[c] = headers[c].size();
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < headers.size() && c < rows[r].size(); ++c) width[c] = std::max(width[c], rows[r][c].size());
  auto line = [&](const std::vector<std::string>& cells) {
    std::string s = "  ";
    for (std::size_t c = 0; c < headers.size(); ++c) {
      const std::string cell = c < cells.size() ? cells[c] : "";
      s += cell;
      if (c + 1 < headers.size()) s += std::string(width[c] - cell.size() + 2, ' ');
    }
    while (!s.empty() && s.back() == ' ') s.pop_back();
    out << s << "\n";
  };
  line(headers);
  for (std::size_t r = 0; r < n; ++r) line(rows[r]);
  if (total > static_cast<std::int64_t>(n)) out << "  " << (total - static_cast<std::int64_t>(n)) << " more, use --json\n";
}

}  // namespace exactvis
