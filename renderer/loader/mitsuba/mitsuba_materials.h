#pragma once
// Mitsuba 3 <bsdf>s, <texture>s and area <emitter>s as ochre materials (docs/mitsuba-import.md): each
// pair (BSDF, area emitter or none) becomes one material graph of ochre's nodes (docs/nodes.md).

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "renderer/loader/mitsuba/mitsuba_xml.h"

namespace ochre {

class MitsubaMaterials {
 public:
  explicit MitsubaMaterials(const MitsubaDocument& document) : document_(document) {}

  // The name of the ochre material for `bsdf` (nullptr: Mitsuba's default, diffuse 0.5) with the radiance
  // of the area emitter `emitter` added (nullptr: none). `owner` names the material when the BSDF has no
  // id ("shapes[3]"). Made once per pair.
  std::string material(const MitsubaElement* bsdf, const MitsubaElement* emitter, const std::string& owner);
  // Whether that material reads a texture (its uvs must then mean what they mean in Mitsuba).
  bool uses_textures(const std::string& material) const;

  const nlohmann::json& json() const { return materials_; }
  // "material 'name'" -> the element it came from.
  const std::vector<std::pair<std::string, std::string>>& origins() const { return origins_; }

 private:
  const MitsubaDocument& document_;
  nlohmann::json materials_ = nlohmann::json::object();
  std::map<std::pair<const MitsubaElement*, const MitsubaElement*>, std::string> made_;
  std::map<std::string, bool> textured_;
  std::vector<std::pair<std::string, std::string>> origins_;
};

}  // namespace ochre
