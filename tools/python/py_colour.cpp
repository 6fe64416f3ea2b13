// Colour in ochre's Python module (docs/python.md): spectra (named, CSV, tables, blackbody, RGB
// upsampling) with their XYZ, CIELAB and RGB; CIEDE2000; ochre-diff's image metrics; display images; EXR
// files.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>

#include "materials/nodes/resource_resolver.h"
#include "materials/nodes/spectrum_source.h"
#include "renderer/compare/image_metrics.h"
#include "renderer/image/display_image.h"
#include "renderer/image/exr_reader.h"
#include "spectra/cie.h"
#include "spectra/ciede2000.h"
#include "spectra/color_space.h"
#include "spectra/constant_spectrum.h"
#include "spectra/input_error.h"
#include "spectra/negative_value.h"
#include "spectra/product_spectrum.h"
#include "spectra/rgb_spectrum.h"
#include "tools/python/py_support.h"

namespace ochre::python {

namespace {

// Files of spectra resolve against the current directory, as Python's own open() does.
class CurrentDirectory final : public ResourceResolver {
 public:
  std::filesystem::path resolve(const std::string& path) const override {
    return std::filesystem::absolute(std::filesystem::path(path));
  }
  int texture(const std::filesystem::path& file, const std::string&, int&) override {
    throw std::runtime_error("textures are not spectra: " + file.string());
  }
};

// A spectrum object of the scene format ({"name": ...}, {"file": ...}, {"wavelengths": ...}, {"blackbody":
// ...}), with the same checks and messages as in a scene.
SpectrumPtr from_object(const nlohmann::json& j, const char* what) {
  try {
    return spectrum_from_object(j, CurrentDirectory());
  } catch (const SpectrumObjectError& e) {
    throw InputError(fmt::format("{}{}: {}", what, e.key.empty() ? "" : "." + e.key, e.what()));
  }
}

struct PySpectrum {
  SpectrumPtr s;
};

PySpectrum illuminant_of(const py::object& illuminant) {
  if (py::isinstance<PySpectrum>(illuminant)) return illuminant.cast<PySpectrum>();
  return {from_object({{"name", illuminant.cast<std::string>()}}, "illuminant")};
}

// XYZ of a reflectance under `illuminant`, Y = 1 for a perfect white (CIE 15:2004, section 7).
XYZ reflected_xyz(const Spectrum& reflectance, const SpectrumPtr& illuminant) {
  const XYZ white = spectrum_to_xyz(*illuminant);
  if (!(white.y > 0.0f)) throw InputError("illuminant: its luminance is 0");
  const XYZ xyz = spectrum_to_xyz(
      ProductSpectrum(std::shared_ptr<const Spectrum>(&reflectance, [](const Spectrum*) {}), illuminant));
  return {xyz.x / white.y, xyz.y / white.y, xyz.z / white.y};
}

py::array_t<double> triple(double a, double b, double c) {
  py::array_t<double> r(3);
  r.mutable_data()[0] = a;
  r.mutable_data()[1] = b;
  r.mutable_data()[2] = c;
  return r;
}

ColorSpace space_of(const std::string& name) {
  try {
    return parse_color_space(name);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("space: ") + e.what());
  }
}

RgbImage rgb_image(const py::object& image, const std::string& colorspace, const char* what) {
  auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(image);
  if (!a || a.ndim() != 3 || a.shape(2) != 3)
    throw py::value_error(fmt::format("{}: expected shape (height, width, 3)", what));
  RgbImage r;
  r.height = static_cast<int>(a.shape(0));
  r.width = static_cast<int>(a.shape(1));
  r.rgb.assign(a.data(), a.data() + a.size());
  r.working_space = colorspace;
  return r;
}

}  // namespace

