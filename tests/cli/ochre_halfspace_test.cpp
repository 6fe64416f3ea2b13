// ochre-halfspace end to end (docs/tools.md): the CSV it writes (comment header with the command,
// columns, one row per grid point), its independence of the thread count, and bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_runner.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::ochre_halfspace_test {
namespace {

TEST(OchreHalfspace, WritesTheGridWithItsCommand) {
  const auto dir = scratch_dir();
  const std::string args = "--c 0.5,0.9 --mu 0.3,1 --phi 0,90,180 --paths 3000 --seed 4";
  CommandResult r = run_tool("ochre-halfspace", args + " --output one.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string text = read_file_contents(dir / "one.csv");
  EXPECT_NE(
      text.find("# regenerate (from the repository root, after building): build/bin/ochre-halfspace " + args),
      std::string::npos)
      << text;
  std::istringstream lines(text);
  std::string line;
  int rows = 0;
  bool header = false;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      EXPECT_EQ(line, "c,mu_i,mu_o,phi_deg,f_single,f_single_se,f_multiple,f_multiple_se,f_total,f_total_se");
      header = true;
      continue;
    }
    ++rows;
  }
  EXPECT_EQ(rows, 2 * 2 * 2 * 3);
  r = run_tool("ochre-halfspace", args + " --threads 2 --output two.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string two = read_file_contents(dir / "two.csv");
  EXPECT_EQ(text.substr(text.find("\n# c=")), two.substr(two.find("\n# c=")))
      << "the numbers do not depend on the thread count";
}

TEST(OchreHalfspace, BadInputExitsWithTwo) {
  const auto dir = scratch_dir();
  for (const std::string args : {"--c 1.5", "--mu 0,0.5", "--phase henyey", "--paths 0"}) {
    const CommandResult r = run_tool("ochre-halfspace", args + " --output out.csv", dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(args.substr(0, args.find(' '))), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
  }
}

// The output follows docs/cli.md, "Output files": a directory, a symbolic link or a device is refused before
// the simulation runs (exit 2), and nothing is left beside it.
TEST(OchreHalfspace, OutputsThatWouldDestroyDataAreRefusedFirst) {
  const auto dir = scratch_dir();
  std::filesystem::create_directory(dir / "adir");
  std::filesystem::create_symlink("target.csv", dir / "link.csv");
  for (const std::string& output : {std::string("adir"), std::string("link.csv"), std::string("/dev/null")}) {
    const CommandResult r =
        run_tool("ochre-halfspace", "--c 0.5 --paths 100 --mu 0.5 --phi 0 --output " + output, dir);
    EXPECT_EQ(r.exit_code, 2) << output << "\n" << r.output;
    EXPECT_NE(r.output.find("cannot write " + output), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("paths, albedo"), std::string::npos) << "the simulation ran: " << r.output;
  }
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 2u) << "only adir and link.csv";
}

}  // namespace
}  // namespace ochre::test::ochre_halfspace_test
