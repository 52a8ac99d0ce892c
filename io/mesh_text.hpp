#pragma once
// Shared pieces of the mesh file readers (io/load_scene.cpp, io/load_ply.cpp): the mesh one file
// contributes, failing with "FILE: problem", tokens and lines of text, exact numbers, the coordinate rule of
// text formats, stand-ins that let OpenMesh read files with coordinates beyond float32, and the text
// encodings we cannot read. Rules: docs/theory.md, section 4.
#include "kernel/scene.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace exactvis::mesh_io {

// What one file contributes, in file order.
struct RawMesh {
  std::vector<Point3> vertices;
  std::vector<std::vector<int>> faces;  // local vertex indices, as in the file
  std::vector<int> face_group;          // OBJ only: group per face (empty: use components)
  std::vector<std::string> group_names;
};

// Throws InputError("PATH: PROBLEM").
[[noreturn]] void fail(const std::string& path, const std::string& problem);

// The double nearest to the decimal `tok` (correctly rounded; "+" allowed; "inf"/"nan" give non-finite
// values, a decimal beyond the largest double gives infinity); nullopt if `tok` is not a number.
std::optional<double> parse_double(std::string_view tok);
// The integer `tok` ("+" allowed); nullopt if it is not an integer or does not fit a long long.
std::optional<long long> parse_int(std::string_view tok);

// Whitespace-separated tokens of a line (views into it).
std::vector<std::string_view> tokens(std::string_view line);

// Calls f(line_number, line) for each line of `text` (line numbers from 1, without the end-of-line
// characters "\n" or "\r\n"), until f returns false.
template <class F>
void for_each_line(std::string_view text, F&& f) {
  std::size_t start = 0;
  long line_no = 1;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!f(line_no, line)) return;
    start = end + 1;
    ++line_no;
  }
}

// The coordinate rule of every text format: a coordinate is the double nearest to its decimal, of any
// magnitude a double holds (beyond float32's range too). Fails with "PATH: WHEREbad coordinate 'TOK'" for a
// token that is not a number, "PATH: WHEREnon-finite coordinate 'TOK'" for NaN or infinity and for a decimal
// beyond the largest double (about 1.8e308). `where` is a prefix such as "line 7: ".
double text_coordinate(const std::string& path, const std::string& where, std::string_view tok);
// The same for a token on line `line` (where = "line L: ", built only for a message).
double text_coordinate(const std::string& path, long line, std::string_view tok);

// OpenMesh parses coordinates as float32 and its stream parsing stops for good at a finite value beyond
// float32's range. Our readers take the coordinates exactly and give OpenMesh (which only has to agree on
// the connectivity) a copy of the text in which each such token is replaced by a float32 stand-in.
struct TokenReplacement {
  std::size_t offset = 0, length = 0;  // of the token in the file's text
  std::string text;                    // what OpenMesh reads instead
};
bool beyond_float32(double v);
// Replacement of `tok`, a view into `text` holding the value v (beyond float32), by +-FLT_MAX.
TokenReplacement float32_stand_in(std::string_view text, std::string_view tok, double v);
// `text` with the replacements applied (any order; they must not overlap).
std::string with_replacements(std::string_view text, std::vector<TokenReplacement> replacements);

// Length of a UTF-8 byte-order mark at the start of `text` (3 or 0); readers skip it.
std::size_t utf8_bom_length(std::string_view text);
// The reason a text file cannot be read as ASCII/UTF-8 text, from its first bytes: "is UTF-16 LE text" or
// "is UTF-16 BE text" (byte-order mark, or NUL bytes between ASCII characters), UTF-32 likewise, or
// "contains NUL bytes (binary data, not text)"; nullopt when it looks like text.
std::optional<std::string> unreadable_encoding(std::string_view text);

}  // namespace exactvis::mesh_io
