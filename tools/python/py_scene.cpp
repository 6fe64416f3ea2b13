// ochre.load_scene, ochre.Scene.render and the render result (docs/python.md).
#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "renderer/image/exr_writer.h"
#include "renderer/integrator/render.h"
#include "renderer/loader/mitsuba/mitsuba_import.h"
#include "renderer/loader/scene_loader.h"
#include "renderer/output/render_output.h"
#include "spectra/input_error.h"
#include "tools/python/py_support.h"

namespace ochre::python {

namespace {

// Render-time options (the command line's output options): they choose the film's layers.
struct RenderOptions {
  std::optional<uint32_t> spp;
  std::optional<uint64_t> seed;
  std::optional<int> threads;
  uint32_t sample_begin = 0;
  bool aovs = false;
  bool stokes = false;
  int spectral_bins = 0;
  std::pair<float, float> spectral_range{360.0f, 830.0f};
  std::string colorspace = "rec709";
};

// A finished render: the film and how it was made. Arrays are made from the EXR the command line would
// write (render_exr_image), so they hold the same bits.
class RenderResult {
 public:
  // `outputs`: the working space and the camera sensor (film_to_rgb) of the render.
  RenderResult(std::unique_ptr<Film> film, RenderSettings settings, RenderStats stats, OutputSettings outputs,
               std::string scene_file)
      : film_(std::move(film)),
        settings_(settings),
        stats_(stats),
        outputs_(std::move(outputs)),
        scene_file_(std::move(scene_file)) {}

  const ExrImage& exr() {
    if (!exr_) {
      const std::vector<float> rgb = film_to_rgb(*film_, outputs_);
      exr_ =
          std::make_unique<ExrImage>(render_exr_image(*film_, rgb, outputs_, settings_, stats_, scene_file_));
    }
    return *exr_;
  }

  int width() const { return film_->width(); }
  int height() const { return film_->height(); }

  // Channels of the EXR stacked along a last axis: (height, width, names.size()), or (height, width)
  // for one name.
  py::array_t<float> stack(const std::vector<std::string>& names, bool squeeze = false) {
    const ExrImage& image = exr();
    const size_t n = size_t(width()) * height(), k = names.size();
    std::vector<float> values(n * k);
    for (size_t c = 0; c < k; ++c) {
      const std::vector<float>* channel = image.find_channel(names[c]);
      if (!channel) throw py::value_error(fmt::format("the render has no channel {}", names[c]));
      for (size_t i = 0; i < n; ++i) values[i * k + c] = (*channel)[i];
    }
    if (squeeze && k == 1) return float_array(values, {height(), width()});
    return float_array(values, {height(), width(), static_cast<py::ssize_t>(k)});
  }

  py::array_t<float> xyz() const {
    std::vector<float> values;
    values.reserve(size_t(width()) * height() * 3);
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x) {
        const XYZ c = film_->mean(x, y);
        values.insert(values.end(), {c.x, c.y, c.z});
      }
    return float_array(values, {height(), width(), 3});
  }

  // Variance of the mean luminance per pixel (sample variance / samples): what a noise-aware comparison of
  // two renders needs.
  py::array_t<double> luminance_variance() const {
    py::array_t<double> a({height(), width()});
    double* out = a.mutable_data();
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x) {
        const double n = static_cast<double>(film_->sample_count(x, y));
        out[size_t(y) * width() + x] = n > 0 ? film_->variance_y(x, y) / n : 0.0;
      }
    return a;
  }

  py::object aovs() {
    if (!film_->has_aovs()) return py::none();
    py::dict d;
    d["albedo"] = stack({"albedo.R", "albedo.G", "albedo.B"});
    d["normal"] = stack({"normal.X", "normal.Y", "normal.Z"});
    d["depth"] = stack({"depth.Z"}, true);
    d["samples"] = stack({"samples.Y"}, true);
    return d;
  }

  // (4, height, width, 3): S0..S3, each weighted by the colour matching functions (X, Y, Z).
  py::object stokes() {
    if (!film_->has_stokes()) return py::none();
    py::list components;
    for (int s = 0; s < 4; ++s) {
      const std::string p = fmt::format("stokes.S{}.", s);
      components.append(stack({p + "X", p + "Y", p + "Z"}));
    }
    return py::module_::import("numpy").attr("stack")(components);
  }

