// ochre.load_scene, ochre.Scene.render and the render result (docs/python.md).
#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <climits>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "renderer/image/exr_writer.h"
#include "renderer/integrator/render.h"
#include "renderer/loader/mitsuba/mitsuba_import.h"
#include "renderer/loader/scene_loader.h"
#include "renderer/output/output_files.h"
#include "renderer/output/render_output.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"
#include "tools/python/py_support.h"

namespace ochre::python {

namespace {

// Render-time options (the command line's output options): they choose the film's layers.
struct RenderOptions {
  std::optional<uint32_t> spp;
  std::optional<uint64_t> seed;
  std::optional<int> threads;
  uint64_t sample_begin = 0;
  bool aovs = false;
  bool stokes = false;
  int spectral_bins = 0;
  std::pair<float, float> spectral_range{360.0f, 830.0f};
  std::string colorspace = "rec709";
  std::optional<double> noise_threshold;  // None: the scene's integrator.noise_threshold
};

// A finished render: the film and how it was made. Arrays are made from the EXR the command line would
// write (render_exr_image), so they hold the same bits.
class RenderResult {
 public:
  // `outputs`: the working space and the camera sensor (film_to_rgb) of the render; `inputs`: the files
  // the scene was loaded from, which write_exr never replaces.
  RenderResult(std::unique_ptr<Film> film, RenderSettings settings, RenderStats stats, OutputSettings outputs,
               std::string scene_file, std::shared_ptr<const InputFileLog> inputs)
      : film_(std::move(film)),
        settings_(settings),
        stats_(stats),
        outputs_(std::move(outputs)),
        scene_file_(std::move(scene_file)),
        inputs_(std::move(inputs)) {}

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

  // The checks of `ochre render -o` before writing (docs/cli.md, "Output files": no link, device, FIFO,
  // directory or input of the scene is replaced), then the file written under a temporary name and renamed.
  void write_exr(const py::handle& path_) {
    const std::filesystem::path path = path_argument(path_, "path");
    check_output_files({path}, *inputs_);
    ochre::write_exr(path, exr());
  }

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
  std::shared_ptr<const InputFileLog> inputs_;
  std::unique_ptr<ExrImage> exr_;
};

class PyScene {
 public:
  PyScene(LoadedScene loaded, std::shared_ptr<const InputFileLog> inputs)
      : loaded_(std::move(loaded)), inputs_(std::move(inputs)) {}

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
    if (o.spp) s.spp = *o.spp;
    if (o.seed) s.seed = *o.seed;
    if (o.threads) s.threads = *o.threads;
    if (o.noise_threshold) s.noise_threshold = *o.noise_threshold;
    // A pixel of a noise-threshold render decides from all its samples so far, so it starts at sample 0,
    // as `ochre render --noise-threshold` refuses --sample-range (docs/cli.md, "Noise threshold").
    if (s.noise_threshold > 0.0 && o.sample_begin != 0)
      throw InputError(
          fmt::format("noise_threshold, sample_begin: a noise-threshold render ({}) starts at "
                      "sample 0, not {}; split it by pixels, not by samples",
                      s.noise_threshold, o.sample_begin));
    // Sample indices are 32-bit: the range ends at 2^32 - 1 at most, as --sample-range A:B (docs/cli.md).
    if (o.sample_begin + s.spp > kMaxSampleEnd)
      throw InputError(
          fmt::format("sample_begin, spp: samples [{}, {}) end past {} (2^32 - 1), where sample "
                      "indices end (as --sample-range A:B with B < 2^32)",
                      o.sample_begin, o.sample_begin + s.spp, kMaxSampleEnd));
    s.sample_begin = static_cast<uint32_t>(o.sample_begin);
    const std::optional<ColorSpace> colorspace = kWorkingSpaces.parse(o.colorspace);
    if (!colorspace)
      throw InputError(
          fmt::format("colorspace: unknown '{}' (known: {})", o.colorspace, kWorkingSpaces.list()));
    if (!(o.spectral_range.first >= 360.0f && o.spectral_range.second <= 830.0f &&
          o.spectral_range.first < o.spectral_range.second))
      throw InputError(
          fmt::format("spectral_range: must be (min, max) with 360 <= min < max <= 830 (got ({}, {}))",
                      o.spectral_range.first, o.spectral_range.second));
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
    // The film and the EXR's channels must fit in memory, as for `ochre render` (docs/cli.md, "Memory").
    OutputSettings estimate = job.outputs;
    estimate.exr = "<RenderResult>";
    estimate.png.clear();
    estimate.polarization_png.clear();
    estimate.aovs = o.aovs;
    estimate.stokes = o.stokes;
    estimate.spectral_bins = o.spectral_bins;
    check_render_memory(s.width, s.height, estimate);
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
    return std::make_unique<RenderResult>(std::move(film), s, stats, outputs, scene.file.string(), inputs_);
  }

