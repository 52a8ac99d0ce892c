#include "io/atomic_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace exactvis {
namespace {

namespace fs = std::filesystem;

// Creates an empty temporary file next to `path` (same extension) and returns its path; throws OutputError.
std::string make_temporary(const std::string& path) {
  const fs::path dest(path);
  if (path.empty() || dest.filename().empty()) throw OutputError(path + ": not a file name");
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
  return templ;
}

// Runs the writer on `temp`; on failure removes `temp` and throws OutputError naming `path`.
void fill(const std::string& path, const std::string& temp, const std::function<bool(const std::string&)>& writer) {
  bool ok = false;
  std::string why;
  try {
    ok = writer(temp);
  } catch (const std::exception& e) {
    why = e.what();
    // Writers name the file they were given, our temporary: the user knows only `path`.
    if (why.rfind(temp + ": ", 0) == 0) why = why.substr(temp.size() + 2);
  }
  if (ok) return;
  std::error_code ec;
  fs::remove(temp, ec);
  throw OutputError(path + ": write failed" + (why.empty() ? std::string() : ": " + why));
}

}  // namespace

void write_atomically(const std::string& path, const std::function<bool(const std::string&)>& writer) {
  OutputFiles out({path});
  out.write(path, writer);
  out.commit();
}

OutputFiles::OutputFiles(const std::vector<std::string>& paths) {
  std::vector<fs::path> resolved;
  for (const std::string& p : paths) {
    if (p.empty()) continue;
    std::error_code ec;
    fs::path r = fs::weakly_canonical(fs::absolute(p), ec);
    if (ec) r = fs::absolute(p).lexically_normal();
    if (std::find(resolved.begin(), resolved.end(), r) != resolved.end())
      throw OutputError(p + ": given twice as an output file");
    resolved.push_back(r);
    destinations_.push_back(p);
  }
  // Probe: can each directory take a new file? (Removed at once: nothing stays if the run is interrupted.)
  for (const std::string& p : destinations_) {
    const std::string probe = make_temporary(p);
    std::error_code ec;
    fs::remove(probe, ec);
  }
}

OutputFiles::~OutputFiles() { discard(); }

void OutputFiles::discard() {
  for (const Staged& s : staged_) {
    std::error_code ec;
    fs::remove(s.temp, ec);
  }
  staged_.clear();
}

void OutputFiles::write(const std::string& path, const std::function<bool(const std::string&)>& writer) {
  if (std::find(destinations_.begin(), destinations_.end(), path) == destinations_.end())
    throw std::logic_error(path + ": not declared as an output of this run");
  try {
    const std::string temp = make_temporary(path);
    fill(path, temp, writer);
    staged_.push_back({path, temp});
  } catch (...) {
    discard();
    throw;
  }
}

void OutputFiles::commit() {
  std::vector<std::string> renamed;
  for (std::size_t i = 0; i < staged_.size(); ++i) {
    std::error_code ec;
    fs::rename(staged_[i].temp, staged_[i].path, ec);
    if (!ec) {
      renamed.push_back(staged_[i].path);
      continue;
    }
    const std::string path = staged_[i].path, why = ec.message();
    staged_.erase(staged_.begin(), staged_.begin() + static_cast<std::ptrdiff_t>(i));
    discard();
    for (const std::string& r : renamed) fs::remove(r, ec);
    throw OutputError(path + ": write failed: cannot rename the temporary file (" + why + ")");
  }
  staged_.clear();
}

}  // namespace exactvis
