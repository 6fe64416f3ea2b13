// Colour in ochre's Python module (docs/python.md): spectra (named, CSV, tables, blackbody, RGB
// upsampling) with their XYZ, CIELAB and RGB; CIEDE2000; ochre-diff's image metrics; display images; EXR
// files.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cfloat>
#include <climits>
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
    throw InputError("textures are not spectra: " + file.string());
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
  if (!PyUnicode_Check(illuminant.ptr()))
    wrong_type("illuminant", "a Spectrum or the name of one (str)", illuminant);
  return {from_object({{"name", string_argument(illuminant, "illuminant")}}, "illuminant")};
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

// A working space named by the argument `what` (rec709, acescg).
ColorSpace space_of(const py::object& value, const char* what) {
  try {
    return parse_color_space(string_argument(value, what));
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string(what) + ": " + e.what());
  }
}

// A linear RGB image (height, width, 3) of numbers, not empty (each side at most INT_MAX / 4 pixels).
RgbImage rgb_image(const py::object& image, const std::string& colorspace, const char* what) {
  const auto numbers = number_array(image, what);
  if (numbers.ndim() != 3 || numbers.shape(2) != 3)
    throw InputError(fmt::format("{}: expected shape (height, width, 3)", what));
  if (numbers.shape(0) < 1 || numbers.shape(1) < 1 || numbers.shape(0) > INT_MAX / 4 ||
      numbers.shape(1) > INT_MAX / 4)
    throw InputError(fmt::format("{}: the image is {}x{} pixels; each side must have 1 to {} pixels", what,
                                 numbers.shape(1), numbers.shape(0), INT_MAX / 4));
  auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(numbers);
  if (!a) wrong_type(what, "an array of numbers", image);
  RgbImage r;
  r.height = static_cast<int>(a.shape(0));
  r.width = static_cast<int>(a.shape(1));
  r.rgb.assign(a.data(), a.data() + a.size());
  r.working_space = colorspace;
  return r;
}

// Three finite numbers (a list, tuple or array), named `what` in errors.
std::array<double, 3> triple_argument(const py::object& value, const char* what, const char* expected) {
  const std::vector<py::object> items = items_argument(value, what, 3, expected);
  std::array<double, 3> c{};
  for (int i = 0; i < 3; ++i) c[i] = number_argument(items[i], fmt::format("{}[{}]", what, i));
  return c;
}

// A CIEDE2000 weighting factor: finite and > 0.
double weight_argument(const py::object& value, const char* what) {
  const double k = number_argument(value, what);
  if (!(k > 0.0)) throw InputError(fmt::format("{}: must be > 0 (got {})", what, k));
  return k;
}

// A wavelength at which a spectrum is evaluated: a finite number of nm (outside 360-830 nm spectra
// extrapolate as they were made to).
float finite_wavelength(double nm, const std::string& what) {
  if (!std::isfinite(nm) || std::abs(nm) > 1e30)
    throw InputError(fmt::format("{}: must be a finite wavelength in nm (got {})", what, nm));
  return static_cast<float>(nm);
}

// --ocio-config: "builtin", "none", "" or the path of a config (a regular file: docs/cli.md, "Input files").
std::string ocio_config_argument(const py::object& value) {
  const std::string config = string_argument(value, "ocio_config");  // "": $OCIO, else the built-in one
  if (!config.empty() && config != "builtin" && config != "none") (void)path_argument(value, "ocio_config");
  return config;
}

}  // namespace