  py::object spectral() {
    if (film_->spectral_bins() == 0) return py::none();
    const int components = film_->has_stokes() ? 4 : 1;
    py::list parts;
    for (int c = 0; c < components; ++c) {
      std::vector<std::string> names;
      for (const auto& [name, values] : exr().channels)
        if (name.rfind(fmt::format("S{}.", c), 0) == 0 && name.size() > 3 &&
            name.compare(name.size() - 2, 2, "nm") == 0)
          names.push_back(name);
      // Channels are named by their bin centre; keep the film's order (increasing wavelength).
      std::vector<std::string> ordered;
      for (int b = 0; b < film_->spectral_bins(); ++b)
        for (const std::string& name : names)
          if (name == spectral_name(c, b)) ordered.push_back(name);
      parts.append(stack(ordered));
    }
    if (components == 1) return parts[0];
    return py::module_::import("numpy").attr("stack")(parts);
  }

  py::array_t<float> wavelengths() const {
    std::vector<float> centres;
    for (int b = 0; b < film_->spectral_bins(); ++b) centres.push_back(film_->spectral_bin_centre(b));
    return float_array(centres, {static_cast<py::ssize_t>(centres.size())});
  }

  py::dict stats() const {
    py::dict d;
    d["seconds"] = stats_.seconds;
    d["samples"] = stats_.samples;
    d["rays"] = stats_.rays;
    d["shadow_rays"] = stats_.shadow_rays;
    d["discarded"] = stats_.discarded;
    d["clamped"] = stats_.clamped;
    d["nonfinite_values"] = stats_.nonfinite_values;
    d["threads"] = stats_.threads;
    d["samples_per_second"] = stats_.samples_per_second();
    d["rays_per_second"] = stats_.rays_per_second();
    return d;
  }

  py::dict channels() {
    py::dict d;
    for (const auto& [name, values] : exr().channels)
      d[py::str(name)] = float_array(values, {height(), width()});
    return d;
  }

  void write_exr(const py::handle& path) { ochre::write_exr(to_path(path), exr()); }

  const char* colorspace() const { return kWorkingSpaces.name(outputs_.colorspace); }
  const RenderSettings& settings() const { return settings_; }

 private:
  std::string spectral_name(int component, int bin) const {
    std::string value = fmt::format("{:.6f}", film_->spectral_bin_centre(bin));
    std::replace(value.begin(), value.end(), '.', ',');
    return fmt::format("S{}.{}nm", component, value);
  }

  std::unique_ptr<Film> film_;
  RenderSettings settings_;
  RenderStats stats_;
  OutputSettings outputs_;
  std::string scene_file_;
  std::unique_ptr<ExrImage> exr_;
};

class PyScene {
 public:
  explicit PyScene(LoadedScene loaded) : loaded_(std::move(loaded)) {}

  const Scene& scene() const { return *loaded_.scene; }
  const RenderJob& job() const { return loaded_.job; }

