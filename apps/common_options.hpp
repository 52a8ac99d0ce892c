#pragma once
// The options and outputs several subcommands share, registered and written one way: -q/--quiet, --json,
// -o/--output, --threads, --samples, --seed (help texts as --help prints them; a subcommand whose option
// means something of its own passes its own text), and a JSON document written to an output file.
// Parsing and checking the values is apps/cli_util.hpp's (parse_uint64, check_thread_count).
#include "io/atomic_file.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace exactvis::app {

// The help of -q/--quiet for a subcommand that draws a progress bar, and for one that draws none.
inline constexpr const char* kQuietHelp = "No progress bar on stderr";
inline constexpr const char* kQuietNoBarHelp =
    "No progress bar on stderr (accepted by every subcommand; this one draws none)";
// The help of --json where it prints the subcommand's documented JSON on stdout.
inline constexpr const char* kJsonHelp = "Machine-readable JSON on stdout";
// The help of --samples and --seed of the exact from-region queries (visible, validate, pvs).
inline constexpr const char* kSamplesHelp = "Random segments cast per source/target pair before the exact query";
inline constexpr const char* kSeedHelp = "Seed of the sampling (answers do not depend on it)";

// Input: the subcommand and the variable the option sets. Output: the registered option (to chain
// ->excludes() and the like). --samples and --seed show their defaults in --help (capture_default_str).
CLI::Option* add_quiet_flag(CLI::App& sub, bool& quiet, const std::string& help = kQuietHelp);
// -q,--quiet,--no-progress (the subcommands that took --no-progress before -q was everywhere), kQuietHelp.
CLI::Option* add_quiet_or_no_progress_flag(CLI::App& sub, bool& quiet);
CLI::Option* add_json_flag(CLI::App& sub, bool& json, const std::string& help = kJsonHelp);
CLI::Option* add_output_option(CLI::App& sub, std::string& output, const std::string& help);
// --threads N: "Worker threads: 0 = all cores (default), else 1 .. 1024" (checked by check_thread_count).
CLI::Option* add_threads_option(CLI::App& sub, int& threads);
CLI::Option* add_samples_option(CLI::App& sub, int& samples, const std::string& help = kSamplesHelp);
// --seed TEXT: kept as text, parsed by parse_uint64 (seeds up to 2^64 - 1).
CLI::Option* add_seed_option(CLI::App& sub, std::string& seed, const std::string& help = kSeedHelp);

// Writes json_text(j) (2-space indentation, then a newline: what --json prints) to `path` through `outputs`
// (a temporary, renamed over `path` at outputs.commit()). Throws OutputError when it cannot be written.
void write_json_output(OutputFiles& outputs, const std::string& path, const nlohmann::json& j);
void write_json_output(OutputFiles& outputs, const std::string& path, const nlohmann::ordered_json& j);

}  // namespace exactvis::app
