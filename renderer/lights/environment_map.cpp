// Lat-long environment map: image, direction <-> (u, v) mapping and importance sampling
// (see environment_map.h for the convention and the formulas).

#include "renderer/lights/environment_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <system_error>

#include "renderer/image/image_library.h"
#include "renderer/util/memory_budget.h"
#include "spectra/color_space.h"
#include "spectra/input_file.h"
#include "spectra/non_finite.h"

namespace ochre {

namespace {

// Texel luminance Y of linear Rec.709 RGB, with the project's D65 white (RGB (1,1,1) -> Y = 1).
double luminance(const RGB& rgb) {
  return rgb_to_xyz(rgb, ColorSpace::LinearRec709).y;
}

// Solid angle of one texel of row `row`: (2 pi / width) * (cos theta_top - cos theta_bottom).
double texel_solid_angle(int row, int width, int height) {
  const double theta0 = M_PI * row / height, theta1 = M_PI * (row + 1) / height;
  return 2.0 * M_PI / width * (std::cos(theta0) - std::cos(theta1));
}

// dw = sin(theta) dtheta dphi = 2 pi^2 sin(theta) du dv: the solid-angle density of a (u, v) density.
float solid_angle_pdf(float pdf_uv, float sin_theta) {
  return sin_theta > 0.0f ? pdf_uv / (2.0f * kPi * kPi * sin_theta) : 0.0f;
}

}  // namespace

Vec2 direction_to_equirect_uv(const Vec3& direction) {
  const Vec3 d = normalize(direction);
  const float phi = std::atan2(d.x, -d.z);
  const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
  float u = 0.5f + phi * (0.5f / kPi);
  if (!(u < 1.0f)) u = 0.0f;  // phi = pi (+z) belongs to the seam at u = 0; also NaN
  return {std::max(u, 0.0f), nan_safe_clamp(theta / kPi, 0.0f, 1.0f)};  // a NaN direction gives (0, 0)
}

Vec3 equirect_uv_to_direction(const Vec2& uv) {
  const float phi = 2.0f * kPi * (uv.x - 0.5f);
  const float theta = kPi * uv.y;
  const float sin_theta = std::sin(theta);
  return {sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi)};
}

EnvironmentMap::EnvironmentMap(int width, int height, std::vector<RGB> rgb)
    : width_(width), height_(height), rgb_(std::move(rgb)) {
  if (width < 1 || height < 1 || rgb_.size() != static_cast<size_t>(width) * static_cast<size_t>(height))
    throw std::invalid_argument(
        fmt::format("environment map: expected {} x {} texels, got {}", width, height, rgb_.size()));
  std::vector<double> lum(rgb_.size());
  double total = 0.0;
  for (int row = 0; row < height; ++row) {
    double row_sum = 0.0;
    for (int column = 0; column < width; ++column) {
      const size_t i = static_cast<size_t>(row) * width + column;
      for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(rgb_[i][c]))
          throw std::invalid_argument(fmt::format("texel (column {}, row {}) is not finite", column, row));
        // A light never emits negative radiance (docs/scene-format.md, "Validation").
        if (rgb_[i][c] < 0.0f)
          throw std::invalid_argument(fmt::format("texel (column {}, row {}) is negative ({}, {}, {})",
                                                  column, row, rgb_[i].r, rgb_[i].g, rgb_[i].b));
      }
      lum[i] = luminance(rgb_[i]);
      row_sum += lum[i];
    }
    total += row_sum * texel_solid_angle(row, width, height);
  }
  mean_luminance_ = total / (4.0 * M_PI);

  // Sampling weights: luminance x sin(theta) is proportional to the texel's power in (u, v) space.
  double mean_texel = 0.0;
  for (double l : lum) mean_texel += l;
  mean_texel /= static_cast<double>(lum.size());
  const double floor = mean_texel > 0.0 ? 1e-3 * mean_texel : 1.0;
  for (int row = 0; row < height; ++row) {
    const double sin_theta = std::sin(M_PI * (row + 0.5) / height);
    for (int column = 0; column < width; ++column) {
      double& w = lum[static_cast<size_t>(row) * width + column];
      w = (w + floor) * sin_theta;
    }
  }
  distribution_ = Distribution2D(lum, width, height);
}

