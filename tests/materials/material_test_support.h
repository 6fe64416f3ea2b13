#pragma once
// Stubs of the renderer's side of the material interfaces, and helpers to compile materials
// written as JSON text in the tests.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "materials/graph/compiled_material.h"
#include "materials/graph/material_compiler.h"
#include "materials/nodes/resource_resolver.h"
#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"
#include "materials/nodes/shading_context.h"
#include "materials/nodes/texture_provider.h"

namespace ochre::test {

// Resolves names relative to `base`; "opens" only the textures registered with add_texture().
class StubResolver : public ResourceResolver {
 public:
  explicit StubResolver(std::filesystem::path base = "/scenes") : base_(std::move(base)) {}

  void add_texture(const std::string& name, int channels) { textures_[resolve(name)] = channels; }

  std::filesystem::path resolve(const std::string& path) const override { return base_ / path; }
  int texture(const std::filesystem::path& file, const std::string& colorspace, int& channels) override;

  // colorspaces passed to texture(), in call order.
  std::vector<std::string> colorspaces;

 private:
  std::filesystem::path base_;
  std::map<std::filesystem::path, int> textures_;
};

// Every texture holds the colour (u, v, 0.25 + id) and channel c > 2 holds 0.1 c; remembers the
// last lookup's arguments.
class StubTextures : public TextureProvider {
 public:
  void lookup(int texture_id, const Vec2& uv, float footprint, int first_channel, int nchannels,
              float* out) const override;

  mutable Vec2 last_uv;
  mutable float last_footprint = -1.0f;
  mutable int last_first_channel = -1;
  mutable int lookups = 0;
};

inline constexpr const char* kSceneFile = "scene.json";

// Compiles `json_text` as material "m" of scene.json.
std::shared_ptr<const CompiledMaterial> compile(const std::string& json_text, ResourceResolver& resolver);
std::shared_ptr<const CompiledMaterial> compile(const std::string& json_text);

// Fixed wavelengths 400, 500, 600, 700 nm.
const SampledWavelengths& test_wavelengths();

// A fixture that compiles materials from JSON text and evaluates them at its shading point `ctx` (with
// the test wavelengths, the stub textures and a resolver rooted in a scratch directory).
class MaterialEvaluation : public ::testing::Test {
 protected:
  const Closure& evaluate(const CompiledMaterial& m);
  const Closure& evaluate(const std::string& json_text);

  SampledWavelengths lambda = test_wavelengths();
  ShadingContext ctx;
  StubResolver resolver;
  StubTextures textures;
  LobeArena arena;
  Closure closure;
  std::shared_ptr<const CompiledMaterial> material;

  MaterialEvaluation();
};

}  // namespace ochre::test
