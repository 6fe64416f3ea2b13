// ochre.material: a material of the scene format evaluated as a BSDF over numpy arrays, as ochre-brdf does
// (docs/python.md, docs/tools.md): eval, the Mueller matrix, sample and the directional albedo.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "materials/core/pcg32.h"
#include "materials/lobes/directional_albedo.h"
#include "renderer/util/memory_budget.h"
#include "spectra/input_error.h"
#include "spectra/sampled_wavelengths.h"
#include "tools/brdf/material_probe.h"
#include "tools/python/py_support.h"

namespace ochre::python {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Row i of an (n, 3) array as a unit vector; a zero or non-finite row is bad input naming it.
Vec3 direction(const Array& a, py::ssize_t i, const char* what) {
  const double* p = a.data() + 3 * i;
  const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  if (!(len > 0.0) || !std::isfinite(len))
    throw InputError(fmt::format("{}[{}]: a direction must be a non-zero finite vector (got [{}, {}, {}])",
                                 what, i, p[0], p[1], p[2]));
  return {static_cast<float>(p[0] / len), static_cast<float>(p[1] / len), static_cast<float>(p[2] / len)};
}

// The indices 0..n-1 sorted by wavelength, so that the material is evaluated once per wavelength.
std::vector<py::ssize_t> by_wavelength(const Array& lambda) {
  std::vector<py::ssize_t> order(static_cast<size_t>(lambda.shape(0)));
  std::iota(order.begin(), order.end(), py::ssize_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](py::ssize_t a, py::ssize_t b) { return lambda.data()[a] < lambda.data()[b]; });
  return order;
}

void same_length(py::ssize_t n, const Array& a, const char* what) {
  if (a.shape(0) != n) throw InputError(fmt::format("{}: expected {} rows, got {}", what, n, a.shape(0)));
}

// Lets Ctrl-C stop a long evaluation (KeyboardInterrupt) every 4096 rows.
void check_signals(py::ssize_t row) {
  if (row % 4096 == 4095 && PyErr_CheckSignals() != 0) throw py::error_already_set();
}

// A wavelength in nm inside the spectral range, named in the error as `what` (e.g. "wavelengths[3]").
float wavelength_at(double lambda_nm, const std::string& what) {
  if (!(lambda_nm >= kLambdaMin && lambda_nm <= kLambdaMax))
    throw InputError(fmt::format("{}: {} nm is outside the spectral range [{}, {}] nm", what, lambda_nm,
                                 kLambdaMin, kLambdaMax));
  return static_cast<float>(lambda_nm);
}

class PyMaterial {
 public:
  explicit PyMaterial(std::unique_ptr<MaterialProbe> probe) : probe_(std::move(probe)) {}

  // f(wi, wo) (Mueller M00, 1/sr, no cosine) of the non-delta lobes, per row.
  py::array_t<double> eval(const py::object& wi_, const py::object& wo_, const py::object& lambda_) {
    const Array wi = rows_of_3(wi_, "wi"), wo = rows_of_3(wo_, "wo"),
                lambda = vector_of(lambda_, "wavelengths");
    const py::ssize_t n = wi.shape(0);
    same_length(n, wo, "wo");
    same_length(n, lambda, "wavelengths");
    py::array_t<double> f(n);
    double* out = f.mutable_data();
    for (py::ssize_t i : by_wavelength(lambda)) {
      const Closure& c = closure_at(lambda, i);
      out[i] = c.eval(direction(wo, i, "wo"), direction(wi, i, "wi"), probe_->wavelengths())[0];
      check_signals(i);
    }
    return f;
  }

