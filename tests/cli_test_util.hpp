#pragma once
// Running the `exactvis` binary from CLI tests (any suite): its exit status, stdout and stderr, captured in
// files of a test's own directory. EXACTVIS_BINARY is defined by tests/CMakeLists.txt.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace cli_test {

struct CliRun {
  int status;
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `exactvis ARGS` (ARGS as a shell would split them) with stdout and stderr in files of `dir`.
inline CliRun run_exactvis(const std::filesystem::path& dir, const std::string& args) {
  const std::string out = (dir / "stdout").string(), err = (dir / "stderr").string();
  const int raw = std::system((std::string(EXACTVIS_BINARY) + " " + args + " >" + out + " 2>" + err).c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

}  // namespace cli_test
