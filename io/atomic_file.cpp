#include "io/atomic_file.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace exactvis {

void write_atomically(const std::string& path, const std::function<bool(const std::string&)>& writer) {
  namespace fs = std::filesystem;
  const fs::path dest(path);
  if (dest.filename().empty()) throw OutputError(path + ": not a file name");
  std::error_code ec;
  if (fs::is_directory(dest, ec)) throw OutputError(path + ": is a directory");
  const fs::path dir = dest.has_parent_path() ? dest.parent_path() : fs::path(".");
  const std::string ext = dest.extension().string();
  std::string templ = (dir / ("." + dest.stem().string() + ".tmp-XXXXXX" + ext)).string();
  const int fd = mkstemps(templ.data(), static_cast<int>(ext.size()));
  if (fd < 0) throw OutputError(path + ": cannot create a file in " + dir.string() + " (" + std::strerror(errno) + ")");
  // mkstemps creates the file 0600; give it the permissions an ordinary new file would get.
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  close(fd);
  bool ok = false;
  std::string why;
  try {
    ok = writer(templ);
  } catch (const std::exception& e) {
    why = e.what();
  }
  if (ok) {
    fs::rename(templ, dest, ec);
    if (!ec) return;
    why = "cannot rename the temporary file (" + ec.message() + ")";
  }
  fs::remove(templ, ec);
  throw OutputError(path + ": write failed" + (why.empty() ? std::string() : ": " + why));
}

}  // namespace exactvis