  // The Mueller matrices (n, 4, 4) with their reference axes in_x (light arriving along -wi) and out_x
  // (light leaving along wo), docs/polarization.md.
  py::dict mueller(const py::object& wi_, const py::object& wo_, const py::object& lambda_) {
    const Array wi = rows_of_3(wi_, "wi"), wo = rows_of_3(wo_, "wo"),
                lambda = vector_of(lambda_, "wavelengths");
    const py::ssize_t n = wi.shape(0);
    same_length(n, wo, "wo");
    same_length(n, lambda, "wavelengths");
    py::array_t<double> m({n, py::ssize_t{4}, py::ssize_t{4}}), in_x({n, py::ssize_t{3}}),
        out_x({n, py::ssize_t{3}});
    for (py::ssize_t i : by_wavelength(lambda)) {
      check_signals(i);
      const Closure& c = closure_at(lambda, i);
      const MuellerResponse r =
          c.eval_mueller(direction(wo, i, "wo"), direction(wi, i, "wi"), probe_->wavelengths());
      for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) m.mutable_data()[16 * i + 4 * row + col] = r.m[0](row, col);
      const float axes[6] = {r.in_x.x, r.in_x.y, r.in_x.z, r.out_x.x, r.out_x.y, r.out_x.z};
      std::copy(axes, axes + 3, in_x.mutable_data() + 3 * i);
      std::copy(axes + 3, axes + 6, out_x.mutable_data() + 3 * i);
    }
    py::dict d;
    d["matrix"] = m;
    d["in_x"] = in_x;
    d["out_x"] = out_x;
    return d;
  }

  // One sample of the closure's own sampler per row of wo: random numbers from `seed` (row i uses the
  // i-th triple of the stream), or given as u (n, 3): (u_choice, u1, u2).
  py::dict sample(const py::object& wo_, const py::object& lambda_, const py::object& u_,
                  const py::object& seed_) {
    const Array wo = rows_of_3(wo_, "wo"), lambda = vector_of(lambda_, "wavelengths");
    const uint64_t seed = unsigned_argument(seed_, "seed");
    const py::ssize_t n = wo.shape(0);
    same_length(n, lambda, "wavelengths");
    Array u;
    if (!u_.is_none()) {
      u = rows_of_3(u_, "u");
      same_length(n, u, "u");
    }
    py::array_t<double> wi({n, py::ssize_t{3}}), weight(n), pdf(n);
    py::array_t<bool> delta(n), valid(n);
    Pcg32 rng(seed);
    std::vector<std::array<float, 3>> numbers(static_cast<size_t>(n));
    for (py::ssize_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        const float drawn = rng.next_float();
        numbers[i][k] = u_.is_none() ? drawn : static_cast<float>(u.data()[3 * i + k]);
        if (!(numbers[i][k] >= 0.0f && numbers[i][k] < 1.0f))
          throw InputError(fmt::format("u[{}]: random numbers must lie in [0, 1)", i));
      }
    for (py::ssize_t i : by_wavelength(lambda)) {
      check_signals(i);
      const Closure& c = closure_at(lambda, i);
      const auto s = c.sample(direction(wo, i, "wo"), numbers[i][0], {numbers[i][1], numbers[i][2]},
                              probe_->wavelengths());
      valid.mutable_data()[i] = s.has_value();
      const float dir[3] = {s ? s->wi.x : 0.0f, s ? s->wi.y : 0.0f, s ? s->wi.z : 0.0f};
      std::copy(dir, dir + 3, wi.mutable_data() + 3 * i);
      weight.mutable_data()[i] = s ? s->weight[0] : 0.0;
      pdf.mutable_data()[i] = s ? s->pdf : 0.0;
      delta.mutable_data()[i] = s && s->delta;
    }
    py::dict d;
    d["wi"] = wi;
    d["weight"] = weight;
    d["pdf"] = pdf;
    d["delta"] = delta;
    d["valid"] = valid;
    return d;
  }

  // The directional albedo at each polar angle of wo (degrees, azimuth 0), two ways (ochre-brdf albedo).
  // As ochre-brdf albedo (docs/tools.md): at least one angle, each in [0, 90); samples >= 1.
  py::dict albedo(const py::object& angles_, const py::object& lambda_, const py::object& samples_,
                  const py::object& seed_) {
    const Array angles = vector_of(angles_, "angles");
    const float lambda_nm = wavelength_at(number_argument(lambda_, "wavelength"), "wavelength");
    const uint64_t samples = unsigned_argument(samples_, "samples", 1);
    const uint64_t seed = unsigned_argument(seed_, "seed");
    const py::ssize_t n = angles.shape(0);
    if (n == 0) throw InputError("angles: give at least one angle");
    for (py::ssize_t i = 0; i < n; ++i)
      if (const double a = angles.data()[i]; !(a >= 0.0 && a < 90.0))
        throw InputError(fmt::format("angles[{}]: must be in [0, 90) degrees (got {})", i, a));
    py::array_t<double> mc(n), se(n), quad(n), quad_error(n);
    const Closure& c = probe_->closure(lambda_nm);
    for (py::ssize_t i = 0; i < n; ++i) {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      const double a = angles.data()[i];
      const double t = a * M_PI / 180.0;
      const Vec3 wo{static_cast<float>(std::sin(t)), 0.0f, static_cast<float>(std::cos(t))};
      // Ctrl-C stops a long estimate (KeyboardInterrupt).
      bool interrupted = false;
      const AlbedoEstimate e = directional_albedo(c, wo, probe_->wavelengths(), samples, seed,
                                                  [&] { return interrupted = PyErr_CheckSignals() != 0; });
      if (interrupted) throw py::error_already_set();
      mc.mutable_data()[i] = e.monte_carlo;
      se.mutable_data()[i] = e.monte_carlo_se;
      quad.mutable_data()[i] = e.quadrature;
      quad_error.mutable_data()[i] = e.quadrature_error;
    }
    py::dict d;
    d["mc_albedo"] = mc;
    d["mc_se"] = se;
    d["quadrature_albedo"] = quad;
    d["quadrature_error"] = quad_error;
    return d;
  }

  bool polarizes(const py::object& lambda_nm) {
    return probe_->closure(wavelength_at(number_argument(lambda_nm, "wavelength"), "wavelength")).polarizes();
  }
  py::str name() const { return text(probe_->name()); }

 private:
  // The closure at row i's wavelength.
  const Closure& closure_at(const Array& lambda, py::ssize_t i) {
    return probe_->closure(wavelength_at(lambda.data()[i], fmt::format("wavelengths[{}]", i)));
  }

  std::unique_ptr<MaterialProbe> probe_;
};

