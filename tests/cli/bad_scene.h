#pragma once
// Renders a scene that must be rejected: exit code 2, a message naming the scene file and the field at
// fault, no output file and no temporary file left behind.

#include <filesystem>
#include <string>
#include <vector>

namespace ochre::test {

// A small scene (8x8 pixels, 1 sample, a constant environment) around the given "materials" and "shapes"
// members, with `extra` members first.
std::string scene_text(const std::string& materials, const std::string& shapes,
                       const std::string& extra = "");

// scene_text(grey lambert material, a plane, a constant environment) as JSON with the value at the JSON
// pointer `pointer` ("/integrator/spp", "/shapes/0") set to `value` (JSON text; null is kept as null).
std::string scene_with(const std::string& pointer, const std::string& value);

struct BadCase {
  std::string name;
  std::string scene;
  std::vector<std::string> expected;  // substrings of the error message
};

// Writes c.scene to `dir`/scene.json (a fresh scratch directory when `dir` is empty; other files the
// scene names may be put there first) and renders it with -o out.exr --png out.png.
void expect_rejected(const BadCase& c, const std::filesystem::path& dir = {});

}  // namespace ochre::test
