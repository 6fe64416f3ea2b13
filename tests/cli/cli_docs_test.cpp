// The usage lines of docs/cli.md and docs/tools.md list every option of every tool, as the tool's own
// --help prints them, so the documentation cannot drift from the code. A usage line is a line of a
// fenced code block that starts with the tool's name (optionally build/bin/), followed by the
// subcommand for tools that have them, together with the indented lines that continue it; example
// command lines (starting with "$ ") do not count.

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include "cli/cli_runner.h"
#include "support/test_paths.h"

namespace ochre::test::cli_docs_test {
namespace {

struct ToolDoc {
  std::string tool;
  std::vector<std::string> subcommands;  // empty: the tool has none
  std::string doc;                       // relative to the source tree
};

const std::vector<ToolDoc>& tool_docs() {
  static const std::vector<ToolDoc> docs = {
      {"ochre", {"render", "merge", "relight", "info", "export-mesh"}, "docs/cli.md"},
      {"ochre-diff", {}, "docs/tools.md"},
      {"ochre-regress", {}, "docs/tools.md"},
      {"ochre-converge", {}, "docs/tools.md"},
      {"ochre-bench", {}, "docs/tools.md"},
      {"ochre-brdf", {"eval", "albedo", "plot", "chi2"}, "docs/tools.md"},
      {"ochre-halfspace", {}, "docs/tools.md"},
      {"ochre-vgroove",
       {"bihemispherical", "directional", "tables", "maps", "profile", "compare"},
       "docs/tools.md"},
      {"ochre-fit", {"powder"}, "docs/tools.md"},
  };
  return docs;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The entries of one section of CLI11's --help ("Options:", "Subcommands:"): the first word of each
// line indented by exactly two spaces, split at commas ("-o,--output" gives "-o" and "--output").
std::set<std::string> help_section(const std::string& help, const std::string& section) {
  std::set<std::string> entries;
  bool inside = false;
  for (const std::string& line : lines_of(help)) {
    if (line.empty() || line[0] != ' ') {
      inside = line == section;
      continue;
    }
    if (!inside || line.size() < 3 || line[2] == ' ') continue;
    std::string word = line.substr(2, line.find(' ', 2) - 2);
    std::stringstream parts(word);
    for (std::string part; std::getline(parts, part, ',');) entries.insert(part);
  }
  return entries;
}

// The usage lines of `tool` (and `subcommand`, when not empty) in a markdown text, joined.
std::string usage_lines(const std::string& markdown, const std::string& tool, const std::string& subcommand) {
  std::string usage;
  bool in_code = false, continuing = false;
  for (const std::string& line : lines_of(markdown)) {
    if (line.rfind("```", 0) == 0) {
      in_code = !in_code;
      continuing = false;
      continue;
    }
    if (!in_code) continue;
    if (continuing && !line.empty() && line[0] == ' ') {
      usage += line + "\n";
      continue;
    }
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    continuing =
        (first == tool || first == "build/bin/" + tool) && (subcommand.empty() || second == subcommand);
    if (continuing) usage += line + "\n";
  }
  return usage;
}

// True when `option` appears in `text` as a whole option (not inside a longer one: "-o" is not found in
// "--output", "--spp" not in "--spp-max").
bool mentions_option(const std::string& text, const std::string& option) {
  const auto is_name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
  };
  for (size_t at = text.find(option); at != std::string::npos; at = text.find(option, at + 1)) {
    const size_t end = at + option.size();
    if ((at == 0 || !is_name_char(text[at - 1])) && (end == text.size() || !is_name_char(text[end])))
      return true;
  }
  return false;
}

TEST(CliDocs, UsageLinesListEveryOptionOfEveryTool) {
  for (const ToolDoc& t : tool_docs()) {
    const std::string markdown = read_text(source_dir() / t.doc);
    const CommandResult top = run_tool(t.tool, "--help", {}, true);
    ASSERT_EQ(top.exit_code, 0) << t.tool << " --help: " << top.output;
    // The test knows every subcommand the tool has.
    const std::set<std::string> subcommands = help_section(top.output, "Subcommands:");
    EXPECT_EQ(subcommands, std::set<std::string>(t.subcommands.begin(), t.subcommands.end())) << t.tool;

    const std::string tool_usage = usage_lines(markdown, t.tool, "");
    for (const std::string& option : help_section(top.output, "Options:"))
      EXPECT_TRUE(mentions_option(tool_usage, option))
          << t.doc << ": the usage lines of " << t.tool << " do not mention " << option << "\n"
          << tool_usage;
    for (const std::string& sub : t.subcommands) {
      const CommandResult help = run_tool(t.tool, sub + " --help", {}, true);
      ASSERT_EQ(help.exit_code, 0) << t.tool << " " << sub << " --help: " << help.output;
      const std::string usage = usage_lines(markdown, t.tool, sub);
      EXPECT_FALSE(usage.empty()) << t.doc << ": no usage line for " << t.tool << " " << sub;
      for (const std::string& option : help_section(help.output, "Options:")) {
        // --help of a subcommand is documented once, with the tool.
        const std::string& where = option == "-h" || option == "--help" ? tool_usage : usage;
        EXPECT_TRUE(mentions_option(where, option)) << t.doc << ": the usage lines of " << t.tool << " "
                                                    << sub << " do not mention " << option << "\n"
                                                    << usage;
      }
    }
  }
}

// The checker itself: an option missing from the usage lines, or only in an example, is found.
TEST(CliDocs, CheckerFindsMissingOptions) {
  const std::string markdown =
      "text --seed\n```\nochre-x A.json [--spp N]\n         [-o OUT]\n$ ochre-x a.json --seed 3\nother "
      "--seed\n```\n";
  const std::string usage = usage_lines(markdown, "ochre-x", "");
  EXPECT_TRUE(mentions_option(usage, "--spp"));
  EXPECT_TRUE(mentions_option(usage, "-o"));
  EXPECT_FALSE(mentions_option(usage, "--seed"));
  EXPECT_FALSE(mentions_option("[--output F]", "-o"));
  EXPECT_FALSE(mentions_option("[--spp-max N]", "--spp"));
  const std::set<std::string> options = help_section(
      "Usage: x\n\nOptions:\n  -h,--help  Print\n  --spp UINT  Samples\n                wrapped "
      "-not\n\nSubcommands:\n"
      "  render   Render\n",
      "Options:");
  EXPECT_EQ(options, (std::set<std::string>{"-h", "--help", "--spp"}));
}

}  // namespace
}  // namespace ochre::test::cli_docs_test
