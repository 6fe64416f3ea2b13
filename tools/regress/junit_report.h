#pragma once
// The JUnit XML of an ochre-regress run (--junit, and junit.xml / history-NN.xml in an HTML report),
// written and read back. Reading accepts any JUnit file (a <testsuite>, or <testsuites> holding several):
// a <testcase> with a <failure> or <error> child failed, one with <skipped> was skipped.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "renderer/util/xml_escape.h"  // xml_escape, for the report's pages

namespace ochre {

struct SceneRecord {
  std::string name;
  bool passed = true;
  bool skipped = false;
  std::optional<double> seconds;  // the testcase's time attribute, when it has one
  std::string message;            // failure message
};

struct RunRecord {
  std::string timestamp;  // ISO 8601 (the testsuite's timestamp attribute), "" when unknown
  std::string source;     // the file it was read from, "" for the current run
  std::vector<SceneRecord> scenes;
  // The scene called name, or nullptr.
  const SceneRecord* find(const std::string& name) const;
};

// The current time as ISO 8601 UTC, "2024-05-01T12:34:56Z".
std::string utc_timestamp_now();

// <testsuite name="ochre-regress" tests=.. failures=.. errors="0" time=.. timestamp=..> with one
// <testcase> per scene.
std::string junit_xml(const RunRecord& run);

// Reads a JUnit file. Throws InputError naming the file (and the line) when it is not well-formed XML,
// has no <testsuite>, or a testcase has no name or a time that is not a number.
RunRecord read_junit(const std::filesystem::path& file);

}  // namespace ochre
