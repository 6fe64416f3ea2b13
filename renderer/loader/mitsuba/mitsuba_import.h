#pragma once
// Mitsuba 3 XML scenes (docs/mitsuba-import.md): the common subset of Mitsuba's format is translated into
// ochre's scene JSON (docs/scene-format.md), which then loads through the one JSON loader with its
// validation (renderer/loader/scene_loader.h calls the translator; the translator knows nothing of the
// loader). Whatever ochre cannot reproduce is refused (InputError, exit 2) with the file, line and
// element and what is supported; nothing is dropped silently. Errors the JSON loader finds in the
// translated scene are reported at the XML element they came from.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace ochre {

// A scene file ochre reads as Mitsuba XML: its name ends in ".xml" (any case).
bool is_mitsuba_scene_file(const std::filesystem::path& file);

struct MitsubaTranslation {
  nlohmann::json scene;  // ochre's scene JSON; file names in it are absolute or relative to the scene file
  // Where each part of the JSON came from: a JSON path prefix ("shapes[3]", "lights[0]", "camera",
  // "film", "integrator", "material 'white'") and the XML element ("cbox.xml:12: <shape type="obj">").
  std::vector<std::pair<std::string, std::string>> origins;

  // "scene.xml: shapes[3].file: ..." -> "fragments/shapes.xml:5: <shape type="obj">: shapes[3].file: ...":
  // a message of the JSON loader about the translated scene (`file` its name), told at the XML element the
  // part came from.
  std::string at_origin(const std::string& message, const std::string& file) const;
};

// Reads and translates `file`; `parameters` (name, value) set $name parameters before the scene's
// <default>s. Throws InputError.
MitsubaTranslation translate_mitsuba_scene(
    const std::filesystem::path& file,
    const std::vector<std::pair<std::string, std::string>>& parameters = {});

}  // namespace ochre
