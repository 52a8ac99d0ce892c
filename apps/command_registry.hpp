#pragma once
// Subcommands register themselves: each apps/<name>.cpp defines a static CommandRegistration that adds its
// subcommand to the CLI11 app and returns the function to run when it is chosen.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace exactvis::app {

struct Command {
  std::string name;
  int order;  // position in --help
  // Adds the subcommand to `parent` and returns the action to run (returns the exit status).
  std::function<std::function<int()>(CLI::App& parent)> setup;
};

std::vector<Command>& commands();

struct CommandRegistration {
  CommandRegistration(std::string name, int order, std::function<std::function<int()>(CLI::App&)> setup) {
    commands().push_back({std::move(name), order, std::move(setup)});
  }
};

}  // namespace exactvis::app
