#include "renderer/util/atomic_directory.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "renderer/util/atomic_file.h"
#include "renderer/util/image_error.h"

namespace ochre {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail_to_replace(const fs::path& final_path, const std::string& why) {
  throw ImageError(fmt::format("cannot write {}: {}", final_path.string(), why));
}

// The old directory renamed aside, the new one renamed in, the old one put back should that fail.
void replace_by_renames(const fs::path& temp, const fs::path& final_path) {
  const fs::path aside = temporary_name(final_path);
  std::error_code error;
  fs::rename(final_path, aside, error);
  if (error) fail_to_replace(final_path, error.message());
  fs::rename(temp, final_path, error);
  if (error) {
    std::error_code ignored;
    fs::rename(aside, final_path, ignored);
    fail_to_replace(final_path, error.message());
  }
  fs::rename(aside, temp, error);  // so that the caller removes the old directory as the scratch one
  if (error) fs::remove_all(aside, error);
}

}  // namespace

AtomicDirectory::AtomicDirectory(fs::path final_path)
    : final_path_(std::move(final_path)),
      temp_path_(temporary_name(final_path_)),
      registration_(temp_path_, TemporaryKind::kDirectory) {
  std::error_code error;
  if (!fs::create_directory(temp_path_, error) || error)
    fail_to_replace(final_path_, fmt::format("cannot create {}: {}", temp_path_.string(),
                                             error ? error.message() : "it exists"));
}

AtomicDirectory::~AtomicDirectory() {
  std::error_code ignored;
  fs::remove_all(temp_path_, ignored);
}

void AtomicDirectory::commit() {
  if (committed_) return;
  const SignalDeferral defer;  // the swap and the removal of the old directory happen together
  std::error_code error;
  if (!fs::exists(fs::symlink_status(final_path_, error))) {
    fs::rename(temp_path_, final_path_, error);
    if (error) fail_to_replace(final_path_, error.message());
  } else if (::renameat2(AT_FDCWD, temp_path_.c_str(), AT_FDCWD, final_path_.c_str(), RENAME_EXCHANGE) != 0) {
    if (errno != EINVAL && errno != ENOSYS) fail_to_replace(final_path_, std::strerror(errno));
    replace_by_renames(temp_path_, final_path_);  // the filesystem cannot exchange
  }
  committed_ = true;
  // temp_path_ now holds the old directory, or nothing: the destructor removes it.
}

}  // namespace ochre
