// The tutorial docs/guide/cave-painting.md, followed step by step: its ```sh blocks run in order in one bash
// session (set -e), its ```json file=NAME blocks are written to NAME first, from a scratch copy of the
// repository layout (scenes/ and the built tools linked in). Renders are made small: the `ochre` the
// tutorial finds on its PATH is a wrapper that replaces --resolution and --spp with 48x27 and 2 samples, so
// the guide shows the real commands and the test takes seconds. Every file the guide's commands write (each
// frame of a --frames sequence) is checked to exist afterwards.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "cli/cli_runner.h"
#include "support/test_paths.h"

namespace ochre::test::tutorial_test {
namespace {

namespace fs = std::filesystem;

struct Block {
  std::string info;  // the fence's info string: "sh", "json file=scan.json", ...
  std::string text;
};

std::vector<Block> fenced_blocks(const std::string& markdown) {
  std::vector<Block> blocks;
  std::istringstream in(markdown);
  std::string line;
  Block* open = nullptr;
  while (std::getline(in, line)) {
    if (line.rfind("```", 0) == 0) {
      if (open) {
        open = nullptr;
      } else {
        blocks.push_back({line.substr(3), ""});
        open = &blocks.back();
      }
    } else if (open) {
      open->text += line + "\n";
    }
  }
  return blocks;
}

// The files one command line writes: its -o, --png and --heatmap arguments; with `--frames N
// [--first-frame K]` each of them once per frame, numbered K to K + N - 1 (docs/cli.md#frame-sequences).
void add_outputs(const std::string& line, std::set<std::string>& outputs) {
  const std::regex output_argument(R"((?:-o|--png|--heatmap) ([^ \n"]+)(\.(?:exr|png)))");
  const std::regex frames(R"(--frames (\d+))"), first_frame(R"(--first-frame (\d+))");
  std::smatch m;
  int count = 0, first = 1;
  if (std::regex_search(line, m, frames)) count = std::stoi(m[1].str());
  if (std::regex_search(line, m, first_frame)) first = std::stoi(m[1].str());
  for (std::sregex_iterator it(line.begin(), line.end(), output_argument), end; it != end; ++it) {
    if (count == 0) outputs.insert((*it)[1].str() + (*it)[2].str());
    for (int k = first; k < first + count; ++k)
      outputs.insert(fmt::format("{}.{:04d}{}", (*it)[1].str(), k, (*it)[2].str()));
  }
}

// The guide as one bash script, and the files its commands write.
std::string tutorial_script(const std::vector<Block>& blocks, std::set<std::string>& outputs) {
  std::string script = "set -euo pipefail\n";
  for (const Block& b : blocks) {
    if (b.info == "sh") {
      script += b.text;
      std::istringstream lines(b.text);
      for (std::string line; std::getline(lines, line);) add_outputs(line, outputs);
    } else if (b.info.rfind("json file=", 0) == 0) {
      script += "cat > " + b.info.substr(10) + " <<'OCHRE_TUTORIAL_EOF'\n" + b.text + "OCHRE_TUTORIAL_EOF\n";
    }
  }
  return script;
}

// A build/bin of its own: the real tools, and an `ochre` that renders small images.
void write_tool_folder(const fs::path& bin) {
  fs::create_directories(bin);
  for (const auto& entry : fs::directory_iterator(bin_dir()))
    if (entry.path().filename().string().rfind("ochre", 0) == 0 && entry.path().filename() != "ochre")
      fs::create_symlink(entry.path(), bin / entry.path().filename());
  write_text(bin / "ochre",
             "#!/bin/bash\n"
             "# Renders small: drops --resolution/--spp and their values, then adds its own.\n"
             "args=()\n"
             "while [ $# -gt 0 ]; do\n"
             "  case \"$1\" in --resolution|--spp) shift 2;; *) args+=(\"$1\"); shift;; esac\n"
             "done\n"
             "if [ \"${args[0]}\" = render ]; then args+=(--resolution 48x27 --spp 2); fi\n"
             "exec '" +
                 (bin_dir() / "ochre").string() + "' \"${args[@]}\"\n");
  fs::permissions(bin / "ochre", fs::perms::owner_all);
}

TEST(Tutorial, EveryCommandOfTheCavePaintingGuideRuns) {
  const std::string guide = read_file_contents(source_dir() / "docs/guide/cave-painting.md");
  const std::vector<Block> blocks = fenced_blocks(guide);
  std::set<std::string> outputs;
  const std::string script = tutorial_script(blocks, outputs);
  ASSERT_GE(outputs.size(), 8u) << script;

  const fs::path root = scratch_dir(), repo = root / "repo";
  fs::create_directories(repo);
  fs::create_symlink(source_dir() / "scenes", repo / "scenes");
  write_tool_folder(repo / "build/bin");
  if (!shared_dir().empty()) fs::create_symlink(shared_dir(), root / "shared");  // the ACES config, if any
  write_text(repo / "tutorial.sh", script);

  const CommandResult r = run_shell("OCHRE_PROGRESS=none bash tutorial.sh 2>&1", repo);
  ASSERT_EQ(r.exit_code, 0) << r.output << "\n--- script ---\n" << script;
  for (const std::string& file : outputs) {
    const bool aces = file.find("aces") != std::string::npos;
    if (aces && shared_dir().empty()) continue;  // the guide renders these only with the ACES config present
    EXPECT_TRUE(fs::exists(repo / "cave-work" / file)) << file << "\n" << r.output;
  }
  // The spectral step lists its 16 spectral layers.
  EXPECT_NE(r.output.find("16\n"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace ochre::test::tutorial_test
