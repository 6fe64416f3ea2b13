// Progress formatting (pure functions, fixed numbers) and the reporter's output in each style.

#include "renderer/util/progress.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace ochre::progress_test {
namespace {

TEST(ProgressFormat, PercentRoundsDown) {
  EXPECT_EQ(progress_percent(0, 100), 0);
  EXPECT_EQ(progress_percent(30, 100), 30);
  EXPECT_EQ(progress_percent(999, 1000), 99);  // 100 % only when finished
  EXPECT_EQ(progress_percent(1000, 1000), 100);
  EXPECT_EQ(progress_percent(0, 0), 100);
  EXPECT_EQ(progress_percent(1, 3), 33);
}

TEST(ProgressFormat, EtaExtrapolatesTheAverageRate) {
  EXPECT_DOUBLE_EQ(progress_eta_seconds(30, 100, 4.1), 4.1 * 70.0 / 30.0);
  EXPECT_DOUBLE_EQ(progress_eta_seconds(100, 100, 4.1), 0.0);
  EXPECT_LT(progress_eta_seconds(0, 100, 4.1), 0.0);
}

TEST(ProgressFormat, Durations) {
  EXPECT_EQ(format_duration(0.0), "0.0 s");
  EXPECT_EQ(format_duration(4.1), "4.1 s");
  EXPECT_EQ(format_duration(59.94), "59.9 s");
  EXPECT_EQ(format_duration(59.96), "1 min 00 s");
  EXPECT_EQ(format_duration(125.0), "2 min 05 s");
  EXPECT_EQ(format_duration(3725.0), "1 h 02 min");
  EXPECT_EQ(format_duration(-3.0), "0.0 s");
}

TEST(ProgressFormat, PlainLines) {
  EXPECT_EQ(format_progress_line("render", 30, 100, 4.1), "render: 30% (elapsed 4.1 s, ETA 9.6 s)");
  EXPECT_EQ(format_progress_line("render", 0, 100, 0.5), "render: 0% (elapsed 0.5 s, ETA unknown)");
  EXPECT_EQ(format_progress_line("render", 100, 100, 13.66), "render: 100% (elapsed 13.7 s)");
  EXPECT_EQ(format_progress_line("render", 1, 10, 30.0), "render: 10% (elapsed 30.0 s, ETA 4 min 30 s)");
}

TEST(ProgressFormat, Bar) {
  EXPECT_EQ(format_progress_bar("render", 30, 100, 4.1, 10),
            "render [###-------]  30% elapsed 4.1 s, ETA 9.6 s");
  EXPECT_EQ(format_progress_bar("render", 5, 100, 1.0, 10),
            "render [----------]   5% elapsed 1.0 s, ETA 19.0 s");
  EXPECT_EQ(format_progress_bar("render", 100, 100, 62.0, 10), "render [##########] 100% elapsed 1 min 02 s");
}

TEST(ProgressStyleChoice, TerminalGetsABarUnlessOverridden) {
  EXPECT_EQ(resolve_progress_style(true, nullptr), ProgressStyle::bar);
  EXPECT_EQ(resolve_progress_style(false, nullptr), ProgressStyle::plain);
  EXPECT_EQ(resolve_progress_style(false, ""), ProgressStyle::plain);
  EXPECT_EQ(resolve_progress_style(true, "plain"), ProgressStyle::plain);
  EXPECT_EQ(resolve_progress_style(false, "bar"), ProgressStyle::bar);
  EXPECT_EQ(resolve_progress_style(true, "none"), ProgressStyle::none);
  try {
    resolve_progress_style(true, "fancy");
    FAIL() << "should throw";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("OCHRE_PROGRESS='fancy'"), std::string::npos) << error.what();
  }
}

// Runs a test body with OCHRE_PROGRESS unset (the reporter reads it), restoring it afterwards.
class ProgressReporterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const char* value = std::getenv("OCHRE_PROGRESS")) saved_ = value;
    ::unsetenv("OCHRE_PROGRESS");
  }
  void TearDown() override {
    if (saved_) {
      ::setenv("OCHRE_PROGRESS", saved_->c_str(), 1);
    } else {
      ::unsetenv("OCHRE_PROGRESS");
    }
  }
  std::optional<std::string> saved_;
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST_F(ProgressReporterTest, PlainPrintsEachTenPercentStepOnceInOrderFromManyThreads) {
  std::ostringstream out;
  {
    ProgressReporter progress("render", 1000, out, /*interactive=*/false);
    EXPECT_EQ(progress.style(), ProgressStyle::plain);
    std::vector<std::thread> workers;
    for (int t = 0; t < 4; ++t) {
      workers.emplace_back([&] {
        for (int i = 0; i < 250; ++i) progress.advance(1);
      });
    }
    for (auto& worker : workers) worker.join();
    progress.finish();
    progress.finish();  // reported once
  }
  const std::vector<std::string> lines = lines_of(out.str());
  ASSERT_EQ(lines.size(), 10u) << out.str();
  int previous = 0;
  for (size_t i = 0; i + 1 < lines.size(); ++i) {
    ASSERT_EQ(lines[i].rfind("render: ", 0), 0u) << lines[i];
    const int percent = std::stoi(lines[i].substr(8));
    EXPECT_GE(percent, 10 * static_cast<int>(i + 1)) << lines[i];
    EXPECT_GT(percent, previous);
    EXPECT_NE(lines[i].find("ETA"), std::string::npos) << lines[i];
    previous = percent;
  }
  EXPECT_EQ(lines.back().rfind("render: 100% (elapsed ", 0), 0u) << lines.back();
}

TEST_F(ProgressReporterTest, BarRedrawsOneLineAndEndsWithANewline) {
  std::ostringstream out;
  ProgressReporter progress("render", 10, out, /*interactive=*/true);
  EXPECT_EQ(progress.style(), ProgressStyle::bar);
  progress.advance(3);  // the first advance always draws
  progress.finish();
  progress.advance(1);  // nothing after the end
  const std::string text = out.str();
  EXPECT_EQ(text.find('\n'), text.size() - 1) << text;
  EXPECT_EQ(text.rfind("\rrender [", 0), 0u) << text;
  EXPECT_NE(text.find("  30% elapsed"), std::string::npos) << text;
  EXPECT_NE(text.find("\rrender [##############################] 100% elapsed "), std::string::npos) << text;
}

TEST_F(ProgressReporterTest, UnfinishedBarIsClosedWithoutClaimingCompletion) {
  std::ostringstream out;
  {
    ProgressReporter progress("render", 10, out, /*interactive=*/true);
    progress.advance(5);
  }
  EXPECT_EQ(out.str().back(), '\n');
  EXPECT_EQ(out.str().find("100%"), std::string::npos) << out.str();
}

TEST_F(ProgressReporterTest, EnvironmentOverridesTheStyle) {
  std::ostringstream out;
  ::setenv("OCHRE_PROGRESS", "none", 1);
  {
    ProgressReporter progress("render", 10, out, /*interactive=*/true);
    EXPECT_EQ(progress.style(), ProgressStyle::none);
    progress.advance(10);
    progress.finish();
  }
  EXPECT_EQ(out.str(), "");
  ::setenv("OCHRE_PROGRESS", "plain", 1);
  ProgressReporter plain("render", 10, out, /*interactive=*/true);
  EXPECT_EQ(plain.style(), ProgressStyle::plain);
}

}  // namespace
}  // namespace ochre::progress_test
