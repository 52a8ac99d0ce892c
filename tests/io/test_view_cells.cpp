// View cells files (io/view_cells.hpp): exact numbers, and one-line errors naming the file and the cell.
#include "io/view_cells.hpp"

#include "io/load_scene.hpp"
#include "tests/io/io_test_util.hpp"

#include <gtest/gtest.h>

using namespace exactvis;

namespace {

std::string error_of(const std::string& content) {
  iotest::TempDir dir;
  const std::string path = iotest::write_file(dir.file("cells.json"), content);
  try {
    read_view_cells(path);
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    return m.substr(path.size() + 2);
  }
  return "";
}

}  // namespace

TEST(ViewCells, ExactNumbers) {
  iotest::TempDir dir;
  const auto cells = read_view_cells(
      iotest::write_file(dir.file("c.json"), R"({"cells": [[0, 0.1, "1/3", 1, 2, "2/3"], [-1e300, 0, 0, 1e300, 1, 1]]})"));
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_EQ(cells[0].lo.y, Exact(0.1));  // the double 0.1, exactly
  EXPECT_EQ(cells[0].lo.z, Exact(1, 3));
  EXPECT_EQ(cells[0].hi.z, Exact(2, 3));
  EXPECT_EQ(cells[1].lo.x, Exact(-1e300));
}

TEST(ViewCells, OneLineErrors) {
  EXPECT_EQ(error_of("[1,2").rfind("not a JSON document (", 0), 0u);
  EXPECT_EQ(error_of("[]"), "expected {\"cells\": [[x0,y0,z0,x1,y1,z1], ...]}");
  EXPECT_EQ(error_of("{\"cells\": []}"), "no cells");
  EXPECT_EQ(error_of("{\"cells\": [[0,0,0,1,1]]}"), "cell 0: expected an array of 6 numbers, got [0,0,0,1,1]");
  EXPECT_EQ(error_of("{\"cells\": [[0,0,0,1,1,1], [0,0,0,1,\"a\",1]]}"), "cell 1: \"a\" is not a number");
  EXPECT_EQ(error_of("{\"cells\": [[0,0,0,1,\"nan\",1]]}"), "cell 0: \"nan\" is not a number");
  EXPECT_EQ(error_of("{\"cells\": [[0,0,0,1,1e400,1]]}").rfind("not a JSON document (", 0), 0u);  // overflow
  EXPECT_EQ(error_of("{\"cells\": [[0,0,0,1,1,0]]}"), "cell 0: empty or inverted (needs x0 < x1, y0 < y1, z0 < z1)");
  EXPECT_EQ(error_of("{\"cells\": [[2,0,0,1,1,1]]}"), "cell 0: empty or inverted (needs x0 < x1, y0 < y1, z0 < z1)");
  EXPECT_EQ(error_of("{\"cells\": [[0,0,0,1,1,1]]}"), "");
}