void register_colour(py::module_& m) {
  py::class_<PySpectrum>(
      m, "Spectrum", "A spectrum: a function of wavelength in nm over 360-830 nm (docs/python.md, colour).")
      .def(py::init(
               [](const py::object& wavelengths, const py::object& values, const py::object& extrapolate) {
                 return PySpectrum{from_object({{"wavelengths", to_json(wavelengths, "wavelengths")},
                                                {"values", to_json(values, "values")},
                                                {"extrapolate", string_argument(extrapolate, "extrapolate")}},
                                               "spectrum")};
               }),
           py::arg("wavelengths"), py::arg("values"), py::arg("extrapolate") = py::str("clamp"),
           "A table: values at increasing wavelengths (nm), linear in between; outside the table \"clamp\" "
           "holds the end values, \"zero\" gives 0")
      .def_static(
          "named",
          [](const py::object& name, const py::object& scale) {
            return PySpectrum{from_object(
                {{"name", string_argument(name, "name")}, {"scale", number_argument(scale, "scale")}},
                "spectrum")};
          },
          py::arg("name"), py::arg("scale") = py::float_(1.0),
          "A named spectrum: D65, A, E (luminance 1 before scale), cie_x, cie_y, cie_z, metal-Au-eta, ...")
      .def_static(
          "blackbody",
          [](const py::object& kelvin, const py::object& scale) {
            return PySpectrum{from_object({{"blackbody", number_argument(kelvin, "kelvin")},
                                           {"scale", number_argument(scale, "scale")}},
                                          "spectrum")};
          },
          py::arg("kelvin"), py::arg("scale") = py::float_(1.0),
          "Planck's law at `kelvin`, normalised to luminance 1, times scale")
      .def_static(
          "from_csv",
          [](const py::object& path, const py::object& column, const py::object& extrapolate) {
            nlohmann::json j = {{"file", path_argument(path, "path").string()},
                                {"extrapolate", string_argument(extrapolate, "extrapolate")}};
            if (!column.is_none()) j["column"] = string_argument(column, "column");
            return PySpectrum{from_object(j, "spectrum")};
          },
          py::arg("path"), py::arg("column") = py::none(), py::arg("extrapolate") = py::str("clamp"),
          "A CSV file: a header, wavelength (nm) then value columns (docs/scene-format.md, spectra)")
      .def_static(
          "from_rgb",
          [](const py::object& rgb_, const py::object& kind_) -> PySpectrum {
            const std::array<double, 3> c = triple_argument(rgb_, "rgb", "(r, g, b)");
            const std::string kind = string_argument(kind_, "kind");
            for (double v : c)
              if (!(v >= 0.0) || v > FLT_MAX) throw InputError("rgb: components must be finite and >= 0");
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
          py::arg("rgb"), py::arg("kind") = py::str("reflectance"),
          "Linear Rec.709 RGB upsampled as ochre does (Jakob & Hanika 2019): a reflectance in [0, 1], an "
          "illuminant (D65 times an unbounded spectrum) or unbounded")
      .def_static(
          "constant",
          [](const py::object& value) {
            const double v = number_argument(value, "value");
            if (std::abs(v) > FLT_MAX)
              throw InputError(fmt::format("value: {} overflows single precision", v));
            return PySpectrum{std::make_shared<ConstantSpectrum>(static_cast<float>(v))};
          },
          py::arg("value"))
      .def(
          "__call__",
          [](const PySpectrum& s, const py::object& wavelengths) -> py::object {
            if (PyFloat_Check(wavelengths.ptr()) ||
                (PyLong_Check(wavelengths.ptr()) && !PyBool_Check(wavelengths.ptr())))
              return py::float_(
                  s.s->eval(finite_wavelength(number_argument(wavelengths, "wavelengths"), "wavelengths")));
            const auto a = number_array(wavelengths, "wavelengths");
            py::array_t<double> out(a.request().shape);
            for (py::ssize_t i = 0; i < a.size(); ++i)
              out.mutable_data()[i] =
                  s.s->eval(finite_wavelength(a.data()[i], fmt::format("wavelengths[{}]", i)));
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
          py::arg("illuminant") = py::str("D65"),
          "CIELAB of the spectrum as a reflectance under the illuminant, white = its white")
      .def(
          "to_rgb",
          [](const PySpectrum& s, const py::object& space, const py::object& illuminant) {
            const ColorSpace working = space_of(space, "space");
            const XYZ xyz = illuminant.is_none() ? spectrum_to_xyz(*s.s)
                                                 : reflected_xyz(*s.s, illuminant_of(illuminant).s);
            const RGB rgb = xyz_to_rgb(xyz, working);
            return triple(rgb.r, rgb.g, rgb.b);
          },
          py::arg("space") = py::str("rec709"), py::arg("illuminant") = py::none(),
          "Linear RGB in ochre's working space (rec709 or acescg) of to_xyz(illuminant); no chromatic "
          "adaptation "
          "(a white under illuminant A is not (1, 1, 1))")
      .def_property_readonly("max_value", [](const PySpectrum& s) { return s.s->max_value(); })
      .def_property_readonly("luminance", [](const PySpectrum& s) { return spectrum_to_xyz(*s.s).y; });

  m.def(
      "xyz_to_lab",
      [](const py::object& xyz_, const py::object& white_) {
        const std::array<double, 3> xyz = triple_argument(xyz_, "xyz", "(X, Y, Z)"),
                                    white = triple_argument(white_, "white", "(X, Y, Z)");
        for (double v : white)
          if (!(v > 0.0)) throw InputError("white: its X, Y and Z must be > 0");
        const Lab lab = xyz_to_lab({xyz[0], xyz[1], xyz[2]}, {white[0], white[1], white[2]});
        return triple(lab.L, lab.a, lab.b);
      },
      py::arg("xyz"), py::arg("white"), "CIE 1976 L*a*b* of xyz relative to the white (CIE 15:2004)");
  m.def(
      "_ciede2000",
      [](const py::object& first, const py::object& second, const py::object& kl_, const py::object& kc_,
         const py::object& kh_) {
        const double kl = weight_argument(kl_, "kl"), kc = weight_argument(kc_, "kc"),
                     kh = weight_argument(kh_, "kh");
        const auto a = rows_of_3(first, "lab1"), b = rows_of_3(second, "lab2");
        if (a.shape(0) != b.shape(0)) throw InputError("lab1, lab2: need the same number of colours");
        py::array_t<double> de(a.shape(0));
        for (py::ssize_t i = 0; i < a.shape(0); ++i)
          de.mutable_data()[i] =
              ciede2000({a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]},
                        {b.data()[3 * i], b.data()[3 * i + 1], b.data()[3 * i + 2]}, kl, kc, kh);
        return de;
      },
      py::arg("lab1"), py::arg("lab2"), py::arg("kl") = py::float_(1.0), py::arg("kc") = py::float_(1.0),
      py::arg("kh") = py::float_(1.0));
  m.def(
      "image_metrics",
      [](const py::object& test, const py::object& reference, const py::object& colorspace_,
         const py::object& ocio_config_) {
        (void)space_of(colorspace_, "colorspace");
        const std::string colorspace = string_argument(colorspace_, "colorspace"),
                          ocio_config = ocio_config_argument(ocio_config_);
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
      py::arg("test"), py::arg("reference"), py::arg("colorspace") = py::str("rec709"),
      py::arg("ocio_config") = py::str("none"),
      "ochre-diff's metrics of two linear RGB images (height, width, 3); the second is the reference "
      "(docs/tools.md, ochre-diff)");
  m.def(
      "to_display",
      [](const py::object& image, const py::object& colorspace_, const py::object& ocio_config,
         const py::object& display, const py::object& view, const py::object& exposure_) {
        (void)space_of(colorspace_, "colorspace");
        const std::string colorspace = string_argument(colorspace_, "colorspace");
        // As --exposure and output.exposure (docs/cli.md).
        const double exposure = number_argument(exposure_, "exposure");
        if (exposure < -64.0 || exposure > 64.0)
          throw InputError(fmt::format("exposure: must be in [-64, 64] stops (got {})", exposure));
        DisplayOptions o;
        o.ocio_config = ocio_config_argument(ocio_config);
        o.display = string_argument(display, "display");
        o.view = string_argument(view, "view");
        const RgbImage a = rgb_image(image, colorspace, "rgb");
        o.working_space = colorspace;
        o.exposure_stops = static_cast<float>(exposure);
        const std::vector<std::uint8_t> rgb8 = to_display_rgb8(a.width, a.height, a.rgb, o);
        py::array_t<std::uint8_t> out({py::ssize_t(a.height), py::ssize_t(a.width), py::ssize_t(3)});
        std::copy(rgb8.begin(), rgb8.end(), out.mutable_data());
        return out;
      },
      py::arg("rgb"), py::kw_only(), py::arg("colorspace") = py::str("rec709"),
      py::arg("ocio_config") = py::str("builtin"), py::arg("display") = py::str(""),
      py::arg("view") = py::str(""), py::arg("exposure") = py::float_(0.0),
      "8-bit display RGB (height, width, 3) of linear RGB through OpenColorIO, as ochre render --png");
  m.def(
      "read_exr", [](const py::object& path) { return exr_to_python(read_exr(path_argument(path, "path"))); },
      py::arg("path"),
      "(channels, attributes): every channel as (height, width) float32, and the string attributes");
}

}  // namespace ochre::python
