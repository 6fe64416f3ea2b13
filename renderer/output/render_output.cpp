#include "renderer/output/render_output.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

#include "ochre/version.h"
#include "renderer/image/display_image.h"
#include "renderer/image/exr_writer.h"
#include "renderer/output/stokes_output.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/image_error.h"
#include "renderer/util/memory_budget.h"
#include "renderer/util/output_transaction.h"
#include "spectra/color_space.h"
#include "spectra/input_error.h"

namespace ochre {

DisplayOptions display_options(const OutputSettings& o) {
  DisplayOptions d;
  d.ocio_config = o.ocio_config;
  d.display = o.display;
  d.view = o.view;
  d.working_space = kWorkingSpaces.name(o.colorspace);
  d.exposure_stops = o.exposure;
  d.white_balance_xyz = o.white_balance_xyz;
  return d;
}

namespace {
// Layers "albedo.R/G/B" (working space), "normal.X/Y/Z" (world), "depth.Z" (distance along the camera
// ray, 0 where nothing was hit) and "samples.Y" (samples per pixel).
void add_aov_channels(const Film& film, ColorSpace space, ExrImage& image) {
  const size_t n = static_cast<size_t>(film.width()) * film.height();
  std::vector<std::vector<float>> c(8, std::vector<float>(n));
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const size_t i = static_cast<size_t>(y) * film.width() + x;
      const RGB albedo = xyz_to_rgb(film.mean_albedo(x, y), space);
      const Vec3f normal = film.mean_normal(x, y);
      const float values[8] = {albedo.r,
                               albedo.g,
                               albedo.b,
                               normal.x,
                               normal.y,
                               normal.z,
                               film.mean_depth(x, y),
                               static_cast<float>(film.sample_count(x, y))};
      for (int k = 0; k < 8; ++k) c[k][i] = values[k];
    }
  const char* names[8] = {"albedo.R", "albedo.G", "albedo.B", "normal.X",
                          "normal.Y", "normal.Z", "depth.Z",  "samples.Y"};
  for (int k = 0; k < 8; ++k) image.channels.emplace_back(names[k], std::move(c[k]));
}

// "samples.Y" alone: where a noise-threshold render put its samples (with AOVs it is one of them).
void add_sample_count_channel(const Film& film, ExrImage& image) {
  std::vector<float> count(static_cast<size_t>(film.width()) * film.height());
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      count[static_cast<size_t>(y) * film.width() + x] = static_cast<float>(film.sample_count(x, y));
  image.channels.emplace_back("samples.Y", std::move(count));
}

}  // namespace

std::string spectral_channel_name(int component, float centre_nm) {
  std::string value = fmt::format("{:.6f}", centre_nm);
  std::replace(value.begin(), value.end(), '.', ',');
  return fmt::format("S{}.{}nm", component, value);
}

void add_spectral_channels(const Film& film, ExrImage& image) {
  const size_t n = static_cast<size_t>(film.width()) * film.height();
  for (int component = 0; component < (film.has_stokes() ? 4 : 1); ++component)
    for (int b = 0; b < film.spectral_bins(); ++b) {
      std::vector<float> channel(n);
      for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
          channel[static_cast<size_t>(y) * film.width() + x] = film.mean_spectral(x, y, b, component);
      image.channels.emplace_back(spectral_channel_name(component, film.spectral_bin_centre(b)),
                                  std::move(channel));
    }
  image.string_attributes["spectralLayoutVersion"] = "1.0";
  image.string_attributes["emissiveUnits"] = "W.m^-2.sr^-1";
}

std::string group_bin_layer(const std::string& group, float centre_nm) {
  std::string value = fmt::format("{:.6f}", centre_nm);
  std::replace(value.begin(), value.end(), '.', ',');
  return fmt::format("group.{}.{}nm", group, value);
}

std::string light_group_emission_attribute(const std::string& group) {
  return fmt::format("ochre.lightGroup.{}.emission", group);
}

