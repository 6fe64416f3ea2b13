#pragma once
// Pieces shared by the pages of an HTML report (tools/regress/index_page.h, scene_page.h): the document
// head, the pass/fail badge (an icon of its own shape and the word, never colour alone), number formats.

#include <optional>
#include <string>

namespace ochre {

// "<!DOCTYPE html>...<body class=...>": UTF-8, the report's own stylesheet, nothing from elsewhere.
std::string html_page_start(const std::string& title, const std::string& body_class);
// The scripts (report-relative file names, loaded in order) and the end of the document.
std::string html_page_end(const std::string& first_script, const std::string& second_script = "");

// Inline SVG icon (a tick in a circle, a cross in a square, a dash for "not run") and the word
// PASS / FAIL / SKIP / "not run"; the icon is hidden from screen readers, the word is not.
enum class SceneStatus { kPass, kFail, kSkipped, kAbsent };
std::string status_badge(SceneStatus status);
std::string status_icon(SceneStatus status);
const char* status_word(SceneStatus status);

// Numbers as the pages show them: 3 significant digits ("0.000286", "1.2e-09"), seconds ("0.05 s").
std::string format_significant(double value);
std::string format_seconds(double seconds);
// "&times;1.25" (ratio of per-sample render times, new / reference) or "" when unknown.
std::string format_time_ratio(std::optional<double> ratio);

}  // namespace ochre
