#include "tools/vgroove/vgroove_maps.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>

#include "tools/vgroove/vgroove_colour.h"
#include "tools/vgroove/vgroove_spectral.h"

namespace ochre {

namespace {

constexpr std::array<std::uint8_t, 3> kWhite{255, 255, 255};

void put(std::vector<std::uint8_t>& image, size_t pixel, const std::array<std::uint8_t, 3>& rgb) {
  for (int c = 0; c < 3; ++c) image[3 * pixel + c] = rgb[c];
}

}  // namespace

std::optional<LambertDirection> lambert_pixel_direction(int column, int row, int size) {
  const double radius = std::numbers::sqrt2;
  const double u = ((column + 0.5) / size * 2.0 - 1.0) * radius;
  const double v = (1.0 - (row + 0.5) / size * 2.0) * radius;
  const double r = std::hypot(u, v);
  if (r >= radius) return std::nullopt;
  return LambertDirection{2.0 * std::asin(0.5 * r), std::atan2(v, u)};
}

std::array<std::uint8_t, 3> count_colour(int reflections) {
  switch (reflections) {
    case 0:
      return kWhite;
    case 1:
      return {211, 211, 211};
    case 2:
      return {68, 119, 170};
    case 3:
      return {238, 153, 51};
    case 4:
      return {204, 51, 17};
    default:
      return {119, 51, 136};
  }
}

ReflectanceMaps reflectance_maps(const VGrooveMaterial& material, double alpha_deg, ChainModel model,
                                 int size) {
  const VGroove groove(alpha_deg * std::numbers::pi / 180.0);
  const std::vector<FacetIndex> facets = facets_at(material, colour_wavelengths());
  ReflectanceMaps maps;
  maps.size = size;
  maps.colour.assign(3 * static_cast<size_t>(size) * size, 255);
  maps.counts.assign(maps.colour.size(), 255);
  tbb::parallel_for(0, size, [&](int row) {
    for (int column = 0; column < size; ++column) {
      const std::optional<LambertDirection> d = lambert_pixel_direction(column, row, size);
      if (!d) continue;
      const DirectionalColour c = directional_colour(groove, d->theta, d->phi, model, facets);
      const size_t pixel = static_cast<size_t>(row) * size + column;
      put(maps.colour, pixel, lab_to_srgb8(c.lab));
      put(maps.counts, pixel, count_colour(c.max_reflections));
    }
  });
  return maps;
}

}  // namespace ochre
