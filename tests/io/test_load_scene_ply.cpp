// PLY coordinates are exact: double properties (ASCII text, binary little- and big-endian) load as the very
// doubles written, including values float32 cannot hold; float32 files still load; broken PLY files give
// InputError. Expected values are the doubles the test itself writes, not anything from the loader.
#include "io/load_scene.hpp"
#include "io_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace exactvis;
using iotest::TempDir;
using iotest::write_file;

namespace {

// Little- or big-endian binary writers.
template <class T>
void put(std::string& s, T v, bool big) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if (big) std::reverse(b, b + sizeof(T));
  s.append(b, sizeof(T));
}

// Four vertices none of whose coordinates (except 0 and 1) float32 can represent.
const std::vector<std::array<double, 3>> kDoubles = {
    {0.1, 1.0 + std::ldexp(1.0, -40), 1e-300 * 3.0},
    {-123456.78901234567, 0.0, std::ldexp(1.0, 200)},
    {1.0 / 3.0, 2.0 / 3.0, -std::ldexp(1.0, -1074)},  // the smallest subnormal double
    {0.3, -0.7, 1.0}};

float as_float_check(double d) { return static_cast<float>(d); }

const char* kDoubleHeaderBody =
    "element vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
    "element face 2\nproperty list uchar int vertex_indices\nend_header\n";

std::string binary_double_ply(bool big) {
  std::string s = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") + " 1.0\n" +
                  kDoubleHeaderBody;
  for (const auto& p : kDoubles)
    for (double c : p) put(s, c, big);
  for (const std::vector<std::int32_t>& f : {std::vector<std::int32_t>{0, 1, 2}, {0, 2, 3}}) {
    s += static_cast<char>(3);
    for (auto v : f) put(s, v, big);
  }
  return s;
}

std::string ascii_number(double d) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", d);  // 17 significant digits name a double uniquely
  return buf;
}

void expect_vertices(const Scene& s, const std::vector<std::array<double, 3>>& want) {
  ASSERT_EQ(s.vertices.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(s.vertices[i][k], want[i][k]) << "vertex " << i << " coordinate " << k;
}

void expect_input_error(const std::string& path, const std::string& mentions = "") {
  try {
    load_scene(path);
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    if (!mentions.empty()) {
      EXPECT_NE(msg.find(mentions), std::string::npos) << msg;
    }
    return;
  } catch (const std::exception& e) {
    ADD_FAILURE() << path << ": expected InputError, got " << e.what();
    return;
  }
  ADD_FAILURE() << path << ": expected InputError, loaded";
}

}  // namespace

TEST(LoadScenePly, TestValuesAreNotFloat32) {
  // The test would prove nothing if float32 could hold the values: all but 0, 1 must differ from their float.
  int not_float = 0;
  for (const auto& p : kDoubles)
    for (double c : p) not_float += static_cast<double>(as_float_check(c)) != c;
  EXPECT_EQ(not_float, 10);
}

TEST(LoadScenePly, AsciiDoubleCoordinatesAreExact) {
  TempDir dir;
  std::string s = std::string("ply\nformat ascii 1.0\ncomment exact doubles\n\nCreated by hand\n") + kDoubleHeaderBody;
  // 2^200 is beyond float32's range, which OpenMesh's ASCII reader cannot take (an error, tested below).
  auto doubles = kDoubles;
  doubles[1][2] = -std::ldexp(1.0, 100) / 3.0;
  for (const auto& p : doubles) s += ascii_number(p[0]) + " " + ascii_number(p[1]) + " " + ascii_number(p[2]) + "\n";
  s += "3 0 1 2\n3 0 2 3\n";
  const Scene sc = load_scene(write_file(dir.file("a.ply"), s));
  expect_vertices(sc, doubles);
  EXPECT_EQ(sc.faces_read, 2);
  // Decimal text is read as the double literal it is, e.g. "0.1" is the double nearest 1/10.
  const Scene lit = load_scene(write_file(
      dir.file("lit.ply"), std::string("ply\nformat ascii 1.0\n") + kDoubleHeaderBody +
                               "0.1 0.2 0.3\n1.0000000000001 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 2 3\n"));
  expect_vertices(lit, {{0.1, 0.2, 0.3}, {1.0000000000001, 0, 0}, {0, 1, 0}, {0, 0, 1}});
}

