// The subcommands' shared option parsing (apps/cli_util.hpp): exact numbers (subnormals are numbers, num/den
// exactly), cells, polygons, seeds, and the messages of bad text.
#include "apps/cli_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

using namespace exactvis;

namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CliUtil, SplitAndTrim) {
  EXPECT_EQ(app::split("a,,b", ','), (std::vector<std::string>{"a", "", "b"}));
  EXPECT_EQ(app::split("a,", ','), (std::vector<std::string>{"a", ""}));
  EXPECT_TRUE(app::split("", ',').empty());
  EXPECT_EQ(app::trim(" \t x y \t"), "x y");
  EXPECT_EQ(app::trim("  "), "");
}

TEST(CliUtil, DoublesIncludingSubnormals) {
  EXPECT_EQ(app::parse_double(" 1.5 ", "--x"), 1.5);
  // 1e-320 is a subnormal double: a number (stod refused it as out of range).
  const double sub = app::parse_double("1e-320", "--cell");
  EXPECT_GT(sub, 0);
  EXPECT_LT(sub, std::numeric_limits<double>::min());
  EXPECT_EQ(sub, std::strtod("1e-320", nullptr));
  EXPECT_EQ(app::parse_double("-4.9e-324", "--x"), -std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(error_of([] { app::parse_double("1e999", "--cell"); }), "--cell: '1e999' is not a number");
  EXPECT_EQ(error_of([] { app::parse_double("inf", "--cell"); }), "--cell: 'inf' is not finite");
  EXPECT_EQ(error_of([] { app::parse_double("1.5x", "--cell"); }), "--cell: '1.5x' is not a number");
  EXPECT_EQ(error_of([] { app::parse_double("", "--cell"); }), "--cell: '' is not a number");
}

TEST(CliUtil, ExactNumbers) {
  EXPECT_EQ(app::parse_exact("1/3", "--cell"), Exact(1) / Exact(3));
  EXPECT_EQ(app::parse_exact(" -6/4 ", "--cell"), Exact(-3) / Exact(2));
  EXPECT_EQ(app::parse_exact("0.1", "--cell"), Exact(0.1));  // the double 0.1 denotes, exactly
  EXPECT_NE(error_of([] { app::parse_exact("1/0", "--cell"); }).find("--cell: zero denominator"), std::string::npos);
  EXPECT_NE(error_of([] { app::parse_exact("1/x", "--cell"); }).find("--cell: "), std::string::npos);
}

TEST(CliUtil, CellAcceptsNumDenAndSubnormals) {
  const region::RationalBox3 b = app::parse_cell("0,1e-320,-1/3,1/3,1,2");
  EXPECT_EQ(b.lo.x, Exact(0));
  EXPECT_EQ(b.lo.y, Exact(std::strtod("1e-320", nullptr)));
  EXPECT_EQ(b.lo.z, Exact(-1) / Exact(3));
  EXPECT_EQ(b.hi.x, Exact(1) / Exact(3));
  EXPECT_EQ(error_of([] { app::parse_cell("0,0,0,1,1"); }), "--cell needs 6 numbers X0,Y0,Z0,X1,Y1,Z1");
  EXPECT_EQ(error_of([] { app::parse_cell("1/3,0,0,1/3,1,1"); }), "--cell: need X0 < X1, Y0 < Y1 and Z0 < Z1");
  // The same number text as --source-polygon takes.
  const region::Polygon3 p = app::parse_source_polygon("0,0,1/3; 1,0,1/3; 0,1,1/3");
  EXPECT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].z, Exact(1) / Exact(3));
}

TEST(CliUtil, Uint64RangeAndThreadCounts) {
  EXPECT_EQ(app::parse_uint64("0", "--seed"), 0u);
  EXPECT_EQ(app::parse_uint64("18446744073709551615", "--seed"), std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(app::parse_uint64("00018446744073709551615", "--seed"), std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(error_of([] { app::parse_uint64("18446744073709551616", "--seed"); }),
            "--seed: '18446744073709551616' is out of range (0 .. 18446744073709551615)");
  EXPECT_EQ(error_of([] { app::parse_uint64("99999999999999999999999", "-s"); }),
            "-s: '99999999999999999999999' is out of range (0 .. 18446744073709551615)");
  EXPECT_EQ(error_of([] { app::parse_uint64("-1", "--seed"); }),
            "--seed: '-1' is not a whole number in 0 .. 18446744073709551615");
  EXPECT_NE(error_of([] { app::parse_uint64("1.5", "--seed"); }), "(no error)");
  EXPECT_EQ(app::check_thread_count(0, "--threads"), 0);
  EXPECT_EQ(app::check_thread_count(1024, "--threads"), 1024);
  EXPECT_EQ(error_of([] { app::check_thread_count(-3, "--threads"); }),
            "--threads: -3 is not a thread count (0 = all cores, or 1 .. 1024)");
  EXPECT_NE(error_of([] { app::check_thread_count(100000, "--threads"); }), "(no error)");
}

TEST(CliUtil, LightSpec) {
  Scene s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  s.triangles = {{0, {0, 1, 2}, 0}};
  s.objects = {{"lamp"}, {"empty"}};
  s.faces_read = 1;
  const LightSource named = app::parse_light(s, "lamp");
  EXPECT_EQ(named.triangles, (std::vector<int>{0}));
  EXPECT_FALSE(named.appended);
  EXPECT_EQ(error_of([&] { app::parse_light(s, "empty"); }), "--light 'empty': object has no triangles");
  EXPECT_EQ(error_of([&] { app::parse_light(s, "nothing"); }),
            "--light 'nothing': no scene object has this name, and it is not a polygon 'x,y,z;x,y,z;x,y,z'");
  EXPECT_EQ(error_of([&] { app::parse_light(s, "0,0,5;1,0,5"); }), "--light '0,0,5;1,0,5': a polygon needs at least 3 points");
  EXPECT_EQ(error_of([&] { app::parse_light(s, "0,0,5;1,0;0,1,5"); }),
            "--light '0,0,5;1,0;0,1,5': point '1,0' needs 3 comma-separated coordinates");
  EXPECT_EQ(error_of([&] { app::parse_light(s, "0,0,5;1,0,x;0,1,5"); }), "--light '0,0,5;1,0,x;0,1,5': 'x' is not a finite number");
  EXPECT_EQ(error_of([&] { app::parse_light(s, "0,0,5;1,0,5;2,0,5"); }), "--light '0,0,5;1,0,5;2,0,5': fan triangle 1 has zero area");
  EXPECT_EQ(s.triangles.size(), 1u);  // failed specs leave the scene as it was
  const LightSource poly = app::parse_light(s, " 0, 0, 5;1,0,5;1,1,5;0,1,5");
  EXPECT_TRUE(poly.appended);
  EXPECT_EQ(poly.triangles, (std::vector<int>{1, 2}));
  EXPECT_EQ(s.triangles[1].id, 1);
  EXPECT_EQ(s.vertices[3], (Point3{0, 0, 5}));
}

}  // namespace
