#include "renderer/output/stokes_output.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/image/display_image.h"
#include "renderer/util/atomic_file.h"

namespace ochre {

float degree_of_linear_polarization(float s0, float s1, float s2) {
  if (!(s0 > 0.0f)) return 0.0f;
  return std::sqrt(s1 * s1 + s2 * s2) / s0;
}

float angle_of_linear_polarization(float s1, float s2) {
  return 0.5f * std::atan2(s2, s1);
}

void add_stokes_channels(const Film& film, ExrImage& image) {
  const size_t n = static_cast<size_t>(film.width()) * film.height();
  const char* axes[3] = {"X", "Y", "Z"};
  std::vector<std::vector<float>> stokes(12, std::vector<float>(n));
  std::vector<float> dolp(n), aolp(n);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const size_t i = static_cast<size_t>(y) * film.width() + x;
      XYZ c[4] = {film.mean(x, y), film.mean_stokes(x, y, 1), film.mean_stokes(x, y, 2),
                  film.mean_stokes(x, y, 3)};
      for (int k = 0; k < 4; ++k) {
        stokes[3 * k + 0][i] = c[k].x;
        stokes[3 * k + 1][i] = c[k].y;
        stokes[3 * k + 2][i] = c[k].z;
      }
      dolp[i] = degree_of_linear_polarization(c[0].y, c[1].y, c[2].y);
      aolp[i] = angle_of_linear_polarization(c[1].y, c[2].y);
    }
  for (int k = 0; k < 4; ++k)
    for (int a = 0; a < 3; ++a)
      image.channels.emplace_back("stokes.S" + std::to_string(k) + "." + axes[a],
                                  std::move(stokes[3 * k + a]));
  image.channels.emplace_back("DoLP", std::move(dolp));
  image.channels.emplace_back("AoLP", std::move(aolp));
  // S3 > 0 is right-circular polarization seen by the sensor looking back at the source.
  image.string_attributes["polarisationHandedness"] = "right";
  image.string_attributes["ochre.stokesFrame"] = "x = image x axis, y = image up, seen from the camera";
}

namespace {

// HSV with full saturation to RGB in [0, 1].
void hue_value_to_rgb(float hue01, float value, float rgb[3]) {
  const float h = (hue01 - std::floor(hue01)) * 6.0f;
  const int sector = std::min(5, static_cast<int>(h));
  const float f = h - static_cast<float>(sector);
  const float rising = value * f, falling = value * (1.0f - f);
  const float table[6][3] = {{value, rising, 0},  {falling, value, 0}, {0, value, rising},
                             {0, falling, value}, {rising, 0, value},  {value, 0, falling}};
  for (int c = 0; c < 3; ++c) rgb[c] = table[sector][c];
}

}  // namespace

void write_polarization_png(const std::filesystem::path& path, const Film& film) {
  AtomicOutput output(path);
  write_polarization_png(output, film);
  output.commit();
}

void write_polarization_png(AtomicOutput& output, const Film& film) {
  std::vector<std::uint8_t> pixels(static_cast<size_t>(film.width()) * film.height() * 3);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const XYZ s0 = film.mean(x, y), s1 = film.mean_stokes(x, y, 1), s2 = film.mean_stokes(x, y, 2);
      const float dolp = std::clamp(degree_of_linear_polarization(s0.y, s1.y, s2.y), 0.0f, 1.0f);
      const float aolp = angle_of_linear_polarization(s1.y, s2.y);  // (-pi/2, pi/2]
      float rgb[3];
      hue_value_to_rgb(aolp / 3.14159265f, dolp, rgb);  // 0 deg red, 60 green, 120 blue
      for (int c = 0; c < 3; ++c)
        pixels[(static_cast<size_t>(y) * film.width() + x) * 3 + c] = quantize_unorm8(rgb[c]);
    }
  write_rgb8(output, "png", film.width(), film.height(), pixels,
             "ochre polarization: hue = angle of linear polarization (0..180 deg from the image x axis), "
             "brightness = degree of linear polarization");
}

}  // namespace ochre
