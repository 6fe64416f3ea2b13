// OutputTransaction: several outputs are all replaced or none is.

#include "renderer/util/output_transaction.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "renderer/util/image_error.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::output_transaction_test {
namespace {

namespace fs = std::filesystem;

using test::read_file_contents;
using test::write_text;

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(OutputTransaction, NothingIsReplacedBeforeCommit) {
  const fs::path dir = test::scratch_dir();
  write_text(dir / "a.txt", "old a");
  {
    OutputTransaction outputs;
    write_text(outputs.add(dir / "a.txt").temp_path(), "new a");
    write_text(outputs.add(dir / "b.txt").temp_path(), "new b");
    EXPECT_EQ(read_file_contents(dir / "a.txt"), "old a");
    outputs.commit();
  }
  EXPECT_EQ(read_file_contents(dir / "a.txt"), "new a");
  EXPECT_EQ(read_file_contents(dir / "b.txt"), "new b");
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST(OutputTransaction, AFailingWriterLeavesEveryExistingFileAsItWas) {
  const fs::path dir = test::scratch_dir();
  write_text(dir / "a.txt", "old a");
  write_text(dir / "c.txt", "old c");
  struct stat before {};
  ASSERT_EQ(::stat((dir / "a.txt").c_str(), &before), 0);
  try {
    OutputTransaction outputs;
    write_text(outputs.add(dir / "a.txt").temp_path(), "new a");
    write_text(outputs.add(dir / "b.txt").temp_path(), "new b");
    outputs.add(dir / "c.txt");
    throw std::runtime_error("the third writer fails");  // before commit
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read_file_contents(dir / "a.txt"), "old a");
  EXPECT_EQ(read_file_contents(dir / "c.txt"), "old c");
  struct stat after {};
  ASSERT_EQ(::stat((dir / "a.txt").c_str(), &after), 0);
  EXPECT_EQ(after.st_ino, before.st_ino);
  EXPECT_EQ(after.st_mtim.tv_nsec, before.st_mtim.tv_nsec);
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"a.txt", "c.txt"})) << "no temporary left";
}

TEST(OutputTransaction, AMissingTemporaryFailsTheCommitBeforeAnyRename) {
  const fs::path dir = test::scratch_dir();
  write_text(dir / "a.txt", "old a");
  OutputTransaction outputs;
  write_text(outputs.add(dir / "a.txt").temp_path(), "new a");
  outputs.add(dir / "b.txt");  // its writer produced nothing
  EXPECT_THROW(outputs.commit(), ImageError);
  EXPECT_EQ(read_file_contents(dir / "a.txt"), "old a");
}

TEST(OutputTransaction, AFailedRenamePutsBackTheFilesAlreadyReplaced) {
  const fs::path dir = test::scratch_dir();
  write_text(dir / "a.txt", "old a");
  {
    OutputTransaction outputs;
    write_text(outputs.add(dir / "a.txt").temp_path(), "new a");
    write_text(outputs.add(dir / "new.txt").temp_path(), "new file");
    write_text(outputs.add(dir / "c").temp_path(), "new c");
    // A directory appears where the third output goes: its rename fails after the first two.
    fs::create_directory(dir / "c");
    write_text(dir / "c" / "inside", "x");
    EXPECT_THROW(outputs.commit(), ImageError);
  }
  EXPECT_EQ(read_file_contents(dir / "a.txt"), "old a");
  EXPECT_FALSE(fs::exists(dir / "new.txt")) << "an output that did not exist before is removed again";
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"a.txt", "c"})) << "no temporary or backup left";
}

}  // namespace
}  // namespace ochre::output_transaction_test
