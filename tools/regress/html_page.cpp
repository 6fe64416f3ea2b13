#include "tools/regress/html_page.h"

#include <fmt/format.h>

#include <cmath>

#include "tools/regress/junit_report.h"

namespace ochre {

std::string html_page_start(const std::string& title, const std::string& body_class) {
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta name=\"generator\" content=\"ochre-regress\">\n<title>{}</title>\n"
      "<link rel=\"stylesheet\" href=\"report.css\">\n</head>\n<body class=\"{}\">\n",
      xml_escape(title), body_class);
}

std::string html_page_end(const std::string& first_script, const std::string& second_script) {
  std::string html = fmt::format("<script src=\"{}\"></script>\n", xml_escape(first_script));
  if (!second_script.empty())
    html += fmt::format("<script src=\"{}\"></script>\n", xml_escape(second_script));
  return html + "</body>\n</html>\n";
}

std::string status_icon(SceneStatus status) {
  const char* shape = "";
  switch (status) {
    case SceneStatus::kPass:  // a tick in a circle
      shape = "<circle cx=\"8\" cy=\"8\" r=\"7\"/><path d=\"M4.5 8.5l2.3 2.3 4.7-5\" class=\"mark\"/>";
      break;
    case SceneStatus::kFail:  // a cross in a square
      shape =
          "<rect x=\"1\" y=\"1\" width=\"14\" height=\"14\" rx=\"2\"/><path d=\"M5 5l6 6M11 5l-6 6\" "
          "class=\"mark\"/>";
      break;
    case SceneStatus::kSkipped:
    case SceneStatus::kAbsent:  // a dash
      shape = "<path d=\"M4 8h8\" class=\"mark\"/>";
      break;
  }
  return fmt::format(
      "<svg class=\"icon\" viewBox=\"0 0 16 16\" width=\"16\" height=\"16\" aria-hidden=\"true\" "
      "focusable=\"false\">{}</svg>",
      shape);
}

const char* status_word(SceneStatus status) {
  switch (status) {
    case SceneStatus::kPass:
      return "PASS";
    case SceneStatus::kFail:
      return "FAIL";
    case SceneStatus::kSkipped:
      return "SKIP";
    case SceneStatus::kAbsent:
      return "not run";
  }
  return "";
}

std::string status_badge(SceneStatus status) {
  static constexpr const char* kClass[] = {"pass", "fail", "skip", "absent"};
  return fmt::format("<span class=\"status {}\">{}<span class=\"word\">{}</span></span>",
                     kClass[static_cast<int>(status)], status_icon(status), status_word(status));
}

std::string format_significant(double value) {
  if (std::isnan(value)) return "NaN";
  return fmt::format("{:.3g}", value);
}

std::string format_seconds(double seconds) {
  return seconds < 10.0 ? fmt::format("{:.2f} s", seconds) : fmt::format("{:.1f} s", seconds);
}

std::string format_time_ratio(std::optional<double> ratio) {
  if (!ratio || !std::isfinite(*ratio)) return "";
  return fmt::format("&times;{:.2f}", *ratio);
}

}  // namespace ochre