std::unique_ptr<PyMaterial> make_material(const py::object& source, const py::object& name_,
                                          const py::object& base_dir) {
  const std::string name = string_argument(name_, "name");
  if (PyDict_Check(source.ptr())) {
    const nlohmann::json json = to_json(source, "material");
    const std::filesystem::path dir = base_dir_argument(base_dir);
    return std::make_unique<PyMaterial>(
        std::make_unique<MaterialProbe>(json, name.empty() ? "<dict>" : name, dir));
  }
  const std::filesystem::path path =
      path_argument(source, "source", "a dict (the material) or a path (str or os.PathLike)");
  if (!base_dir.is_none()) throw InputError("base_dir: applies to materials given as a dict only");
  return std::make_unique<PyMaterial>(std::make_unique<MaterialProbe>(path, name));
}

}  // namespace

void register_material(py::module_& m) {
  py::class_<PyMaterial>(m, "_Material")
      .def_property_readonly("name", &PyMaterial::name)
      .def("eval", &PyMaterial::eval, py::arg("wi"), py::arg("wo"), py::arg("wavelengths"))
      .def("mueller", &PyMaterial::mueller, py::arg("wi"), py::arg("wo"), py::arg("wavelengths"))
      .def("sample", &PyMaterial::sample, py::arg("wo"), py::arg("wavelengths"), py::arg("u") = py::none(),
           py::arg("seed") = py::int_(1))
      .def("albedo", &PyMaterial::albedo, py::arg("angles"), py::arg("wavelength") = py::float_(550.0),
           py::arg("samples") = py::int_(200000), py::arg("seed") = py::int_(1))
      .def("polarizes", &PyMaterial::polarizes, py::arg("wavelength") = py::float_(550.0));
  m.def("_material", &make_material, py::arg("source"), py::arg("name") = py::str(""),
        py::arg("base_dir") = py::none());
  // The memory check of large requests (docs/cli.md, "Memory"), for the arrays the package broadcasts.
  m.def(
      "_check_memory", [](double bytes, const std::string& what) { check_memory_estimate(bytes, what); },
      py::arg("bytes"), py::arg("what"));
}

}  // namespace ochre::python