  // Renders with the GIL released on a worker thread; this thread wakes every 0.1 s to report progress and
  // to let Python see Ctrl-C (KeyboardInterrupt), which stops the render at a pixel boundary.
  std::unique_ptr<RenderResult> render(const RenderOptions& o, const py::object& progress) {
    // The render's own job, a copy of the scene's with the call's options: the scene is not changed, so
    // renders of one scene may run side by side (a progress callback may start another).
    const Scene& scene = *loaded_.scene;
    RenderJob job = loaded_.job;
    RenderSettings& s = job.settings;
    if (o.spp) {
      if (*o.spp < 1 || *o.spp > (1u << 24))
        throw InputError(fmt::format("spp: must be in [1, {}]", 1 << 24));
      s.spp = *o.spp;
    }
    if (o.seed) s.seed = *o.seed;
    if (o.threads) {
      if (*o.threads < 0 || *o.threads > 4096) throw InputError("threads: must be in [0, 4096]");
      s.threads = *o.threads;
    }
    s.sample_begin = o.sample_begin;
    const std::optional<ColorSpace> colorspace = kWorkingSpaces.parse(o.colorspace);
    if (!colorspace)
      throw InputError(
          fmt::format("colorspace: unknown '{}' (known: {})", o.colorspace, kWorkingSpaces.list()));
    if (o.spectral_bins < 0 || o.spectral_bins > 471) throw InputError("spectral_bins: must be in [0, 471]");
    if (!(o.spectral_range.first >= 360.0f && o.spectral_range.second <= 830.0f &&
          o.spectral_range.first < o.spectral_range.second))
      throw InputError("spectral_range: must be (min, max) with 360 <= min < max <= 830");
    job.outputs.stokes = o.stokes;
    const PolarizationSetting mode = s.polarization;
    if (o.stokes && mode != PolarizationSetting::kAuto && mode != PolarizationSetting::kStokes)
      throw InputError(fmt::format("stokes: needs polarization mode stokes or auto, not '{}'",
                                   kPolarizationSettings.name(mode)));
    FilmLayers layers;
    layers.aovs = o.aovs;
    layers.stokes = o.stokes;
    layers.spectral_bins = o.spectral_bins;
    layers.spectral_min = o.spectral_range.first;
    layers.spectral_max = o.spectral_range.second;
    layers.light_groups = scene.light_groups;  // docs/lights.md, "Light groups"
    auto film = std::make_unique<Film>(s.width, s.height, layers);

    const uint64_t total = uint64_t(s.width) * s.height * s.spp;
    std::atomic<uint64_t> done{0};
    std::atomic<bool> cancel{false};
    RenderStats stats;
    std::exception_ptr failure;
    std::mutex mutex;
    std::condition_variable finished_cv;
    bool finished = false;
    {
      py::gil_scoped_release release;
      std::thread worker([&] {
        try {
          stats = ochre::render(
              scene, job, *film, [&](uint64_t n) { done += n; }, &cancel);
        } catch (...) {
          failure = std::current_exception();
        }
        std::lock_guard lock(mutex);
        finished = true;
        finished_cv.notify_all();
      });
      try {
        while (true) {
          {
            std::unique_lock lock(mutex);
            if (finished_cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; })) break;
          }
          py::gil_scoped_acquire acquire;
          if (PyErr_CheckSignals() != 0) throw py::error_already_set();
          if (!progress.is_none()) progress(done.load(), total);
        }
      } catch (...) {
        cancel = true;  // Ctrl-C or an exception from the progress callback: stop and re-raise
        worker.join();
        throw;
      }
      worker.join();
    }
    if (failure) std::rethrow_exception(failure);
    if (!progress.is_none()) progress(total, total);
    OutputSettings outputs = job.outputs;
    outputs.colorspace = *colorspace;
    return std::make_unique<RenderResult>(std::move(film), s, stats, outputs, scene.file.string());
  }

 private:
  LoadedScene loaded_;
};

// {"spp": 64, ...}: the values of Mitsuba $parameters, written as str() writes them.
std::vector<std::pair<std::string, std::string>> mitsuba_parameters(const py::object& parameters) {
  std::vector<std::pair<std::string, std::string>> p;
  if (!parameters.is_none())
    for (const auto& [key, value] : parameters.cast<py::dict>())
      p.emplace_back(key.cast<std::string>(), py::str(value).cast<std::string>());
  return p;
}

// A choice argument (polarization, sampler): its enum value; a ValueError naming the argument and the known
// values for any other string.
template <class Enum, size_t N>
Enum parsed_choice(const py::object& value, const char* argument, const NamedChoices<Enum, N>& choices) {
  const std::string text = value.cast<std::string>();
  const std::optional<Enum> parsed = choices.parse(text);
  if (!parsed) throw InputError(fmt::format("{}: unknown '{}' (known: {})", argument, text, choices.list()));
  return *parsed;
}

