#pragma once
// The HTML report of an ochre-regress run (--html DIR, docs/tools.md): a static, self-contained folder
// (index.html, a page per scene, PNG images, the pixel values as <script> files, report.css and
// report.js; nothing loaded from elsewhere, usable from a file:// URL), written all or nothing: the files
// go into a scratch directory that replaces DIR only when complete (renderer/util/atomic_directory.h), and
// only an earlier report or an empty directory is ever replaced.

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "renderer/util/atomic_directory.h"
#include "tools/regress/index_page.h"
#include "tools/regress/junit_report.h"
#include "tools/regress/scene_report.h"

namespace ochre {

struct ReportStats {
  size_t files = 0;
  std::uintmax_t bytes = 0;
  double seconds = 0.0;  // spent writing the report (not rendering)
};

class HtmlReport {
 public:
  // Throws InputError naming dir when it cannot become a report: its parent is missing or not
  // writable, or it exists and is not a directory, or is a directory that is neither empty nor a
  // report. `others` are paths the run writes besides (--junit, --output-dir): none may lie inside dir.
  static void check_destination(const std::filesystem::path& dir,
                                const std::vector<std::filesystem::path>& others);

  // scenes: every scene name of the run, in order (for the file names and the links between pages);
  // history: the earlier runs, oldest first.
  HtmlReport(std::filesystem::path dir, const std::vector<std::string>& scenes,
             std::vector<RunRecord> history, ReportHeading heading);

  // Writes the scene's page, images and pixel data (into the scratch directory).
  void add_scene(const SceneReport& scene);

  // Writes the index, the assets and the JUnit files of this run and its history, then puts the report
  // in place. Throws ImageError naming the directory when it cannot.
  ReportStats commit(const RunRecord& run);

 private:
  std::string page_of(size_t scene) const;

  AtomicDirectory dir_;
  std::vector<std::string> names_, prefixes_;
  std::vector<RunRecord> history_;
  ReportHeading heading_;
  std::vector<SceneSummary> summaries_;
  std::chrono::steady_clock::duration writing_time_{};
};

}  // namespace ochre
