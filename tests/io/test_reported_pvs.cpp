// Reading another tool's PVS (io/reported_pvs.hpp): the three forms (PVS JSON, JSON lines, text lines), ids
// mapped to the scene's triangles, and one-line errors naming the file and the cell or line.
#include "io/reported_pvs.hpp"

#include "io/load_scene.hpp"
#include "tests/io/io_test_util.hpp"

#include <gtest/gtest.h>

using namespace exactvis;

namespace {

Scene three_triangles_with_id_1_dropped() {
  Scene s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (std::int64_t id : {0, 2, 3}) s.triangles.push_back({id, {0, 1, 2}, 0});
  s.faces_read = 4;
  s.degenerate_dropped = 1;
  return s;
}

std::vector<region::RationalBox3> two_cells() {
  return {{{Exact(0), Exact(0), Exact(0)}, {Exact(1), Exact(1), Exact(1)}},
          {{Exact(1, 3), Exact(0), Exact(0)}, {Exact(2), Exact(1), Exact(1)}}};
}

// The InputError message of reading (and resolving) `content`, or "" when it reads.
std::string error_of(const std::string& content) {
  iotest::TempDir dir;
  const std::string path = iotest::write_file(dir.file("pvs.txt"), content);
  try {
    reported_indices(read_reported_pvs(path), three_triangles_with_id_1_dropped(), two_cells());
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;  // names the file first
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    return m.substr(path.size() + 2);
  }
  return "";
}

std::vector<std::vector<std::int64_t>> read(const std::string& content, std::string* format = nullptr) {
  iotest::TempDir dir;
  const std::string path = iotest::write_file(dir.file("pvs"), content);
  const ReportedPvs pvs = read_reported_pvs(path);
  if (format) *format = pvs.format;
  return reported_indices(pvs, three_triangles_with_id_1_dropped(), two_cells());
}

using Lists = std::vector<std::vector<std::int64_t>>;

}  // namespace

TEST(ReportedPvs, ThreeForms) {
  std::string format;
  // Ids 0, 2, 3 are the triangles at indices 0, 1, 2.
  EXPECT_EQ(read("# comment\n\n1: 3 0\t2\n0:\n", &format), (Lists{{}, {2, 0, 1}}));
  EXPECT_EQ(format, "text");
  EXPECT_EQ(read(R"({"scene": "s.obj", "triangles": 3, "cells": [
      {"box": [0, 0, 0, 1, 1, 1], "visible": [2], "objects": ["a"], "witnesses": {"2": [[0,0,0],[1,1,1]]}, "stats": {}},
      {"box": ["1/3", 0, 0, 2, 1, 1], "visible": [0, 3]}], "stats": {}})", &format),
            (Lists{{1}, {0, 2}}));
  EXPECT_EQ(format, "json");
  EXPECT_EQ(read("{\"cell\": 1, \"visible\": [3]}\n{\"cell\": 0, \"visible\": [0, 0]}\n", &format), (Lists{{0, 0}, {2}}));
  EXPECT_EQ(format, "json-lines");
  EXPECT_EQ(read("{\"visible\": [3]}\n\n{\"visible\": [2]}\n"), (Lists{{2}, {1}}));
  EXPECT_EQ(read("0: 2\n"), (Lists{{1}, {}}));  // cell 1 not mentioned: empty
}

TEST(ReportedPvs, OneLineErrors) {
  EXPECT_EQ(error_of(""), "empty file (no cells)");
  EXPECT_EQ(error_of("# only a comment\n"), "no cell lines ('cell_index: id id ...')");
  EXPECT_EQ(error_of("0 1 2\n"), "line 1: expected 'cell_index: id id ...', got '0 1 2'");
  EXPECT_EQ(error_of("x: 1\n"), "line 1: 'x' is not a cell index (a whole number >= 0)");
  EXPECT_EQ(error_of("0: 1 -2\n"), "line 1: '-2' is not a triangle id (a whole number >= 0)");
  EXPECT_EQ(error_of("0: 0 1.5\n"), "line 1: '1.5' is not a triangle id (a whole number >= 0)");
  EXPECT_EQ(error_of("0: 0\n0: 2\n"), "line 2: cell 0 is given twice");
  EXPECT_EQ(error_of("2: 0\n"), "line 1: cell 2 is out of range (the cells file has 2 cells)");
  EXPECT_EQ(error_of("0: 0\n1: 1\n"),
            "line 2: triangle id 1 is not in the scene (out of range, or dropped as degenerate)");
  EXPECT_EQ(error_of("0: 4\n"), "line 1: triangle id 4 is not in the scene (out of range, or dropped as degenerate)");
  EXPECT_EQ(error_of("{\"cells\": [{\"visible\": [0]}, {\"box\": [0,0,0,1,1,1], \"visible\": []}]}"),
            "cell 1: box differs from cell 1 of the cells file");
  EXPECT_EQ(error_of("{\"cells\": [{\"visible\": [0]}, {}]}"), "cell 1: no \"visible\" array of triangle ids");
  EXPECT_EQ(error_of("{\"cells\": [{\"visible\": [\"a\"]}]}"), "cell 0: \"a\" is not a triangle id (a whole number >= 0)");
  EXPECT_EQ(error_of("{\"cells\": [{\"visible\": [-1]}]}"), "cell 0: -1 is not a triangle id (a whole number >= 0)");
  EXPECT_EQ(error_of("{\"cells\": 3}"), "\"cells\" is not an array");
  EXPECT_EQ(error_of("{\"cells\": []}"), "no cells");
  EXPECT_EQ(error_of("{\"cells\": [1, 2, 3]}"), "cell 0: expected a cell object {\"visible\": [ids...], ...}");
  EXPECT_EQ(error_of("{\"cells\": [{\"visible\": [0]}, {\"visible\": [0]}, {\"visible\": [0]}]}"),
            "cell 2: cell 2 is out of range (the cells file has 2 cells)");
  EXPECT_EQ(error_of("{\"visible\": [0]}\n{\"visible\": [0]\n"), "line 2: not a JSON cell object");
  EXPECT_EQ(error_of("{\"cell\": 0, \"visible\": [0]}\n{\"cell\": 0, \"visible\": [0]}\n"), "line 2: cell 0 is given twice");
  EXPECT_EQ(error_of("{\"cells\": [{\"visible\": [0]}").rfind("not a JSON document", 0), 0u);
}

TEST(ReportedPvs, MissingFile) {
  EXPECT_THROW(read_reported_pvs("/nonexistent/pvs.json"), InputError);
}
