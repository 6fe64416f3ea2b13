#include "renderer/output/relight.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "renderer/json/spectrum_json.h"
#include "renderer/output/output_files.h"
#include "renderer/output/render_output.h"
#include "renderer/scene/render_settings.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/image_error.h"
#include "renderer/util/output_transaction.h"
#include "spectra/color_space.h"
#include "spectra/emission_shape.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

std::vector<std::string> split(std::string_view text, char separator) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t end; (end = text.find(separator, start)) != std::string_view::npos; start = end + 1)
    parts.emplace_back(text.substr(start, end - start));
  parts.emplace_back(text.substr(start));
  return parts;
}

bool kept_without_change(const std::string& channel) {
  for (const char* prefix : {"albedo.", "normal.", "depth.", "samples."})
    if (channel.rfind(prefix, 0) == 0) return true;
  return false;
}

double attribute_number(const ExrImage& image, const std::string& file, const char* name, double lo,
                        double hi, double fallback) {
  const auto it = image.string_attributes.find(name);
  if (it == image.string_attributes.end()) return fallback;
  const std::string& text = it->second;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !(value >= lo && value <= hi))
    throw InputError(
        fmt::format("{}: {}: expected a number in [{}, {}], got '{}'", file, name, lo, hi, text));
  return value;
}

// The spectrum of "cct=T" or "spectrum=NAME|FILE.csv", parsed as a scene's light spectrum is.
SpectrumPtr new_emission(std::string_view text, const std::string& key, const std::string& value) {
  const std::string where = fmt::format("--group '{}': {}", text, key);
  nlohmann::json spec;
  if (key == "cct") {
    double kelvin = 0.0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), kelvin);
    if (error != std::errc() || end != value.data() + value.size() || !(kelvin >= 500.0 && kelvin <= 1e5))
      throw InputError(fmt::format(
          "{}: expected a temperature in kelvin in [500, 100000], as a flame's cct, got '{}'", where, value));
    spec = {{"blackbody", kelvin}};
  } else if (value.empty()) {
    throw InputError(fmt::format("{}: expected a spectrum name or a CSV file", where));
  } else if (value.find('/') != std::string::npos ||
             (value.size() > 4 && value.substr(value.size() - 4) == ".csv")) {
    spec = {{"file", value}};
  } else {
    spec = {{"name", value}};
  }
  return parse_spectrum(spec, SpectrumRole::Illuminant, where, std::filesystem::current_path());
}

// The bin layers of `group` (group.<group>.<centre>nm), by centre.
std::map<float, std::string> group_bin_layers(const ExrImage& image, const std::string& group) {
  std::map<float, std::string> layers;
  const std::string prefix = "group." + group + ".";
  for (const auto& [name, values] : image.channels) {
    if (name.size() < prefix.size() + 5 || name.rfind(prefix, 0) != 0 ||
        name.substr(name.size() - 4) != "nm.R")
      continue;
    std::string centre = name.substr(prefix.size(), name.size() - prefix.size() - 4);
    std::replace(centre.begin(), centre.end(), ',', '.');
    float nm = 0.0f;
    const auto [end, error] = std::from_chars(centre.data(), centre.data() + centre.size(), nm);
    if (error == std::errc() && end == centre.data() + centre.size())
      layers[nm] = name.substr(0, name.size() - 2);
  }
  return layers;
}

// True when the image's R, G, B are CIE XYZ in a working space (no camera sensor's response).
bool cie_render(const ExrImage& image) {
  const auto sensor = image.string_attributes.find("ochre.sensor");
  return sensor == image.string_attributes.end() || sensor->second == "cie1931";
}

