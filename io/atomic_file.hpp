#pragma once
// Writing a file atomically: the content goes to a temporary file in the destination's directory, which is
// renamed over the destination only when writing succeeded. A failure leaves no partial output.
#include <functional>
#include <stdexcept>
#include <string>

namespace exactvis {

// Output could not be written; what() is one line "FILE: problem".
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Input: destination path, and a writer that fills the temporary file whose path it receives (same extension
// as `path`, so extension-driven writers pick the right format). The writer throws or returns false on
// failure. Output: `path` exists with the full content, or an OutputError is thrown and nothing is left.
void write_atomically(const std::string& path, const std::function<bool(const std::string& temp_path)>& writer);

}  // namespace exactvis
