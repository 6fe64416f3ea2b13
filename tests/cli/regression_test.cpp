// The image regression suite itself (every committed scene of tests/regression against its committed
// reference, one test per scene) and ochre-regress end to end: a perturbed scene fails and writes its
// p-value image, the JUnit report, --update, a missing reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>

#include "cli/regress_suite.h"
#include "renderer/compare/regression_compare.h"
#include "renderer/image/exr_reader.h"
#include "renderer/image/exr_writer.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::regression_test {
namespace {

namespace fs = std::filesystem;

// --- The regression suite: one ctest test per committed scene. ---
class CommittedScene : public ::testing::TestWithParam<std::string> {};

TEST_P(CommittedScene, MatchesItsReference) {
  const auto dir = scratch_dir();
  const CommandResult r = run_regress(quoted(suite_dir()) + " --scene " + GetParam(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("PASS"), std::string::npos) << r.output;
}

INSTANTIATE_TEST_SUITE_P(Regression, CommittedScene, ::testing::ValuesIn(suite_scenes()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(OchreRegress, SuiteCoversTheFeaturesAndReferencesAreSmall) {
  EXPECT_GE(suite_scenes().size(), 7u);
  for (const auto& name : suite_scenes()) {
    const fs::path reference = suite_dir() / "references" / (name + ".exr");
    ASSERT_TRUE(fs::exists(reference)) << reference;
    EXPECT_LT(fs::file_size(reference), 100u * 1024u) << reference;
    // The HTML report compares render times with the reference's.
    EXPECT_EQ(read_exr(reference).string_attributes.count("ochre:render_seconds"), 1u) << reference;
  }
}

TEST(OchreRegress, PerturbedAlbedoFailsAndWritesPValueImage) {
  const auto dir = scratch_dir();
  const fs::path suite = perturbed_suite(dir);
  const CommandResult r = run_regress("suite --output-dir out --junit report.xml", dir);
  EXPECT_EQ(r.exit_code, 4) << r.output;  // a scene failed (docs/cli.md, "Exit codes")
  EXPECT_NE(r.output.find("FAIL"), std::string::npos) << r.output;
  const fs::path p_exr = dir / "out" / "lambert_environment.pvalue.exr";
  ASSERT_TRUE(fs::exists(p_exr)) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "lambert_environment.pvalue.png"));
  const ExrImage image = read_exr(p_exr);
  const auto* p = image.find_channel("p.Y");
  const auto* z = image.find_channel("z.Y");
  ASSERT_NE(p, nullptr);
  ASSERT_NE(z, nullptr);
  const double level = sidak_pixel_level(kRegressionAlpha, p->size());
  EXPECT_LT(*std::min_element(p->begin(), p->end()), level);
  // Brighter albedo: the failing pixels are brighter than the reference (positive z).
  EXPECT_GT(*std::max_element(z->begin(), z->end()), 4.0);
  const std::string xml = read_file_contents(dir / "report.xml");
  EXPECT_NE(xml.find("<failure message="), std::string::npos) << xml;

  // The unperturbed scene passes against the same reference.
  fs::copy_file(suite_dir() / "lambert_environment.json", suite / "lambert_environment.json",
                fs::copy_options::overwrite_existing);
  EXPECT_EQ(run_regress("suite", dir).exit_code, 0);
}

// Element names in document order, with a check that every element closes in order (a small
// well-formedness check: the report has no text content, comments or CDATA).
std::vector<std::string> xml_elements(const std::string& xml, bool& well_formed) {
  std::vector<std::string> names, open;
  well_formed = xml.rfind("<?xml version=\"1.0\"", 0) == 0;
  const std::regex tag(
      R"(<(/?)([A-Za-z_][\w.-]*)((?:\s+[\w:.-]+="[^"<&]*(?:&(?:amp|lt|gt|quot|apos);[^"<&]*)*")*)\s*(/?)>)");
  std::string rest = xml.substr(xml.find("?>") + 2);
  std::smatch m;
  while (std::regex_search(rest, m, tag)) {
    for (char c : m.prefix().str())
      if (!std::isspace(static_cast<unsigned char>(c))) well_formed = false;
    const std::string name = m[2];
    if (m[1] == "/") {
      if (open.empty() || open.back() != name) well_formed = false;
      if (!open.empty()) open.pop_back();
    } else {
      names.push_back(name);
      if (m[4] != "/") open.push_back(name);
    }
    rest = m.suffix();
  }
  for (char c : rest)
    if (!std::isspace(static_cast<unsigned char>(c))) well_formed = false;
  if (!open.empty()) well_formed = false;
  return names;
}

TEST(OchreRegress, JUnitReportListsEveryScene) {
  const auto dir = scratch_dir();
  const CommandResult r = run_regress(quoted(suite_dir()) + " --junit report.xml", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string xml = read_file_contents(dir / "report.xml");
  bool well_formed = false;
  const std::vector<std::string> elements = xml_elements(xml, well_formed);
  EXPECT_TRUE(well_formed) << xml;
  ASSERT_FALSE(elements.empty());
  EXPECT_EQ(elements.front(), "testsuite");
  EXPECT_EQ(std::count(elements.begin(), elements.end(), "testcase"),
            static_cast<long>(suite_scenes().size()));
  EXPECT_EQ(std::count(elements.begin(), elements.end(), "failure"), 0);
  for (const auto& name : suite_scenes()) {
    EXPECT_NE(xml.find("name=\"" + name + "\""), std::string::npos) << name;
    EXPECT_NE(r.output.find(name), std::string::npos) << r.output;  // the summary table
  }
  EXPECT_NE(xml.find("tests=\"" + std::to_string(suite_scenes().size()) + "\""), std::string::npos);
}

TEST(OchreRegress, MissingReferenceIsBadInputAndUpdateCreatesIt) {
  const auto dir = scratch_dir();
  fs::create_directories(dir / "suite");
  fs::copy_file(suite_dir() / "lambert_environment.json", dir / "suite" / "lambert_environment.json");
  CommandResult r = run_regress("suite", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--update"), std::string::npos) << r.output;

  r = run_regress("suite --update --reference-spp 64", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage reference = read_exr(dir / "suite" / "references" / "lambert_environment.exr");
  for (const char* channel : {"R", "G", "B", "Y", "variance.Y"})
    EXPECT_NE(reference.find_channel(channel), nullptr) << channel;
  EXPECT_EQ(reference.string_attributes.at("ochre:regress_spp"), "64");
  EXPECT_GT(std::stod(reference.string_attributes.at("ochre:render_seconds")), 0.0);
  EXPECT_EQ(run_regress("suite", dir).exit_code, 0);
}

// A reference that cannot be one (a NaN, infinite or negative variance, a NaN mean, a sample count below 1
// or not a number) is bad input naming the reference and the pixel or attribute, never a render regression.
TEST(OchreRegress, ABadReferenceIsBadInputNotARegression) {
  const auto dir = scratch_dir();
  fs::create_directories(dir / "suite");
  fs::copy_file(suite_dir() / "lambert_environment.json", dir / "suite" / "lambert_environment.json");
  ASSERT_EQ(run_regress("suite --update --reference-spp 16", dir).exit_code, 0);
  const fs::path file = dir / "suite" / "references" / "lambert_environment.exr";
  const ExrImage good = read_exr(file);
  const auto forged = [&](const std::string& channel, float value, const std::string& spp) {
    ExrImage image = good;
    for (auto& [name, values] : image.channels)
      if (name == channel) values[5] = value;
    image.string_attributes["ochre:regress_spp"] = spp;
    write_exr(file, image);
    return run_regress("suite", dir);
  };
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const struct {
    std::string channel;
    float value;
    std::string spp, expected;
  } cases[] = {
      {"variance.Y", nan, "16", "pixel (5, 0): variance.Y is nan"},
      {"variance.Y", -1.0f, "16", "pixel (5, 0): variance.Y is -1"},
      {"variance.Y", inf, "16", "pixel (5, 0): variance.Y is inf"},
      {"Y", nan, "16", "pixel (5, 0): Y is nan"},
      {"Y", 0.5f, "0", "'ochre:regress_spp': expected a sample count of at least 1, got '0'"},
      {"Y", 0.5f, "nan", "got 'nan'"},
      {"Y", 0.5f, "2.5", "got '2.5'"},
      {"Y", 0.5f, "-16", "got '-16'"},
  };
  for (const auto& c : cases) {
    const CommandResult r = forged(c.channel, c.value, c.spp);
    EXPECT_EQ(r.exit_code, 2) << c.expected << "\n" << r.output;
    EXPECT_NE(r.output.find("lambert_environment.exr"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << r.output;
  }
}

TEST(OchreRegress, BadArguments) {
  const auto dir = scratch_dir();
  EXPECT_EQ(run_regress("does-not-exist", dir).exit_code, 2);
  EXPECT_EQ(run_regress(quoted(suite_dir()) + " --scene nope", dir).exit_code, 2);
  EXPECT_EQ(run_regress("", dir).exit_code, 2);
}

}  // namespace
}  // namespace ochre::test::regression_test
