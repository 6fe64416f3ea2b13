#pragma once
// Earlier runs for the history columns of an HTML report (ochre-regress --history, docs/tools.md).

#include <filesystem>
#include <string>
#include <vector>

#include "tools/regress/junit_report.h"

namespace ochre {

// The file that marks a directory as an ochre-regress HTML report (so that only a report, or an empty
// directory, is ever replaced by a new one), and the JUnit files a report keeps.
inline constexpr const char* kReportMarker = ".ochre-regress-report";
inline constexpr const char* kReportJUnit = "junit.xml";
// history-01.xml, history-02.xml, ...: the runs before the report's own, oldest first.
std::string report_history_file_name(size_t index);

// A report shows at most this many earlier runs (and keeps as many in its folder).
inline constexpr size_t kMaxHistoryRuns = 20;

// The runs of each argument, in the order given, oldest first:
//   a JUnit XML file: its run;
//   an HTML report's directory: the history it kept, then its own run;
//   another directory: its *.xml files in name order.
// Only the last kMaxHistoryRuns are kept. Throws InputError naming the file or directory that is missing,
// malformed or holds no run.
std::vector<RunRecord> load_history(const std::vector<std::string>& sources);

}  // namespace ochre
