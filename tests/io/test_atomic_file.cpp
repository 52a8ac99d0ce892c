// Whole-or-nothing output: write_atomically and OutputFiles (all files of a run appear together or none).
// Checked from outside by listing the directory and reading the files back.
#include "io/atomic_file.hpp"
#include "io_test_util.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using exactvis::OutputError;
using exactvis::OutputFiles;
using iotest::TempDir;

namespace {

bool put(const std::string& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
  return static_cast<bool>(out);
}

}  // namespace

TEST(OutputFiles, CommitsAllTogether) {
  TempDir dir;
  const std::string a = dir.file("a.svg"), b = dir.file("b.vtp");
  OutputFiles out({a, "", b});
  out.write(a, [](const std::string& t) { return put(t, "first"); });
  EXPECT_EQ(iotest::entries(dir.path), 1);  // a's temporary only, no destination yet
  EXPECT_FALSE(std::filesystem::exists(a));
  out.write(b, [](const std::string& t) { return put(t, "second"); });
  EXPECT_FALSE(std::filesystem::exists(a));
  out.commit();
  EXPECT_EQ(iotest::read_file(a), "first");
  EXPECT_EQ(iotest::read_file(b), "second");
  EXPECT_EQ(iotest::entries(dir.path), 2);
}

TEST(OutputFiles, AFailedWriteLeavesNothingAndKeepsOldFiles) {
  TempDir dir;
  const std::string a = dir.file("a.svg"), b = dir.file("b.vtp");
  put(a, "old");
  {
    OutputFiles out({a, b});
    out.write(a, [](const std::string& t) { return put(t, "new"); });
    EXPECT_THROW(out.write(b, [](const std::string&) -> bool { throw std::runtime_error("disk on fire"); }),
                 OutputError);
  }
  EXPECT_EQ(iotest::read_file(a), "old");  // the run's first file never replaced it
  EXPECT_FALSE(std::filesystem::exists(b));
  EXPECT_EQ(iotest::entries(dir.path), 1);
  {  // returning false is a failure too; the message names the destination, not the temporary
    OutputFiles out({b});
    try {
      out.write(b, [](const std::string& t) { put(t, "partial"); return false; });
      ADD_FAILURE() << "no error";
    } catch (const OutputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(b + ": ", 0), 0u) << e.what();
    }
  }
  EXPECT_EQ(iotest::entries(dir.path), 1);
  {  // no commit (an error elsewhere in the run): the temporaries go, nothing appears
    OutputFiles out({b});
    out.write(b, [](const std::string& t) { return put(t, "done"); });
  }
  EXPECT_FALSE(std::filesystem::exists(b));
  EXPECT_EQ(iotest::entries(dir.path), 1);
}

TEST(OutputFiles, BadDestinationsFailBeforeAnyWork) {
  TempDir dir;
  const std::string good = dir.file("a.svg");
  std::filesystem::create_directory(dir.file("sub"));
  put(dir.file("plain"), "x");
  for (const std::string& bad : {dir.file("missing/b.vtp"), dir.file("plain/b.vtp"), dir.file("sub"), std::string("/")}) {
    try {
      OutputFiles out({good, bad});
      ADD_FAILURE() << bad << ": accepted";
    } catch (const OutputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(bad + ": ", 0), 0u) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  }
  EXPECT_THROW(OutputFiles({good, dir.file("./a.svg")}), OutputError);  // the same file twice
  EXPECT_EQ(iotest::entries(dir.path), 2);  // sub and plain: the probes left nothing
}

TEST(OutputFiles, WriteAtomicallyIsOneFileRun) {
  TempDir dir;
  const std::string a = dir.file("a.txt");
  exactvis::write_atomically(a, [](const std::string& t) { return put(t, "ok"); });
  EXPECT_EQ(iotest::read_file(a), "ok");
  EXPECT_THROW(exactvis::write_atomically(a, [](const std::string&) { return false; }), OutputError);
  EXPECT_EQ(iotest::read_file(a), "ok");
  EXPECT_EQ(iotest::entries(dir.path), 1);
}