EnvironmentMap EnvironmentMap::load(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw std::runtime_error("no such file");
  check_regular_input(path, kEnvironmentMapInput);  // a FIFO or a device is refused before OIIO opens it
  const ImageLibrary& library = image_library();
  const ImageHeader spec = library.read_header(path.string());
  if (spec.width < 1 || spec.height < 1 || spec.channels < 1) throw std::runtime_error("the image is empty");
  if (!spec.floating_point)
    throw std::runtime_error(fmt::format(
        "expected a linear HDR image (.hdr or .exr, floating-point pixels), got {} pixels", spec.pixel_type));
  const int channels = spec.channels;
  // The float pixels, the RGB texels, the luminance (double) and the sampling distribution (2 floats).
  check_memory_estimate(static_cast<double>(spec.width) * spec.height *
                            static_cast<double>(channels * sizeof(float) + sizeof(RGB) + sizeof(double) + 8),
                        fmt::format("environment map {} ({}x{})", path.string(), spec.width, spec.height));
  const std::vector<float> pixels = library.read_float(path.string(), 0, {spec.width, spec.height, channels});
  std::vector<RGB> rgb(static_cast<size_t>(spec.width) * spec.height);
  for (size_t i = 0; i < rgb.size(); ++i) {
    const float* p = &pixels[i * channels];
    rgb[i] = channels >= 3 ? RGB{p[0], p[1], p[2]} : RGB{p[0], p[0], p[0]};
  }
  try {
    return EnvironmentMap(spec.width, spec.height, std::move(rgb));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }
}

size_t EnvironmentMap::texel_index(const Vec3& direction) const {
  const Vec2 uv = direction_to_equirect_uv(direction);
  return static_cast<size_t>(distribution_.row_of(uv.y)) * width_ + distribution_.column_of(uv.x);
}

size_t EnvironmentMap::texel_key(const Vec3& direction) const {
  const Vec2 uv = direction_to_equirect_uv(direction);
  return distribution_.cell_key(distribution_.column_of(uv.x), distribution_.row_of(uv.y));
}

EnvironmentMap::Sample EnvironmentMap::sample_in_block(const Distribution2D::BlockChoice& choice) const {
  const Distribution2D::Sample s = distribution_.sample_in_block(choice);
  Sample result;
  result.direction = equirect_uv_to_direction(s.uv);
  result.index = static_cast<size_t>(s.row) * width_ + s.column;
  result.key = s.key;
  // sin theta from the direction, as texel_key_and_pdf() computes it for a ray escaping that way.
  const Vec3& d = result.direction;
  result.pdf = solid_angle_pdf(s.pdf, std::sqrt(d.x * d.x + d.z * d.z));
  return result;
}

size_t EnvironmentMap::texel_key_and_pdf(const Vec3& direction, float* pdf) const {
  const Vec3 d = normalize(direction);
  const Vec2 uv = direction_to_equirect_uv(d);
  const size_t key = distribution_.cell_key(distribution_.column_of(uv.x), distribution_.row_of(uv.y));
  *pdf = solid_angle_pdf(distribution_.pdf_of_key(key), std::sqrt(d.x * d.x + d.z * d.z));
  return key;
}

float EnvironmentMap::pdf(const Vec3& direction) const {
  const Vec3 d = normalize(direction);
  const float sin_theta = std::sqrt(d.x * d.x + d.z * d.z);
  if (!(sin_theta > 0.0f)) return 0.0f;
  return solid_angle_pdf(distribution_.pdf(direction_to_equirect_uv(d)), sin_theta);
}

}  // namespace ochre
