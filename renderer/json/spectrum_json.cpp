#include "renderer/json/spectrum_json.h"

#include <fmt/format.h>

#include <cmath>
#include <memory>

#include "materials/nodes/resource_resolver.h"
#include "materials/nodes/json_literal.h"
#include "materials/nodes/spectrum_source.h"
#include "renderer/json/json_fields.h"
#include "spectra/constant_spectrum.h"
#include "spectra/input_error.h"
#include "spectra/negative_value.h"
#include "spectra/rgb_spectrum.h"

namespace ochre {

namespace {

SpectrumPtr from_rgb(const nlohmann::json& value, SpectrumRole role, const std::string& where) {
  const Vec3 c = json_vec3(value, where);
  if (c.x < 0 || c.y < 0 || c.z < 0)
    throw InputError(fmt::format("{}: colour components must be >= 0 (got {})", where, json_excerpt(value)));
  const RGB rgb{c.x, c.y, c.z};
  switch (role) {
    case SpectrumRole::Illuminant:
      return std::make_shared<RGBIlluminantSpectrum>(rgb);
    case SpectrumRole::Reflectance:
      if (c.x > 1 || c.y > 1 || c.z > 1)
        throw InputError(
            fmt::format("{}: reflectance components must be <= 1 (got {})", where, json_excerpt(value)));
      return std::make_shared<RGBAlbedoSpectrum>(rgb);
    case SpectrumRole::Unbounded:
      break;
  }
  return std::make_shared<RGBUnboundedSpectrum>(rgb);
}

// Paths in a spectrum object resolve relative to the scene directory.
class SceneDirectory final : public ResourceResolver {
 public:
  explicit SceneDirectory(std::filesystem::path dir) : dir_(std::move(dir)) {}
  std::filesystem::path resolve(const std::string& path) const override {
    const std::filesystem::path p(path);
    return p.is_absolute() ? p : dir_ / p;
  }
  int texture(const std::filesystem::path& file, const std::string&, int&) override {
    throw std::runtime_error("textures are not allowed here: " + file.string());
  }

 private:
  std::filesystem::path dir_;
};

SpectrumPtr from_object(const nlohmann::json& value, const std::string& where,
                        const std::filesystem::path& scene_dir) {
  const SceneDirectory directory(scene_dir);
  SpectrumPtr spectrum;
  try {
    spectrum = spectrum_from_object(value, directory);
  } catch (const SpectrumObjectError& e) {
    throw InputError(fmt::format("{}{}: {}", where, e.key.empty() ? "" : "." + e.key, e.what()));
  }
  // Named spectra and blackbodies are >= 0 and the scale is checked: only a table can be negative.
  if (const auto negative = first_negative_value(*spectrum)) {
    const std::string file = value.contains("file") ? value["file"].get<std::string>() : "";
    const char* key = !file.empty() ? ".file" : value.contains("values") ? ".values" : "";
    throw InputError(
        fmt::format("{}{}: {}negative value {} at {} nm (spectra of lights, emission and "
                    "reflectances must be >= 0 at every wavelength)",
                    where, key, file.empty() ? "" : file + ": ", negative->value, negative->lambda_nm));
  }
  return spectrum;
}

}  // namespace

SpectrumPtr parse_spectrum(const nlohmann::json& value, SpectrumRole role, const std::string& where,
                           const std::filesystem::path& scene_dir) {
  if (value.is_number())
    return std::make_shared<ConstantSpectrum>(static_cast<float>(json_number(value, where, 0.0)));
  if (value.is_array()) return from_rgb(value, role, where);
  if (value.is_object()) return from_object(value, where, scene_dir);
  throw InputError(
      fmt::format("{}: expected a spectrum (number, [r, g, b] or object), got {}", where, value.dump()));
}

}  // namespace ochre
