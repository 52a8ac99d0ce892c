#pragma once
// The one harness for tests that run the `exactvis` binary (any suite): a fresh temporary directory per test,
// the command's exit status, stdout and stderr, and a GoogleTest fixture holding both. EXACTVIS_BINARY is
// defined by tests/CMakeLists.txt.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>

namespace cli_test {

struct CliRun {
  int status;  // the exit status; -1 when the command did not exit normally (a signal)
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A unique directory under the system's temporary directory (exactvis-TAG-XXXXXX, made by mkdtemp: unique
// across the processes ctest runs at once), removed with everything in it at destruction.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& tag = "test") {
    std::string templ = (std::filesystem::temp_directory_path() / ("exactvis-" + tag + "-XXXXXX")).string();
    if (!mkdtemp(templ.data())) throw std::runtime_error("mkdtemp failed for " + templ);
    path = templ;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path / name).string(); }
  // Writes `content` (bytes as given) to file(name) and returns that path.
  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(file(name), std::ios::binary) << content;
    return file(name);
  }
};

// Runs `command` through /bin/sh with stdout and stderr captured in dir/.stdout and dir/.stderr, removed
// again afterwards (so they never show in a listing of `dir`).
inline CliRun run_shell(const std::filesystem::path& dir, const std::string& command) {
  const std::string out = (dir / ".stdout").string(), err = (dir / ".stderr").string();
  const int raw = std::system(("(" + command + ") >" + out + " 2>" + err).c_str());
  CliRun r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
  std::error_code ec;
  std::filesystem::remove(out, ec);
  std::filesystem::remove(err, ec);
  return r;
}

// Runs `exactvis ARGS` (ARGS as a shell would split them) with stdout and stderr captured in `dir`.
inline CliRun run_exactvis(const std::filesystem::path& dir, const std::string& args) {
  return run_shell(dir, std::string(EXACTVIS_BINARY) + " " + args);
}

// A fixture whose every test gets its own TempDir (dir_): path(name) names a file there, write(name, text)
// writes one, run(args) runs `exactvis ARGS` there.
class CliTest : public ::testing::Test {
 protected:
  explicit CliTest(const std::string& tag = "cli") : dir_(tag) {}
  std::string path(const std::string& name) const { return dir_.file(name); }
  std::string write(const std::string& name, const std::string& content) const { return dir_.write(name, content); }
  CliRun run(const std::string& args) const { return run_exactvis(dir_.path, args); }
  TempDir dir_;
};

}  // namespace cli_test