std::optional<float> spectral_channel_wavelength(std::string_view name, int component) {
  const std::string prefix = fmt::format("S{}.", component);
  if (name.size() <= prefix.size() + 2 || name.substr(0, prefix.size()) != prefix ||
      name.substr(name.size() - 2) != "nm")
    return std::nullopt;
  std::string value(name.substr(prefix.size(), name.size() - prefix.size() - 2));
  std::replace(value.begin(), value.end(), ',', '.');
  float nm = 0.0f;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), nm);
  if (error != std::errc() || end != value.data() + value.size() || !(nm > 0.0f)) return std::nullopt;
  return nm;
}

namespace {

// The working-space RGB of one film value (XYZ, or a camera sensor's R, G, B), as the image's R, G, B.
RGB output_rgb(const XYZ& m, const OutputSettings& outputs) {
  if (outputs.camera_rgb) return {m.x, m.y, m.z};
  if (!outputs.sensor_to_xyz) return xyz_to_rgb(m, outputs.colorspace);
  const Array3d xyz = *outputs.sensor_to_xyz * Array3d{m.x, m.y, m.z};
  return xyz_to_rgb({static_cast<float>(xyz[0]), static_cast<float>(xyz[1]), static_cast<float>(xyz[2])},
                    outputs.colorspace);
}

// The layer `layer` (group.<name> or group.<name>.<centre>nm): R, G, B of a group, or of one of its bins.
void add_group_layer(const Film& film, const OutputSettings& outputs, size_t group, std::optional<int> bin,
                     const std::string& layer, ExrImage& image) {
  const size_t n = static_cast<size_t>(film.width()) * film.height();
  std::array<std::vector<float>, 3> c{std::vector<float>(n), std::vector<float>(n), std::vector<float>(n)};
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const XYZ m = bin ? film.mean_group(x, y, group, *bin) : film.mean_group(x, y, group);
      const RGB rgb = output_rgb(m, outputs);
      const size_t i = static_cast<size_t>(y) * film.width() + x;
      c[0][i] = rgb.r;
      c[1][i] = rgb.g;
      c[2][i] = rgb.b;
    }
  for (int k = 0; k < 3; ++k)
    image.channels.emplace_back(fmt::format("{}.{}", layer, "RGB"[k]), std::move(c[k]));
}

void add_light_group_channels(const Film& film, const OutputSettings& outputs, ExrImage& image) {
  std::string names;
  for (size_t g = 0; g < film.light_groups().size(); ++g) {
    const std::string& group = film.light_groups()[g];
    add_group_layer(film, outputs, g, std::nullopt, "group." + group, image);
    if (film.group_bins() > 1)
      for (int b = 0; b < film.group_bins(); ++b)
        add_group_layer(film, outputs, g, b, group_bin_layer(group, film.spectral_bin_centre(b)), image);
    if (g < outputs.light_group_emission.size() && !outputs.light_group_emission[g].empty())
      image.string_attributes[light_group_emission_attribute(group)] = outputs.light_group_emission[g];
    names += (names.empty() ? "" : ",") + group;
  }
  image.string_attributes["ochre.lightGroups"] = names;
  // The display transform, for `ochre relight` to make the display image as the render did.
  image.string_attributes["ochre.display.ocioConfig"] = outputs.ocio_config;
  image.string_attributes["ochre.display.display"] = outputs.display;
  image.string_attributes["ochre.display.view"] = outputs.view;
  image.string_attributes["ochre.display.exposure"] = fmt::format("{}", outputs.exposure);
  if (outputs.white_balance_xyz)
    image.string_attributes["ochre.display.whiteBalance"] =
        fmt::format("{} {} {}", (*outputs.white_balance_xyz)[0], (*outputs.white_balance_xyz)[1],
                    (*outputs.white_balance_xyz)[2]);
}

}  // namespace

std::vector<float> film_to_rgb(const Film& film, const OutputSettings& outputs) {
  if (!outputs.camera_rgb && !outputs.sensor_to_xyz) return film_to_rgb(film, outputs.colorspace);
  std::vector<float> rgb(static_cast<size_t>(film.width()) * film.height() * 3);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const RGB c = output_rgb(film.mean(x, y), outputs);  // the sensor's R, G, B, or XYZ from them
      const size_t i = (static_cast<size_t>(y) * film.width() + x) * 3;
      rgb[i] = c.r;
      rgb[i + 1] = c.g;
      rgb[i + 2] = c.b;
    }
  return rgb;
}