// The weights of each bin layer of `group` for `change` (BinWeights).
BinWeights bin_weights(const ExrImage& image, const std::string& file, const GroupChange& change,
                       const std::map<float, std::string>& bins) {
  const auto recorded = image.string_attributes.find(light_group_emission_attribute(change.group));
  if (bins.empty())
    throw InputError(fmt::format(
        "{}: light group '{}' has no spectral bins, in which a change of spectrum ({}) divides out: render "
        "with --spectral-bins N (docs/lights.md, \"Relighting\")",
        file, change.group, change.spectrum_text));
  if (recorded == image.string_attributes.end())
    throw InputError(fmt::format(
        "{}: light group '{}' has no one emission spectrum to change ({}): its lights emit different "
        "spectra, "
        "one is a map or a textured emissive surface, or it is \"other\" (docs/lights.md, \"Relighting\")",
        file, change.group, change.spectrum_text));
  const std::optional<std::vector<double>> from = parse_emission_shape(recorded->second);
  if (!from)
    throw InputError(
        fmt::format("{}: {}: expected {} numbers >= 0", file, recorded->first, kEmissionShapeCount));
  const std::optional<std::vector<double>> to = emission_shape(*change.spectrum);
  if (!to)
    throw InputError(
        fmt::format("--group {}:{}: the spectrum has no luminance", change.group, change.spectrum_text));
  const float first = bins.begin()->first, last = bins.rbegin()->first;
  const int count = static_cast<int>(bins.size());
  const double width = count > 1 ? (static_cast<double>(last) - first) / (count - 1) : 470.0;
  const double lambda_min = count > 1 ? first - width / 2 : 360.0;
  const double lambda_max = lambda_min + width * count;
  BinWeights w;
  const auto space = image.string_attributes.find("ochre.colorspace");
  const std::optional<ColorSpace> working =
      space == image.string_attributes.end() ? ColorSpace::LinearRec709 : kWorkingSpaces.parse(space->second);
  if (cie_render(image) && working) {
    w.weights = emission_bin_ratios_xyz(*from, *to, count, lambda_min, lambda_max);
    w.to_xyz = rgb_to_xyz_matrix(*working);
    w.to_rgb = xyz_to_rgb_matrix(*working);
  } else {
    for (const double r : emission_bin_ratios(*from, *to, count, lambda_min, lambda_max))
      w.weights.push_back({r, r, r});
  }
  for (std::array<double, 3>& bin : w.weights)
    for (double& v : bin) v *= change.scale;
  return w;
}

}  // namespace

std::vector<std::string> light_group_names(const ExrImage& image, const std::string& file) {
  const auto listed = image.string_attributes.find("ochre.lightGroups");
  if (listed == image.string_attributes.end() || listed->second.empty())
    throw InputError(
        fmt::format("{}: has no light groups (attribute ochre.lightGroups): render a scene whose "
                    "lights name groups (docs/lights.md, \"Light groups\")",
                    file));
  return split(listed->second, ',');
}

std::vector<std::string> group_bin_layer_names(const ExrImage& image, const std::string& group) {
  std::vector<std::string> names;
  for (const auto& [centre, name] : group_bin_layers(image, group)) names.push_back(name);
  return names;
}

Array3d BinWeights::apply(size_t bin, const Array3d& rgb) const {
  Array3d xyz = to_xyz * rgb;
  for (size_t k = 0; k < 3; ++k) xyz[k] *= weights[bin][k];
  return to_rgb * xyz;
}

BinWeights group_bin_weights(const ExrImage& image, const GroupChange& change, const std::string& file) {
  return bin_weights(image, file, change, group_bin_layers(image, change.group));
}

GroupChange parse_group_change(std::string_view text) {
  const size_t colon = text.find(':');
  GroupChange change;
  change.group = std::string(text.substr(0, colon));
  if (change.group.empty() || colon == std::string_view::npos)
    throw InputError(fmt::format("--group '{}': expected NAME:scale=S, NAME:off or NAME:on", text));
  for (const std::string& item : split(text.substr(colon + 1), ',')) {
    if (item == "off") {
      change.scale = 0.0;
      continue;
    }
    if (item == "on") continue;
    const size_t equals = item.find('=');
    const std::string key = item.substr(0, equals);
    const std::string value = equals == std::string::npos ? "" : item.substr(equals + 1);
    if (key == "scale") {
      double scale = -1.0;
      const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), scale);
      if (error != std::errc() || end != value.data() + value.size() || !std::isfinite(scale) || scale < 0.0)
        throw InputError(
            fmt::format("--group '{}': scale must be a finite number >= 0, got '{}'", text, value));
      change.scale *= scale;
    } else if (key == "cct" || key == "spectrum") {
      if (change.spectrum)
        throw InputError(
            fmt::format("--group '{}': one change of spectrum per group (cct= or spectrum=)", text));
      change.spectrum = new_emission(text, key, value);
      change.spectrum_text = item;
    } else {
      throw InputError(fmt::format(
          "--group '{}': unknown change '{}' (known: scale=S, off, on, cct=T, spectrum=NAME|FILE.csv)", text,
          item));
    }
  }
  return change;
}