SceneOverrides overrides_of(const py::object& spp, const py::object& resolution, const py::object& seed,
                            const py::object& threads, const py::object& polarization,
                            const py::object& sampler, const py::object& parameters) {
  SceneOverrides o;
  if (!spp.is_none()) {
    const long long v = spp.cast<long long>();
    if (v < 1 || v > (1 << 24)) throw InputError(fmt::format("spp: must be in [1, {}] (got {})", 1 << 24, v));
    o.spp = static_cast<uint32_t>(v);
  }
  if (!resolution.is_none()) {
    const auto r = resolution.cast<std::pair<long long, long long>>();
    if (r.first < 1 || r.second < 1 || r.first > 65536 || r.second > 65536)
      throw InputError(
          fmt::format("resolution: must be (width, height) in [1, 65536] (got ({}, {}))", r.first, r.second));
    o.width = static_cast<int>(r.first);
    o.height = static_cast<int>(r.second);
  }
  if (!seed.is_none()) {
    const long long v = seed.cast<long long>();
    if (v < 0) throw InputError(fmt::format("seed: must be >= 0 (got {})", v));
    o.seed = static_cast<uint64_t>(v);
  }
  if (!threads.is_none()) o.threads = threads.cast<int>();
  if (!polarization.is_none())
    o.polarization = parsed_choice(polarization, "polarization", kPolarizationSettings);
  if (!sampler.is_none()) o.sampler = parsed_choice(sampler, "sampler", kSamplerKinds);
  o.parameters = mitsuba_parameters(parameters);
  return o;
}

std::unique_ptr<PyScene> load(const py::object& source, const py::object& spp, const py::object& resolution,
                              const py::object& seed, const py::object& threads,
                              const py::object& polarization, const py::object& sampler,
                              const py::object& parameters, const py::object& base_dir) {
  const SceneOverrides o = overrides_of(spp, resolution, seed, threads, polarization, sampler, parameters);
  if (py::isinstance<py::dict>(source)) {
    const nlohmann::json root = to_json(source, "scene");
    const std::filesystem::path dir =
        base_dir.is_none() ? std::filesystem::current_path() : to_path(base_dir);
    py::gil_scoped_release release;
    return std::make_unique<PyScene>(load_scene_json(root, "<dict>", dir / "<dict>", o));
  }
  const std::filesystem::path path = to_path(source);
  if (!base_dir.is_none()) throw py::value_error("base_dir applies to scenes given as a dict");
  py::gil_scoped_release release;
  return std::make_unique<PyScene>(load_scene(path, o));
}

py::dict settings_of(const PyScene& p) {
  const RenderSettings& s = p.job().settings;
  py::dict d;
  d["width"] = s.width;
  d["height"] = s.height;
  d["spp"] = s.spp;
  d["max_depth"] = s.max_depth;
  d["rr_depth"] = s.rr_depth;
  d["branches"] = s.branches;
  d["seed"] = s.seed;
  d["threads"] = s.threads;
  d["sampler"] = kSamplerKinds.name(s.sampler);
  d["polarization"] = kPolarizationSettings.name(s.polarization);
  d["filter"] = p.scene().pixel_filter.description();
  return d;
}

}  // namespace

