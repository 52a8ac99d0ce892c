#pragma once
// Reading a view cells file (`exactvis pvs --cells cells.json`): {"cells": [[x0,y0,z0,x1,y1,z1], ...]},
// each coordinate a JSON number or an exact "num/den" string (io/json_number.hpp).
#include "io/load_scene.hpp"
#include "region/convex_polygon_3.hpp"

#include <string>
#include <vector>

namespace exactvis {

// Input: the file's path. Output: the cells, exact, in file order. Throws InputError "FILE: problem" for an
// unreadable file, invalid JSON, a wrong shape (no "cells" list, a cell that is not a list of 6), a
// coordinate that is not a finite number, an empty or inverted cell (need x0 < x1, y0 < y1, z0 < z1), or no
// cells at all.
std::vector<region::RationalBox3> read_view_cells(const std::string& path);

// The same for the file's text, named `name` in the messages ("NAME: problem"; the file's path above).
std::vector<region::RationalBox3> view_cells_from_json_text(const std::string& text, const std::string& name);

}  // namespace exactvis