std::vector<float> film_to_rgb(const Film& film, ColorSpace space) {
  std::vector<float> rgb(static_cast<size_t>(film.width()) * film.height() * 3);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const RGB c = xyz_to_rgb(film.mean(x, y), space);
      const size_t i = (static_cast<size_t>(y) * film.width() + x) * 3;
      rgb[i] = c.r;
      rgb[i + 1] = c.g;
      rgb[i + 2] = c.b;
    }
  return rgb;
}

ExrImage render_exr_image(const Film& film, const std::vector<float>& rgb, const OutputSettings& outputs,
                          const RenderSettings& settings, const RenderStats& stats,
                          const std::string& scene_file) {
  const ColorSpace colorspace = outputs.colorspace;
  ExrImage image;
  image.width = film.width();
  image.height = film.height();
  const size_t n = static_cast<size_t>(image.width) * image.height;
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    std::vector<float> channel(n);
    for (size_t i = 0; i < n; ++i) channel[i] = rgb[i * 3 + c];
    image.channels.emplace_back(names[c], std::move(channel));
  }
  if (film.has_aovs()) add_aov_channels(film, colorspace, image);
  if (!film.has_aovs() && settings.noise_threshold > 0.0) add_sample_count_channel(film, image);
  if (film.spectral_bins() > 0) add_spectral_channels(film, image);
  if (film.has_stokes()) add_stokes_channels(film, image);
  if (!film.light_groups().empty()) add_light_group_channels(film, outputs, image);
  // Camera RGB has the sensor's own primaries: no chromaticities are claimed for it.
  if (!outputs.camera_rgb)
    image.chromaticities =
        colorspace == ColorSpace::ACEScg ? acescg_chromaticities() : rec709_chromaticities();
  if (outputs.sensor != "cie1931") {
    image.string_attributes["ochre.sensor"] = outputs.sensor;
    image.string_attributes["ochre.sensorOutput"] = outputs.camera_rgb ? "camera_rgb" : "white_balanced";
  }
  image.string_attributes["software"] = "ochre " OCHRE_VERSION;
  image.string_attributes["ochre.scene"] = scene_file;
  image.string_attributes["ochre.colorspace"] = kWorkingSpaces.name(colorspace);
  image.string_attributes["ochre.spp"] = std::to_string(settings.spp);
  image.string_attributes["ochre.sampleRange"] =
      fmt::format("{}-{}", settings.sample_begin, settings.sample_begin + settings.spp);
  image.string_attributes["ochre.seed"] = std::to_string(settings.seed);
  if (settings.noise_threshold > 0.0) {
    image.string_attributes["ochre.noiseThreshold"] = fmt::format("{}", settings.noise_threshold);
    image.string_attributes["ochre.samples"] = std::to_string(stats.samples);
  }
  image.string_attributes["ochre.discardedSamples"] = std::to_string(stats.discarded);
  // Written only when samples were clamped, so that every other image keeps its header.
  if (stats.clamped > 0) image.string_attributes["ochre.clampedSamples"] = std::to_string(stats.clamped);
  image.string_attributes["ochre.nonFiniteShadingValues"] = std::to_string(stats.nonfinite_values);
  return image;
}

void check_stokes_mode(const RenderJob& job, const std::string& scene_name) {
  const PolarizationSetting mode = job.settings.polarization;
  if (!job.outputs.stokes || mode == PolarizationSetting::kAuto || mode == PolarizationSetting::kStokes)
    return;
  throw InputError(fmt::format(
      "{}: integrator.polarization: Stokes output (--stokes, output.stokes or a polarization PNG) "
      "needs polarization mode stokes or auto, not '{}'",
      scene_name, kPolarizationSettings.name(mode)));
}

void check_outputs(const OutputSettings& outputs) {
  try {
    if (outputs.exr.empty() && outputs.png.empty())
      throw InputError("no output: give -o OUT.exr and/or --png OUT.png");
    if (!outputs.exr.empty()) check_output_writable(outputs.exr);
    if (!outputs.polarization_png.empty()) check_output_writable(outputs.polarization_png);
    if (!outputs.png.empty()) {
      check_output_writable(outputs.png);
      // Build the display transform on one pixel now: an unknown config, display or view fails
      // before any rendering.
      to_display_rgb8(1, 1, {0.18f, 0.18f, 0.18f}, display_options(outputs));
    }
  } catch (const ImageError& e) {
    throw InputError(e.what());
  }
}