 private:
  LoadedScene loaded_;
  std::shared_ptr<const InputFileLog> inputs_;
};

// {"spp": 64, ...}: the values of Mitsuba $parameters (-D NAME=VALUE), str, int or float, written as str()
// writes them.
std::vector<std::pair<std::string, std::string>> mitsuba_parameters(const py::object& parameters) {
  std::vector<std::pair<std::string, std::string>> p;
  if (parameters.is_none()) return p;
  if (!PyDict_Check(parameters.ptr()))
    wrong_type("parameters", "a dict of str to str, int or float", parameters);
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(parameters)) {
    if (!PyUnicode_Check(key.ptr())) wrong_type("parameters", "str keys (parameter names)", key);
    const std::string name = string_argument(key, "parameters");
    const std::string where = fmt::format("parameters['{}']", name);
    if (name.empty() || name.find('=') != std::string::npos)
      throw InputError(fmt::format("{}: a parameter name is not empty and has no '='", where));
    std::string text;
    if (PyUnicode_Check(value.ptr()))
      text = string_argument(value, where);
    else if (PyLong_Check(value.ptr()) && !PyBool_Check(value.ptr()))
      text = std::to_string(integer_argument(value, where, LLONG_MIN, LLONG_MAX));
    else if (PyFloat_Check(value.ptr()))
      text = py::repr(py::float_(number_argument(value, where))).cast<std::string>();
    else
      wrong_type(where, "a str, int or float", value);
    p.emplace_back(name, text);
  }
  return p;
}

// A choice argument (polarization, sampler): its enum value; InputError naming the argument and the known
// values for any other string.
template <class Enum, size_t N>
Enum parsed_choice(const py::object& value, const char* argument, const NamedChoices<Enum, N>& choices) {
  const std::string text = string_argument(value, argument);
  const std::optional<Enum> parsed = choices.parse(text);
  if (!parsed) throw InputError(fmt::format("{}: unknown '{}' (known: {})", argument, text, choices.list()));
  return *parsed;
}

constexpr long long kMaxSpp = 1 << 24;       // as --spp
constexpr long long kMaxThreads = 4096;      // as --threads
constexpr long long kMaxResolution = 65536;  // pixels per side

std::optional<uint32_t> spp_argument(const py::object& spp) {
  if (spp.is_none()) return std::nullopt;
  return static_cast<uint32_t>(integer_argument(spp, "spp", 1, kMaxSpp));
}

std::optional<int> threads_argument(const py::object& threads) {
  if (threads.is_none()) return std::nullopt;
  return static_cast<int>(integer_argument(threads, "threads", 0, kMaxThreads));
}

std::optional<uint64_t> seed_argument(const py::object& seed) {
  if (seed.is_none()) return std::nullopt;
  return unsigned_argument(seed, "seed");
}

SceneOverrides overrides_of(const py::object& spp, const py::object& resolution, const py::object& seed,
                            const py::object& threads, const py::object& polarization,
                            const py::object& sampler, const py::object& parameters) {
  SceneOverrides o;
  o.spp = spp_argument(spp);
  if (!resolution.is_none()) {
    const std::vector<py::object> r = items_argument(resolution, "resolution", 2, "(width, height)");
    const long long w = integer_argument(r[0], "resolution[0]", LLONG_MIN, LLONG_MAX),
                    h = integer_argument(r[1], "resolution[1]", LLONG_MIN, LLONG_MAX);
    if (w < 1 || h < 1 || w > kMaxResolution || h > kMaxResolution)
      throw InputError(
          fmt::format("resolution: must be (width, height) in [1, {}] (got ({}, {}))", kMaxResolution, w, h));
    o.width = static_cast<int>(w);
    o.height = static_cast<int>(h);
  }
  o.seed = seed_argument(seed);
  o.threads = threads_argument(threads);
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
  auto inputs = std::make_shared<InputFileLog>();
  if (PyDict_Check(source.ptr())) {
    const nlohmann::json root = to_json(source, "scene");
    const std::filesystem::path dir = base_dir_argument(base_dir);
    py::gil_scoped_release release;
    const std::lock_guard lock(input_recording_mutex());
    const InputFileLog::Recording recording(*inputs);
    return std::make_unique<PyScene>(load_scene_json(root, "<dict>", dir / "<dict>", o), inputs);
  }
  const std::filesystem::path path =
      path_argument(source, "source", "a dict (the scene) or a path (str or os.PathLike)");
  if (!base_dir.is_none()) throw InputError("base_dir: applies to scenes given as a dict only");
  py::gil_scoped_release release;
  const std::lock_guard lock(input_recording_mutex());
  const InputFileLog::Recording recording(*inputs);
  return std::make_unique<PyScene>(load_scene(path, o), inputs);
}

// Names and messages from the scene's files as a list of str (bytes that are not UTF-8 become U+FFFD).
py::list texts(const std::vector<std::string>& lines) {
  py::list list;
  for (const std::string& line : lines) list.append(text(line));
  return list;
}

