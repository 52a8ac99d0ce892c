#pragma once
// Writing files atomically: content goes to a temporary file in the destination's directory, which is renamed
// over the destination only when writing succeeded. A failure leaves no partial output. OutputFiles does the
// same for all the output files of one command run: they appear together, or none does (docs/cli.md).
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace exactvis {

// Output could not be written; what() is one line "FILE: problem".
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Input: destination path, and a writer that fills the temporary file whose path it receives (same extension
// as `path`, so extension-driven writers pick the right format). The writer throws or returns false on
// failure. Output: `path` exists with the full content, or an OutputError is thrown and nothing is left.
void write_atomically(const std::string& path, const std::function<bool(const std::string& temp_path)>& writer);

// The output files of one run. Construction checks every destination (not a directory, not given twice, its
// directory accepts a new file: a probe file is created and removed), so a run fails before its work rather
// than after it. write() fills a temporary next to one destination (writer as in write_atomically; on
// failure every temporary is removed and OutputError thrown). commit() renames all temporaries over their
// destinations, only after every write succeeded; if a rename fails, the destinations already renamed in
// this commit are removed too. Without commit (an error, an exception), the destructor removes the
// temporaries and no destination is touched.
class OutputFiles {
 public:
  // Input: destination paths; empty strings (options not given) are skipped. Throws OutputError.
  explicit OutputFiles(const std::vector<std::string>& paths);
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  void write(const std::string& path, const std::function<bool(const std::string& temp_path)>& writer);
  void commit();

 private:
  struct Staged {
    std::string path, temp;
  };
  void discard();
  std::vector<std::string> destinations_;
  std::vector<Staged> staged_;
};

}  // namespace exactvis