ExrImage relight(const ExrImage& image, const std::vector<GroupChange>& changes, const std::string& file) {
  const std::vector<std::string> groups = light_group_names(image, file);
  std::map<std::string, GroupChange> change;
  for (const std::string& g : groups) change[g].group = g;
  std::map<std::string, int> named;
  for (const GroupChange& c : changes) {
    if (!change.count(c.group))
      throw InputError(fmt::format("{}: no light group '{}' (the render has: {})", file, c.group,
                                   fmt::join(groups, ", ")));
    if (named[c.group]++) throw InputError(fmt::format("--group {}: given twice", c.group));
    change[c.group] = c;
  }
  const size_t n = static_cast<size_t>(image.width) * image.height;
  ExrImage out;
  out.width = image.width;
  out.height = image.height;
  out.chromaticities = image.chromaticities;
  out.string_attributes = image.string_attributes;
  std::array<std::vector<float>, 3> rgb{std::vector<float>(n, 0.0f), std::vector<float>(n, 0.0f),
                                        std::vector<float>(n, 0.0f)};
  const auto channel = [&](const std::string& name, const std::string& g) {
    const std::vector<float>* layer = image.find_channel(name);
    if (!layer || layer->size() != n)
      throw InputError(
          fmt::format("{}: channel {} missing (ochre.lightGroups lists group '{}')", file, name, g));
    return layer;
  };
  for (const std::string& g : groups) {
    const GroupChange& c = change[g];
    const std::map<float, std::string> bins = group_bin_layers(image, g);
    const auto rgb_of = [&](const std::string& layer) {
      return std::array<const std::vector<float>*, 3>{channel(layer + ".R", g), channel(layer + ".G", g),
                                                      channel(layer + ".B", g)};
    };
    // A change of spectrum weighs the bins (BinWeights); a change of scale scales the group and its bins.
    const bool spectral = c.spectrum != nullptr;
    const BinWeights weights = spectral ? bin_weights(image, file, c, bins) : BinWeights{};
    std::array<std::vector<double>, 3> sum{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0),
                                           std::vector<double>(n, 0.0)};
    if (!spectral) {
      const auto group_rgb = rgb_of("group." + g);
      for (int k = 0; k < 3; ++k)
        for (size_t i = 0; i < n; ++i) sum[k][i] = c.scale * (*group_rgb[k])[i];
    }
    size_t b = 0;
    for (const auto& [centre, bin_layer] : bins) {
      const auto values = rgb_of(bin_layer);
      std::array<std::vector<float>, 3> relit_bin{std::vector<float>(n), std::vector<float>(n),
                                                  std::vector<float>(n)};
      for (size_t i = 0; i < n; ++i) {
        const Array3d v{(*values[0])[i], (*values[1])[i], (*values[2])[i]};
        const Array3d r =
            spectral ? weights.apply(b, v) : Array3d{c.scale * v[0], c.scale * v[1], c.scale * v[2]};
        for (int k = 0; k < 3; ++k) {
          relit_bin[k][i] = static_cast<float>(r[k]);
          if (spectral) sum[k][i] += r[k];
        }
      }
      for (int k = 0; k < 3; ++k)
        out.channels.emplace_back(fmt::format("{}.{}", bin_layer, "RGB"[k]), std::move(relit_bin[k]));
      ++b;
    }
    for (int k = 0; k < 3; ++k) {
      std::vector<float> relit(n);
      for (size_t i = 0; i < n; ++i) {
        relit[i] = static_cast<float>(sum[k][i]);
        rgb[k][i] += relit[i];
      }
      out.channels.emplace_back(fmt::format("group.{}.{}", g, "RGB"[k]), std::move(relit));
    }
    if (c.spectrum)
      out.string_attributes[light_group_emission_attribute(g)] =
          format_emission_shape(*emission_shape(*c.spectrum));
  }
  for (int c = 0; c < 3; ++c) out.channels.emplace_back(std::string(1, "RGB"[c]), std::move(rgb[c]));
  for (const auto& [name, values] : image.channels)
    if (kept_without_change(name)) out.channels.emplace_back(name, values);
  std::string applied;
  for (const std::string& g : groups)
    applied += fmt::format("{}{}:scale={}{}{}", applied.empty() ? "" : " ", g, change[g].scale,
                           change[g].spectrum ? "," : "", change[g].spectrum_text);
  out.string_attributes["ochre.relight"] = applied;
  return out;
}

