// ochre-regress --html end to end (docs/tools.md, "HTML report"): the report of a failing suite, that it
// loads nothing from elsewhere, the history from earlier reports and JUnit files, and that a report is
// written all or nothing and replaces only an earlier report. The browser tests are in tests/browser.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "cli/regress_suite.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::regress_html_test {
namespace {

namespace fs = std::filesystem;

// dir/suite: the failing lambert_environment and the passing spot_light.
fs::path failing_suite(const fs::path& dir) {
  const fs::path suite = perturbed_suite(dir);
  copy_suite_scene("spot_light", suite);
  return suite;
}

std::vector<fs::path> report_files(const fs::path& report) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(report)) files.push_back(entry.path());
  return files;
}

bool has_extension(const fs::path& file, std::initializer_list<const char*> extensions) {
  for (const char* extension : extensions)
    if (file.extension() == extension) return true;
  return false;
}

// Every reference a page, stylesheet or script makes to something outside the report: URLs with a scheme
// or host, protocol-relative and absolute paths, CSS imports and fonts, script loaders.
std::vector<std::string> external_references(const std::string& text) {
  std::vector<std::string> found;
  for (const char* pattern : {"http://", "https://", "ftp://", "@import", "@font-face", "url(", "fetch(",
                              "XMLHttpRequest", "import(", "WebSocket", "EventSource", "sendBeacon"}) {
    if (text.find(pattern) != std::string::npos) found.emplace_back(pattern);
  }
  const std::regex attribute(R"re(\b(src|href|action|poster|srcset)\s*=\s*["']([^"']*)["'])re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), attribute); it != std::sregex_iterator();
       ++it) {
    const std::string value = (*it)[2];
    const bool absolute = value.rfind("/", 0) == 0;  // "/x" and "//host/x"
    const bool scheme = std::regex_search(value, std::regex(R"(^[A-Za-z][A-Za-z0-9+.-]*:)"));
    if (absolute || scheme) found.push_back((*it)[0]);
  }
  return found;
}

// The report-relative files that src and href attributes name (fragments and queries dropped).
std::set<std::string> linked_files(const std::string& html) {
  std::set<std::string> files;
  const std::regex attribute(R"re(\b(?:src|href)="([^"#?]+)[^"]*")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), attribute); it != std::sregex_iterator();
       ++it)
    files.insert((*it)[1]);
  return files;
}

bool no_temporaries_beside(const fs::path& report) {
  for (const auto& entry : fs::directory_iterator(report.parent_path()))
    if (entry.path().filename().string().find(".tmp-") != std::string::npos) return false;
  return true;
}

TEST(OchreRegressHtml, ExternalReferenceScanFindsEachKind) {
  // The scan below must be able to fail.
  for (const char* bad : {"<script src=\"https://cdn.example/x.js\">", "<link href=\"//fonts.example/css\">",
                          "<img src=\"/etc/x.png\">", "@import 'x.css';", "src: url(font.woff2)",
                          "fetch('data.json')", "<a href=\"file:///tmp/x\">"})
    EXPECT_FALSE(external_references(bad).empty()) << bad;
  EXPECT_TRUE(external_references("<img src=\"scene-a.new.png\"> <a href=\"index.html#x\">").empty());
}

TEST(OchreRegressHtml, ReportOfAFailingSuite) {
  const auto dir = scratch_dir();
  failing_suite(dir);
  const CommandResult r = run_regress("suite --html report --output-dir out", dir);
  ASSERT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("HTML report: report/index.html ("), std::string::npos) << r.output;
  const fs::path report = dir / "report";
  for (const char* file : {"index.html", "report.css", "report.js", "junit.xml", ".ochre-regress-report",
                           "scene-lambert_environment.html", "scene-lambert_environment.data.js",
                           "scene-lambert_environment.reference.png", "scene-lambert_environment.new.png",
                           "scene-lambert_environment.difference.png", "scene-lambert_environment.z.png",
                           "scene-spot_light.html"})
    EXPECT_TRUE(fs::is_regular_file(report / file)) << file;

  const std::string index = read_file_contents(report / "index.html");
  EXPECT_NE(index.find("1 of 2 scenes failed"), std::string::npos) << index;
  // Pass and fail as words, not only colours.
  const std::regex fail_row(
      R"(<tr class="fail" data-scene="lambert_environment">\s*<td><span class="status fail"><svg[^>]*>.*?</svg><span class="word">FAIL</span>)");
  EXPECT_TRUE(std::regex_search(index, fail_row)) << index;
  const std::regex pass_row(
      R"(<tr class="pass" data-scene="spot_light">\s*<td><span class="status pass"><svg[^>]*>.*?</svg><span class="word">PASS</span>)");
  EXPECT_TRUE(std::regex_search(index, pass_row)) << index;
  // The committed reference records its render time: the index compares with it.
  EXPECT_NE(index.find("at 1024 spp"), std::string::npos) << index;

  // The scene page names the worst pixel that the command line reports.
  std::smatch worst;
  ASSERT_TRUE(
      std::regex_search(r.output, worst, std::regex(R"(worst p = \S+ at (x=\d+ y=\d+) \(z = (-?[\d.]+)\))")))
      << r.output;
  const std::string page = read_file_contents(report / "scene-lambert_environment.html");
  EXPECT_NE(page.find(worst[1].str() + " (z = " + worst[2].str() + ")"), std::string::npos) << page;
  EXPECT_NE(page.find("<script src=\"scene-lambert_environment.data.js\"></script>"), std::string::npos);

  // Every file a page links to is in the report.
  for (const fs::path& file : report_files(report)) {
    if (file.extension() != ".html") continue;
    for (const std::string& linked : linked_files(read_file_contents(file)))
      EXPECT_TRUE(fs::is_regular_file(report / linked)) << file.filename() << " links to missing " << linked;
  }
  const std::string junit = read_file_contents(report / "junit.xml");
  EXPECT_NE(junit.find("tests=\"2\" failures=\"1\""), std::string::npos) << junit;
  EXPECT_TRUE(no_temporaries_beside(report));
}

