#pragma once
// View cells files (issue #11's `--cells cells.json`): {"cells": [[x0,y0,z0,x1,y1,z1], ...]}, each number a
// JSON number (taken as the exact double it is) or a "num/den" string, exactly.
#include "region/convex_polygon_3.hpp"

#include <string>
#include <vector>

namespace exactvis {

// Input: the file's path. Output: the cells in file order (lo < hi in every coordinate, exact).
// Throws InputError "FILE: problem" (one line) for an unreadable file, text that is not JSON, a missing or
// empty "cells" array, a cell that is not an array of 6 numbers, a number that is not finite, or an empty or
// inverted cell (x0 >= x1, y0 >= y1 or z0 >= z1); the message names the cell by its index.
// Cost: linear in the file's size.
std::vector<region::RationalBox3> read_view_cells(const std::string& path);

}  // namespace exactvis