DisplayOptions recorded_display(const ExrImage& image, const std::string& file) {
  DisplayOptions d;
  const auto text = [&](const char* name) {
    const auto it = image.string_attributes.find(name);
    return it == image.string_attributes.end() ? std::string() : it->second;
  };
  d.ocio_config = text("ochre.display.ocioConfig");
  d.display = text("ochre.display.display");
  d.view = text("ochre.display.view");
  d.working_space = text("ochre.colorspace").empty() ? "rec709" : text("ochre.colorspace");
  d.exposure_stops =
      static_cast<float>(attribute_number(image, file, "ochre.display.exposure", -64, 64, 0.0));
  if (const std::string wb = text("ochre.display.whiteBalance"); !wb.empty()) {
    const std::vector<std::string> parts = split(wb, ' ');
    std::array<double, 3> xyz{};
    bool valid = parts.size() == 3;
    for (size_t k = 0; valid && k < 3; ++k) {
      const auto [end, error] = std::from_chars(parts[k].data(), parts[k].data() + parts[k].size(), xyz[k]);
      valid =
          error == std::errc() && end == parts[k].data() + parts[k].size() && xyz[k] > 0.0 && xyz[k] < 1e6;
    }
    if (!valid)
      throw InputError(
          fmt::format("{}: ochre.display.whiteBalance: expected three positive numbers, got '{}'", file, wb));
    d.white_balance_xyz = xyz;
  }
  return d;
}

std::vector<std::string> write_relit(const ExrImage& relit, const DisplayOptions& display,
                                     const std::string& exr, const std::string& png,
                                     const InputFileLog& inputs) {
  if (exr.empty() && png.empty()) throw InputError("relight: no output: give an EXR and/or a PNG path");
  std::vector<std::filesystem::path> paths;
  std::vector<std::uint8_t> pixels;
  try {
    for (const std::string& path : {exr, png})
      if (!path.empty()) {
        check_output_writable(path);
        paths.emplace_back(path);
      }
    if (!png.empty()) {
      std::vector<float> rgb(static_cast<size_t>(relit.width) * relit.height * 3);
      for (int c = 0; c < 3; ++c) {
        const std::vector<float>& channel = *relit.find_channel(std::string(1, "RGB"[c]));
        for (size_t i = 0; i < channel.size(); ++i) rgb[i * 3 + c] = channel[i];
      }
      pixels = to_display_rgb8(relit.width, relit.height, rgb, display);
    }
  } catch (const ImageError& e) {
    throw InputError(e.what());
  }
  check_output_files(paths, inputs);
  OutputTransaction transaction;
  std::vector<std::string> written;
  if (!exr.empty()) {
    write_exr(transaction.add(exr), relit);
    written.push_back("wrote " + exr);
  }
  if (!png.empty()) {
    write_rgb8(transaction.add(png), "png", relit.width, relit.height, pixels, "relit display image");
    written.push_back("wrote " + png);
  }
  transaction.commit();
  return written;
}

}  // namespace ochre
