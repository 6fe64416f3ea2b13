#pragma once
// Input files: every file ochre reads is checked here first, so that a FIFO, a device, a directory or
// an endless or oversized file is refused with a message naming it ("scene.json: the scene file is a
// FIFO, not a regular file") instead of hanging the reader or exhausting memory (docs/cli.md, "Input
// files"). Symbolic links to regular files are followed.
//
// - check_regular_input(path, kind): stat() only, for libraries that open the file by name
//   themselves (OpenImageIO, OpenColorIO). Nothing is opened, so a device with side effects on
//   open(2) is never touched.
// - InputFile::open(path, kind): the same check, then an open(2) that cannot block (O_NONBLOCK: a FIFO
//   put in place after the check does not hang) and the same check on the opened descriptor (fstat).
// - read_input_file(path, kind): the whole content of a checked file, never more than kind.max_bytes.
//
// Every failure throws InputError. Every file that passes while an InputFileLog is recording is added
// to it, so that a command can refuse outputs that would overwrite one of its inputs.

#include <cstdint>
#include <filesystem>
#include <istream>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "spectra/byte_size.h"

namespace ochre {

// What a file is for (named in messages) and how large it may be.
struct InputKind {
  std::string_view name;  // "scene file"
  std::uint64_t max_bytes;
};

// The size limits of docs/cli.md. Text formats are parsed whole into memory, hence the lower limits;
// meshes are read whole by Assimp; images are bounded again by their decoded size
// (renderer/util/memory_budget.h).
inline constexpr std::uint64_t kJsonFileLimit = 256 * kMiB;
inline constexpr InputKind kSceneFileInput{"scene file", kJsonFileLimit};
inline constexpr InputKind kMaterialFileInput{"material file", kJsonFileLimit};
inline constexpr InputKind kCsvFileInput{"CSV file", 64 * kMiB};
inline constexpr InputKind kMeshFileInput{"mesh file", 4 * kGiB};
inline constexpr std::uint64_t kImageFileLimit = 16 * kGiB;
inline constexpr InputKind kImageFileInput{"image file", kImageFileLimit};
inline constexpr InputKind kTextureInput{"texture", kImageFileLimit};
inline constexpr InputKind kEnvironmentMapInput{"environment map", kImageFileLimit};
inline constexpr InputKind kOcioConfigInput{"OCIO config", 16 * kMiB};

// Identity of a file on this machine: equal for hard links and for different spellings of one path.
struct FileIdentity {
  std::uint64_t device = 0;
  std::uint64_t inode = 0;
  bool operator==(const FileIdentity&) const = default;
};

// "a FIFO", "a directory", "a character device", "a block device", "a socket", "a special file": what a
// stat(2) mode that is not a regular file names, for messages.
const char* file_type_name(unsigned mode);

// Throws InputError unless `path` is (or links to) a regular file of at most kind.max_bytes:
//   "<path>: the scene file does not exist"
//   "<path>: the scene file is a FIFO, not a regular file" (directory, character device, ...)
//   "<path>: the scene file is 3.2 GiB, larger than the 256 MiB limit for a scene file"
// Returns the file's identity.
FileIdentity check_regular_input(const std::filesystem::path& path, const InputKind& kind);

// A checked regular file open for reading (read-only, close-on-exec, blocking reads).
class InputFile {
 public:
  static InputFile open(const std::filesystem::path& path, const InputKind& kind);
  InputFile(InputFile&& other) noexcept;
  InputFile& operator=(InputFile&& other) noexcept;
  ~InputFile();

  int fd() const { return fd_; }
  std::uint64_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }
  // The whole file from the current offset; throws InputError when it grew beyond the kind's limit
  // since it was checked or cannot be read.
  std::string read_all();
  // A buffered stream over the descriptor (which stays owned by this InputFile).
  std::unique_ptr<std::istream> stream();

 private:
  InputFile(int fd, std::uint64_t size, std::filesystem::path path, InputKind kind)
      : fd_(fd), size_(size), path_(std::move(path)), kind_(kind) {}
  int fd_ = -1;
  std::uint64_t size_ = 0;
  std::filesystem::path path_;
  InputKind kind_;
};

// The whole content of a checked regular file.
std::string read_input_file(const std::filesystem::path& path, const InputKind& kind);

struct InputFileRecord {
  std::filesystem::path path;  // as given to the check
  std::string kind;
  FileIdentity identity;
};

// The files a command has read. While a Recording is alive, every file that passes
// check_regular_input or InputFile::open (on any thread) is added to its log.
class InputFileLog {
 public:
  class Recording {
   public:
    explicit Recording(InputFileLog& log);
    ~Recording();
    Recording(const Recording&) = delete;
    Recording& operator=(const Recording&) = delete;

   private:
    InputFileLog* previous_;
  };

  void add(const std::filesystem::path& path, std::string_view kind, FileIdentity identity);
  std::vector<InputFileRecord> records() const;

 private:
  mutable std::mutex mutex_;
  std::vector<InputFileRecord> records_;
};

}  // namespace ochre
