// The one command line (apps/main.cpp): `exactvis --version`, and CLI11's own parse errors (unknown options,
// failed checks, missing arguments) as one line "exactvis SUB: error: ..." with exit status 1, like every
// other error (docs/cli.md conventions).
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

class CommandLine : public cli_test::CliTest {
 protected:
  CommandLine() : CliTest("command-line") {}
};

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST_F(CommandLine, Version) {
  const auto r = run("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(std::regex_match(r.out, std::regex("exactvis [0-9]+\\.[0-9]+\\.[0-9]+\n"))) << r.out;
}

TEST_F(CommandLine, ParseErrorsAreOneLineWithExitOne) {
  const std::string out = path("x.obj");
  const std::pair<std::string, std::string> cases[] = {
      {"generate random -n 0 -o " + out, "exactvis generate: error: "},       // a failed Range check
      {"generate nosuchkind -o " + out, "exactvis generate: error: "},        // a failed IsMember check
      {"generate random", "exactvis generate: error: "},                      // a missing required option
      {"visible --no-such-option x.obj", "exactvis visible: error: "},        // an unknown option
      {"events", "exactvis events: error: "},                                 // a missing positional
      {"nosuchcommand", "exactvis: error: "},                                 // no subcommand
  };
  for (const auto& [args, prefix] : cases) {
    const auto r = run(args);
    EXPECT_EQ(r.status, 1) << args;
    EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << args << ": " << r.err;
    EXPECT_EQ(lines(r.err), prefix == "exactvis: error: " ? 2 : 1) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}

TEST_F(CommandLine, HelpStillExitsZero) {
  for (const char* args : {"--help", "generate --help", "visible --help"}) {
    const auto r = run(args);
    EXPECT_EQ(r.status, 0) << args;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << args;
  }
}

}  // namespace
