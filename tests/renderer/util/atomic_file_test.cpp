// AtomicOutput and check_output_writable: files appear complete or not at all, old files survive
// failures, bad output paths fail before any work.

#include "renderer/util/atomic_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "renderer/util/image_error.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::atomic_file_test {
namespace {

namespace fs = std::filesystem;

using test::read_file_contents;
using test::write_text;

size_t count_entries(const fs::path& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AtomicOutput, TempNameSitsBesideTheFinalFileAndIsUnique) {
  const fs::path final_path = test::scratch_dir() / "image.exr";
  AtomicOutput a(final_path), b(final_path);
  EXPECT_EQ(a.temp_path().parent_path(), final_path.parent_path());
  const std::string prefix = "image.exr.tmp-" + std::to_string(::getpid()) + "-";
  EXPECT_EQ(a.temp_path().filename().string().rfind(prefix, 0), 0u) << a.temp_path();
  EXPECT_NE(a.temp_path(), b.temp_path());
}

TEST(AtomicOutput, CommitMovesTheTempFileToTheFinalName) {
  const fs::path dir = test::scratch_dir();
  const fs::path final_path = dir / "out.txt";
  AtomicOutput output(final_path);
  write_text(output.temp_path(), "new");
  EXPECT_FALSE(fs::exists(final_path));
  output.commit();
  EXPECT_EQ(read_file_contents(final_path), "new");
  EXPECT_EQ(count_entries(dir), 1u);
}

TEST(AtomicOutput, CommitReplacesAnExistingFile) {
  const fs::path dir = test::scratch_dir();
  const fs::path final_path = dir / "out.txt";
  write_text(final_path, "old");
  AtomicOutput output(final_path);
  write_text(output.temp_path(), "new");
  EXPECT_EQ(read_file_contents(final_path), "old");  // untouched until the new file is complete
  output.commit();
  EXPECT_EQ(read_file_contents(final_path), "new");
  EXPECT_EQ(count_entries(dir), 1u);
}

TEST(AtomicOutput, FailureBeforeCommitKeepsTheOldFileAndRemovesTheTemp) {
  const fs::path dir = test::scratch_dir();
  const fs::path final_path = dir / "out.txt";
  write_text(final_path, "old");
  EXPECT_THROW(
      {
        AtomicOutput output(final_path);
        write_text(output.temp_path(), "half-written");
        throw std::runtime_error("simulated crash of the writer");
      },
      std::runtime_error);
  EXPECT_EQ(read_file_contents(final_path), "old");
  EXPECT_EQ(count_entries(dir), 1u);
}

TEST(AtomicOutput, CommitWithoutATempFileThrowsNamingTheFile) {
  const fs::path final_path = test::scratch_dir() / "never.txt";
  AtomicOutput output(final_path);
  try {
    output.commit();
    FAIL() << "commit() should throw";
  } catch (const ImageError& error) {
    EXPECT_NE(std::string(error.what()).find(final_path.string()), std::string::npos) << error.what();
  }
  EXPECT_FALSE(fs::exists(final_path));
}

TEST(CheckOutputWritable, AcceptsAWritableDirectoryAndAnExistingFile) {
  const fs::path dir = test::scratch_dir();
  EXPECT_NO_THROW(check_output_writable(dir / "new.png"));
  write_text(dir / "old.png", "x");
  EXPECT_NO_THROW(check_output_writable(dir / "old.png"));
}

// A name the file system cannot hold (with the temporary file's suffix) is refused before any work, not
// when the output is written at the end.
TEST(CheckOutputWritable, ANameTooLongForTheFileSystemIsRefusedFirst) {
  const fs::path dir = test::scratch_dir();
  const long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  ASSERT_GT(name_max, 20);
  const std::string fits(static_cast<size_t>(name_max) - 30, 'a');
  EXPECT_NO_THROW(check_output_writable(dir / (fits + ".exr")));
  AtomicOutput output(dir / (fits + ".exr"));
  write_text_file(output, "x");
  EXPECT_NO_THROW(output.commit());
  const std::string too_long(static_cast<size_t>(name_max) - 4, 'b');
  try {
    check_output_writable(dir / (too_long + ".xml"));
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    EXPECT_NE(
        std::string(error.what())
            .find(fmt::format("its name is {} bytes long; this file system allows {}", name_max, name_max)),
        std::string::npos)
        << error.what();
  }
}

TEST(CheckOutputWritable, MissingDirectoryIsNamed) {
  const fs::path dir = test::scratch_dir() / "missing";
  const fs::path out = dir / "image.exr";
  try {
    check_output_writable(out);
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    EXPECT_EQ(std::string(error.what()),
              "cannot write " + out.string() + ": directory " + dir.string() + " does not exist");
  }
}

TEST(CheckOutputWritable, ParentThatIsAFileOrOutputThatIsADirectoryIsRejected) {
  const fs::path dir = test::scratch_dir();
  write_text(dir / "file", "x");
  EXPECT_THROW(check_output_writable(dir / "file" / "image.exr"), ImageError);
  fs::create_directory(dir / "sub");
  EXPECT_THROW(check_output_writable(dir / "sub"), ImageError);
  EXPECT_THROW(check_output_writable(""), ImageError);
}

}  // namespace
}  // namespace ochre::atomic_file_test