TEST(OchreRegressHtml, ReportHoldsNoExternalReference) {
  const auto dir = scratch_dir();
  failing_suite(dir);
  ASSERT_EQ(run_regress("suite --html report", dir).exit_code, 4);
  size_t scanned = 0;
  for (const fs::path& file : report_files(dir / "report")) {
    if (!has_extension(file, {".html", ".js", ".css"})) continue;
    ++scanned;
    for (const std::string& reference : external_references(read_file_contents(file)))
      ADD_FAILURE() << file.filename() << ": external reference " << reference;
  }
  EXPECT_EQ(scanned, 7u);  // index.html, report.css, report.js, and a page and a data script per scene
}

TEST(OchreRegressHtml, HistoryFromEarlierReportsAndJUnitFiles) {
  const auto dir = scratch_dir();
  failing_suite(dir);
  write_text(dir / "old.xml",
             "<?xml version=\"1.0\"?>\n<testsuites><testsuite name=\"x\" timestamp=\"2024-01-02T03:04:05Z\">"
             "<testcase name=\"lambert_environment\" time=\"1.5\"/>"
             "<testcase name=\"spot_light\" time=\"0.25\"><failure message=\"&lt;broken&gt;\"/></testcase>"
             "</testsuite></testsuites>\n");
  ASSERT_EQ(run_regress("suite --html first --history old.xml", dir).exit_code, 4);
  const std::string first = read_file_contents(dir / "first" / "index.html");
  EXPECT_NE(first.find("2024-01-02T03:04:05Z: PASS, 1.50 s"), std::string::npos) << first;
  EXPECT_NE(first.find("2024-01-02T03:04:05Z: FAIL, 0.25 s"), std::string::npos) << first;
  EXPECT_NE(first.find("this run: FAIL"), std::string::npos) << first;
  EXPECT_TRUE(fs::exists(dir / "first" / "history-01.xml"));

  // A report given as history brings its own history and its run.
  ASSERT_EQ(run_regress("suite --html second --history first", dir).exit_code, 4);
  const std::string second = read_file_contents(dir / "second" / "index.html");
  EXPECT_NE(second.find("2024-01-02T03:04:05Z: FAIL, 0.25 s"), std::string::npos) << second;
  EXPECT_TRUE(fs::exists(dir / "second" / "history-02.xml"));
  EXPECT_FALSE(fs::exists(dir / "second" / "history-03.xml"));
  EXPECT_EQ(read_file_contents(dir / "second" / "history-02.xml"),
            read_file_contents(dir / "first" / "junit.xml"));
  // A scene missing from an earlier run shows as not run.
  write_text(dir / "runs" / "a.xml", "<testsuite><testcase name=\"spot_light\" time=\"0.1\"/></testsuite>");
  ASSERT_EQ(run_regress("suite --html third --history runs", dir).exit_code, 4);
  EXPECT_NE(read_file_contents(dir / "third" / "index.html").find("run 1: not run"), std::string::npos);
}

