#include "tools/regress/scene_page.h"

#include <fmt/format.h>

#include <cmath>

#include "tools/regress/html_page.h"
#include "tools/regress/index_page.h"
#include "tools/regress/junit_report.h"

namespace ochre {

namespace {

std::string navigation(const ScenePageLinks& links) {
  std::string html = "<nav aria-label=\"Scenes\"><a href=\"index.html\">All scenes</a>";
  if (!links.previous_page.empty())
    html += fmt::format(" <a href=\"{}\" rel=\"prev\">&larr; {}</a>", xml_escape(links.previous_page),
                        xml_escape(links.previous_name));
  if (!links.next_page.empty())
    html += fmt::format(" <a href=\"{}\" rel=\"next\">{} &rarr;</a>", xml_escape(links.next_page),
                        xml_escape(links.next_name));
  return html + "</nav>\n";
}

std::string metric(const std::string& name, const std::string& value, const std::string& id = "") {
  return fmt::format("<dt>{}</dt><dd{}>{}</dd>\n", name, id.empty() ? "" : " id=\"" + id + "\"", value);
}

std::string metrics(const SceneReport& report) {
  const RegressionResult& r = report.result;
  const ImageMetrics& m = report.comparison.metrics;
  const double z =
      r.z_scores.empty() ? 0.0 : r.z_scores[static_cast<size_t>(r.worst_y) * r.width + r.worst_x];
  std::string html = "<dl class=\"metrics\">\n";
  html += metric(
      "Worst p-value",
      fmt::format("{} at x={} y={} (z = {:.2f})", format_significant(r.worst_p), r.worst_x, r.worst_y, z),
      "worst");
  html +=
      metric("Failing pixels",
             fmt::format("{} of {} (per-pixel level {}, |z| &gt; {:.2f}; Sidak correction of &alpha; = {})",
                         r.failing_pixels, r.p_values.size(), format_significant(r.alpha_pixel),
                         critical_z(r), r.alpha),
             "failing-count");
  html += metric("relMSE", format_significant(m.relmse));
  html +=
      metric("Mean &Delta;E<sub>00</sub>", fmt::format("{:.2f} (largest {:.2f})", m.mean_de00, m.max_de00));
  std::string time = fmt::format("{} at {} spp", format_seconds(report.timing.seconds), report.timing.spp);
  if (report.reference_timing)
    time += fmt::format("; reference {} at {} spp ({} per sample)",
                        format_seconds(report.reference_timing->seconds), report.reference_timing->spp,
                        format_time_ratio(per_sample_time_ratio(report.timing, report.reference_timing)));
  html += metric("Render time", time);
  html += metric("Display",
                 fmt::format("working space {}; images through the transform of the scene's PNG output",
                             xml_escape(report.working_space)));
  if (!report.message.empty()) html += metric("Message", xml_escape(report.message));
  return html + "</dl>\n";
}

std::string panel(const char* key, const std::string& file, const std::string& alt,
                  const std::string& caption, const SceneReport& report) {
  return fmt::format(
      "<figure class=\"panel\" data-image=\"{}\">\n<div class=\"viewport\" style=\"aspect-ratio: {} / {}\">"
      "<img src=\"{}\" alt=\"{}\" width=\"{}\" "
      "height=\"{}\"></div>\n<figcaption>{}</figcaption>\n</figure>\n",
      key, report.result.width, report.result.height, xml_escape(file), xml_escape(alt), report.result.width,
      report.result.height, caption);
}

std::string legends(const SceneReport& report) {
  const double z_full = kZFullScaleFactor * critical_z(report.result);
  return fmt::format(
      "<div class=\"legends\">\n"
      "<p class=\"legend\"><span class=\"ramp diverging\" aria-hidden=\"true\"></span> z-score: "
      "&minus;{0:.1f} (new darker, blue) &hellip; 0 (white) &hellip; +{0:.1f} (new brighter, red); "
      "failing pixels (|z| &gt; {1:.2f}) are outlined in black and white.</p>\n"
      "<p class=\"legend\"><span class=\"ramp sequential\" aria-hidden=\"true\"></span> "
      "&Delta;E<sub>00</sub>: "
      "0 (white) &hellip; {2:g} or more (dark red).</p>\n</div>\n",
      z_full, critical_z(report.result), kDe00FullScale);
}

std::string viewer(const SceneReport& report, const SceneImageFiles& images, const PixelGrid& grid) {
  const std::string& name = report.name;
  std::string html =
      "<section id=\"viewer\" aria-labelledby=\"viewer-heading\">\n<h2 id=\"viewer-heading\">Images</h2>\n";
  html +=
      "<div class=\"toolbar js-only\" role=\"group\" aria-label=\"Image viewer\">\n"
      "<fieldset><legend>View</legend>"
      "<label><input type=\"radio\" name=\"mode\" value=\"side\" checked> Side by side</label>"
      "<label><input type=\"radio\" name=\"mode\" value=\"slider\"> Slider</label>"
      "<label><input type=\"radio\" name=\"mode\" value=\"flip\"> Flip</label></fieldset>\n"
      "<span class=\"zoom\"><button type=\"button\" id=\"zoom-out\" aria-label=\"Zoom out\">&minus;</button>"
      "<output id=\"zoom-level\" aria-live=\"polite\">fit</output>"
      "<button type=\"button\" id=\"zoom-in\" aria-label=\"Zoom in\">+</button>"
      "<button type=\"button\" id=\"zoom-fit\">Fit</button></span>\n"
      "<label><input type=\"checkbox\" id=\"mark-failing\" checked> Mark failing pixels</label>\n"
      "<button type=\"button\" id=\"worst-pixel\">Worst pixel</button>\n</div>\n";
  html += "<div id=\"side-by-side\" class=\"panels\">\n";
  html += panel("reference", images.reference, "reference render of " + name, "Reference", report);
  html += panel("new", images.render, "new render of " + name, "New render", report);
  html += panel("difference", images.difference,
                "display-referred Delta E00 between new and reference of " + name,
                "Difference (&Delta;E<sub>00</sub>)", report);
  html += panel("z", images.z, "z-scores of the luminance test of " + name, "z-scores, failing pixels marked",
                report);
  html += "</div>\n";
  html += fmt::format(
      "<div id=\"compare\" class=\"js-only\" hidden>\n"
      "<div class=\"viewport compare\" style=\"aspect-ratio: {} / {}\"></div>\n"
      "<p id=\"slider-controls\"><label for=\"split\">Reference (left) | New (right): split at</label> "
      "<input type=\"range\" id=\"split\" min=\"0\" max=\"100\" value=\"50\"> <output id=\"split-value\">50 "
      "%</output></p>\n"
      "<p id=\"flip-controls\"><button type=\"button\" id=\"flip\" aria-pressed=\"false\">Flip (F)</button> "
      "Showing: <output id=\"flip-state\">Reference</output></p>\n</div>\n",
      report.result.width, report.result.height);
  html += legends(report);
  if (grid.step > 1)
    html += fmt::format(
        "<p class=\"note\">The pixel readout uses blocks of {0}&times;{0} pixels (the report's size "
        "limit): means of the values, the largest |z| of the block.</p>\n",
        grid.step);
  return html + "</section>\n";
}

bool has_channel(const SceneReport& report, const char* name) {
  return report.reference.find_channel(name) || report.render.find_channel(name);
}

std::string readout(const SceneReport& report) {
  std::string rows;
  const auto row = [&](const char* label, const char* id) {
    rows += fmt::format(
        "<tr><th scope=\"row\">{}</th><td id=\"ro-reference-{}\">&ndash;</td>"
        "<td id=\"ro-new-{}\">&ndash;</td></tr>\n",
        label, id, id);
  };
  row(fmt::format("Linear RGB ({})", xml_escape(report.working_space)).c_str(), "rgb");
  row("CIE XYZ", "xyz");
  if (has_channel(report, "stokes.S1.Y")) {
    row("Stokes S<sub>0</sub>&hellip;S<sub>3</sub> (Y-weighted)", "stokes");
    row("DoLP", "dolp");
    row("AoLP (degrees)", "aolp");
  }
  return fmt::format(
      "<section id=\"pixel\" class=\"js-only\" aria-labelledby=\"pixel-heading\">\n<h2 "
      "id=\"pixel-heading\">Pixel</h2>\n"
      "<p id=\"ro-position\" aria-live=\"polite\">Point at an image for the values of a pixel; click to pin "
      "it "
      "(arrow keys then move it, Escape releases it).</p>\n"
      "<table class=\"readout\" id=\"readout\">\n<thead><tr><th scope=\"col\"></th><th "
      "scope=\"col\">Reference</th>"
      "<th scope=\"col\">New render</th></tr></thead>\n<tbody>\n{}</tbody>\n</table>\n"
      "<dl class=\"metrics\" id=\"readout-test\">"
      "<dt>z-score</dt><dd id=\"ro-z\">&ndash;</dd><dt>p-value</dt><dd id=\"ro-p\">&ndash;</dd>"
      "<dt>Fails the test</dt><dd id=\"ro-failing\">&ndash;</dd>"
      "<dt>&Delta;E<sub>00</sub></dt><dd id=\"ro-de00\">&ndash;</dd></dl>\n</section>\n",
      rows);
}

std::string spectrum_section() {
  return "<section id=\"spectrum-section\" class=\"js-only\" aria-labelledby=\"spectrum-heading\" hidden>\n"
         "<h2 id=\"spectrum-heading\">Spectrum of the pixel</h2>\n"
         "<svg id=\"spectrum\" viewBox=\"0 0 520 240\" role=\"img\" "
         "aria-labelledby=\"spectrum-heading\"></svg>\n"
         "<p class=\"legend\"><span class=\"line-key new\" aria-hidden=\"true\"></span> new render (solid, "
         "circles) "
         "<span class=\"line-key reference\" aria-hidden=\"true\"></span> reference (dashed, squares); "
         "radiance S<sub>0</sub> in W&middot;m<sup>&minus;2</sup>&middot;sr<sup>&minus;1</sup> per bin.</p>\n"
         "<details><summary>Values</summary><table class=\"readout\" "
         "id=\"spectrum-table\"></table></details>\n"
         "</section>\n";
}

}  // namespace

std::string scene_page(const SceneReport& report, const SceneImageFiles& images, const PixelGrid& grid,
                       const ScenePageLinks& links) {
  std::string html = html_page_start("ochre-regress: " + report.name, "scene-page");
  html += "<header>\n" + navigation(links);
  html +=
      fmt::format("<h1>{} {}</h1>\n", status_badge(report.passed() ? SceneStatus::kPass : SceneStatus::kFail),
                  xml_escape(report.name));
  if (!report.description.empty())
    html += fmt::format("<p class=\"description\">{}</p>\n", xml_escape(report.description));
  html +=
      "</header>\n<main>\n<section aria-labelledby=\"result-heading\">\n<h2 "
      "id=\"result-heading\">Result</h2>\n";
  html += metrics(report) + "</section>\n";
  html += viewer(report, images, grid);
  html += readout(report);
  html += spectrum_section();
  html += "</main>\n";
  return html + html_page_end(links.data_script, "report.js");
}

}  // namespace ochre