py::dict settings_of(const PyScene& p) {
  const RenderSettings& s = p.job().settings;
  py::dict d;
  d["width"] = s.width;
  d["height"] = s.height;
  d["spp"] = s.spp;
  d["max_depth"] = s.max_depth;
  if (s.rr_depth == RenderSettings::kAutoRoulette)
    d["rr_depth"] = "auto";
  else
    d["rr_depth"] = s.rr_depth;
  if (s.branches == RenderSettings::kAutoBranches)
    d["branches"] = "auto";
  else
    d["branches"] = s.branches;
  d["light_selection"] = kLightSelections.name(s.light_selection);
  d["guiding"] = kGuidingSettings.name(s.guiding);
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
           "Writes the EXR `ochre render -o` would write for the same settings, with its checks: a link, a "
           "device, a FIFO, a directory or an input of the scene raises ochre.InputError and is left as it "
           "was "
           "(docs/cli.md, \"Output files\")");

  py::class_<PyScene>(m, "Scene", "A loaded scene (docs/python.md).")
      .def_property_readonly("settings", [](const PyScene& p) { return settings_of(p); })
      .def_property_readonly("file", [](const PyScene& p) { return text(p.scene().file.string()); })
      .def_property_readonly("width", [](const PyScene& p) { return p.job().settings.width; })
      .def_property_readonly("height", [](const PyScene& p) { return p.job().settings.height; })
      .def_property_readonly("mesh_count", [](const PyScene& p) { return p.scene().meshes.size(); })
      .def_property_readonly("light_count", [](const PyScene& p) { return p.scene().lights.size(); })
      .def_property_readonly("material_names",
                             [](const PyScene& p) { return texts(p.scene().material_names); })
      .def_property_readonly(
          "warnings", [](const PyScene& p) { return texts(p.scene().warnings); },
          "What the scene loads but a user should know (docs/scene-format.md)")
      .def(
          "polarization_mode",
          [](const PyScene& p, const py::object& stokes) {
            RenderJob job = p.job();
            job.outputs.stokes = bool_argument(stokes, "stokes");
            const PolarizationChoice c = polarization_for(p.scene(), job);
            return py::make_tuple(polarization_mode_name(c.mode), c.reason);
          },
          py::arg("stokes") = py::bool_(false), "(mode, reason) the render would use")
      .def(
          "render",
          [](PyScene& p, const py::object& spp, const py::object& seed, const py::object& threads,
             const py::object& sample_begin, const py::object& aovs, const py::object& stokes,
             const py::object& spectral_bins, const py::object& spectral_range, const py::object& colorspace,
             const py::object& noise_threshold, const py::object& progress) {
            RenderOptions o;
            o.spp = spp_argument(spp);
            o.seed = seed_argument(seed);
            o.threads = threads_argument(threads);
            o.sample_begin = unsigned_argument(sample_begin, "sample_begin", 0, kMaxSampleEnd);
            o.aovs = bool_argument(aovs, "aovs");
            o.stokes = bool_argument(stokes, "stokes");
            o.spectral_bins = static_cast<int>(integer_argument(spectral_bins, "spectral_bins", 0, 471));
            const std::vector<py::object> range =
                items_argument(spectral_range, "spectral_range", 2, "(min, max)");
            o.spectral_range = {static_cast<float>(number_argument(range[0], "spectral_range[0]")),
                                static_cast<float>(number_argument(range[1], "spectral_range[1]"))};
            o.colorspace = string_argument(colorspace, "colorspace");
            if (!noise_threshold.is_none()) {
              o.noise_threshold = number_argument(noise_threshold, "noise_threshold");
              if (!(*o.noise_threshold >= 0.0 && *o.noise_threshold <= 1.0))
                throw InputError(
                    fmt::format("noise_threshold: must be a number in [0, 1] (0 turns it off), not {}",
                                *o.noise_threshold));
            }
            return p.render(o, callable_argument(progress, "progress"));
          },
          py::kw_only(), py::arg("spp") = py::none(), py::arg("seed") = py::none(),
          py::arg("threads") = py::none(), py::arg("sample_begin") = py::int_(0),
          py::arg("aovs") = py::bool_(false), py::arg("stokes") = py::bool_(false),
          py::arg("spectral_bins") = py::int_(0), py::arg("spectral_range") = py::make_tuple(360.0, 830.0),
          py::arg("colorspace") = py::str("rec709"), py::arg("noise_threshold") = py::none(),
          py::arg("progress") = py::none(),
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
        return from_json(
            translate_mitsuba_scene(path_argument(path, "path"), mitsuba_parameters(parameters)).scene);
      },
      py::arg("path"), py::arg("parameters") = py::none(),
      "The ochre scene (a dict) a Mitsuba 3 XML scene translates into (docs/mitsuba-import.md)");
}

}  // namespace ochre::python