TEST(OchreRegressHtml, ReplacesAnEarlierReportOnlyWhenComplete) {
  const auto dir = scratch_dir();
  failing_suite(dir);
  ASSERT_EQ(run_regress("suite --html report --scene spot_light", dir).exit_code, 0);
  const std::string before = read_file_contents(dir / "report" / "index.html");
  ASSERT_EQ(before.find("lambert_environment"), std::string::npos);

  // A run that ends in bad input (a scene without reference) leaves the earlier report as it was.
  fs::copy_file(suite_dir() / "mix_add_closures.json", dir / "suite" / "mix_add_closures.json");
  CommandResult r = run_regress("suite --html report", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(read_file_contents(dir / "report" / "index.html"), before);
  EXPECT_FALSE(fs::exists(dir / "report" / "scene-lambert_environment.html"));
  EXPECT_TRUE(no_temporaries_beside(dir / "report"));

  // A complete run replaces it, old files and all.
  fs::remove(dir / "suite" / "mix_add_closures.json");
  write_text(dir / "report" / "stale.txt", "from an earlier report");
  r = run_regress("suite --html report/", dir);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(read_file_contents(dir / "report" / "index.html").find("lambert_environment"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "report" / "stale.txt"));
  EXPECT_TRUE(no_temporaries_beside(dir / "report"));
}

// Each way a report directory can be refused: exit 2 before any rendering, a message naming the
// directory, nothing touched.
struct BadDestination {
  const char* name;
  const char* args;
  const char* message;
};

class HtmlDestination : public ::testing::TestWithParam<BadDestination> {};

TEST_P(HtmlDestination, IsRefusedAndNothingIsTouched) {
  const auto dir = scratch_dir();
  failing_suite(dir);
  write_text(dir / "notes" / "keep.txt", "mine");
  write_text(dir / "a-file", "mine");
  fs::create_symlink("notes", dir / "link");
  fs::create_directories(dir / "report");  // empty: a report may go there
  const CommandResult r = run_regress(std::string("suite ") + GetParam().args, dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(GetParam().message), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("scene "), std::string::npos) << "rendered before refusing: " << r.output;
  EXPECT_EQ(read_file_contents(dir / "notes" / "keep.txt"), "mine");
  EXPECT_EQ(read_file_contents(dir / "a-file"), "mine");
  EXPECT_FALSE(fs::exists(dir / "regress-output"));
  EXPECT_TRUE(fs::is_empty(dir / "report"));
  EXPECT_TRUE(no_temporaries_beside(dir / "notes"));
}

INSTANTIATE_TEST_SUITE_P(
    OchreRegressHtml, HtmlDestination,
    ::testing::Values(
        BadDestination{"NonReportDirectory", "--html notes",
                       "notes: cannot write the HTML report there: the directory is not empty and is not an "
                       "ochre-regress report"},
        BadDestination{"RegularFile", "--html a-file",
                       "a-file: cannot write the HTML report there: it exists and "
                       "is not a directory"},
        BadDestination{"SymbolicLink", "--html link",
                       "link: cannot write the HTML report there: it is a symbolic link"},
        BadDestination{"MissingParent", "--html missing/report", "does not exist"},
        BadDestination{"JUnitInside", "--html report --junit report/junit.xml",
                       "report/junit.xml lies inside it"},
        BadDestination{"OutputDirInside", "--html report --output-dir report/out",
                       "report/out lies inside it"},
        BadDestination{"HistoryWithoutHtml", "--history x.xml", "--history requires --html"}),
    [](const ::testing::TestParamInfo<BadDestination>& info) { return info.param.name; });

// Each way a history source can be bad: exit 2 naming the file, before rendering, no report.
struct BadHistory {
  const char* name;
  const char* content;  // written to dir/history.xml (nullptr: not written)
  const char* source;
  const char* message;
};

class HtmlHistory : public ::testing::TestWithParam<BadHistory> {};

TEST_P(HtmlHistory, IsRefusedNamingTheFile) {
  const auto dir = scratch_dir();
  failing_suite(dir);
  if (GetParam().content) write_text(dir / "history.xml", GetParam().content);
  fs::create_directories(dir / "empty");
  const CommandResult r = run_regress(std::string("suite --html report --history ") + GetParam().source, dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(GetParam().message), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("scene "), std::string::npos) << "rendered before refusing: " << r.output;
  EXPECT_FALSE(fs::exists(dir / "report"));
  EXPECT_TRUE(no_temporaries_beside(dir / "report"));
}

INSTANTIATE_TEST_SUITE_P(
    OchreRegressHtml, HtmlHistory,
    ::testing::Values(
        BadHistory{"Missing", nullptr, "nope.xml", "nope.xml: --history: no such file or directory"},
        BadHistory{"NotWellFormed", "<testsuite>\n<testcase name=\"a\">\n</testsuite>\n", "history.xml",
                   "history.xml: line 3: not well-formed XML (mismatched tag)"},
        BadHistory{"NotXml", "scene,time\na,1\n", "history.xml", "history.xml: line 1: not well-formed XML"},
        BadHistory{"NoTestsuite", "<results><case name=\"a\"/></results>", "history.xml",
                   "history.xml: no <testsuite> element (not a JUnit XML report)"},
        BadHistory{"TestcaseWithoutName", "<testsuite>\n<testcase time=\"1\"/></testsuite>", "history.xml",
                   "history.xml: line 2: <testcase> without a name"},
        BadHistory{"TimeNotANumber", "<testsuite><testcase name=\"a\" time=\"fast\"/></testsuite>",
                   "history.xml",
                   "history.xml: line 1: testcase 'a': time 'fast' is not a number of seconds"},
        BadHistory{"NegativeTime", "<testsuite><testcase name=\"a\" time=\"-1\"/></testsuite>", "history.xml",
                   "time '-1' is not a number of seconds"},
        BadHistory{
            "DirectoryWithoutRuns", nullptr, "empty",
            "empty: --history: the directory holds no JUnit *.xml file and is not an ochre-regress report"},
        BadHistory{"Device", nullptr, "/dev/null", "/dev/null: the JUnit file is a character device"}),
    [](const ::testing::TestParamInfo<BadHistory>& info) { return info.param.name; });

}  // namespace
}  // namespace ochre::test::regress_html_test
