#include "renderer/lights/environment_light.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "materials/core/sampling.h"
#include "renderer/json/spectrum_json.h"
#include "renderer/lights/light_type.h"
#include "spectra/cie.h"
#include "spectra/rgb_spectrum.h"

namespace ochre {

EnvironmentLight::EnvironmentLight(SpectrumPtr radiance, float scene_radius, float scale)
    : radiance_(std::move(radiance)),
      scene_radius_(scene_radius),
      scale_(scale),
      mean_luminance_(spectrum_to_xyz(*radiance_).y) {}

EnvironmentLight::EnvironmentLight(std::shared_ptr<const EnvironmentMap> map, float scene_radius, float scale,
                                   float rotation_degrees)
    : map_(std::move(map)),
      d65_(d65()),
      scene_radius_(scene_radius),
      scale_(scale),
      mean_luminance_(map_->mean_luminance()) {
  const double radians = rotation_degrees * M_PI / 180.0;
  cos_rotation_ = static_cast<float>(std::cos(radians));
  sin_rotation_ = static_cast<float>(std::sin(radians));
  texel_spectra_.resize(map_->texel_key_count() / Distribution2D::kCellsPerBlock);
  for (int row = 0; row < map_->height(); ++row)
    for (int column = 0; column < map_->width(); ++column) {
      const UnboundedRGB texel = decompose_unbounded(map_->texel(column, row));
      if (!(texel.scale > 0.0f)) continue;
      const size_t key = map_->texel_key(column, row);
      texel_spectra_[key / Distribution2D::kCellsPerBlock].texel[key % Distribution2D::kCellsPerBlock] = {
          texel.poly, texel.scale};
    }
}

// map_to_world is the right-handed rotation R_y(angle): (x, z) -> (c x + s z, -s x + c z);
// world_to_map is its inverse R_y(-angle).
Vec3 EnvironmentLight::world_to_map(const Vec3& d) const {
  return {cos_rotation_ * d.x - sin_rotation_ * d.z, d.y, sin_rotation_ * d.x + cos_rotation_ * d.z};
}

Vec3 EnvironmentLight::map_to_world(const Vec3& d) const {
  return {cos_rotation_ * d.x + sin_rotation_ * d.z, d.y, -sin_rotation_ * d.x + cos_rotation_ * d.z};
}

// RGBIlluminantSpectrum(rgb).sample(lambda) (spectra/rgb_spectrum.cpp) without building the object:
// m = 2 max(rgb), sigmoid polynomial of rgb / m, times m times D65; times the light's scale. D65 x scale is
// the same for every texel a path sees, so it is memoized per thread for the path's wavelengths.
SampledSpectrum EnvironmentLight::texel_radiance(size_t key, const SampledWavelengths& lambda) const {
  const TexelSpectrum& t = texel_spectrum(key);
  if (!(t.m > 0.0f)) return SampledSpectrum(0.0f);
  SampledSpectrum s = memo_sampled(white_memo_key_, lambda, [&] { return d65_->sample(lambda) * scale_; });
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] *= t.m * t.poly.eval(lambda[i]);
  return s;
}

std::optional<LightSample> EnvironmentLight::sample(const Vec3&, const Vec2& u,
                                                    const SampledWavelengths& lambda) const {
  LightSample s;
  s.distance = INFINITY;
  if (!map_) {
    s.wi = sample_uniform_sphere(u);
    s.radiance = radiance_->sample(lambda) * scale_;
    s.pdf = kUniformSpherePdf;
    return s;
  }
  // The texel's spectrum is read after the inversion inside the block, which waits for the block's line:
  // prefetching the block's 16 spectra (4 lines) as soon as the block is known overlaps the two misses.
  const Distribution2D::BlockChoice block = map_->distribution().choose_block(u);
  const char* spectra = reinterpret_cast<const char*>(&texel_spectra_[block.block]);
  for (size_t offset = 0; offset < sizeof(BlockSpectra); offset += 64) __builtin_prefetch(spectra + offset);
  const EnvironmentMap::Sample m = map_->sample_in_block(block);
  if (!(m.pdf > 0.0f)) return std::nullopt;
  s.wi = map_to_world(m.direction);
  s.radiance = texel_radiance(m.key, lambda);
  s.pdf = m.pdf;
  return s;
}

float EnvironmentLight::power() const {
  // Flux of the radiance field through the scene's bounding sphere (pbrt's estimate):
  // pi r^2 x (integral of L over the sphere) = 4 pi^2 r^2 x mean luminance.
  return static_cast<float>(4.0 * M_PI * M_PI * scene_radius_ * scene_radius_ * mean_luminance_ * scale_);
}

float EnvironmentLight::importance(const Vec3&) const {
  // The illuminance of a plane under a whole sky of the mean radiance.
  return static_cast<float>(kPi * mean_luminance_ * scale_);
}

SampledSpectrum EnvironmentLight::radiance(const Vec3& direction, const SampledWavelengths& lambda) const {
  if (!map_) return radiance_->sample(lambda) * scale_;
  return texel_radiance(map_->texel_key(world_to_map(direction)), lambda);
}

SampledSpectrum EnvironmentLight::radiance(const Vec3& direction, const SampledWavelengths& lambda,
                                           float* pdf) const {
  if (!map_) {
    *pdf = kUniformSpherePdf;
    return radiance_->sample(lambda) * scale_;
  }
  return texel_radiance(map_->texel_key_and_pdf(world_to_map(direction), pdf), lambda);
}

float EnvironmentLight::pdf(const Vec3& direction) const {
  if (!map_) return kUniformSpherePdf;
  return map_->pdf(world_to_map(direction));
}

namespace {

BuiltLight build_environment(const LightContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const auto scale = static_cast<float>(f.number("scale"));
  const auto rotation = static_cast<float>(f.number("rotation"));
  if (f.has("radiance") == f.has("file"))
    f.fail("", "an environment light needs exactly one of 'radiance' (constant) and 'file' (HDR map)");
  if (f.has("radiance")) {  // a rotation is accepted and has no effect on a constant
    const JsonFields& j = f.fields();
    return {std::make_unique<EnvironmentLight>(
                parse_spectrum(j.require("radiance"), SpectrumRole::Illuminant, j.child("radiance"), ctx.dir),
                ctx.scene_radius, scale),
            std::nullopt, f.has("scale") ? "scale" : "radiance"};
  }
  const std::filesystem::path path = ctx.dir / f.string("file");
  std::shared_ptr<const EnvironmentMap> map;
  try {
    map = std::make_shared<const EnvironmentMap>(EnvironmentMap::load(path));
  } catch (const std::exception& e) {
    f.fail("file", fmt::format("cannot read environment map '{}': {}", path.string(), e.what()));
  }
  return {std::make_unique<EnvironmentLight>(std::move(map), ctx.scene_radius, scale, rotation), std::nullopt,
          f.has("scale") ? "scale" : "file"};
}

}  // namespace

LightType environment_light_type() {
  return {
      "environment",
      "light arriving from every direction at infinity: a constant `radiance` or an HDR latitude-longitude "
      "map `file`, importance-sampled; one per scene",
      {spectrum_field("radiance", false, "a spectrum arriving from every direction (not with `file`)"),
       string_field("file", false,
                    "a lat-long HDR map (.hdr, .exr; linear Rec.709 texels), relative to the scene file"),
       number_field("scale", 1.0, 0.0, kNoMaximum, "multiplies the radiance"),
       number_field("rotation", 0.0, kNoMinimum, kNoMaximum,
                    "degrees about +y, counter-clockwise seen from above (maps only)")},
      true,
      build_environment};
}

}  // namespace ochre
