#include "tools/regress/scene_data.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "renderer/output/render_output.h"
#include "spectra/color_space.h"

namespace ochre {

namespace {

// Interleaves named channels of an image (`components` per pixel); empty when one is missing.
std::vector<float> interleave(const ExrImage& image, const std::vector<std::string>& names) {
  std::vector<const std::vector<float>*> channels;
  for (const std::string& name : names) {
    const std::vector<float>* channel = image.find_channel(name);
    if (!channel) return {};
    channels.push_back(channel);
  }
  const size_t n = static_cast<size_t>(image.width) * image.height;
  std::vector<float> values(n * names.size());
  for (size_t p = 0; p < n; ++p)
    for (size_t c = 0; c < names.size(); ++c) values[p * names.size() + c] = (*channels[c])[p];
  return values;
}

std::vector<std::string> stokes_channel_names() {
  return {"stokes.S0.Y", "stokes.S1.Y", "stokes.S2.Y", "stokes.S3.Y"};
}

// The S0 spectral channels of an image, sorted by wavelength.
struct SpectralLayers {
  std::vector<float> wavelengths;
  std::vector<std::string> names;
};

SpectralLayers spectral_layers(const ExrImage& image) {
  std::vector<std::pair<float, std::string>> found;
  for (const auto& [name, values] : image.channels)
    if (const auto nm = spectral_channel_wavelength(name)) found.emplace_back(*nm, name);
  std::sort(found.begin(), found.end());
  SpectralLayers layers;
  for (auto& [nm, name] : found) {
    layers.wavelengths.push_back(nm);
    layers.names.push_back(std::move(name));
  }
  return layers;
}

template <typename T>
std::string number_list(const std::vector<T>& values) {
  std::string text = "[";
  for (size_t i = 0; i < values.size(); ++i) text += fmt::format("{}{}", i ? "," : "", values[i]);
  return text + "]";
}

std::string js_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '<' || static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned char>(c));  // no "</script>", no raw control
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// One entry of the layers object.
struct Layer {
  std::string name;
  int components;
  std::vector<float> values;  // per pixel
  BlockReduce reduce;
};

std::string layer_js(const Layer& layer, const PixelGrid& grid) {
  return fmt::format("    {}: {{components: {}, data: \"{}\"}}", js_string(layer.name), layer.components,
                     base64_floats(reduce_to_grid(layer.values, layer.components, grid, layer.reduce)));
}

std::vector<float> as_floats(const std::vector<double>& values) {
  return {values.begin(), values.end()};
}

std::vector<Layer> scene_layers(const SceneReport& report) {
  const RegressionResult& r = report.result;
  std::vector<float> nlp(r.p_values.size()), failing(r.p_values.size());
  for (size_t i = 0; i < nlp.size(); ++i) {
    nlp[i] = static_cast<float>(-std::log10(std::max(r.p_values[i], 1e-300)));
    failing[i] = r.p_values[i] < r.alpha_pixel ? 1.0f : 0.0f;
  }
  std::vector<Layer> layers = {
      {"reference.rgb", 3, report_rgb(report.reference, report.working_space).rgb, BlockReduce::kMean},
      {"new.rgb", 3, report_rgb(report.render, report.working_space).rgb, BlockReduce::kMean},
      {"z", 1, as_floats(r.z_scores), BlockReduce::kExtreme},
      {"nlp", 1, std::move(nlp), BlockReduce::kMax},
      {"failing", 1, std::move(failing), BlockReduce::kSum},
      {"de00", 1, report.comparison.maps.de00, BlockReduce::kMean},
  };
  for (const auto& [side, image] : {std::pair{"reference", &report.reference}, {"new", &report.render}})
    if (std::vector<float> stokes = interleave(*image, stokes_channel_names()); !stokes.empty())
      layers.push_back({std::string(side) + ".stokes", 4, std::move(stokes), BlockReduce::kMean});
  return layers;
}

std::string spectral_js(const char* side, const ExrImage& image, const PixelGrid& grid) {
  const SpectralLayers layers = spectral_layers(image);
  if (layers.names.empty()) return "";
  const int bins = static_cast<int>(layers.names.size());
  return fmt::format(
      "    {}: {{wavelengths: {}, components: {}, data: \"{}\"}}", js_string(side),
      number_list(layers.wavelengths), bins,
      base64_floats(reduce_to_grid(interleave(image, layers.names), bins, grid, BlockReduce::kMean)));
}

std::string join(const std::vector<std::string>& parts, const char* separator) {
  std::string text;
  for (const std::string& part : parts) {
    if (part.empty()) continue;
    if (!text.empty()) text += separator;
    text += part;
  }
  return text;
}

}  // namespace

std::string scene_data_js(const SceneReport& report, PixelGrid& grid) {
  const std::vector<Layer> layers = scene_layers(report);
  size_t per_cell = 0;
  for (const Layer& layer : layers) per_cell += static_cast<size_t>(layer.components);
  per_cell += spectral_layers(report.reference).names.size() + spectral_layers(report.render).names.size();
  grid = choose_pixel_grid(report.result.width, report.result.height, per_cell, kMaxSceneDataValues);

  std::vector<std::string> layer_entries;
  for (const Layer& layer : layers) layer_entries.push_back(layer_js(layer, grid));
  const Mat3& to_xyz = rgb_to_xyz_matrix(parse_color_space(report.working_space));
  const std::vector<double> matrix(to_xyz.m.begin(), to_xyz.m.end());

  std::string js = "// Generated by ochre-regress --html: pixel values of one scene (docs/tools.md).\n";
  js += "window.ochreSceneData = {\n";
  js += fmt::format("  name: {},\n  width: {}, height: {}, step: {}, columns: {}, rows: {},\n",
                    js_string(report.name), grid.width, grid.height, grid.step, grid.columns, grid.rows);
  js += fmt::format("  workingSpace: {},\n  rgbToXyz: {},\n", js_string(report.working_space),
                    number_list(matrix));
  js +=
      fmt::format("  alphaPixel: {}, criticalZ: {},\n", report.result.alpha_pixel, critical_z(report.result));
  js += "  layers: {\n" + join(layer_entries, ",\n") + "\n  },\n";
  js += "  spectral: {\n" +
        join({spectral_js("reference", report.reference, grid), spectral_js("new", report.render, grid)},
             ",\n") +
        "\n  }\n};\n";
  return js;
}

}  // namespace ochre
