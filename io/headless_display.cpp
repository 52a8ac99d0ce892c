#include "io/headless_display.hpp"

#include "io/atomic_file.hpp"

#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace exactvis {

HeadlessDisplay::HeadlessDisplay(const std::string& what) {
  const char* d = std::getenv("DISPLAY");
  if (d && *d) return;
  int fds[2];
  if (pipe(fds) != 0) throw OutputError(what + ": cannot start Xvfb (no pipe)");
  const pid_t pid = fork();
  if (pid < 0) throw OutputError(what + ": cannot start Xvfb (fork failed)");
  if (pid == 0) {
    close(fds[0]);
    const int null = open("/dev/null", O_RDWR);
    if (null >= 0) dup2(null, 0), dup2(null, 1), dup2(null, 2);
    const std::string fd = std::to_string(fds[1]);
    execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
           static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  pid_ = pid;
  std::string number;
  pollfd p{fds[0], POLLIN, 0};
  while (poll(&p, 1, 10000) > 0) {
    char c = 0;
    if (read(fds[0], &c, 1) != 1) break;
    if (c == '\n') break;
    number += c;
  }
  close(fds[0]);
  if (number.empty()) {
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
    throw OutputError(what + ": no X display and Xvfb could not be started (install the xvfb package, or set DISPLAY)");
  }
  setenv("DISPLAY", (":" + number).c_str(), 1);
}

HeadlessDisplay::~HeadlessDisplay() {
  if (pid_ <= 0) return;
  unsetenv("DISPLAY");
  kill(pid_, SIGTERM);
  waitpid(pid_, nullptr, 0);
}

}  // namespace exactvis
