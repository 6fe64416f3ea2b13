// ochre.relight (docs/python.md, "Relighting"): `ochre relight` for Python, the same checks and outputs.
#include <fmt/format.h>

#include <mutex>

#include "renderer/image/exr_reader.h"
#include "renderer/output/relight.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"
#include "tools/python/py_support.h"

namespace ochre::python {

namespace {

// {"torch": 0.5, "lamp": "off"}: a scale (a finite number >= 0: int, float or numpy number, never bool) or
// "off" / "on" per group; TypeError naming the argument for a value of another type, InputError naming the
// group for a bad value (docs/python.md, "Errors").
std::vector<GroupChange> group_changes(const py::handle& groups) {
  std::vector<GroupChange> changes;
  if (groups.is_none()) return changes;
  if (!PyDict_Check(groups.ptr()))
    wrong_type("groups", "a dict of group name -> scale, 'off' or 'on'", groups);
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(groups)) {
    if (!PyUnicode_Check(key.ptr())) wrong_type("groups", "str keys (group names)", key);
    const std::string name = string_argument(key, "groups");
    const std::string where = fmt::format("groups['{}']", name);
    if (PyUnicode_Check(value.ptr())) {
      // The words of NAME:off and NAME:on; anything else (a change of spectrum, "scale=2") is parsed as
      // ochre relight parses --group, for its message.
      const std::string word = string_argument(value, where);
      if (word == "off" || word == "on") {
        changes.push_back({name, word == "off" ? 0.0 : 1.0});
        continue;
      }
      try {
        changes.push_back(parse_group_change(name + ":" + word));
      } catch (const InputError& e) {
        throw InputError(fmt::format("{}: {}", where, e.what()));
      }
      continue;
    }
    double scale = 0.0;
    try {
      scale = number_argument(value, where);
    } catch (const py::type_error&) {
      wrong_type(where, "a number (the scale), 'off' or 'on'", value);
    }
    if (scale < 0.0)
      throw InputError(fmt::format("{}: a scale must be a finite number >= 0 (got {})", where, scale));
    changes.push_back({name, scale});
  }
  return changes;
}

}  // namespace

void register_relight(py::module_& m) {
  m.def(
      "relight",
      [](const py::object& render, const py::object& groups, const py::object& exr, const py::object& png) {
        const std::vector<GroupChange> changes = group_changes(groups);
        const std::filesystem::path file = path_argument(render, "render");
        const std::string exr_path = exr.is_none() ? "" : path_argument(exr, "exr").string();
        const std::string png_path = png.is_none() ? "" : path_argument(png, "png").string();
        InputFileLog inputs;
        ExrImage image;
        {
          py::gil_scoped_release release;
          const std::lock_guard lock(input_recording_mutex());
          const InputFileLog::Recording recording(inputs);
          image = read_exr(file);
        }
        const ExrImage relit = relight(image, changes, file.string());
        if (!exr_path.empty() || !png_path.empty())
          write_relit(relit, recorded_display(image, file.string()), exr_path, png_path, inputs);
        return exr_to_python(relit);
      },
      py::arg("render"), py::kw_only(), py::arg("groups") = py::none(), py::arg("exr") = py::none(),
      py::arg("png") = py::none(),
      "(channels, attributes) of a render with light groups recombined with new scales, as ochre relight; "
      "writes exr / png when given");
}

}  // namespace ochre::python
