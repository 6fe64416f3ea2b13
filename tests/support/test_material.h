#pragma once
// Compiles a material written as JSON text, for tests that need no files (a texture is refused).

#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "materials/graph/material_compiler.h"

namespace ochre::test {

class NoFiles : public ResourceResolver {
 public:
  std::filesystem::path resolve(const std::string& path) const override { return path; }
  int texture(const std::filesystem::path&, const std::string&, int&) override {
    throw std::runtime_error("no textures in this test");
  }
};

inline std::shared_ptr<const CompiledMaterial> compile_test_material(const std::string& json,
                                                                     const std::string& name = "m") {
  NoFiles files;
  return compile_material(nlohmann::json::parse(json), name, "test.json", files);
}

}  // namespace ochre::test
