// Zip archive members through libzip, on stored archives written by the tests' own writer
// (bsp_test_writer.hpp): names in order, bytes back exactly, case-insensitive lookup, the size limit
// checked before reading, bad checksums, missing members and non-zip files as one-line InputErrors.
#include "io/zip_archive.hpp"

#include "bsp_test_writer.hpp"
#include "io/load_scene.hpp"
#include "io_test_util.hpp"

#include <gtest/gtest.h>

using namespace exactvis;
using iotest::TempDir;
using iotest::write_file;

namespace {
// The call must throw InputError with one line starting "BLAME: " and containing `words`.
template <class F>
void expect_error(F call, const std::string& blame, const std::string& words) {
  try {
    call();
    ADD_FAILURE() << "no error (expected \"" << words << "\")";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(blame + ": ", 0), 0u) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_NE(msg.find(words), std::string::npos) << msg;
  }
}
}  // namespace

TEST(ZipArchive, NamesAndMembers) {
  TempDir dir;
  std::string binary;
  for (int i = 0; i < 300; ++i) binary.push_back(static_cast<char>(i * 7));
  const std::string zip = write_file(dir.file("a.pk3"), bsptest::zip_stored({{"maps/", ""}, {"maps/One.bsp", binary},
                                                                            {"scripts/x.shader", "text"}}));
  EXPECT_TRUE(looks_like_zip(zip));
  EXPECT_EQ(zip_member_names(zip), (std::vector<std::string>{"maps/", "maps/One.bsp", "scripts/x.shader"}));
  EXPECT_EQ(read_zip_member(zip, "maps/One.bsp", 1000), binary);
  EXPECT_EQ(read_zip_member(zip, "MAPS/one.BSP", 1000), binary);
  EXPECT_EQ(read_zip_member(zip, "scripts/x.shader", 4), "text");  // exactly at the limit
  expect_error([&] { read_zip_member(zip, "scripts/x.shader", 3); }, zip + ":scripts/x.shader", "larger than the limit of 3");
  expect_error([&] { read_zip_member(zip, "maps/two.bsp", 1000); }, zip + ":maps/two.bsp", "no such member");
}

TEST(ZipArchive, BadArchives) {
  TempDir dir;
  const std::string crc = write_file(dir.file("crc.pk3"), bsptest::zip_stored({{"a.txt", "hello world"}}, 0));
  expect_error([&] { read_zip_member(crc, "a.txt", 100); }, crc + ":a.txt", "cannot decompress");
  const std::string text = write_file(dir.file("text.pk3"), "not a zip archive at all");
  EXPECT_FALSE(looks_like_zip(text));
  expect_error([&] { zip_member_names(text); }, text, "cannot open as a zip archive");
  const std::string full = bsptest::zip_stored({{"a.txt", "hello world"}});
  const std::string cut = write_file(dir.file("cut.pk3"), full.substr(0, full.size() - 10));
  EXPECT_TRUE(looks_like_zip(cut));
  expect_error([&] { zip_member_names(cut); }, cut, "cannot open as a zip archive");
  EXPECT_FALSE(looks_like_zip(dir.file("absent.pk3")));
  expect_error([&] { zip_member_names(dir.file("absent.pk3")); }, dir.file("absent.pk3"), "cannot open");
}
