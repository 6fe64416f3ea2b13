#include "renderer/util/atomic_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <system_error>

#include "renderer/util/image_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace fs = std::filesystem;

namespace {

// Distinguishes several outputs of one process that target the same final name.
std::atomic<unsigned> temp_counter{0};

fs::path directory_of(const fs::path& file) {
  const fs::path dir = file.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

// Forces the file's data to disk before the rename makes it visible under the final name; without it a
// power loss right after the rename could leave an empty file on some filesystems. Best effort: a
// filesystem that cannot fsync still gets the atomic rename.
void sync_to_disk(const fs::path& path, int open_flags) {
  const int fd = ::open(path.c_str(), open_flags | O_CLOEXEC);
  if (fd < 0) return;
  (void)::fsync(fd);
  ::close(fd);
}

}  // namespace

fs::path temporary_name(const fs::path& final_path) {
  const unsigned counter = temp_counter.fetch_add(1, std::memory_order_relaxed);
  fs::path temp = final_path;
  temp += fmt::format(".tmp-{}-{}", static_cast<long>(::getpid()), counter);
  return temp;
}

AtomicOutput::AtomicOutput(fs::path final_path)
    : final_path_(std::move(final_path)),
      temp_path_(temporary_name(final_path_)),
      registration_(temp_path_) {}

AtomicOutput::~AtomicOutput() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove(temp_path_, ignored);
}

void AtomicOutput::check_written() {
  std::error_code error;
  if (!fs::is_regular_file(temp_path_, error)) {
    throw ImageError(fmt::format("cannot write {}: the writer produced no file", final_path_.string()));
  }
  sync_to_disk(temp_path_, O_RDONLY);
}

void AtomicOutput::commit() {
  if (committed_) return;
  check_written();
  std::error_code error;
  fs::rename(temp_path_, final_path_, error);
  if (error) {
    fs::remove(temp_path_, error);
    throw ImageError(fmt::format("cannot write {}: {}", final_path_.string(), error.message()));
  }
  committed_ = true;
  registration_.release();
  sync_to_disk(directory_of(final_path_), O_RDONLY | O_DIRECTORY);
}

void check_output_writable(const fs::path& output) {
  const std::string out = output.string();
  if (output.empty()) throw ImageError("cannot write an output with an empty file name");
  const fs::path dir = directory_of(output);
  std::error_code error;
  if (!fs::exists(dir, error)) {
    throw ImageError(fmt::format("cannot write {}: directory {} does not exist", out, dir.string()));
  }
  if (!fs::is_directory(dir, error)) {
    throw ImageError(fmt::format("cannot write {}: {} is not a directory", out, dir.string()));
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    throw ImageError(fmt::format("cannot write {}: directory {} is not writable", out, dir.string()));
  }
  // The temporary file beside it (temporary_name) needs room in the name too: a name the file system cannot
  // hold would fail only when the output is written, after the work.
  const long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  const size_t temporary_suffix =
      temporary_name(output.filename()).string().size() - output.filename().string().size();
  if (name_max > 0 && output.filename().string().size() + temporary_suffix > static_cast<size_t>(name_max))
    throw ImageError(
        fmt::format("cannot write {}: its name is {} bytes long; this file system allows {} "
                    "(less {} for the temporary file written first)",
                    out.size() > 300 ? out.substr(0, 200) + "..." : out, output.filename().string().size(),
                    name_max, temporary_suffix));
  struct stat info {};
  if (::lstat(output.c_str(), &info) != 0) return;  // a new file
  if (S_ISDIR(info.st_mode)) throw ImageError(fmt::format("cannot write {}: it is a directory", out));
  if (S_ISLNK(info.st_mode)) {
    const fs::path target = fs::read_symlink(output, error);
    throw ImageError(fmt::format(
        "cannot write {}: it is a symbolic link{}; outputs replace only regular files (give the target's "
        "path to overwrite it)",
        out, error ? "" : " to " + target.string()));
  }
  if (!S_ISREG(info.st_mode))
    throw ImageError(
        fmt::format("cannot write {}: it is {}, not a regular file", out, file_type_name(info.st_mode)));
}

void write_text_file(const AtomicOutput& output, std::string_view text) {
  std::ofstream file(output.temp_path(), std::ios::binary);
  file << text;
  if (!file.flush()) throw ImageError(fmt::format("cannot write {}", output.final_path().string()));
}

void write_text_file(const fs::path& path, std::string_view text) {
  AtomicOutput output(path);
  write_text_file(output, text);
  output.commit();
}

}  // namespace ochre
