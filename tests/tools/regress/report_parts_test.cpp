// The parts of ochre-regress's HTML report (tools/regress): the pixel grid and its base64 encoding, the
// z-score colours and failure level, JUnit reading and writing, and the history sources.
#include <gtest/gtest.h>

#include <cmath>

#include "spectra/input_error.h"
#include "support/test_paths.h"
#include "support/text_files.h"
#include "tools/regress/junit_report.h"
#include "tools/regress/pixel_grid.h"
#include "tools/regress/report_history.h"
#include "tools/regress/report_images.h"
#include "tools/regress/scene_report.h"

namespace ochre::test::report_parts_test {
namespace {

namespace fs = std::filesystem;

TEST(PixelGrid, Base64OfLittleEndianFloats) {
  EXPECT_EQ(base64_floats({}), "");
  EXPECT_EQ(base64_floats({1.0f}), "AACAPw==");             // 00 00 80 3f
  EXPECT_EQ(base64_floats({1.0f, -2.0f}), "AACAPwAAAMA=");  // ... 00 00 00 c0
  EXPECT_EQ(base64_floats({0.0f, 0.0f, 0.0f}), "AAAAAAAAAAAAAAAA");
}

TEST(PixelGrid, StepKeepsTheValuesUnderTheLimit) {
  EXPECT_EQ(choose_pixel_grid(32, 32, 10, 1 << 19).step, 1);
  const PixelGrid big = choose_pixel_grid(1920, 1080, 10, 1 << 19);
  EXPECT_LE(big.cells() * 10, size_t{1} << 19);
  EXPECT_GT(make_pixel_grid(1920, 1080, big.step - 1).cells() * 10, size_t{1} << 19);
  EXPECT_EQ(big.columns, (1920 + big.step - 1) / big.step);
  EXPECT_EQ(make_pixel_grid(5, 3, 2).columns, 3);
  EXPECT_EQ(make_pixel_grid(5, 3, 2).rows, 2);
}

TEST(PixelGrid, BlocksCombineByTheirKind) {
  // 3x2 image, blocks of 2: cells (0,1 | 2) over both rows.
  const PixelGrid grid = make_pixel_grid(3, 2, 2);
  const std::vector<float> values = {1, -5, 2, 3, 4, 6};
  EXPECT_EQ(reduce_to_grid(values, 1, grid, BlockReduce::kMean), (std::vector<float>{0.75f, 4.0f}));
  EXPECT_EQ(reduce_to_grid(values, 1, grid, BlockReduce::kSum), (std::vector<float>{3.0f, 8.0f}));
  EXPECT_EQ(reduce_to_grid(values, 1, grid, BlockReduce::kMax), (std::vector<float>{4.0f, 6.0f}));
  EXPECT_EQ(reduce_to_grid(values, 1, grid, BlockReduce::kExtreme), (std::vector<float>{-5.0f, 6.0f}));
  const std::vector<float> with_nan = {1, NAN, 2, 3, 4, 6};
  EXPECT_TRUE(std::isnan(reduce_to_grid(with_nan, 1, grid, BlockReduce::kExtreme)[0]));
  // Two components per pixel stay apart.
  const PixelGrid one = make_pixel_grid(2, 1, 2);
  EXPECT_EQ(reduce_to_grid({1, 10, 3, 30}, 2, one, BlockReduce::kMean), (std::vector<float>{2.0f, 20.0f}));
}

TEST(ReportImages, DivergingColoursAndFailureLevel) {
  EXPECT_EQ(diverging_colour(0.0), (std::array<std::uint8_t, 3>{247, 247, 247}));
  EXPECT_EQ(diverging_colour(-1.0), (std::array<std::uint8_t, 3>{33, 102, 172}));
  EXPECT_EQ(diverging_colour(5.0), (std::array<std::uint8_t, 3>{178, 24, 43}));
  EXPECT_EQ(diverging_colour(NAN), (std::array<std::uint8_t, 3>{0, 0, 0}));
  RegressionResult result;
  result.alpha_pixel = sidak_pixel_level(kRegressionAlpha, 1024);
  EXPECT_NEAR(two_sided_p_value(critical_z(result)), result.alpha_pixel, 1e-12);
  EXPECT_NEAR(critical_z(result), 4.42, 0.01);
}

TEST(JUnit, WrittenRunReadsBack) {
  RunRecord run;
  run.timestamp = "2024-05-01T12:00:00Z";
  run.scenes = {{"a", true, false, 0.25, ""},
                {"b<&>\"'", false, false, 1.5, "worst p = 1e-9 <at> x=1"},
                {"c", true, true, std::nullopt, ""}};
  const fs::path file = scratch_dir() / "run.xml";
  write_text(file, junit_xml(run));
  const RunRecord back = read_junit(file);
  EXPECT_EQ(back.timestamp, run.timestamp);
  EXPECT_EQ(back.source, file.string());
  ASSERT_EQ(back.scenes.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.scenes[i].name, run.scenes[i].name);
    EXPECT_EQ(back.scenes[i].passed, run.scenes[i].passed);
    EXPECT_EQ(back.scenes[i].skipped, run.scenes[i].skipped);
    EXPECT_EQ(back.scenes[i].seconds, run.scenes[i].seconds);
    EXPECT_EQ(back.scenes[i].message, run.scenes[i].message);
  }
  EXPECT_EQ(junit_xml(back), junit_xml(run));
  EXPECT_EQ(back.find("c"), &back.scenes[2]);
  EXPECT_EQ(back.find("d"), nullptr);
}

TEST(JUnit, ReadsOtherToolsFiles) {
  // Several suites, errors count as failures, text content and comments, entities.
  const fs::path file = scratch_dir() / "other.xml";
  write_text(
      file,
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- from another tool -->\n<testsuites>\n"
      "<testsuite name=\"one\" timestamp=\"2023-01-01T00:00:00\"><properties/>"
      "<testcase classname=\"k\" name=\"x &amp; y\" time=\"2\"><system-out>text</system-out></testcase>"
      "</testsuite>\n<testsuite name=\"two\"><testcase name=\"z\"><error type=\"crash\"/></testcase>"
      "</testsuite>\n</testsuites>\n");
  const RunRecord run = read_junit(file);
  EXPECT_EQ(run.timestamp, "2023-01-01T00:00:00");
  ASSERT_EQ(run.scenes.size(), 2u);
  EXPECT_EQ(run.scenes[0].name, "x & y");
  EXPECT_TRUE(run.scenes[0].passed);
  EXPECT_EQ(run.scenes[0].seconds, 2.0);
  EXPECT_FALSE(run.scenes[1].passed);
  EXPECT_FALSE(run.scenes[1].seconds.has_value());
}

TEST(ReportHistory, SourcesInOrderAndOnlyTheLastRuns) {
  const fs::path dir = scratch_dir();
  const auto run_file = [&](const fs::path& path, int n) {
    write_text(path,
               "<testsuite timestamp=\"t" + std::to_string(n) + "\"><testcase name=\"a\"/></testsuite>");
  };
  // A report directory: its history, then its own run.
  run_file(dir / "report" / "history-01.xml", 1);
  run_file(dir / "report" / "history-02.xml", 2);
  run_file(dir / "report" / "junit.xml", 3);
  write_text(dir / "report" / kReportMarker, "");
  run_file(dir / "single.xml", 4);
  // A directory of JUnit files: in name order.
  run_file(dir / "ci" / "b.xml", 6);
  run_file(dir / "ci" / "a.xml", 5);
  write_text(dir / "ci" / "notes.txt", "not a run");
  const std::vector<RunRecord> runs =
      load_history({(dir / "report").string(), (dir / "single.xml").string(), (dir / "ci").string()});
  std::vector<std::string> stamps;
  for (const RunRecord& run : runs) stamps.push_back(run.timestamp);
  EXPECT_EQ(stamps, (std::vector<std::string>{"t1", "t2", "t3", "t4", "t5", "t6"}));

  std::vector<std::string> many;
  for (int i = 0; i < 25; ++i) {
    run_file(dir / "many" / (report_history_file_name(static_cast<size_t>(i)) + ".xml"), i);
    many.push_back((dir / "many" / (report_history_file_name(static_cast<size_t>(i)) + ".xml")).string());
  }
  const std::vector<RunRecord> last = load_history(many);
  ASSERT_EQ(last.size(), kMaxHistoryRuns);
  EXPECT_EQ(last.front().timestamp, "t5");
  EXPECT_EQ(last.back().timestamp, "t24");
  EXPECT_THROW(load_history({(dir / "nothing").string()}), InputError);
}

}  // namespace
}  // namespace ochre::test::report_parts_test
