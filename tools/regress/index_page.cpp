#include "tools/regress/index_page.h"

#include <fmt/format.h>

#include <algorithm>

namespace ochre {

namespace {

SceneStatus record_status(const SceneRecord* record) {
  if (!record) return SceneStatus::kAbsent;
  if (record->skipped) return SceneStatus::kSkipped;
  return record->passed ? SceneStatus::kPass : SceneStatus::kFail;
}

std::string run_label(const RunRecord& run, size_t index) {
  return run.timestamp.empty() ? fmt::format("run {}", index + 1) : run.timestamp;
}

std::string thumbnail(const std::string& file, const std::string& alt, const SceneSummary& scene) {
  // Small images keep their aspect in a 72-pixel box, drawn with square pixels (report.css).
  const double scale = 72.0 / std::max(scene.width, scene.height);
  return fmt::format("<img class=\"thumb\" src=\"{}\" alt=\"{}\" width=\"{}\" height=\"{}\">",
                     xml_escape(file), xml_escape(alt), static_cast<int>(scene.width * scale + 0.5),
                     static_cast<int>(scene.height * scale + 0.5));
}

std::string time_cell(const SceneSummary& scene) {
  std::string html = format_seconds(scene.timing.seconds);
  if (scene.reference_timing) {
    const std::string ratio = format_time_ratio(per_sample_time_ratio(scene.timing, scene.reference_timing));
    html += fmt::format(
        "<br><span class=\"secondary\">reference {} at {} spp</span><br>"
        "<span class=\"ratio\" title=\"render time per sample per pixel, new / reference\">{} per "
        "sample</span>",
        format_seconds(scene.reference_timing->seconds), scene.reference_timing->spp, ratio);
  } else {
    html += "<br><span class=\"secondary\">reference time not recorded</span>";
  }
  return html;
}

// Times of a scene over the runs as a small line chart (its numbers are also in the list beside it).
std::string time_sparkline(const std::vector<std::optional<double>>& times) {
  double longest = 0.0;
  for (const auto& t : times)
    if (t) longest = std::max(longest, *t);
  if (longest <= 0.0 || times.size() < 2) return "";
  constexpr double kWidth = 120.0, kHeight = 24.0;
  std::string points;
  for (size_t i = 0; i < times.size(); ++i) {
    if (!times[i]) continue;
    const double x = kWidth * static_cast<double>(i) / static_cast<double>(times.size() - 1);
    const double y = kHeight - 2.0 - (kHeight - 4.0) * (*times[i] / longest);
    points += fmt::format("{}{:.1f},{:.1f}", points.empty() ? "" : " ", x, y);
  }
  return fmt::format(
      "<svg class=\"sparkline\" viewBox=\"0 0 {} {}\" width=\"{}\" height=\"{}\" aria-hidden=\"true\">"
      "<polyline points=\"{}\"/></svg>",
      kWidth, kHeight, kWidth, kHeight, points);
}

std::string history_cell(const std::string& scene, const std::vector<RunRecord>& history,
                         const RunRecord& current) {
  std::string items;
  std::vector<std::optional<double>> times;
  const auto add = [&](const RunRecord& run, const std::string& label) {
    const SceneRecord* record = run.find(scene);
    const SceneStatus status = record_status(record);
    const std::optional<double> seconds = record ? record->seconds : std::nullopt;
    times.push_back(seconds);
    const std::string text =
        fmt::format("{}: {}{}", label, status_word(status), seconds ? ", " + format_seconds(*seconds) : "");
    items += fmt::format("<li class=\"{}\" title=\"{}\">{}<span class=\"sr-only\">{}</span></li>",
                         status == SceneStatus::kFail ? "fail" : "", xml_escape(text), status_icon(status),
                         xml_escape(text));
  };
  for (size_t i = 0; i < history.size(); ++i) add(history[i], run_label(history[i], i));
  add(current, "this run");
  return fmt::format("<ol class=\"history\" aria-label=\"results, oldest first\">{}</ol>{}", items,
                     time_sparkline(times));
}

std::string scene_row(const SceneSummary& s, const std::vector<RunRecord>& history,
                      const RunRecord& current) {
  const SceneStatus status = s.passed ? SceneStatus::kPass : SceneStatus::kFail;
  std::string row =
      fmt::format("<tr class=\"{}\" data-scene=\"{}\">\n", s.passed ? "pass" : "fail", xml_escape(s.name));
  row += fmt::format("<td>{}</td>\n", status_badge(status));
  row += fmt::format(
      "<th scope=\"row\"><a href=\"{}\">{}</a>{}</th>\n", xml_escape(s.page), xml_escape(s.name),
      s.description.empty() ? ""
                            : "<br><span class=\"description\">" + xml_escape(s.description) + "</span>");
  row += fmt::format("<td class=\"num\">{}<br><span class=\"secondary\">{} of {} px failing</span></td>\n",
                     format_significant(s.worst_p), s.failing, s.pixels);
  row += fmt::format("<td class=\"num\">{}</td>\n<td class=\"num\">{}</td>\n", format_significant(s.relmse),
                     fmt::format("{:.2f}", s.mean_de00));
  row += fmt::format("<td class=\"num time\">{}</td>\n", time_cell(s));
  row += fmt::format("<td class=\"thumbs\"><a href=\"{}\">{}{}</a></td>\n", xml_escape(s.page),
                     thumbnail(s.images.reference_thumbnail, "reference of " + s.name, s),
                     thumbnail(s.images.render_thumbnail, "new render of " + s.name, s));
  row += fmt::format("<td>{}</td>\n</tr>\n", history_cell(s.name, history, current));
  return row;
}

std::string runs_table(const std::vector<RunRecord>& history, const RunRecord& current) {
  std::string rows;
  const auto add = [&](const RunRecord& run, const std::string& label, const std::string& source) {
    size_t failed = 0;
    for (const SceneRecord& scene : run.scenes) failed += scene.passed ? 0 : 1;
    rows += fmt::format("<tr><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td>{}</td></tr>\n",
                        xml_escape(label), run.scenes.size() - failed, failed, xml_escape(source));
  };
  for (size_t i = 0; i < history.size(); ++i) add(history[i], run_label(history[i], i), history[i].source);
  add(current, "this run (" + current.timestamp + ")", "");
  return fmt::format(
      "<section aria-labelledby=\"runs-heading\">\n<h2 id=\"runs-heading\">Runs</h2>\n"
      "<table class=\"runs\">\n<thead><tr><th scope=\"col\">Run</th><th scope=\"col\">Passed</th>"
      "<th scope=\"col\">Failed</th><th scope=\"col\">Read "
      "from</th></tr></thead>\n<tbody>\n{}</tbody>\n</table>\n"
      "</section>\n",
      rows);
}

}  // namespace

std::optional<double> per_sample_time_ratio(const SceneTiming& timing,
                                            const std::optional<SceneTiming>& reference) {
  if (!reference || reference->seconds <= 0.0 || timing.spp <= 0.0) return std::nullopt;
  return (timing.seconds / timing.spp) / (reference->seconds / reference->spp);
}

SceneSummary summarize_scene(const SceneReport& report, const std::string& page,
                             const SceneImageFiles& images) {
  SceneSummary s;
  s.name = report.name;
  s.description = report.description;
  s.page = page;
  s.passed = report.passed();
  s.worst_p = report.result.worst_p;
  s.failing = report.result.failing_pixels;
  s.pixels = report.result.p_values.size();
  s.relmse = report.comparison.metrics.relmse;
  s.mean_de00 = report.comparison.metrics.mean_de00;
  s.timing = report.timing;
  s.reference_timing = report.reference_timing;
  s.images = images;
  s.width = report.result.width;
  s.height = report.result.height;
  return s;
}

std::string index_page(const ReportHeading& heading, const std::vector<SceneSummary>& scenes,
                       const std::vector<RunRecord>& history, const RunRecord& current) {
  const size_t failed = static_cast<size_t>(
      std::count_if(scenes.begin(), scenes.end(), [](const SceneSummary& s) { return !s.passed; }));
  std::string html = html_page_start("ochre-regress: " + heading.suite, "index-page");
  html += "<header>\n";
  html += fmt::format("<h1>Regression report: {}</h1>\n", xml_escape(heading.suite));
  html += fmt::format("<p class=\"summary\">{} {} of {} scenes failed.</p>\n",
                      status_badge(failed ? SceneStatus::kFail : SceneStatus::kPass), failed, scenes.size());
  html += fmt::format(
      "<p class=\"secondary\">ochre {}, run {}. Per-pixel luminance z-test with Sidak "
      "correction at image level 1 %: a scene fails when any pixel does.</p>\n",
      xml_escape(heading.version), xml_escape(heading.timestamp));
  html += "<p><label><input type=\"checkbox\" id=\"failed-only\"> Show failed scenes only</label></p>\n";
  html +=
      "</header>\n<main>\n<div class=\"scroll\">\n<table class=\"scenes\" id=\"scenes\">\n"
      "<caption>One row per scene</caption>\n";
  html +=
      "<thead><tr><th scope=\"col\">Result</th><th scope=\"col\">Scene</th><th scope=\"col\">Worst p</th>"
      "<th scope=\"col\">relMSE</th><th scope=\"col\">Mean &Delta;E<sub>00</sub></th>"
      "<th scope=\"col\">Render time</th><th scope=\"col\">Reference, new</th>"
      "<th scope=\"col\">History (oldest first)</th></tr></thead>\n<tbody>\n";
  for (const SceneSummary& scene : scenes) html += scene_row(scene, history, current);
  html += "</tbody>\n</table>\n</div>\n";
  html += runs_table(history, current);
  html += "</main>\n";
  return html + html_page_end("report.js");
}

}  // namespace ochre