void register_colour(py::module_& m) {
  py::class_<PySpectrum>(
      m, "Spectrum", "A spectrum: a function of wavelength in nm over 360-830 nm (docs/python.md, colour).")
      .def(py::init(
               [](const py::object& wavelengths, const py::object& values, const std::string& extrapolate) {
                 return PySpectrum{from_object({{"wavelengths", to_json(wavelengths, "wavelengths")},
                                                {"values", to_json(values, "values")},
                                                {"extrapolate", extrapolate}},
                                               "spectrum")};
               }),
           py::arg("wavelengths"), py::arg("values"), py::arg("extrapolate") = "clamp",
           "A table: values at increasing wavelengths (nm), linear in between; outside the table \"clamp\" "
           "holds the end values, \"zero\" gives 0")
      .def_static(
          "named",
          [](const std::string& name, double scale) {
            return PySpectrum{from_object({{"name", name}, {"scale", scale}}, "spectrum")};
          },
          py::arg("name"), py::arg("scale") = 1.0,
          "A named spectrum: D65, A, E (luminance 1 before scale), cie_x, cie_y, cie_z, metal-Au-eta, ...")
      .def_static(
          "blackbody",
          [](double kelvin, double scale) {
            return PySpectrum{from_object({{"blackbody", kelvin}, {"scale", scale}}, "spectrum")};
          },
          py::arg("kelvin"), py::arg("scale") = 1.0,
          "Planck's law at `kelvin`, normalised to luminance 1, times scale")
      .def_static(
          "from_csv",
          [](const py::object& path, const py::object& column, const std::string& extrapolate) {
            nlohmann::json j = {{"file", to_path(path).string()}, {"extrapolate", extrapolate}};
            if (!column.is_none()) j["column"] = column.cast<std::string>();
            return PySpectrum{from_object(j, "spectrum")};
          },
          py::arg("path"), py::arg("column") = py::none(), py::arg("extrapolate") = "clamp",
          "A CSV file: a header, wavelength (nm) then value columns (docs/scene-format.md, spectra)")
      .def_static(
          "from_rgb",
          [](const std::array<double, 3>& c, const std::string& kind) -> PySpectrum {
            for (double v : c)
              if (!(v >= 0.0) || !std::isfinite(v))
                throw InputError("rgb: components must be finite and >= 0");
            const RGB rgb{static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
            if (kind == "reflectance") {
              if (c[0] > 1 || c[1] > 1 || c[2] > 1)
                throw InputError("rgb: a reflectance's components must be <= 1");
              return {std::make_shared<RGBAlbedoSpectrum>(rgb)};
            }
            if (kind == "illuminant") return {std::make_shared<RGBIlluminantSpectrum>(rgb)};
            if (kind == "unbounded") return {std::make_shared<RGBUnboundedSpectrum>(rgb)};
            throw InputError(
                fmt::format("kind: unknown '{}' (known: reflectance, illuminant, unbounded)", kind));
          },
          py::arg("rgb"), py::arg("kind") = "reflectance",
          "Linear Rec.709 RGB upsampled as ochre does (Jakob & Hanika 2019): a reflectance in [0, 1], an "
          "illuminant (D65 times an unbounded spectrum) or unbounded")
      .def_static(
          "constant",
          [](double v) {
            if (!std::isfinite(v)) throw InputError("constant: must be finite");
            return PySpectrum{std::make_shared<ConstantSpectrum>(static_cast<float>(v))};
          },
          py::arg("value"))
      .def(
          "__call__",
          [](const PySpectrum& s, const py::object& wavelengths) -> py::object {
            if (py::isinstance<py::float_>(wavelengths) || py::isinstance<py::int_>(wavelengths))
              return py::float_(s.s->eval(wavelengths.cast<float>()));
            auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(wavelengths);
            if (!a) throw py::type_error("wavelengths: expected numbers");
            py::array_t<double> out(a.request().shape);
            for (py::ssize_t i = 0; i < a.size(); ++i)
              out.mutable_data()[i] = s.s->eval(static_cast<float>(a.data()[i]));
            return out;
          },
          py::arg("wavelengths"), "The values at the given wavelengths (nm)")
      .def(
          "to_xyz",
          [](const PySpectrum& s, const py::object& illuminant) {
            const XYZ xyz = illuminant.is_none() ? spectrum_to_xyz(*s.s)
                                                 : reflected_xyz(*s.s, illuminant_of(illuminant).s);
            return triple(xyz.x, xyz.y, xyz.z);
          },
          py::arg("illuminant") = py::none(),
          "CIE 1931 XYZ (2 degree observer, 1 nm over 360-830 nm). Without an illuminant, of the spectrum as "
          "light (Y = luminance; a constant 1 has Y = 1); with one (a Spectrum or a name such as \"D65\"), "
          "of "
          "the spectrum as a reflectance under it (a perfect white has Y = 1)")
      .def(
          "to_lab",
          [](const PySpectrum& s, const py::object& illuminant) {
            const PySpectrum light = illuminant_of(illuminant);
            const XYZ white = reflected_xyz(ConstantSpectrum(1.0f), light.s),
                      xyz = reflected_xyz(*s.s, light.s);
            const Lab lab = xyz_to_lab({xyz.x, xyz.y, xyz.z}, {white.x, white.y, white.z});
            return triple(lab.L, lab.a, lab.b);
          },
          py::arg("illuminant") = "D65",
          "CIELAB of the spectrum as a reflectance under the illuminant, white = its white")
      .def(
          "to_rgb",
          [](const PySpectrum& s, const std::string& space, const py::object& illuminant) {
            const XYZ xyz = illuminant.is_none() ? spectrum_to_xyz(*s.s)
                                                 : reflected_xyz(*s.s, illuminant_of(illuminant).s);
            const RGB rgb = xyz_to_rgb(xyz, space_of(space));
            return triple(rgb.r, rgb.g, rgb.b);
          },
          py::arg("space") = "rec709", py::arg("illuminant") = py::none(),
          "Linear RGB in ochre's working space (rec709 or acescg) of to_xyz(illuminant); no chromatic "
          "adaptation "
          "(a white under illuminant A is not (1, 1, 1))")
      .def_property_readonly("max_value", [](const PySpectrum& s) { return s.s->max_value(); })
      .def_property_readonly("luminance", [](const PySpectrum& s) { return spectrum_to_xyz(*s.s).y; });

  m.def(
      "xyz_to_lab",
      [](const std::array<double, 3>& xyz, const std::array<double, 3>& white) {
        const Lab lab = xyz_to_lab({xyz[0], xyz[1], xyz[2]}, {white[0], white[1], white[2]});
        return triple(lab.L, lab.a, lab.b);
      },
      py::arg("xyz"), py::arg("white"), "CIE 1976 L*a*b* of xyz relative to the white (CIE 15:2004)");
  m.def(
      "_ciede2000",
      [](const py::object& first, const py::object& second, double kl, double kc, double kh) {
        const auto a = rows_of_3(first, "lab1"), b = rows_of_3(second, "lab2");
        if (a.shape(0) != b.shape(0)) throw py::value_error("lab1, lab2: need the same number of colours");
        py::array_t<double> de(a.shape(0));
        for (py::ssize_t i = 0; i < a.shape(0); ++i)
          de.mutable_data()[i] =
              ciede2000({a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]},
                        {b.data()[3 * i], b.data()[3 * i + 1], b.data()[3 * i + 2]}, kl, kc, kh);
        return de;
      },
      py::arg("lab1"), py::arg("lab2"), py::arg("kl") = 1.0, py::arg("kc") = 1.0, py::arg("kh") = 1.0);
  m.def(
      "image_metrics",
      [](const py::object& test, const py::object& reference, const std::string& colorspace,
         const std::string& ocio_config) {
        const RgbImage a = rgb_image(test, colorspace, "test"),
                       b = rgb_image(reference, colorspace, "reference");
        check_comparable(a, b, "test", "reference");
        DisplayOptions display;
        display.ocio_config = ocio_config;
        display.working_space = colorspace;
        const ImageComparison c = compare_images(a, b, display);
        py::dict d;
        d["rmse"] = c.metrics.rmse;
        d["relmse"] = c.metrics.relmse;
        d["max_error"] = c.metrics.max_error;
        d["max_error_at"] =
            py::make_tuple(c.metrics.max_error_x, c.metrics.max_error_y, c.metrics.max_error_channel);
        d["mean_de00"] = c.metrics.mean_de00;
        d["max_de00"] = c.metrics.max_de00;
        d["de00_map"] = float_array(c.maps.de00, {b.height, b.width});
        return d;
      },
      py::arg("test"), py::arg("reference"), py::arg("colorspace") = "rec709",
      py::arg("ocio_config") = "none",
      "ochre-diff's metrics of two linear RGB images (height, width, 3); the second is the reference "
      "(docs/tools.md, ochre-diff)");
  m.def(
      "to_display",
      [](const py::object& image, const std::string& colorspace, const std::string& ocio_config,
         const std::string& display, const std::string& view, float exposure) {
        const RgbImage a = rgb_image(image, colorspace, "image");
        DisplayOptions o;
        o.ocio_config = ocio_config;
        o.display = display;
        o.view = view;
        o.working_space = colorspace;
        o.exposure_stops = exposure;
        const std::vector<std::uint8_t> rgb8 = to_display_rgb8(a.width, a.height, a.rgb, o);
        py::array_t<std::uint8_t> out({py::ssize_t(a.height), py::ssize_t(a.width), py::ssize_t(3)});
        std::copy(rgb8.begin(), rgb8.end(), out.mutable_data());
        return out;
      },
      py::arg("rgb"), py::kw_only(), py::arg("colorspace") = "rec709", py::arg("ocio_config") = "builtin",
      py::arg("display") = "", py::arg("view") = "", py::arg("exposure") = 0.0f,
      "8-bit display RGB (height, width, 3) of linear RGB through OpenColorIO, as ochre render --png");
  m.def(
      "read_exr", [](const py::object& path) { return exr_to_python(read_exr(to_path(path))); },
      py::arg("path"),
      "(channels, attributes): every channel as (height, width) float32, and the string attributes");
}

}  // namespace ochre::python
