#include "tools/regress/html_report.h"

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <set>
#include <system_error>

#include "renderer/util/atomic_file.h"
#include "spectra/input_error.h"
#include "tools/regress/report_assets.h"
#include "tools/regress/report_history.h"
#include "tools/regress/scene_data.h"
#include "tools/regress/scene_page.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

fs::path normal_absolute(const fs::path& path) {
  fs::path p = fs::absolute(path).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();  // "out/report/"
  return p;
}

[[noreturn]] void refuse(const fs::path& dir, const std::string& why) {
  throw InputError(fmt::format("{}: cannot write the HTML report there: {}", dir.string(), why));
}

bool inside(const fs::path& path, const fs::path& dir) {
  const fs::path p = normal_absolute(path);
  auto d = dir.begin();
  auto q = p.begin();
  for (; d != dir.end(); ++d, ++q)
    if (q == p.end() || *d != *q) return false;
  return true;
}

// "scene-<name>" with every character but letters, digits, '-', '_' and '.' replaced by '_', made unique.
std::vector<std::string> file_prefixes(const std::vector<std::string>& names) {
  std::vector<std::string> prefixes;
  std::set<std::string> used;
  for (const std::string& name : names) {
    std::string base = "scene-";
    for (const char c : name)
      base += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '_';
    std::string prefix = base;
    for (int n = 2; used.count(prefix); ++n) prefix = fmt::format("{}-{}", base, n);
    used.insert(prefix);
    prefixes.push_back(prefix);
  }
  return prefixes;
}

ReportStats count_files(const fs::path& dir) {
  ReportStats stats;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++stats.files;
    stats.bytes += entry.file_size();
  }
  return stats;
}

}  // namespace

void HtmlReport::check_destination(const fs::path& dir, const std::vector<fs::path>& others) {
  if (dir.empty()) throw InputError("--html: give a directory for the report");
  const fs::path report = normal_absolute(dir);
  const fs::path parent = report.parent_path();
  std::error_code error;
  if (!fs::is_directory(parent, error))
    refuse(dir, fmt::format("directory {} does not exist", parent.string()));
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    refuse(dir, fmt::format("directory {} is not writable", parent.string()));
  struct stat info {};
  if (::lstat(report.c_str(), &info) == 0) {
    if (S_ISLNK(info.st_mode)) refuse(dir, "it is a symbolic link");
    if (!S_ISDIR(info.st_mode)) refuse(dir, "it exists and is not a directory");
    if (!fs::is_empty(report, error) && !fs::exists(report / kReportMarker, error))
      refuse(dir, fmt::format("the directory is not empty and is not an ochre-regress report (it has no {}); "
                              "the report replaces its directory as a whole",
                              kReportMarker));
  }
  for (const fs::path& other : others)
    if (!other.empty() && inside(other, report))
      refuse(dir, fmt::format("{} lies inside it, and the report replaces its directory as a whole",
                              other.string()));
}

HtmlReport::HtmlReport(fs::path dir, const std::vector<std::string>& scenes, std::vector<RunRecord> history,
                       ReportHeading heading)
    : dir_(normal_absolute(dir)),
      names_(scenes),
      prefixes_(file_prefixes(scenes)),
      history_(std::move(history)),
      heading_(std::move(heading)) {}

std::string HtmlReport::page_of(size_t scene) const {
  return prefixes_[scene] + ".html";
}

void HtmlReport::add_scene(const SceneReport& scene) {
  const auto start = std::chrono::steady_clock::now();
  const size_t i = static_cast<size_t>(std::find(names_.begin(), names_.end(), scene.name) - names_.begin());
  if (i == names_.size()) throw std::logic_error("HtmlReport: unknown scene " + scene.name);
  const fs::path& dir = dir_.temp_path();
  const SceneImageFiles images = write_scene_images(scene, dir, prefixes_[i]);
  PixelGrid grid;
  ScenePageLinks links;
  links.data_script = prefixes_[i] + ".data.js";
  write_text_file(dir / links.data_script, scene_data_js(scene, grid));
  if (i > 0) {
    links.previous_page = page_of(i - 1);
    links.previous_name = names_[i - 1];
  }
  if (i + 1 < names_.size()) {
    links.next_page = page_of(i + 1);
    links.next_name = names_[i + 1];
  }
  write_text_file(dir / page_of(i), scene_page(scene, images, grid, links));
  summaries_.push_back(summarize_scene(scene, page_of(i), images));
  writing_time_ += std::chrono::steady_clock::now() - start;
}

ReportStats HtmlReport::commit(const RunRecord& run) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path& dir = dir_.temp_path();
  write_text_file(dir / "index.html", index_page(heading_, summaries_, history_, run));
  for (const spectra::EmbeddedFile& asset : report_assets()) write_text_file(dir / asset.name, asset.content);
  write_text_file(dir / kReportJUnit, junit_xml(run));
  for (size_t i = 0; i < history_.size(); ++i)
    write_text_file(dir / report_history_file_name(i), junit_xml(history_[i]));
  write_text_file(dir / kReportMarker,
                  "An HTML report of ochre-regress; replaced as a whole by the next one.\n");
  ReportStats stats = count_files(dir);
  dir_.commit();
  writing_time_ += std::chrono::steady_clock::now() - start;
  stats.seconds = std::chrono::duration<double>(writing_time_).count();
  return stats;
}

}  // namespace ochre
