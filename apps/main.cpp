// exactvis: exact 3D visibility. One subcommand per job; each lives in its own apps/<name>.cpp.
#include "apps/command_registry.hpp"

#include <algorithm>
#include <exception>
#include <iostream>
#include <map>

namespace exactvis::app {
std::vector<Command>& commands() {
  static std::vector<Command> c;
  return c;
}
}  // namespace exactvis::app

int main(int argc, char** argv) {
  using namespace exactvis::app;
  CLI::App app{"exactvis: exact 3D visibility (Plücker-space predicates with exact arithmetic)"};
  app.require_subcommand(1);
  auto& cmds = commands();
  std::sort(cmds.begin(), cmds.end(), [](const Command& a, const Command& b) { return a.order < b.order; });
  std::map<std::string, std::function<int()>> actions;
  std::vector<std::pair<CLI::App*, std::string>> subs;
  for (auto& c : cmds) actions[c.name] = c.setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  for (auto* sub : app.get_subcommands()) {
    try {
      return actions.at(sub->get_name())();
    } catch (const std::exception& e) {
      std::cerr << "exactvis " << sub->get_name() << ": error: " << e.what() << "\n";
      return 1;
    }
  }
  return 1;
}
