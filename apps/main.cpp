// exactvis: exact 3D visibility. One subcommand per job; each lives in its own apps/<name>.cpp.
#include "api/version.hpp"
#include "apps/command_registry.hpp"

#include <algorithm>
#include <exception>
#include <iostream>
#include <map>
#include <string>

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
  app.set_version_flag("--version", std::string("exactvis ") + EXACTVIS_VERSION, "Print the version and exit");
  auto& cmds = commands();
  std::sort(cmds.begin(), cmds.end(), [](const Command& a, const Command& b) { return a.order < b.order; });
  std::map<std::string, std::function<int()>> actions;
  std::vector<std::pair<CLI::App*, std::string>> subs;
  for (auto& c : cmds) actions[c.name] = c.setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Every parse error (unknown option, a check such as generate's -n range, a missing argument) is one
    // line "exactvis SUB: error: ..." with exit status 1, like the subcommands' own errors (docs/cli.md).
    std::string sub;
    for (int i = 1; i < argc && sub.empty(); ++i)
      if (actions.count(argv[i])) sub = argv[i];
    std::string what = e.what();
    for (char& c : what)
      if (c == '\n' || c == '\r') c = ' ';
    std::cerr << "exactvis" << (sub.empty() ? "" : " " + sub) << ": error: " << what << "\n";
    if (sub.empty()) std::cerr << "Run with --help for the list of subcommands.\n";
    return 1;
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
