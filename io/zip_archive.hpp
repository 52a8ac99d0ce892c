#pragma once
// Reading members of zip archives (Quake 3's .pk3 files) through libzip.
#include <cstdint>
#include <string>
#include <vector>

namespace exactvis {

// True iff the file at `path` starts with a zip local-file signature ("PK\3\4"); false when it cannot be
// read or is shorter. Cost: reads 4 bytes.
bool looks_like_zip(const std::string& path);

// The names of an archive's members, in the archive's order (directories included, as stored).
// Throws InputError "ARCHIVE: problem" when it cannot be opened as a zip archive. Cost: reads the
// central directory.
std::vector<std::string> zip_member_names(const std::string& archive);

// The uncompressed bytes of one member. `member` is matched case-insensitively. Throws InputError
// "ARCHIVE: problem" when the archive cannot be opened, and "ARCHIVE:MEMBER: problem" when the member is
// missing, larger than max_bytes (checked before anything is allocated) or fails to decompress (bad
// checksum, truncated data, a size that differs from the directory's).
std::string read_zip_member(const std::string& archive, const std::string& member, std::int64_t max_bytes);

}  // namespace exactvis
