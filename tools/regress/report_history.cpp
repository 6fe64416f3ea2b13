#include "tools/regress/report_history.h"

#include <fmt/format.h>

#include <algorithm>
#include <system_error>

#include "spectra/input_error.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> sorted_files(const fs::path& dir, const std::string& prefix,
                                   const std::string& extension) {
  std::vector<fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == extension && name.rfind(prefix, 0) == 0 && !entry.is_directory())
      files.push_back(entry.path());
  }
  if (error)
    throw InputError(fmt::format("{}: cannot list the directory: {}", dir.string(), error.message()));
  std::sort(files.begin(), files.end());
  return files;
}

// The JUnit files a source stands for, oldest first.
std::vector<fs::path> history_files(const fs::path& source) {
  std::error_code error;
  const fs::file_status status = fs::status(source, error);
  if (!fs::exists(status))
    throw InputError(fmt::format("{}: --history: no such file or directory", source.string()));
  if (!fs::is_directory(status)) return {source};
  if (fs::exists(source / kReportMarker, error)) {
    std::vector<fs::path> files = sorted_files(source, "history-", ".xml");
    files.push_back(source / kReportJUnit);
    return files;
  }
  std::vector<fs::path> files = sorted_files(source, "", ".xml");
  if (files.empty())
    throw InputError(fmt::format(
        "{}: --history: the directory holds no JUnit *.xml file and is not an ochre-regress report",
        source.string()));
  return files;
}

}  // namespace

std::string report_history_file_name(size_t index) {
  return fmt::format("history-{:02}.xml", index + 1);
}

std::vector<RunRecord> load_history(const std::vector<std::string>& sources) {
  std::vector<RunRecord> runs;
  for (const std::string& source : sources)
    for (const fs::path& file : history_files(source)) runs.push_back(read_junit(file));
  if (runs.size() > kMaxHistoryRuns) runs.erase(runs.begin(), runs.end() - kMaxHistoryRuns);
  return runs;
}

}  // namespace ochre
