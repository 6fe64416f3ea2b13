#pragma once
// index.html of an HTML report (docs/tools.md, "HTML report"): one row per scene (result, worst p-value,
// failing pixels, relMSE, mean Delta E00, render time against the reference's, thumbnails) and each
// scene's results and times over the earlier runs given with --history.

#include <optional>
#include <string>
#include <vector>

#include "tools/regress/html_page.h"
#include "tools/regress/junit_report.h"
#include "tools/regress/report_images.h"
#include "tools/regress/scene_report.h"

namespace ochre {

// What the index shows of a scene (the scene page has the rest).
struct SceneSummary {
  std::string name, description;
  std::string page;  // the scene page's file name
  bool passed = true;
  double worst_p = 1.0;
  size_t failing = 0, pixels = 0;
  double relmse = 0.0, mean_de00 = 0.0;
  SceneTiming timing;
  std::optional<SceneTiming> reference_timing;
  SceneImageFiles images;
  int width = 0, height = 0;
};

SceneSummary summarize_scene(const SceneReport& report, const std::string& page,
                             const SceneImageFiles& images);

// New render time per sample over the reference's, when the reference recorded its time.
std::optional<double> per_sample_time_ratio(const SceneTiming& timing,
                                            const std::optional<SceneTiming>& reference);

struct ReportHeading {
  std::string suite;      // the suite directory as given
  std::string timestamp;  // of this run
  std::string version;    // ochre's
};

// history: earlier runs, oldest first; current: this run (its scenes' JUnit times).
std::string index_page(const ReportHeading& heading, const std::vector<SceneSummary>& scenes,
                       const std::vector<RunRecord>& history, const RunRecord& current);

}  // namespace ochre
