#include "io/mesh_text.hpp"

#include "io/load_scene.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace exactvis::mesh_io {

void fail(const std::string& path, const std::string& problem) {
  // Problems quote file content: control bytes become '?' so the message stays one printable line.
  std::string p = problem;
  for (char& c : p)
    if ((static_cast<unsigned char>(c) < 0x20) || c == 0x7f) c = '?';
  throw InputError(path + ": " + p);
}

std::optional<double> parse_double(std::string_view tok) {
  if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
  double v = 0;
  auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ptr != tok.data() + tok.size()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) {
    // Overflow is a non-finite coordinate; underflow rounds to a (sub)normal or zero, which strtod does exactly.
    v = std::strtod(std::string(tok).c_str(), nullptr);
  } else if (ec != std::errc()) {
    return std::nullopt;
  }
  return v;
}

std::optional<long long> parse_int(std::string_view tok) {
  if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
  long long v = 0;
  auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec != std::errc() || ptr != tok.data() + tok.size()) return std::nullopt;
  return v;
}

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

double text_coordinate(const std::string& path, const std::string& where, std::string_view tok) {
  const auto v = parse_double(tok);
  if (!v) fail(path, where + "bad coordinate '" + std::string(tok) + "'");
  if (std::isfinite(*v)) return *v;
  // A finite decimal that overflowed: say so (it is not "nan" or "inf" in the file).
  std::string t(tok);
  std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool named = t.find("inf") != std::string::npos || t.find("nan") != std::string::npos;
  if (named) fail(path, where + "non-finite coordinate '" + std::string(tok) + "'");
  fail(path, where + "non-finite coordinate '" + std::string(tok) + "' (beyond the range of doubles, about 1.8e308)");
}

double text_coordinate(const std::string& path, long line, std::string_view tok) {
  if (const auto v = parse_double(tok); v && std::isfinite(*v)) return *v;
  return text_coordinate(path, "line " + std::to_string(line) + ": ", tok);
}

bool beyond_float32(double v) { return std::isfinite(v) && std::fabs(v) > std::numeric_limits<float>::max(); }

TokenReplacement float32_stand_in(std::string_view text, std::string_view tok, double v) {
  return {static_cast<std::size_t>(tok.data() - text.data()), tok.size(), v < 0 ? "-3.40282346e38" : "3.40282346e38"};
}

std::string with_replacements(std::string_view text, std::vector<TokenReplacement> r) {
  std::sort(r.begin(), r.end(), [](const auto& a, const auto& b) { return a.offset < b.offset; });
  std::string out;
  out.reserve(text.size());
  std::size_t at = 0;
  for (const auto& x : r) {
    out.append(text.substr(at, x.offset - at));
    out += x.text;
    at = x.offset + x.length;
  }
  out.append(text.substr(at));
  return out;
}

std::size_t utf8_bom_length(std::string_view text) { return text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0; }

std::optional<std::string> unreadable_encoding(std::string_view text) {
  using namespace std::string_view_literals;
  if (text.substr(0, 4) == "\xFF\xFE\0\0"sv) return "is UTF-32 LE text (byte-order mark FF FE 00 00)";
  if (text.substr(0, 4) == "\0\0\xFE\xFF"sv) return "is UTF-32 BE text (byte-order mark 00 00 FE FF)";
  if (text.substr(0, 2) == "\xFF\xFE"sv) return "is UTF-16 LE text (byte-order mark FF FE)";
  if (text.substr(0, 2) == "\xFE\xFF"sv) return "is UTF-16 BE text (byte-order mark FE FF)";
  const std::string_view head = text.substr(0, 4096);
  std::size_t nul_even = 0, nul_odd = 0;
  for (std::size_t i = 0; i < head.size(); ++i)
    if (head[i] == '\0') ++(i % 2 ? nul_odd : nul_even);
  if (nul_even + nul_odd == 0) return std::nullopt;
  // UTF-16 of ASCII text: every other byte is NUL (the high byte: odd offsets for LE, even for BE).
  const std::size_t half = head.size() / 2;
  if (nul_odd * 10 >= half * 9 && nul_even * 10 < half) return "is UTF-16 LE text (NUL bytes between ASCII characters)";
  if (nul_even * 10 >= half * 9 && nul_odd * 10 < half) return "is UTF-16 BE text (NUL bytes between ASCII characters)";
  return "contains NUL bytes (binary data, not text)";
}

}  // namespace exactvis::mesh_io
