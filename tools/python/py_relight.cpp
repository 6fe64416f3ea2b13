// ochre.relight (docs/python.md, "Relighting"): `ochre relight` for Python, the same checks and outputs.
#include <fmt/format.h>

#include <mutex>

#include "renderer/image/exr_reader.h"
#include "renderer/output/relight.h"
#include "renderer/output/relight_page.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"
#include "tools/python/py_support.h"

namespace ochre::python {

namespace {

// {"torch": 0.5, "lamp": "off", "fire": "scale=2,cct=1500"}: per group a scale (a finite number >= 0: int,
// float or numpy number, never bool) or the changes of `ochre relight --group NAME:...` as a str. TypeError
// naming the argument for a value of another type (docs/python.md, "Errors"). Returns (where, --group text)
// pairs, parsed by parse_group_text while the input files are recorded (a CSV spectrum is an input).
std::vector<std::pair<std::string, std::string>> group_texts(const py::handle& groups) {
  std::vector<std::pair<std::string, std::string>> texts;
  if (groups.is_none()) return texts;
  if (!PyDict_Check(groups.ptr()))
    wrong_type("groups", "a dict of group name -> scale, 'off', 'on' or changes ('scale=S,cct=T')", groups);
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(groups)) {
    if (!PyUnicode_Check(key.ptr())) wrong_type("groups", "str keys (group names)", key);
    const std::string name = string_argument(key, "groups");
    const std::string where = fmt::format("groups['{}']", name);
    if (PyUnicode_Check(value.ptr())) {
      texts.emplace_back(where, name + ":" + string_argument(value, where));
      continue;
    }
    double scale = 0.0;
    try {
      scale = number_argument(value, where);
    } catch (const py::type_error&) {
      wrong_type(where, "a number (the scale), 'off', 'on' or changes ('scale=S,cct=T')", value);
    }
    if (scale < 0.0)
      throw InputError(fmt::format("{}: a scale must be a finite number >= 0 (got {})", where, scale));
    texts.emplace_back(where, fmt::format("{}:scale={}", name, scale));  // shortest exact decimal
  }
  return texts;
}

// The changes of group_texts, each InputError naming the dict entry.
std::vector<GroupChange> group_changes(const std::vector<std::pair<std::string, std::string>>& texts) {
  std::vector<GroupChange> changes;
  for (const auto& [where, text] : texts) try {
      changes.push_back(parse_group_change(text));
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", where, e.what()));
    }
  return changes;
}

}  // namespace

void register_relight(py::module_& m) {
  m.def(
      "relight",
      [](const py::object& render, const py::object& groups, const py::object& exr, const py::object& png,
         const py::object& html) {
        const std::vector<std::pair<std::string, std::string>> texts = group_texts(groups);
        const std::filesystem::path file = path_argument(render, "render");
        const std::string exr_path = exr.is_none() ? "" : path_argument(exr, "exr").string();
        const std::string png_path = png.is_none() ? "" : path_argument(png, "png").string();
        const std::filesystem::path html_dir = html.is_none() ? "" : path_argument(html, "html");
        if (!html_dir.empty()) check_relight_page_destination(html_dir);  // before anything is written
        InputFileLog inputs;
        ExrImage image;
        std::vector<GroupChange> changes;
        {
          py::gil_scoped_release release;
          const std::lock_guard lock(input_recording_mutex());
          const InputFileLog::Recording recording(inputs);
          changes = group_changes(texts);
          image = read_exr(file);
        }
        const ExrImage relit = relight(image, changes, file.string());
        const DisplayOptions display = recorded_display(image, file.string());
        if (!exr_path.empty() || !png_path.empty()) write_relit(relit, display, exr_path, png_path, inputs);
        // The page starts from the render as it is, as `ochre relight --html` (docs/lights.md).
        if (!html_dir.empty()) write_relight_page(image, display, file.string(), html_dir);
        return exr_to_python(relit);
      },
      py::arg("render"), py::kw_only(), py::arg("groups") = py::none(), py::arg("exr") = py::none(),
      py::arg("png") = py::none(), py::arg("html") = py::none(),
      "(channels, attributes) of a render with light groups recombined with new scales and spectra, as ochre "
      "relight; writes exr / png when given, and the relighting page html/index.html (docs/lights.md)");
}

}  // namespace ochre::python
