// AtomicDirectory (renderer/util/atomic_directory.h): a directory appears complete or not at all, and an
// existing one is replaced only by commit().
#include "renderer/util/atomic_directory.h"

#include <gtest/gtest.h>

#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::atomic_directory_test {
namespace {

namespace fs = std::filesystem;

size_t entries(const fs::path& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AtomicDirectory, AppearsOnlyOnCommit) {
  const fs::path dir = scratch_dir();
  {
    AtomicDirectory out(dir / "report");
    EXPECT_EQ(out.temp_path().parent_path(), dir);
    write_text(out.temp_path() / "a.txt", "new");
    EXPECT_FALSE(fs::exists(dir / "report"));
    out.commit();
  }
  EXPECT_EQ(read_file_contents(dir / "report" / "a.txt"), "new");
  EXPECT_EQ(entries(dir), 1u);  // no scratch directory left
}

TEST(AtomicDirectory, ReplacesAnExistingDirectoryWhole) {
  const fs::path dir = scratch_dir();
  write_text(dir / "report" / "old.txt", "old");
  write_text(dir / "report" / "a.txt", "old");
  {
    AtomicDirectory out(dir / "report");
    write_text(out.temp_path() / "a.txt", "new");
    out.commit();
  }
  EXPECT_EQ(read_file_contents(dir / "report" / "a.txt"), "new");
  EXPECT_FALSE(fs::exists(dir / "report" / "old.txt"));
  EXPECT_EQ(entries(dir), 1u);
}

TEST(AtomicDirectory, WithoutCommitNothingChanges) {
  const fs::path dir = scratch_dir();
  write_text(dir / "report" / "a.txt", "old");
  {
    AtomicDirectory out(dir / "report");
    write_text(out.temp_path() / "a.txt", "new");
  }
  EXPECT_EQ(read_file_contents(dir / "report" / "a.txt"), "old");
  EXPECT_EQ(entries(dir), 1u);
}

TEST(AtomicDirectory, MissingParentIsAnError) {
  const fs::path dir = scratch_dir();
  try {
    AtomicDirectory out(dir / "missing" / "report");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "missing" / "report").string()), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ochre::test::atomic_directory_test
