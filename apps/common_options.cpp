#include "apps/common_options.hpp"

#include "apps/cli_util.hpp"

#include <fstream>

namespace exactvis::app {

CLI::Option* add_quiet_flag(CLI::App& sub, bool& quiet, const std::string& help) {
  return sub.add_flag("-q,--quiet", quiet, help);
}

CLI::Option* add_quiet_or_no_progress_flag(CLI::App& sub, bool& quiet) {
  return sub.add_flag("-q,--quiet,--no-progress", quiet, kQuietHelp);
}

CLI::Option* add_json_flag(CLI::App& sub, bool& json, const std::string& help) {
  return sub.add_flag("--json", json, help);
}

CLI::Option* add_output_option(CLI::App& sub, std::string& output, const std::string& help) {
  return sub.add_option("-o,--output", output, help);
}

CLI::Option* add_threads_option(CLI::App& sub, int& threads) {
  return sub.add_option("--threads", threads, "Worker threads: 0 = all cores (default), else 1 .. 1024");
}

CLI::Option* add_samples_option(CLI::App& sub, int& samples, const std::string& help) {
  return sub.add_option("--samples", samples, help)->capture_default_str();
}

CLI::Option* add_seed_option(CLI::App& sub, std::string& seed, const std::string& help) {
  return sub.add_option("--seed", seed, help)->capture_default_str();
}

namespace {

template <class Json>
void write_json_document(OutputFiles& outputs, const std::string& path, const Json& j) {
  outputs.write(path, [&](const std::string& temp) {
    std::ofstream out(temp);
    out << json_text(j);
    return static_cast<bool>(out);
  });
}

}  // namespace

void write_json_output(OutputFiles& outputs, const std::string& path, const nlohmann::json& j) {
  write_json_document(outputs, path, j);
}

void write_json_output(OutputFiles& outputs, const std::string& path, const nlohmann::ordered_json& j) {
  write_json_document(outputs, path, j);
}

}  // namespace exactvis::app