void register_scene(py::module_& m) {
  py::class_<RenderResult>(m, "RenderResult", "The images and statistics of one render (docs/python.md).")
      .def_property_readonly("width", &RenderResult::width)
      .def_property_readonly("height", &RenderResult::height)
      .def_property_readonly("colorspace", &RenderResult::colorspace)
      .def_property_readonly(
          "rgb",
          [](RenderResult& r) {
            return r.stack({"R", "G", "B"});
          },
          "(height, width, 3) float32: linear working-space RGB, the EXR's R, G, B bit for bit")
      .def_property_readonly("xyz", &RenderResult::xyz, "(height, width, 3) float32: CIE 1931 XYZ per pixel")
      .def_property_readonly("luminance_variance", &RenderResult::luminance_variance,
                             "(height, width) float64: variance of each pixel's mean Y")
      .def_property_readonly("aovs", &RenderResult::aovs,
                             "dict of albedo (h, w, 3), normal (h, w, 3), depth (h, w), samples (h, w); None "
                             "unless rendered with aovs=True")
      .def_property_readonly("stokes", &RenderResult::stokes,
                             "(4, h, w, 3): S0..S3 weighted by X, Y, Z; None unless stokes=True")
      .def_property_readonly(
          "dolp",
          [](RenderResult& r) -> py::object {
            return r.exr().find_channel("DoLP") ? py::object(r.stack({"DoLP"}, true)) : py::none();
          },
          "(h, w): degree of linear polarization of the Y-weighted components (stokes=True)")
      .def_property_readonly(
          "aolp",
          [](RenderResult& r) -> py::object {
            return r.exr().find_channel("AoLP") ? py::object(r.stack({"AoLP"}, true)) : py::none();
          },
          "(h, w): angle of linear polarization in radians from the image x axis toward up (stokes=True)")
      .def_property_readonly(
          "spectral", &RenderResult::spectral,
          "(h, w, bins) spectral radiance, or (4, h, w, bins) with stokes=True; None unless "
          "spectral_bins > 0")
      .def_property_readonly("wavelengths", &RenderResult::wavelengths, "(bins,) bin centres in nm")
      .def_property_readonly("stats", &RenderResult::stats)
      .def_property_readonly("channels", &RenderResult::channels, "every EXR channel by name, (h, w) each")
      .def("write_exr", &RenderResult::write_exr, py::arg("path"),
           "Writes the EXR `ochre render -o` would write for the same settings");

  py::class_<PyScene>(m, "Scene", "A loaded scene (docs/python.md).")
      .def_property_readonly("settings", [](const PyScene& p) { return settings_of(p); })
      .def_property_readonly("file", [](const PyScene& p) { return p.scene().file.string(); })
      .def_property_readonly("width", [](const PyScene& p) { return p.job().settings.width; })
      .def_property_readonly("height", [](const PyScene& p) { return p.job().settings.height; })
      .def_property_readonly("mesh_count", [](const PyScene& p) { return p.scene().meshes.size(); })
      .def_property_readonly("light_count", [](const PyScene& p) { return p.scene().lights.size(); })
      .def_property_readonly("material_names", [](const PyScene& p) { return p.scene().material_names; })
      .def_property_readonly(
          "warnings", [](const PyScene& p) { return p.scene().warnings; },
          "What the scene loads but a user should know (docs/scene-format.md)")
      .def(
          "polarization_mode",
          [](const PyScene& p, bool stokes) {
            RenderJob job = p.job();
            job.outputs.stokes = stokes;
            const PolarizationChoice c = polarization_for(p.scene(), job);
            return py::make_tuple(polarization_mode_name(c.mode), c.reason);
          },
          py::arg("stokes") = false, "(mode, reason) the render would use")
      .def(
          "render",
          [](PyScene& p, std::optional<uint32_t> spp, std::optional<uint64_t> seed,
             std::optional<int> threads, uint32_t sample_begin, bool aovs, bool stokes, int spectral_bins,
             std::pair<float, float> spectral_range, const std::string& colorspace,
             const py::object& progress) {
            RenderOptions o;
            o.spp = spp;
            o.seed = seed;
            o.threads = threads;
            o.sample_begin = sample_begin;
            o.aovs = aovs;
            o.stokes = stokes;
            o.spectral_bins = spectral_bins;
            o.spectral_range = spectral_range;
            o.colorspace = colorspace;
            return p.render(o, progress);
          },
          py::kw_only(), py::arg("spp") = py::none(), py::arg("seed") = py::none(),
          py::arg("threads") = py::none(), py::arg("sample_begin") = 0, py::arg("aovs") = false,
          py::arg("stokes") = false, py::arg("spectral_bins") = 0,
          py::arg("spectral_range") = std::pair<float, float>(360.0f, 830.0f),
          py::arg("colorspace") = "rec709", py::arg("progress") = py::none(),
          "Renders the scene; the GIL is released meanwhile. progress(done, total) is called about every 0.1 "
          "s "
          "with the pixel-samples done; Ctrl-C stops the render and raises KeyboardInterrupt.");

  m.def(
      "load_scene", &load, py::arg("source"), py::kw_only(), py::arg("spp") = py::none(),
      py::arg("resolution") = py::none(), py::arg("seed") = py::none(), py::arg("threads") = py::none(),
      py::arg("polarization") = py::none(), py::arg("sampler") = py::none(),
      py::arg("parameters") = py::none(), py::arg("base_dir") = py::none(),
      "Loads a scene: a path to a JSON scene or a Mitsuba 3 XML scene, or the JSON scene as a dict (relative "
      "paths in it resolve against base_dir, default the current directory). Bad input raises "
      "ochre.InputError naming the file (or <dict>) and the field.");

  m.def(
      "mitsuba_to_json",
      [](const py::object& path, const py::object& parameters) {
        return from_json(translate_mitsuba_scene(to_path(path), mitsuba_parameters(parameters)).scene);
      },
      py::arg("path"), py::arg("parameters") = py::none(),
      "The ochre scene (a dict) a Mitsuba 3 XML scene translates into (docs/mitsuba-import.md)");
}

}  // namespace ochre::python
