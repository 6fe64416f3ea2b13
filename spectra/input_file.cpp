#include "spectra/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <streambuf>
#include <utility>

#include "spectra/input_error.h"

namespace ochre {

namespace {

std::mutex active_log_mutex;
InputFileLog* active_log = nullptr;  // guarded by active_log_mutex

std::string where(const std::filesystem::path& path, const InputKind& kind) {
  return path.string() + ": the " + std::string(kind.name);
}

[[noreturn]] void fail_errno(const std::filesystem::path& path, const InputKind& kind, int error) {
  if (error == ENOENT || error == ENOTDIR) throw InputError(where(path, kind) + " does not exist");
  throw InputError(path.string() + ": cannot read the " + std::string(kind.name) + ": " +
                   std::strerror(error));
}

// Throws unless `info` describes a regular file within the kind's size limit.
void check_stat(const struct stat& info, const std::filesystem::path& path, const InputKind& kind) {
  if (!S_ISREG(info.st_mode))
    throw InputError(where(path, kind) + " is " + file_type_name(info.st_mode) + ", not a regular file");
  const auto size = static_cast<std::uint64_t>(info.st_size);
  if (size > kind.max_bytes)
    throw InputError(where(path, kind) + " is " + format_bytes(size) + ", larger than the " +
                     format_bytes(kind.max_bytes) + " limit for a " + std::string(kind.name));
}

FileIdentity identity_of(const struct stat& info) {
  return {static_cast<std::uint64_t>(info.st_dev), static_cast<std::uint64_t>(info.st_ino)};
}

void record(const std::filesystem::path& path, const InputKind& kind, const struct stat& info) {
  std::lock_guard lock(active_log_mutex);
  if (active_log != nullptr) active_log->add(path, kind.name, identity_of(info));
}

struct stat stat_checked(const std::filesystem::path& path, const InputKind& kind) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) fail_errno(path, kind, errno);
  check_stat(info, path, kind);
  return info;
}

// A read-only stream buffer over a file descriptor it does not own.
class DescriptorBuffer final : public std::streambuf {
 public:
  explicit DescriptorBuffer(int fd) : fd_(fd) {}

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    ssize_t n;
    do {
      n = ::read(fd_, buffer_, sizeof buffer_);
    } while (n < 0 && errno == EINTR);
    if (n <= 0) return traits_type::eof();
    setg(buffer_, buffer_, buffer_ + n);
    return traits_type::to_int_type(*gptr());
  }

 private:
  int fd_;
  char buffer_[64 * 1024];
};

class DescriptorStream final : public std::istream {
 public:
  explicit DescriptorStream(int fd) : std::istream(nullptr), buffer_(fd) { rdbuf(&buffer_); }

 private:
  DescriptorBuffer buffer_;
};

}  // namespace

const char* file_type_name(unsigned mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISREG(mode)) return "a regular file";
  return "a special file";
}

FileIdentity check_regular_input(const std::filesystem::path& path, const InputKind& kind) {
  const struct stat info = stat_checked(path, kind);
  record(path, kind, info);
  return identity_of(info);
}

InputFile InputFile::open(const std::filesystem::path& path, const InputKind& kind) {
  // stat() first: opening a device can have side effects (a tape rewinds), so only what looks like a
  // regular file is opened at all.
  stat_checked(path, kind);
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) fail_errno(path, kind, errno);
  InputFile file(fd, 0, path, kind);
  struct stat info {};
  if (::fstat(fd, &info) != 0) fail_errno(path, kind, errno);
  check_stat(info, path, kind);  // what was opened, should the path have changed since the stat()
  // Regular files ignore O_NONBLOCK, but clear it so that reads are plain blocking reads.
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) (void)::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  file.size_ = static_cast<std::uint64_t>(info.st_size);
  record(path, kind, info);
  return file;
}

InputFile::InputFile(InputFile&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      size_(other.size_),
      path_(std::move(other.path_)),
      kind_(other.kind_) {}

InputFile& InputFile::operator=(InputFile&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
    size_ = other.size_;
    path_ = std::move(other.path_);
    kind_ = other.kind_;
  }
  return *this;
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::string InputFile::read_all() {
  std::string content;
  content.reserve(static_cast<size_t>(size_));
  char buffer[64 * 1024];
  while (true) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail_errno(path_, kind_, errno);
    if (n == 0) return content;
    content.append(buffer, static_cast<size_t>(n));
    if (content.size() > kind_.max_bytes)
      throw InputError(where(path_, kind_) + " grew beyond the " + format_bytes(kind_.max_bytes) +
                       " limit for a " + std::string(kind_.name) + " while it was read");
  }
}

std::unique_ptr<std::istream> InputFile::stream() {
  return std::make_unique<DescriptorStream>(fd_);
}

std::string read_input_file(const std::filesystem::path& path, const InputKind& kind) {
  return InputFile::open(path, kind).read_all();
}

InputFileLog::Recording::Recording(InputFileLog& log) {
  std::lock_guard lock(active_log_mutex);
  previous_ = active_log;
  active_log = &log;
}

InputFileLog::Recording::~Recording() {
  std::lock_guard lock(active_log_mutex);
  active_log = previous_;
}

void InputFileLog::add(const std::filesystem::path& path, std::string_view kind, FileIdentity identity) {
  std::lock_guard lock(mutex_);
  records_.push_back({path, std::string(kind), identity});
}

std::vector<InputFileRecord> InputFileLog::records() const {
  std::lock_guard lock(mutex_);
  return records_;
}

}  // namespace ochre
