#include "tools/regress/junit_report.h"

#include <expat.h>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

constexpr InputKind kJUnitFileInput{"JUnit file", 64 * kMiB};

// What the expat callbacks collect, and the first problem they found.
struct JUnitParse {
  XML_Parser parser = nullptr;
  RunRecord run;
  bool saw_testsuite = false;
  SceneRecord* open_testcase = nullptr;
  std::string error;  // "line N: ..." once something is wrong

  void fail(const std::string& what) {
    if (error.empty()) error = fmt::format("line {}: {}", XML_GetCurrentLineNumber(parser), what);
    XML_StopParser(parser, XML_FALSE);
  }
};

const char* attribute(const XML_Char** attributes, const char* name) {
  for (int i = 0; attributes[i]; i += 2)
    if (std::strcmp(attributes[i], name) == 0) return attributes[i + 1];
  return nullptr;
}

std::optional<double> parse_seconds(JUnitParse& parse, const std::string& scene, const char* text) {
  if (!text) return std::nullopt;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(seconds >= 0.0) || seconds > 1e12) {
    parse.fail(fmt::format("testcase '{}': time '{}' is not a number of seconds", scene, text));
    return std::nullopt;
  }
  return seconds;
}

void XMLCALL start_element(void* data, const XML_Char* name, const XML_Char** attributes) {
  auto& parse = *static_cast<JUnitParse*>(data);
  if (std::strcmp(name, "testsuite") == 0) {
    if (!parse.saw_testsuite)
      if (const char* timestamp = attribute(attributes, "timestamp")) parse.run.timestamp = timestamp;
    parse.saw_testsuite = true;
  } else if (std::strcmp(name, "testcase") == 0) {
    const char* scene = attribute(attributes, "name");
    if (!scene || !*scene) return parse.fail("<testcase> without a name");
    SceneRecord record;
    record.name = scene;
    record.seconds = parse_seconds(parse, scene, attribute(attributes, "time"));
    parse.run.scenes.push_back(std::move(record));
    parse.open_testcase = &parse.run.scenes.back();
  } else if (parse.open_testcase && (std::strcmp(name, "failure") == 0 || std::strcmp(name, "error") == 0)) {
    parse.open_testcase->passed = false;
    if (const char* message = attribute(attributes, "message")) parse.open_testcase->message = message;
  } else if (parse.open_testcase && std::strcmp(name, "skipped") == 0) {
    parse.open_testcase->skipped = true;
  }
}

void XMLCALL end_element(void* data, const XML_Char* name) {
  auto& parse = *static_cast<JUnitParse*>(data);
  if (std::strcmp(name, "testcase") == 0) parse.open_testcase = nullptr;
}

std::string junit_seconds(double seconds) {
  return fmt::format("{:.3f}", seconds);
}

}  // namespace

const SceneRecord* RunRecord::find(const std::string& name) const {
  for (const SceneRecord& scene : scenes)
    if (scene.name == name) return &scene;
  return nullptr;
}

std::string utc_timestamp_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string junit_xml(const RunRecord& run) {
  size_t failures = 0;
  double total = 0.0;
  for (const SceneRecord& scene : run.scenes) {
    failures += scene.passed ? 0 : 1;
    // The sum of the times as written (milliseconds), so that a file read back and written again is the same.
    total += std::round(scene.seconds.value_or(0.0) * 1000.0) / 1000.0;
  }
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml +=
      fmt::format("<testsuite name=\"ochre-regress\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{}\"",
                  run.scenes.size(), failures, junit_seconds(total));
  if (!run.timestamp.empty()) xml += fmt::format(" timestamp=\"{}\"", xml_escape(run.timestamp));
  xml += ">\n";
  for (const SceneRecord& scene : run.scenes) {
    xml += fmt::format("  <testcase classname=\"ochre-regress\" name=\"{}\"", xml_escape(scene.name));
    if (scene.seconds) xml += fmt::format(" time=\"{}\"", junit_seconds(*scene.seconds));
    if (scene.passed && !scene.skipped) {
      xml += "/>\n";
    } else if (scene.skipped) {
      xml += ">\n    <skipped/>\n  </testcase>\n";
    } else {
      xml += fmt::format(">\n    <failure message=\"{}\"/>\n  </testcase>\n", xml_escape(scene.message));
    }
  }
  xml += "</testsuite>\n";
  return xml;
}

RunRecord read_junit(const fs::path& file) {
  const std::string text = read_input_file(file, kJUnitFileInput);
  JUnitParse parse;
  parse.parser = XML_ParserCreate(nullptr);
  if (!parse.parser) throw std::bad_alloc();
  XML_SetUserData(parse.parser, &parse);
  XML_SetElementHandler(parse.parser, start_element, end_element);
  const XML_Status status = XML_Parse(parse.parser, text.data(), static_cast<int>(text.size()), XML_TRUE);
  if (status != XML_STATUS_OK && parse.error.empty())
    parse.error = fmt::format("line {}: not well-formed XML ({})", XML_GetCurrentLineNumber(parse.parser),
                              XML_ErrorString(XML_GetErrorCode(parse.parser)));
  XML_ParserFree(parse.parser);
  if (!parse.error.empty())
    throw InputError(fmt::format("{}: {} (not a JUnit XML report)", file.string(), parse.error));
  if (!parse.saw_testsuite)
    throw InputError(file.string() + ": no <testsuite> element (not a JUnit XML report)");
  parse.run.source = file.string();
  return std::move(parse.run);
}

}  // namespace ochre
