#include "renderer/compare/regression_compare.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "renderer/compare/image_metrics.h"
#include "renderer/output/render_output.h"
#include "renderer/output/stokes_output.h"
#include "renderer/util/atomic_file.h"
#include "spectra/input_error.h"

namespace ochre {
namespace {

// Variance floor added to every pixel: an absolute part so two exactly black pixels give z = 0, and a
// part relative to the reference mean for the float rounding of the stored reference (2^-23 relative).
constexpr double kAbsoluteVarianceFloor = 1e-14;
constexpr double kRelativeStdFloor = 1e-6;

const char* const kRgbNames[3] = {"R", "G", "B"};

}  // namespace

double sidak_pixel_level(double alpha, size_t pixels) {
  if (pixels == 0) return alpha;
  // 1 - (1 - alpha)^(1/n) = -expm1(log1p(-alpha) / n)
  return -std::expm1(std::log1p(-alpha) / static_cast<double>(pixels));
}

double two_sided_p_value(double z) {
  return std::erfc(std::fabs(z) / std::sqrt(2.0));
}

LuminanceEstimate luminance_from_film(const Film& film) {
  LuminanceEstimate e;
  e.width = film.width();
  e.height = film.height();
  const size_t n = static_cast<size_t>(e.width) * e.height;
  e.mean_y.resize(n);
  e.variance_of_mean.resize(n);
  for (int y = 0; y < e.height; ++y) {
    for (int x = 0; x < e.width; ++x) {
      const size_t i = static_cast<size_t>(y) * e.width + x;
      const uint64_t count = film.sample_count(x, y);
      e.mean_y[i] = film.mean(x, y).y;
      e.variance_of_mean[i] = count > 0 ? film.variance_y(x, y) / static_cast<double>(count) : 0.0;
      e.samples_per_pixel = std::max(e.samples_per_pixel, static_cast<double>(count));
    }
  }
  return e;
}

RegressionResult compare_luminance(const LuminanceEstimate& test, const LuminanceEstimate& reference,
                                   double alpha) {
  if (test.width != reference.width || test.height != reference.height)
    throw std::invalid_argument("compare_luminance: test is " + std::to_string(test.width) + "x" +
                                std::to_string(test.height) + ", reference is " +
                                std::to_string(reference.width) + "x" + std::to_string(reference.height));
  RegressionResult r;
  r.width = test.width;
  r.height = test.height;
  r.alpha = alpha;
  const size_t n = static_cast<size_t>(r.width) * r.height;
  r.alpha_pixel = sidak_pixel_level(alpha, n);
  r.p_values.resize(n);
  r.z_scores.resize(n);
  // Under the null hypothesis both renders sample the same distribution, so the reference's per-sample
  // variance (from 16x more samples, far better estimated) also bounds the test's: a test pixel whose
  // few samples all missed a rare bright path must not look noise-free.
  const double ref_to_test =
      test.samples_per_pixel > 0 ? reference.samples_per_pixel / test.samples_per_pixel : 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double var_test = std::max(test.variance_of_mean[i], reference.variance_of_mean[i] * ref_to_test);
    const double relative_floor = kRelativeStdFloor * std::fabs(reference.mean_y[i]);
    const double variance =
        var_test + reference.variance_of_mean[i] + kAbsoluteVarianceFloor + relative_floor * relative_floor;
    const double z = (test.mean_y[i] - reference.mean_y[i]) / std::sqrt(variance);
    const double p = std::isfinite(z) ? two_sided_p_value(z) : 0.0;  // NaN/Inf renders always fail
    r.z_scores[i] = z;
    r.p_values[i] = p;
    if (p < r.alpha_pixel) ++r.failing_pixels;
    if (i == 0 || p < r.worst_p) {
      r.worst_p = p;
      r.worst_x = static_cast<int>(i % r.width);
      r.worst_y = static_cast<int>(i / r.width);
    }
  }
  return r;
}

