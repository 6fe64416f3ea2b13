// `ochre relight RENDER.exr --html DIR` (docs/lights.md, "Relighting page"): one self-contained page, with
// nothing fetched from elsewhere; refused, nothing written, when DIR is a file or a directory not empty.
// The page in a browser, against `ochre relight --png`: tests/browser/test_relight_page.py.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "cli/cli_runner.h"
#include "cli/file_test_support.h"
#include "support/test_paths.h"

namespace ochre::test::relight_page_test {
namespace {

namespace fs = std::filesystem;

// The browser test's wall (torch and lamp of one emission spectrum each, the sky in "other") with 16 bins.
fs::path rendered() {
  const fs::path dir = scratch_dir();
  fs::copy_file(source_dir() / "tests" / "browser" / "relight_wall.json", dir / "wall.json");
  const CommandResult r = run_ochre("render wall.json -o render.exr -q --spp 4 --spectral-bins 16", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return dir;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(RelightPage, ThePageIsOneFileWithNothingFromElsewhere) {
  const fs::path dir = rendered();
  const CommandResult r = run_ochre("relight render.exr --html page", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "3 groups, 2 with a colour-temperature slider")) << r.output;
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir / "page")) files.push_back(entry.path().filename());
  EXPECT_EQ(files, std::vector<std::string>{"index.html"});
  const std::string html = read_text(dir / "page" / "index.html");
  for (const char* external : {"http://", "https://", "src=", "href=", "@import", "url("})
    EXPECT_FALSE(contains(html, external)) << external;
  // The groups, the torch's colour temperature (a blackbody at 1700 K: the slider starts there) and the
  // render the page's command names.
  for (const char* data : {"\"name\":\"torch\"", "\"name\":\"lamp\"", "\"name\":\"other\"",
                           "\"unchanged_at\":1700", "\"render\":\"render.exr\""})
    EXPECT_TRUE(contains(html, data)) << data;
  EXPECT_TRUE(temporaries_in(dir).empty());
}

TEST(RelightPage, WithTheRelitImagesAndIntoAnEmptyDirectory) {
  const fs::path dir = rendered();
  fs::create_directory(dir / "empty");
  const CommandResult r =
      run_ochre("relight render.exr --group lamp:off -o relit.exr --png relit.png --html empty", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* file : {"relit.exr", "relit.png", "empty/index.html"}) EXPECT_TRUE(fs::exists(dir / file));
}

TEST(RelightPage, ADirectoryThatIsAFileOrNotEmptyIsRefusedAndNothingIsWritten) {
  const fs::path dir = rendered();
  write_old_file(dir / "file", "a file\n");
  write_old_file(dir / "full" / "notes.txt", "kept\n");
  fs::create_directory_symlink("full", dir / "link");
  const struct {
    std::string html, expected;
  } cases[] = {
      {"file", "file: cannot write the relighting page there: it exists and is not a directory"},
      {"full", "full: cannot write the relighting page there: the directory is not empty"},
      {"link", "link: cannot write the relighting page there: it is a symbolic link"},
      {"missing/page", "does not exist"},
  };
  const FileSnapshot file = snapshot(dir / "file"), notes = snapshot(dir / "full" / "notes.txt");
  for (const auto& c : cases) {
    const CommandResult r = run_ochre(fmt::format("relight render.exr -o out.exr --html {}", c.html), dir);
    EXPECT_EQ(r.exit_code, 2) << c.html << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, c.expected)) << c.html << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "out.exr")) << c.html;
  }
  EXPECT_TRUE(snapshot(dir / "file") == file);
  EXPECT_TRUE(snapshot(dir / "full" / "notes.txt") == notes);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "full"), fs::directory_iterator()), 1);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  EXPECT_TRUE(temporaries_in(dir).empty());
}

}  // namespace
}  // namespace ochre::test::relight_page_test
