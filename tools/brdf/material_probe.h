#pragma once
// MaterialProbe: one material of the scene format, read from its own JSON file, evaluated as a BSDF in
// its local shading frame (z = normal) for the material explorer ochre-brdf (docs/tools.md).
//
// The file holds either the material itself (a one-node shorthand such as {"type": "lambert", ...} or
// a graph {"nodes": ..., "output": ...}), or a scene-like object {"materials": {NAME: material, ...}}
// from which one material is chosen by name (or the only one). Relative file names inside the material
// resolve against the JSON file's directory, as in a scene. The shading point has uv = (0.5, 0.5),
// vertex colour (1, 1, 1), a point-sampled texture footprint, and all four wavelength lanes set to the
// requested wavelength.

#include <filesystem>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "materials/graph/compiled_material.h"
#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"
#include "spectra/sampled_wavelengths.h"

namespace ochre {

class OiioTextureProvider;

class MaterialProbe {
 public:
  // Throws InputError naming the file (with line and column for malformed JSON, the material names
  // for an ambiguous choice) or GraphError naming the file, material, node and parameter.
  explicit MaterialProbe(const std::filesystem::path& file, const std::string& material_name = "");
  // One material given as JSON (a Python dict): `name` names it in messages, files named in it resolve
  // against `base_dir`.
  MaterialProbe(const nlohmann::json& material, const std::string& name,
                const std::filesystem::path& base_dir);
  ~MaterialProbe();
  MaterialProbe(const MaterialProbe&) = delete;
  MaterialProbe& operator=(const MaterialProbe&) = delete;

  // The closure at lambda_nm (evaluated again only when the wavelength changes). The reference stays
  // valid until the next call. Throws InputError for a wavelength outside the spectral range.
  const Closure& closure(float lambda_nm);
  const SampledWavelengths& wavelengths() const { return lambda_; }
  const std::string& name() const { return name_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  void compile(const nlohmann::json& material, const std::string& label, const std::filesystem::path& dir);

  std::filesystem::path file_;
  std::string name_;
  std::unique_ptr<OiioTextureProvider> textures_;
  std::shared_ptr<const CompiledMaterial> material_;
  LobeArena arena_;
  Closure closure_;
  SampledWavelengths lambda_;
  float evaluated_at_ = -1.0f;
};

}  // namespace ochre