ExrImage make_reference_image(const Film& film, const std::vector<float>& rgb, uint32_t spp) {
  const LuminanceEstimate e = luminance_from_film(film);
  ExrImage image;
  image.width = e.width;
  image.height = e.height;
  const size_t n = e.mean_y.size();
  for (int c = 0; c < 3; ++c) {
    std::vector<float> plane(n);
    for (size_t p = 0; p < n; ++p) plane[p] = rgb[3 * p + c];
    image.channels.emplace_back(kRgbNames[c], std::move(plane));
  }
  image.channels.emplace_back("Y", std::vector<float>(e.mean_y.begin(), e.mean_y.end()));
  image.channels.emplace_back("variance.Y",
                              std::vector<float>(e.variance_of_mean.begin(), e.variance_of_mean.end()));
  image.string_attributes["ochre:regress_spp"] = std::to_string(spp);
  // The layers the scene asks for, for the HTML report's pixel readout (ochre-regress --html).
  if (film.has_stokes()) add_stokes_channels(film, image);
  if (film.spectral_bins() > 0) add_spectral_channels(film, image);
  return image;
}

LuminanceEstimate luminance_from_reference(const ExrImage& image, const std::filesystem::path& file) {
  const auto require = [&](const char* name) {
    const std::vector<float>* channel = image.find_channel(name);
    if (!channel)
      throw InputError(file.string() + ": channel '" + name +
                       "' missing (not a reference written by ochre-regress --update)");
    return channel;
  };
  const auto spp = image.string_attributes.find("ochre:regress_spp");
  if (spp == image.string_attributes.end())
    throw InputError(file.string() +
                     ": attribute 'ochre:regress_spp' missing (not a reference written by "
                     "ochre-regress --update)");
  LuminanceEstimate e;
  e.width = image.width;
  e.height = image.height;
  // A bad reference is bad input, never a render regression: the sample count must be a whole number of at
  // least 1, every mean finite and every variance finite and >= 0 (fmt/strtod accept "nan" and "inf").
  const std::string& text = spp->second;
  char* end = nullptr;
  const double count = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(count) || count < 1.0 || count != std::floor(count))
    throw InputError(
        fmt::format("{}: attribute 'ochre:regress_spp': expected a sample count of at least 1, got "
                    "'{}' (regenerate the reference with ochre-regress --update)",
                    file.string(), text));
  e.samples_per_pixel = count;
  const std::vector<float>* y = require("Y");
  const std::vector<float>* variance = require("variance.Y");
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  for (size_t i = 0; i < pixels; ++i) {
    const float mean = (*y)[i], var = (*variance)[i];
    if (!std::isfinite(mean) || !std::isfinite(var) || var < 0.0f)
      throw InputError(fmt::format(
          "{}: pixel ({}, {}): {} (regenerate the reference with ochre-regress "
          "--update)",
          file.string(), i % image.width, i / image.width,
          !std::isfinite(mean) ? fmt::format("Y is {}", mean) : fmt::format("variance.Y is {}", var)));
  }
  e.mean_y.assign(y->begin(), y->end());
  e.variance_of_mean.assign(variance->begin(), variance->end());
  return e;
}

ExrImage p_value_image(const RegressionResult& result) {
  ExrImage image;
  image.width = result.width;
  image.height = result.height;
  image.channels.emplace_back("p.Y", std::vector<float>(result.p_values.begin(), result.p_values.end()));
  image.channels.emplace_back("z.Y", std::vector<float>(result.z_scores.begin(), result.z_scores.end()));
  return image;
}

void write_p_value_heatmap(const std::filesystem::path& path, const RegressionResult& result) {
  AtomicOutput output(path);
  write_p_value_heatmap(output, result);
  output.commit();
}

void write_p_value_heatmap(AtomicOutput& output, const RegressionResult& result) {
  std::vector<float> significance(result.p_values.size());
  for (size_t i = 0; i < significance.size(); ++i)
    significance[i] = static_cast<float>(-std::log10(std::max(result.p_values[i], 1e-300)));
  write_heatmap_png(output, result.width, result.height, significance, -2.0 * std::log10(result.alpha_pixel));
}

}  // namespace ochre
