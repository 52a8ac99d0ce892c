// View cells files (io/view_cells_json.hpp): exact coordinates, and one-line "FILE: problem" errors for bad
// files (empty, not JSON, wrong shapes, non-numbers, NaN and infinities, empty and inverted cells).
#include "io/view_cells_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace exactvis;
namespace fs = std::filesystem;

namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("exactvis_cells_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p) << text;
  return p.string();
}

TEST(ViewCellsJson, ReadsExactCells) {
  const std::string path = write_temp("ok.json", R"({"cells": [[0, 0, 0, 1, 1, 1], ["1/3", -2, 0.5, "2/3", 1e3, 7]]})");
  const auto cells = read_view_cells(path);
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_TRUE(cells[1].lo.x == Exact(1, 3));
  EXPECT_TRUE(cells[1].hi.y == Exact(1000));
  EXPECT_TRUE(cells[1].lo.z == Exact(1, 2));
  fs::remove(path);
}

TEST(ViewCellsJson, BadFilesGiveOneLineErrorsNamingTheFile) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"empty", ""},
      {"notjson", "cells: 1 2 3"},
      {"nocells", R"({"boxes": [[0,0,0,1,1,1]]})"},
      {"notlist", R"({"cells": {"a": 1}})"},
      {"emptylist", R"({"cells": []})"},
      {"short", R"({"cells": [[0,0,0,1,1]]})"},
      {"flat", R"({"cells": [0,0,0,1,1,1]})"},
      {"string", R"({"cells": [[0,0,"abc",1,1,1]]})"},
      {"bool", R"({"cells": [[0,0,true,1,1,1]]})"},
      {"nan", R"({"cells": [[0,0,NaN,1,1,1]]})"},
      {"nanstring", R"({"cells": [[0,0,"nan",1,1,1]]})"},
      {"inf", R"({"cells": [[0,0,0,1,1,1e999]]})"},
      {"infstring", R"({"cells": [[0,0,0,1,1,"inf"]]})"},
      {"zerodenominator", R"({"cells": [[0,0,0,1,1,"1/0"]]})"},
      {"inverted", R"({"cells": [[0,0,0,1,1,1], [1,0,0,0,1,1]]})"},
      {"emptycell", R"({"cells": [[0,0,0,1,0,1]]})"},
  };
  for (const auto& [name, text] : bad) {
    const std::string path = write_temp(name + ".json", text);
    try {
      read_view_cells(path);
      ADD_FAILURE() << name << ": accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << name << ": " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << name << ": " << what;
    }
    fs::remove(path);
  }
  EXPECT_THROW(read_view_cells("/nonexistent/cells.json"), InputError);
}

}  // namespace
