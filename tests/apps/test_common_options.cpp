// The shared option registration and JSON output of the subcommands (apps/common_options.hpp): names, help
// texts as --help prints them, defaults shown, values parsed, and the JSON file written whole at commit.
#include "apps/common_options.hpp"
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace exactvis;

namespace {

// Parses `args` (without the program name) into `app`.
void parse(CLI::App& app, std::vector<std::string> args) {
  std::reverse(args.begin(), args.end());  // CLI11 takes the vector in reverse order
  app.parse(args);
}

TEST(CommonOptions, NamesValuesAndHelp) {
  CLI::App app("test");
  bool quiet = false, json = false;
  std::string output, seed = "1";
  int threads = 0, samples = 48;
  app::add_quiet_flag(app, quiet);
  app::add_json_flag(app, json);
  app::add_output_option(app, output, "Write it here");
  app::add_threads_option(app, threads);
  app::add_samples_option(app, samples);
  app::add_seed_option(app, seed);
  parse(app, {"-q", "--json", "-o", "out.json", "--threads", "3", "--samples", "7", "--seed", "18446744073709551615"});
  EXPECT_TRUE(quiet);
  EXPECT_TRUE(json);
  EXPECT_EQ(output, "out.json");
  EXPECT_EQ(threads, 3);
  EXPECT_EQ(samples, 7);
  EXPECT_EQ(seed, "18446744073709551615");  // kept as text: parse_uint64 reads it
  EXPECT_EQ(app.get_option("--quiet")->get_description(), "No progress bar on stderr");
  EXPECT_EQ(app.get_option("--json")->get_description(), "Machine-readable JSON on stdout");
  EXPECT_EQ(app.get_option("--output")->get_description(), "Write it here");
  EXPECT_EQ(app.get_option("--threads")->get_description(), "Worker threads: 0 = all cores (default), else 1 .. 1024");
  EXPECT_EQ(app.get_option("--samples")->get_description(),
            "Random segments cast per source/target pair before the exact query");
  EXPECT_EQ(app.get_option("--seed")->get_description(), "Seed of the sampling (answers do not depend on it)");
  // --samples and --seed show their defaults in --help; --threads does not (its text names the default).
  EXPECT_EQ(app.get_option("--samples")->get_default_str(), "48");
  EXPECT_EQ(app.get_option("--seed")->get_default_str(), "1");
  EXPECT_EQ(app.get_option("--threads")->get_default_str(), "");
}

TEST(CommonOptions, OwnHelpTextsAndNoProgress) {
  CLI::App app("test");
  bool quiet = false, json = false;
  app::add_quiet_or_no_progress_flag(app, quiet);
  app::add_json_flag(app, json, "Print it");
  parse(app, {"--no-progress"});
  EXPECT_TRUE(quiet);
  EXPECT_FALSE(json);
  EXPECT_EQ(app.get_option("-q")->get_description(), "No progress bar on stderr");
  EXPECT_EQ(app.get_option("--json")->get_description(), "Print it");
  CLI::App other("other");
  app::add_quiet_flag(other, quiet, app::kQuietNoBarHelp);
  EXPECT_EQ(other.get_option("--quiet")->get_description(),
            "No progress bar on stderr (accepted by every subcommand; this one draws none)");
}

TEST(CommonOptions, JsonOutputIsWrittenAtCommitAsJsonText) {
  const cli_test::TempDir dir("common-options");
  const std::string path = dir.file("out.json");
  nlohmann::ordered_json j;
  j["b"] = 1;
  j["a"] = {1, 2};
  {
    OutputFiles outputs({path});
    app::write_json_output(outputs, path, j);
    EXPECT_FALSE(std::filesystem::exists(path));  // a temporary until commit
    outputs.commit();
  }
  EXPECT_EQ(cli_test::slurp(path), "{\n  \"b\": 1,\n  \"a\": [\n    1,\n    2\n  ]\n}\n");
  const std::string plain = dir.file("plain.json");
  {
    OutputFiles outputs({plain});
    app::write_json_output(outputs, plain, nlohmann::json{{"x", "y"}});
  }  // no commit: nothing is left
  EXPECT_FALSE(std::filesystem::exists(plain));
}

}  // namespace
