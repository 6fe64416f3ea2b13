#include "tools/brdf/material_probe.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "materials/graph/material_compiler.h"
#include "materials/nodes/resource_resolver.h"
#include "renderer/json/json_file.h"
#include "renderer/texture/texture_system.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

// The material's JSON and its name: the whole file, or one entry of its "materials" object.
std::pair<nlohmann::json, std::string> select_material(const nlohmann::json& root,
                                                       const std::filesystem::path& file,
                                                       const std::string& wanted) {
  if (!root.is_object())
    throw InputError(fmt::format("{}: expected a JSON object (one material)", file.string()));
  if (!root.contains("materials")) {
    if (!wanted.empty() && wanted != file.stem().string())
      throw InputError(fmt::format("{}: --name {}: the file holds one material (no \"materials\" object)",
                                   file.string(), wanted));
    return {root, file.stem().string()};
  }
  const nlohmann::json& materials = root["materials"];
  if (!materials.is_object() || materials.empty())
    throw InputError(
        fmt::format("{}: materials: expected an object with at least one material", file.string()));
  std::string names;
  for (const auto& [name, value] : materials.items()) names += (names.empty() ? "" : ", ") + name;
  if (wanted.empty()) {
    if (materials.size() != 1)
      throw InputError(fmt::format("{}: materials: {} materials ({}); choose one with --name", file.string(),
                                   materials.size(), names));
    return {materials.begin().value(), materials.begin().key()};
  }
  if (!materials.contains(wanted))
    throw InputError(fmt::format("{}: materials: no material '{}' (have: {})", file.string(), wanted, names));
  return {materials[wanted], wanted};
}

// Files named in the material resolve against the material file's directory; the OIIO texture system is
// created only when a texture is named.
class ProbeResources final : public ResourceResolver {
 public:
  ProbeResources(std::filesystem::path dir, std::unique_ptr<OiioTextureProvider>& textures)
      : dir_(std::move(dir)), textures_(textures) {}
  std::filesystem::path resolve(const std::string& path) const override {
    const std::filesystem::path p(path);
    return p.is_absolute() ? p : dir_ / p;
  }
  int texture(const std::filesystem::path& file, const std::string& colorspace, int& channels) override {
    if (!textures_) textures_ = std::make_unique<OiioTextureProvider>();
    return textures_->add_texture(file, colorspace, channels);
  }

 private:
  std::filesystem::path dir_;
  std::unique_ptr<OiioTextureProvider>& textures_;
};

}  // namespace

MaterialProbe::MaterialProbe(const std::filesystem::path& file, const std::string& material_name)
    : file_(file) {
  const auto [json, name] = select_material(read_json_file(file, "material file"), file, material_name);
  name_ = name;
  compile(json, file.string(), std::filesystem::absolute(file).parent_path());
}

MaterialProbe::MaterialProbe(const nlohmann::json& material, const std::string& name,
                             const std::filesystem::path& base_dir)
    : file_(name), name_(name) {
  compile(material, name, std::filesystem::absolute(base_dir));
}

void MaterialProbe::compile(const nlohmann::json& material, const std::string& label,
                            const std::filesystem::path& dir) {
  ProbeResources resources(dir, textures_);
  try {
    material_ = compile_material(material, name_, label, resources);
  } catch (const nlohmann::json::exception& e) {
    // A read that escaped the graph parser's checks: still bad input in this file.
    throw InputError(fmt::format("{}: material '{}': {}", label, name_, e.what()));
  }
}

MaterialProbe::~MaterialProbe() = default;

const Closure& MaterialProbe::closure(float lambda_nm) {
  if (lambda_nm == evaluated_at_) return closure_;
  if (!(lambda_nm >= kLambdaMin && lambda_nm <= kLambdaMax))
    throw InputError(
        fmt::format("wavelength {} nm is outside [{}, {}] nm", lambda_nm, kLambdaMin, kLambdaMax));
  lambda_ = SampledWavelengths::fixed(SampledSpectrum(lambda_nm));
  ShadingContext ctx;
  ctx.p = {0.0f, 0.0f, 0.0f};
  ctx.n = {0.0f, 0.0f, 1.0f};
  ctx.uv = {0.5f, 0.5f};
  ctx.lambda = &lambda_;
  ctx.textures = textures_.get();
  arena_.reset();
  material_->evaluate(ctx, arena_, closure_);
  evaluated_at_ = lambda_nm;
  return closure_;
}

}  // namespace ochre