TEST(LoadScenePly, BinaryLittleEndianDoubleCoordinatesAreExact) {
  TempDir dir;
  const Scene sc = load_scene(write_file(dir.file("le.ply"), binary_double_ply(false)));
  expect_vertices(sc, kDoubles);
  EXPECT_EQ(sc.faces_read, 2);
  EXPECT_EQ(sc.triangles.size(), 2u);
}

TEST(LoadScenePly, BinaryBigEndianDoubleCoordinatesAreExact) {
  TempDir dir;
  const Scene sc = load_scene(write_file(dir.file("be.ply"), binary_double_ply(true)));
  expect_vertices(sc, kDoubles);
  EXPECT_EQ(sc.faces_read, 2);
  EXPECT_EQ(sc.triangles.size(), 2u);
}

TEST(LoadScenePly, Float32AndOtherVertexPropertiesStillLoad) {
  TempDir dir;
  // float32 coordinates among other vertex properties (colour bytes, a double, a list) in either byte order.
  const std::vector<std::array<float, 3>> pts = {{0.1f, 0.2f, 0.3f}, {1.5f, -2.25f, 0}, {0, 3.75f, 1e-3f}};
  for (bool big : {false, true}) {
    std::string s = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 3\nproperty uchar red\nproperty float32 x\nproperty float64 quality\n"
                    "property float y\nproperty uint8 green\nproperty float z\n"
                    "element face 1\nproperty list uint8 int32 vertex_indices\nend_header\n";
    for (const auto& p : pts) {
      put<std::uint8_t>(s, 200, big);
      put(s, p[0], big);
      put(s, 0.123456789, big);
      put(s, p[1], big);
      put<std::uint8_t>(s, 7, big);
      put(s, p[2], big);
    }
    s += static_cast<char>(3);
    for (std::int32_t v : {0, 1, 2}) put(s, v, big);
    const Scene sc = load_scene(write_file(dir.file(big ? "f32be.ply" : "f32le.ply"), s));
    std::vector<std::array<double, 3>> want;
    for (const auto& p : pts) want.push_back({p[0], p[1], p[2]});
    expect_vertices(sc, want);
    EXPECT_EQ(sc.triangles.size(), 1u);
  }
  // ASCII float32 declaration and integer coordinates.
  const Scene a = load_scene(write_file(dir.file("f32.ply"),
                                        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                        "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                        "end_header\n0.5 0 0\n1 0.25 0\n0 1 -4\n3 0 1 2\n"));
  expect_vertices(a, {{0.5, 0, 0}, {1, 0.25, 0}, {0, 1, -4}});
  const Scene i = load_scene(write_file(dir.file("int.ply"),
                                        "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty short y\n"
                                        "property int z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                        "end_header\n100000 0 0\n0 -300 0\n0 0 7\n3 0 1 2\n"));
  expect_vertices(i, {{100000, 0, 0}, {0, -300, 0}, {0, 0, 7}});
}

TEST(LoadScenePly, BrokenFilesAreInputErrors) {
  TempDir dir;
  // Truncated binary vertex data (cut in the middle of the third vertex, both byte orders).
  for (bool big : {false, true}) {
    const std::string full = binary_double_ply(big);
    const size_t header = full.find("end_header\n") + 11;
    expect_input_error(write_file(dir.file("cut.ply"), full.substr(0, header + 2 * 24 + 5)));
    expect_input_error(write_file(dir.file("cut2.ply"), full.substr(0, full.size() - 3)));
  }
  // Truncated ASCII vertex data.
  expect_input_error(write_file(dir.file("cut.ply"), std::string("ply\nformat ascii 1.0\n") + kDoubleHeaderBody +
                                                         "0.1 0.2 0.3\n1 0 0\n0 1\n"));
  // A header declaring a huge vertex count (binary and ASCII): refused, no attempt to allocate.
  for (const char* fmt : {"binary_little_endian", "ascii"})
    expect_input_error(write_file(dir.file("huge.ply"),
                                  std::string("ply\nformat ") + fmt +
                                      " 1.0\nelement vertex 999999999999\nproperty double x\nproperty double y\n"
                                      "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                       "more than the file can hold");
  // Missing end_header.
  expect_input_error(write_file(dir.file("noend.ply"),
                                "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                                "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                     "end_header");
  // Malformed headers: unknown format, unknown type, no x property, property before element.
  const std::string rest = "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_input_error(write_file(dir.file("fmt.ply"), "ply\nformat binary_middle_endian 1.0\nelement vertex 3\n"
                                                     "property double x\nproperty double y\nproperty double z\n" + rest));
  expect_input_error(write_file(dir.file("type.ply"), "ply\nformat ascii 1.0\nelement vertex 3\n"
                                                      "property quad x\nproperty double y\nproperty double z\n" + rest));
  expect_input_error(write_file(dir.file("nox.ply"), "ply\nformat ascii 1.0\nelement vertex 3\n"
                                                     "property double w\nproperty double y\nproperty double z\n" + rest));
  expect_input_error(write_file(dir.file("prop.ply"), "ply\nformat ascii 1.0\nproperty double x\nelement vertex 3\n"
                                                      "property double y\nproperty double z\n" + rest));
  expect_input_error(write_file(dir.file("bad.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                                                     "property double y\nproperty double z\nelement face 1\n"
                                                     "property list uchar int vertex_indices\nend_header\n"
                                                     "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n"));
  // A finite ASCII value beyond float32's range is no longer refused: LoadScenePly.ValuesBeyondFloat32 loads it.
  // NaN / infinite coordinates: ASCII text and binary doubles.
  for (const char* v : {"nan", "NaN", "inf", "-inf", "1e400"})
    expect_input_error(write_file(dir.file("nan.ply"), std::string("ply\nformat ascii 1.0\n") + kDoubleHeaderBody +
                                                           "0 0 0\n1 0 0\n0 " + v + " 0\n0 0 1\n3 0 1 2\n3 0 2 3\n"),
                       "non-finite");
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    std::string s = std::string("ply\nformat binary_little_endian 1.0\n") + kDoubleHeaderBody;
    for (double c : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, bad, 0.0, 0.0, 0.0, 1.0}) put(s, c, false);
    for (int f = 0; f < 2; ++f) {
      s += static_cast<char>(3);
      for (std::int32_t v : {0, 1, 2}) put(s, v, false);
    }
    expect_input_error(write_file(dir.file("nan_bin.ply"), s), "non-finite");
  }
}

// Finite values beyond float32's range are coordinates like any other (docs/theory.md, section 4): exact in
// ASCII (any declared type) and binary, also in skipped float properties; OpenMesh, which reads float32 and
// stops at such a value, only has to agree on the connectivity.
TEST(LoadScenePly, ValuesBeyondFloat32) {
  TempDir dir;
  const std::string header = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\nproperty float q\n"
                             "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const Scene a = load_scene(write_file(dir.file("big.ply"), "ply\nformat ascii 1.0\n" + header +
                                                                "0 0 0 1e39\n1 0 1e300 0\n0 -3.5e38 0 0\n0 0 1 0\n"
                                                                "3 0 1 2\n3 0 2 3\n"));
  ASSERT_EQ(a.vertices.size(), 4u);
  EXPECT_EQ(a.vertices[1].z, 1e300);
  EXPECT_EQ(a.vertices[2].y, -3.5e38);
  EXPECT_EQ(a.triangles.size(), 2u);
  // Binary doubles: the same values.
  std::string s = std::string("ply\nformat binary_little_endian 1.0\n") + kDoubleHeaderBody;
  for (double c : {0.0, 0.0, 0.0, 1.0, 0.0, 1e300, 0.0, -3.5e38, 0.0, 0.0, 0.0, 1.0}) put(s, c, false);
  for (int f = 0; f < 2; ++f) {
    s += static_cast<char>(3);
    for (std::int32_t v : {0, f + 1, f + 2}) put(s, v, false);
  }
  const Scene b = load_scene(write_file(dir.file("big_bin.ply"), s));
  EXPECT_EQ(b.vertices[1].z, 1e300);
  EXPECT_EQ(b.vertices[2].y, -3.5e38);
}
