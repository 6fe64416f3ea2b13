// ochre.relight (docs/python.md, "Relighting"): `ochre relight` for Python, the same checks and outputs.
#include "renderer/image/exr_reader.h"
#include "renderer/output/relight.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"
#include "tools/python/py_support.h"

namespace ochre::python {

namespace {

// {"torch": 0.5, "lamp": "off"}: a scale (a finite number >= 0, not a bool) or "off" / "on" per group.
std::vector<GroupChange> group_changes(const py::handle& groups) {
  std::vector<GroupChange> changes;
  if (groups.is_none()) return changes;
  if (!py::isinstance<py::dict>(groups))
    throw py::type_error("groups: expected a dict of group name -> scale, 'off' or 'on'");
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(groups)) {
    if (!py::isinstance<py::str>(key)) throw py::type_error("groups: the keys are group names (str)");
    const std::string name = key.cast<std::string>();
    if (py::isinstance<py::str>(value)) {
      changes.push_back(parse_group_change(name + ":" + value.cast<std::string>()));
    } else if (!py::isinstance<py::bool_>(value) &&
               (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))) {
      const double scale = value.cast<double>();
      if (!std::isfinite(scale) || scale < 0.0)
        throw InputError("groups['" + name + "']: a scale must be a finite number >= 0");
      changes.push_back({name, scale});
    } else {
      throw py::type_error("groups['" + name + "']: expected a number (the scale), 'off' or 'on'");
    }
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
        InputFileLog inputs;
        ExrImage image;
        {
          const InputFileLog::Recording recording(inputs);
          image = read_exr(file);
        }
        const ExrImage relit = relight(image, changes, file.string());
        const std::string exr_path = exr.is_none() ? "" : path_argument(exr, "exr").string();
        const std::string png_path = png.is_none() ? "" : path_argument(png, "png").string();
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
