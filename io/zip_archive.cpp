#include "io/zip_archive.hpp"

#include "io/load_scene.hpp"

#include <zip.h>

#include <fstream>
#include <memory>

namespace exactvis {

namespace {

struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }  // read-only: nothing to write back
};
struct ZipFileCloser {
  void operator()(zip_file_t* f) const { zip_fclose(f); }
};
using ZipPtr = std::unique_ptr<zip_t, ZipCloser>;

ZipPtr open_archive(const std::string& archive) {
  int code = 0;
  zip_t* z = zip_open(archive.c_str(), ZIP_RDONLY, &code);
  if (!z) {
    zip_error_t error;
    zip_error_init_with_code(&error, code);
    const std::string why = zip_error_strerror(&error);
    zip_error_fini(&error);
    throw InputError(archive + ": cannot open as a zip archive (" + why + ")");
  }
  return ZipPtr(z);
}

}  // namespace

bool looks_like_zip(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  if (!in.read(magic, 4)) return false;
  return magic[0] == 'P' && magic[1] == 'K' && magic[2] == 3 && magic[3] == 4;
}

std::vector<std::string> zip_member_names(const std::string& archive) {
  ZipPtr z = open_archive(archive);
  const zip_int64_t n = zip_get_num_entries(z.get(), 0);
  std::vector<std::string> names;
  for (zip_int64_t i = 0; i < n; ++i) {
    const char* name = zip_get_name(z.get(), static_cast<zip_uint64_t>(i), ZIP_FL_ENC_GUESS);
    if (name) names.emplace_back(name);
  }
  return names;
}

std::string read_zip_member(const std::string& archive, const std::string& member, std::int64_t max_bytes) {
  ZipPtr z = open_archive(archive);
  const std::string where = archive + ":" + member;
  const zip_int64_t index = zip_name_locate(z.get(), member.c_str(), ZIP_FL_NOCASE);
  if (index < 0) throw InputError(where + ": no such member in the archive");
  zip_stat_t st;
  zip_stat_init(&st);
  if (zip_stat_index(z.get(), static_cast<zip_uint64_t>(index), 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
    throw InputError(where + ": cannot read the member's size (" + zip_strerror(z.get()) + ")");
  if (st.size > static_cast<zip_uint64_t>(max_bytes))
    throw InputError(where + ": member of " + std::to_string(st.size) + " bytes is larger than the limit of " +
                     std::to_string(max_bytes));
  std::unique_ptr<zip_file_t, ZipFileCloser> file(zip_fopen_index(z.get(), static_cast<zip_uint64_t>(index), 0));
  if (!file) throw InputError(where + ": cannot open the member (" + zip_strerror(z.get()) + ")");
  std::string bytes(static_cast<std::size_t>(st.size), '\0');
  zip_uint64_t done = 0;
  while (done < st.size) {
    const zip_int64_t got = zip_fread(file.get(), bytes.data() + done, st.size - done);
    if (got < 0) throw InputError(where + ": cannot decompress the member (" + zip_file_strerror(file.get()) + ")");
    if (got == 0) break;
    done += static_cast<zip_uint64_t>(got);
  }
  // One more read reaches the end of the data, where libzip checks the CRC.
  char extra = 0;
  const zip_int64_t more = done == st.size ? zip_fread(file.get(), &extra, 1) : 0;
  if (more < 0) throw InputError(where + ": cannot decompress the member (" + zip_file_strerror(file.get()) + ")");
  if (done != st.size || more > 0)
    throw InputError(where + ": member's data does not match its directory size of " + std::to_string(st.size) +
                     " bytes");
  return bytes;
}

}  // namespace exactvis
