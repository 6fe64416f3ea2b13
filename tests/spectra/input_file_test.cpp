// Input files (spectra/input_file.h): only regular files within a size limit are read; FIFOs, devices
// and directories are refused by stat() before anything is opened, so nothing blocks.

#include "spectra/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "spectra/csv_table.h"
#include "spectra/input_error.h"
#include "support/input_error_of.h"
#include "support/test_paths.h"

namespace ochre::input_file_test {
namespace {

namespace fs = std::filesystem;

constexpr InputKind kTiny{"test file", 16};

using test::input_error_of;

fs::path make_fifo(const fs::path& dir) {
  const fs::path fifo = dir / "pipe.json";
  EXPECT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  return fifo;
}

TEST(InputFile, FifoIsRefusedByEveryEntryPointWithoutBlocking) {
  const fs::path fifo = make_fifo(test::scratch_dir());
  const std::string expected = fifo.string() + ": the scene file is a FIFO, not a regular file";
  EXPECT_EQ(input_error_of([&] { check_regular_input(fifo, kSceneFileInput); }), expected);
  EXPECT_EQ(input_error_of([&] { InputFile::open(fifo, kSceneFileInput); }), expected);
  EXPECT_EQ(input_error_of([&] { read_input_file(fifo, kSceneFileInput); }), expected);
}

TEST(InputFile, DevicesAreRefused) {
  EXPECT_EQ(input_error_of([] { read_input_file("/dev/zero", kCsvFileInput); }),
            "/dev/zero: the CSV file is a character device, not a regular file");
  EXPECT_EQ(input_error_of([] { read_input_file("/dev/urandom", kMeshFileInput); }),
            "/dev/urandom: the mesh file is a character device, not a regular file");
}

TEST(InputFile, DirectoryIsRefused) {
  const fs::path dir = test::scratch_dir();
  EXPECT_EQ(input_error_of([&] { read_input_file(dir, kSceneFileInput); }),
            dir.string() + ": the scene file is a directory, not a regular file");
}

TEST(InputFile, MissingFileIsNamed) {
  const fs::path missing = test::scratch_dir() / "missing.json";
  EXPECT_EQ(input_error_of([&] { read_input_file(missing, kSceneFileInput); }),
            missing.string() + ": the scene file does not exist");
}

TEST(InputFile, FileAboveTheLimitIsRefusedWithItsSize) {
  // A sparse file: its size is 3 GiB, its disk use nothing.
  const fs::path big = test::scratch_dir() / "big.json";
  std::ofstream(big).close();
  ASSERT_EQ(::truncate(big.c_str(), 3 * static_cast<off_t>(kGiB)), 0);
  EXPECT_EQ(input_error_of([&] { read_input_file(big, kSceneFileInput); }),
            big.string() + ": the scene file is 3 GiB, larger than the 256 MiB limit for a scene file");
  fs::remove(big);
}

TEST(InputFile, LimitIsInclusive) {
  const fs::path file = test::scratch_dir() / "f.txt";
  std::ofstream(file) << std::string(16, 'x');
  EXPECT_EQ(read_input_file(file, kTiny), std::string(16, 'x'));
  std::ofstream(file) << std::string(17, 'x');
  EXPECT_EQ(input_error_of([&] { read_input_file(file, kTiny); }),
            file.string() + ": the test file is 17 bytes, larger than the 16 bytes limit for a test file");
}

TEST(InputFile, SymbolicLinkToARegularFileIsRead) {
  const fs::path dir = test::scratch_dir();
  std::ofstream(dir / "real.txt") << "content";
  fs::create_symlink("real.txt", dir / "link.txt");
  EXPECT_EQ(read_input_file(dir / "link.txt", kTiny), "content");
}

TEST(InputFile, StreamReadsLines) {
  const fs::path file = test::scratch_dir() / "lines.txt";
  std::ofstream(file) << "one\ntwo\n";
  InputFile input = InputFile::open(file, kTiny);
  EXPECT_EQ(input.size(), 8u);
  const auto stream = input.stream();
  std::string a, b, c;
  EXPECT_TRUE(std::getline(*stream, a) && std::getline(*stream, b));
  EXPECT_FALSE(std::getline(*stream, c));
  EXPECT_EQ(a + b, "onetwo");
}

TEST(InputFileLog, RecordsCheckedFilesOnlyWhileRecording) {
  const fs::path dir = test::scratch_dir();
  std::ofstream(dir / "a.txt") << "a";
  std::ofstream(dir / "b.txt") << "b";
  fs::create_hard_link(dir / "a.txt", dir / "a-link.txt");
  InputFileLog log;
  read_input_file(dir / "b.txt", kTiny);  // before: not recorded
  {
    const InputFileLog::Recording recording(log);
    read_input_file(dir / "a.txt", kTiny);
    check_regular_input(dir / "a-link.txt", kTiny);
  }
  read_input_file(dir / "b.txt", kTiny);  // after: not recorded
  const auto records = log.records();
  ASSERT_EQ(records.size(), 2u);  // InputFile::open records once, after its fstat
  EXPECT_EQ(records[0].path, dir / "a.txt");
  EXPECT_EQ(records[0].kind, "test file");
  EXPECT_EQ(records[0].identity, records.back().identity) << "a hard link is the same file";
  struct stat info {};
  ASSERT_EQ(::stat((dir / "a.txt").c_str(), &info), 0);
  EXPECT_EQ(records[0].identity.inode, static_cast<std::uint64_t>(info.st_ino));
}

TEST(InputFile, CsvTableRefusesDevicesAndFifos) {
  EXPECT_EQ(input_error_of([] { CsvTable::load("/dev/zero"); }),
            "/dev/zero: the CSV file is a character device, not a regular file");
  const fs::path fifo = make_fifo(test::scratch_dir());
  EXPECT_NE(input_error_of([&] { CsvTable::load(fifo); }).find("is a FIFO"), std::string::npos);
}

}  // namespace
}  // namespace ochre::input_file_test