FilmLayers film_layers(const OutputSettings& outputs) {
  FilmLayers layers;
  const bool exr = !outputs.exr.empty();
  layers.aovs = outputs.aovs && exr;
  layers.spectral_bins = exr ? outputs.spectral_bins : 0;
  layers.spectral_min = outputs.spectral_min;
  layers.spectral_max = outputs.spectral_max;
  layers.stokes = outputs.stokes || !outputs.polarization_png.empty();
  if (exr) layers.light_groups = outputs.light_groups;
  return layers;
}

void check_render_memory(int width, int height, const OutputSettings& outputs) {
  const FilmLayers layers = film_layers(outputs);
  // write_outputs(): the working-space RGB (3 floats), then one of: the EXR's channels (floats), the
  // display image (a float copy and 8-bit RGB), the polarization PNG (8-bit RGB).
  size_t exr_channels = 0;
  if (!outputs.exr.empty()) {
    exr_channels = 3 + (layers.aovs ? 8 : 0) + (layers.stokes ? 14 : 0);
    exr_channels += static_cast<size_t>(layers.spectral_bins) * (layers.stokes ? 4 : 1);
    // A light group's R, G, B, and per spectral bin.
    exr_channels += layers.light_groups.size() * 3 * (1 + static_cast<size_t>(layers.spectral_bins));
  }
  const size_t png_bytes = outputs.png.empty() ? 0 : 3 * sizeof(float) + 3;
  const size_t polarization_bytes = outputs.polarization_png.empty() ? 0 : 3;
  const size_t output_bytes =
      3 * sizeof(float) + std::max({exr_channels * sizeof(float), png_bytes, polarization_bytes});
  const double pixels = static_cast<double>(width) * height;
  check_memory_estimate(pixels * static_cast<double>(Film::bytes_per_pixel(layers) + output_bytes),
                        film_description(width, height, layers) + " with its output buffers");
}

std::vector<std::string> output_paths(const OutputSettings& outputs) {
  std::vector<std::string> paths;
  for (const std::string* path : {&outputs.exr, &outputs.polarization_png, &outputs.png})
    if (!path->empty()) paths.push_back(*path);
  return paths;
}

std::vector<std::string> write_outputs(const Film& film, const OutputSettings& outputs,
                                       const RenderSettings& settings, const RenderStats& stats,
                                       const std::string& scene_file) {
  OutputTransaction transaction;  // every file is complete before any existing one is replaced
  std::vector<std::string> written = add_outputs(transaction, film, outputs, settings, stats, scene_file);
  transaction.commit();
  return written;
}

std::vector<std::string> add_outputs(OutputTransaction& transaction, const Film& film,
                                     const OutputSettings& outputs, const RenderSettings& settings,
                                     const RenderStats& stats, const std::string& scene_file) {
  std::vector<std::string> written;
  const std::vector<float> rgb = film_to_rgb(film, outputs);
  if (!outputs.exr.empty()) {
    const ExrImage image = render_exr_image(film, rgb, outputs, settings, stats, scene_file);
    write_exr(transaction.add(outputs.exr), image);
    written.push_back(fmt::format("wrote {} ({}, {}x{})", outputs.exr,
                                  outputs.camera_rgb
                                      ? "camera RGB of " + outputs.sensor
                                      : std::string("linear ") + kWorkingSpaces.name(outputs.colorspace),
                                  image.width, image.height));
  }
  if (!outputs.polarization_png.empty() && film.has_stokes()) {
    write_polarization_png(transaction.add(outputs.polarization_png), film);
    written.push_back(fmt::format("wrote {} (hue: angle, brightness: degree of linear polarization)",
                                  outputs.polarization_png));
  }
  if (!outputs.png.empty()) {
    const DisplayTransformReport report = write_display_png(transaction.add(outputs.png), film.width(),
                                                            film.height(), rgb, display_options(outputs));
    written.push_back(fmt::format("wrote {} ({})", outputs.png, report.description));
    for (const std::string& w : report.warnings) written.push_back("warning: " + w);
  }
  return written;
}

}  // namespace ochre
