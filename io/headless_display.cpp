#include "io/headless_display.hpp"

#include "io/atomic_file.hpp"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace exactvis {

HeadlessDisplay::HeadlessDisplay(const std::string& path) {
  const char* d = std::getenv("DISPLAY");
  if (d && *d) return;
  int fds[2];
  if (pipe(fds) != 0) throw OutputError(path + ": cannot render: pipe failed");
  const std::string fd = std::to_string(fds[1]);
  std::vector<std::string> args{"Xvfb", "-displayfd", fd, "-screen", "0", "1600x1200x24", "-nolisten", "tcp",
                                "-noreset"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);  // Xvfb's log
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  const int rc = posix_spawnp(&pid_, "Xvfb", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  if (rc != 0) {
    close(fds[0]);
    throw OutputError(path + ": cannot render: no DISPLAY and Xvfb could not be started (install xvfb)");
  }
  // Xvfb writes the display number followed by a newline once it accepts connections.
  std::string number;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd p{fds[0], POLLIN, 0};
    if (poll(&p, 1, 200) <= 0) continue;
    char c;
    const ssize_t n = read(fds[0], &c, 1);
    if (n <= 0) break;
    if (c == '\n') break;
    number += c;
  }
  close(fds[0]);
  if (number.empty()) {
    stop();
    throw OutputError(path + ": cannot render: Xvfb did not start");
  }
  display_ = ":" + number;
  setenv("DISPLAY", display_.c_str(), 1);
}

HeadlessDisplay::~HeadlessDisplay() {
  if (pid_ > 0) {
    unsetenv("DISPLAY");
    stop();
  }
}

void HeadlessDisplay::stop() {
  if (pid_ <= 0) return;
  kill(pid_, SIGTERM);
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = -1;
}

}  // namespace exactvis
