// Every field of docs/scene-format.md given a value of the wrong type: exit 2 and a message naming the
// scene file and the field's JSON path. The documented keys are read from the document itself, so a key
// documented later without a case here fails DocumentedKeysAllHaveACase.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "cli/cli_runner.h"
#include "support/test_paths.h"

namespace ochre::test::scene_field_types_test {
namespace {

std::string data_file(const char* name) {
  return (source_dir() / "tests" / "data" / name).string();
}

// Every section with valid values: lights[0] environment, [1] point, [2] spot; shapes[0] sphere,
// [1] plane, [2] disk, [3] mesh, [4] groove_plate, [5] cylinder, [6] grooved_cylinder.
nlohmann::json base_scene() {
  auto scene = nlohmann::json::parse(R"({
    "description": "every section",
    "camera": {"type": "perspective", "fov": 40, "eye": [0, 0, 6], "target": [0, 0, 0], "up": [0, 1, 0]},
    "film": {"resolution": [8, 8], "colorspace": "rec709"},
    "integrator": {"type": "path", "spp": 1, "max_depth": 3, "rr_depth": 3, "branches": 1, "seed": 0, "threads": 0,
                   "polarization": "auto", "sampler": "sobol", "mirror_lights": true, "light_selection": "local",
                   "noise_threshold": 0, "guiding": "off"},
    "output": {"exposure": 0, "spectral_bins": 2, "spectral_range": [400, 700], "stokes": false, "aovs": false},
    "materials": {"grey": {"type": "lambert", "color": 0.5}},
    "lights": [{"type": "environment", "radiance": 1, "scale": 1, "rotation": 0},
               {"type": "point", "position": [0, 2, 2], "intensity": 5},
               {"type": "spot", "position": [0, 0, 3], "direction": [0, 0, -1], "cone_angle": 30,
                "falloff_start": 20, "intensity": 5}],
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "subdivisions": 16, "material": "grey"},
               {"type": "plane", "size": [4, 4], "material": "grey", "transform": {"translate": [0, 0, -1]}},
               {"type": "disk", "radius": 0.5, "segments": 16, "material": "grey", "name": "lid"},
               {"type": "mesh", "smooth_normals": false, "flip_uv_v": false, "material": "grey"},
               {"type": "groove_plate", "alpha": 60, "pitch": 0.1, "count": 4, "length": 1, "tile": 4, "orientation": 10,
                "material": "grey", "transform": {"translate": [0, 0, -2]}},
               {"type": "cylinder", "radius": 0.2, "height": 0.5, "segments": 8, "material": "grey"},
               {"type": "grooved_cylinder", "radius": 0.2, "height": 0.5, "alpha": 90, "pitch": 0.1,
                "segments": 8, "material": "grey"}]})");
  scene["shapes"][3]["file"] = data_file("quad.obj");
  return scene;
}

struct FieldCase {
  std::string pointer;  // where the wrong value goes
  std::string value;    // JSON text
  std::string path;     // the message must contain "scene.json: <path>:"
  std::string also = {};
};

// A subdivided mesh with the displacement members `members`.
std::string displaced(const std::string& members) {
  return fmt::format(R"({{"type": "mesh", "file": "{}", "material": "grey", "subdivision": {{"level": 1}},
                          "displacement": {{{}}}}})",
                     data_file("cube_quads.obj"), members);
}

// A subdivided mesh displaced by procedural noise with the noise members `members`.
std::string rock(const std::string& members) {
  return displaced(fmt::format(R"("noise": {{{}}}, "scale": 0.1)", members));
}

std::vector<FieldCase> cases() {
  return {
      {"/description", "5", "description"},
      {"/ochre", "[1]", "ochre"},
      {"/camera", "5", "camera"},
      {"/film", "[8]", "film"},
      {"/integrator", R"("path")", "integrator"},
      {"/output", "true", "output"},
      {"/materials", "[1]", "materials"},
      {"/lights", "{}", "lights"},
      {"/shapes", "{}", "shapes"},
      {"/include", "5", "include"},
      {"/include", "[5]", "include[0]"},
      {"/presets", "[1]", "presets"},
      {"/presets", R"({"fast": {"description": 5}})", "presets.fast.description"},
      {"/presets", R"({"fast": {"camera": 5}})", "presets.fast.camera"},
      {"/presets", R"({"fast": {"film": 5}})", "presets.fast.film"},
      {"/presets", R"({"fast": {"integrator": 5}})", "presets.fast.integrator"},
      {"/presets", R"({"fast": {"output": 5}})", "presets.fast.output"},
      {"/presets", R"({"fast": {"shapes": 5}})", "presets.fast.shapes"},

      {"/camera/type", "5", "camera.type"},
      {"/camera/eye", R"("x")", "camera.eye"},
      {"/camera/target", "[0, 0]", "camera.target"},
      {"/camera/up", "true", "camera.up"},
      {"/camera/fov", R"("wide")", "camera.fov"},
      {"/camera/size", R"("big")", "camera.size"},  // checked on a perspective camera too
      {"/camera", R"({"transform": "rotate"})", "camera.transform"},
      {"/camera/fov_axis", "5", "camera.fov_axis"},
      {"/camera/polarizer", "5", "camera.polarizer"},
      {"/camera/polarizer", R"({"angle": "x"})", "camera.polarizer.angle"},

      {"/film/resolution", R"("8x8")", "film.resolution"},
      {"/film/resolution", R"([8, "8"])", "film.resolution[1]"},
      {"/film/colorspace", "709", "film.colorspace"},
      {"/film/filter", R"("box")", "film.filter"},
      {"/film/filter", R"({"type": 1})", "film.filter.type"},
      {"/film/filter", R"({"type": "box", "radius": [1]})", "film.filter.radius"},
      {"/film/filter", R"({"type": "gaussian", "stddev": "wide"})", "film.filter.stddev"},

      {"/integrator/type", "1", "integrator.type"},
      {"/integrator/spp", R"("64")", "integrator.spp"},
      {"/integrator/max_depth", "true", "integrator.max_depth"},
      {"/integrator/rr_depth", "[3]", "integrator.rr_depth"},
      {"/integrator/branches", "2.5", "integrator.branches"},
      {"/integrator/seed", R"("0")", "integrator.seed"},
      {"/integrator/threads", "null", "integrator.threads"},
      {"/integrator/polarization", "false", "integrator.polarization"},
      {"/integrator/sampler", "3", "integrator.sampler"},
      {"/integrator/mirror_lights", "1", "integrator.mirror_lights"},
      {"/integrator/light_selection", "[]", "integrator.light_selection"},
      {"/integrator/guiding", "true", "integrator.guiding"},
      {"/integrator/noise_threshold", R"("0.01")", "integrator.noise_threshold"},

      {"/output/exr", "5", "output.exr"},
      {"/output/png", "true", "output.png"},
      {"/output/ocio_config", "1", "output.ocio_config"},
      {"/output/display", "2", "output.display"},
      {"/output/view", "3", "output.view"},
      {"/output/exposure", R"("1")", "output.exposure"},
      {"/output/spectral_bins", R"("4")", "output.spectral_bins"},
      {"/output/spectral_range", R"("visible")", "output.spectral_range"},
      {"/output/spectral_range", R"([400, "700"])", "output.spectral_range[1]"},
      {"/output/stokes", R"("yes")", "output.stokes"},
      {"/output/polarization_png", "1", "output.polarization_png"},
      {"/output/aovs", "1", "output.aovs"},
      {"/output/white_balance", "true", "output.white_balance"},

      {"/materials/grey/color", R"("red")", "", "material 'grey', parameter 'color'"},
      {"/materials/grey", R"({"type": 5})", "", "material 'grey', parameter 'type'"},

      {"/lights/0/type", "5", "lights[0].type"},
      {"/lights/0/radiance", R"("bright")", "lights[0].radiance"},
      {"/lights/0/scale", R"("2")", "lights[0].scale"},
      {"/lights/0/rotation", R"("90")", "lights[0].rotation"},
      {"/lights/0", R"({"type": "environment", "file": 5})", "lights[0].file"},
      {"/lights/1/position", R"("here")", "lights[1].position"},
      {"/lights/1/intensity", R"("x")", "lights[1].intensity"},
      {"/lights/1/intensity", R"({"name": 5})", "lights[1].intensity.name"},
      {"/lights/1/intensity", R"({"file": 5})", "lights[1].intensity.file"},
      {"/lights/1/intensity", R"({"file": "x.csv", "column": 5})", "lights[1].intensity.column"},
      {"/lights/1/intensity", R"({"name": "D65", "scale": "2"})", "lights[1].intensity.scale"},
      {"/lights/1/polarizer", "5", "lights[1].polarizer"},
      {"/lights/1/polarizer", R"({"axis": "x"})", "lights[1].polarizer.axis"},
      {"/lights/2/direction", R"("down")", "lights[2].direction"},
      {"/lights/2", R"({"type": "spot", "position": [0, 0, 2], "target": "origin", "intensity": 1})",
       "lights[2].target"},
      {"/lights/2/cone_angle", R"("30")", "lights[2].cone_angle"},
      {"/lights/2/falloff_start", "[10]", "lights[2].falloff_start"},
      {"/lights/2/falloff", "1", "lights[2].falloff"},
      {"/lights/1/intensity", R"({"wavelengths": [400, "x"], "values": [1, 2]})",
       "lights[1].intensity.wavelengths[1]"},
      {"/lights/1/intensity", R"({"wavelengths": [400, 500], "values": "flat"})",
       "lights[1].intensity.values"},
      {"/lights/2/intensity", R"({"blackbody": "hot"})", "lights[2].intensity.blackbody"},
      {"/lights/2/position", "null", "lights[2].position"},
      {"/lights/2", R"({"type": "spot", "preset": 5, "position": [0, 0, 2], "target": [0, 0, 0]})",
       "lights[2].preset"},
      {"/lights/2", R"({"type": "flame", "preset": "torch", "position": [0, 0, 2], "radius": "big"})",
       "lights[2].radius"},
      {"/lights/2", R"({"type": "flame", "preset": "torch", "position": [0, 0, 2], "cct": "warm"})",
       "lights[2].cct"},
      {"/lights/2", R"({"type": "flame", "preset": "torch", "position": [0, 0, 2], "scale": [2]})",
       "lights[2].scale"},
      {"/lights/2", R"({"type": "flame", "preset": "torch", "position": [0, 0, 2], "flicker": 5})",
       "lights[2].flicker"},
      {"/lights/2",
       R"({"type": "flame", "preset": "torch", "position": [0, 0, 2], "flicker": {"relative_std": "x"}})",
       "lights[2].flicker.relative_std"},
      {"/lights/2",
       R"({"type": "flame", "preset": "torch", "position": [0, 0, 2], "flicker": {"frequency": "x"}})",
       "lights[2].flicker.frequency"},
      {"/lights/2",
       R"({"type": "flame", "preset": "torch", "position": [0, 0, 2], "flicker": {"cct_std": true}})",
       "lights[2].flicker.cct_std"},
      {"/lights/2",
       R"({"type": "flame", "preset": "torch", "position": [0, 0, 2], "flicker": {"position_std": null}})",
       "lights[2].flicker.position_std"},
      {"/lights/2", R"({"type": "camera_flash", "offset": "up"})", "lights[2].offset"},
      {"/lights/2", R"({"type": "directional", "direction": "down", "irradiance": 1})",
       "lights[2].direction"},
      {"/lights/2", R"({"type": "directional", "direction": [0, 0, -1], "irradiance": "x"})",
       "lights[2].irradiance"},
      {"/camera/sensor", "5", "camera.sensor"},
      {"/camera/sensor", R"({"name": 5})", "camera.sensor.name"},

      {"/shapes/0/type", "5", "shapes[0].type"},
      {"/shapes/0/material", "5", "shapes[0].material"},
      {"/shapes/0/name", "5", "shapes[0].name"},
      {"/shapes/0/transform", R"("x")", "shapes[0].transform"},
      {"/shapes/0/transform", R"([{"rotate": {"axis": "x", "angle": 1}}])",
       "shapes[0].transform[0].rotate.axis"},
      {"/shapes/0/transform", R"({"rotate": {"axis": [0, 1, 0], "angle": "9"}})",
       "shapes[0].transform.rotate.angle"},
      {"/shapes/0/transform", R"({"scale": "2"})", "shapes[0].transform.scale"},
      {"/shapes/0/transform", R"({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, "1"]})",
       "shapes[0].transform.matrix[15]"},
      {"/shapes/0/transform", R"({"look_at": {"eye": 1, "target": [0, 0, 0], "up": [0, 1, 0]}})",
       "shapes[0].transform.look_at.eye"},
      {"/shapes/0/center", R"("x")", "shapes[0].center"},
      {"/shapes/0/radius", R"("1")", "shapes[0].radius"},
      {"/shapes/0/subdivisions", R"("96")", "shapes[0].subdivisions"},
      {"/shapes/0/polarizer", "5", "shapes[0].polarizer"},
      {"/shapes/1/size", R"("2")", "shapes[1].size"},
      {"/shapes/1/size", R"([2, "2"])", "shapes[1].size[1]"},
      {"/shapes/2/radius", "true", "shapes[2].radius"},
      {"/shapes/2/segments", R"("x")", "shapes[2].segments"},
      {"/shapes/2", R"({"type": "cone", "top_radius": "0", "material": "grey"})", "shapes[2].top_radius"},
      {"/shapes/2", R"({"type": "cone", "height": [1], "material": "grey"})", "shapes[2].height"},
      {"/shapes/3/file", "5", "shapes[3].file"},
      {"/shapes/3/smooth_normals", R"("yes")", "shapes[3].smooth_normals"},
      {"/shapes/3/flip_uv_v", "1", "shapes[3].flip_uv_v"},
      {"/shapes/3/face_normals", R"("no")", "shapes[3].face_normals"},
      {"/shapes/3/flip_normals", "0", "shapes[3].flip_normals"},
      {"/shapes/0/flip_uv_v", "1", "shapes[0].flip_uv_v"},
      {"/shapes/1/flip_normals", R"("yes")", "shapes[1].flip_normals"},
      {"/shapes/3/subdivision", R"("x")", "shapes[3].subdivision"},
      {"/shapes/3/subdivision", R"({"level": 1.5})", "shapes[3].subdivision.level"},
      {"/shapes/3/subdivision", R"({"scheme": 4})", "shapes[3].subdivision.scheme"},
      {"/shapes/3/displacement", "5", "shapes[3].displacement"},
      {"/shapes/3", displaced(R"("file": "height.exr", "scale": "x")"), "shapes[3].displacement.scale"},
      {"/shapes/3", displaced(R"("file": "height.exr", "offset": [0])"), "shapes[3].displacement.offset"},
      {"/shapes/3", displaced(R"("file": "height.exr", "colorspace": 5)"),
       "shapes[3].displacement.colorspace"},
      {"/shapes/3", displaced(R"("file": 5)"), "shapes[3].displacement.file"},
      {"/shapes/3", rock(R"("frequency": "x")"), "shapes[3].displacement.noise.frequency"},
      {"/shapes/3", rock(R"("octaves": 2.5)"), "shapes[3].displacement.noise.octaves"},
      {"/shapes/3", rock(R"("lacunarity": [2])"), "shapes[3].displacement.noise.lacunarity"},
      {"/shapes/3", rock(R"("gain": "half")"), "shapes[3].displacement.noise.gain"},
      {"/shapes/3", rock(R"("seed": -1)"), "shapes[3].displacement.noise.seed"},
      {"/shapes/3", rock(R"("cracks": true)"), "shapes[3].displacement.noise.cracks"},
      {"/shapes/3", rock(R"("crack_frequency": "x")"), "shapes[3].displacement.noise.crack_frequency"},
      {"/shapes/3", rock(R"("crack_width": null)"), "shapes[3].displacement.noise.crack_width"},
      {"/shapes/3", rock(R"("flowstone": "x")"), "shapes[3].displacement.noise.flowstone"},
      {"/shapes/3", rock(R"("flowstone_frequency": [3])"),
       "shapes[3].displacement.noise.flowstone_frequency"},
      {"/shapes/3", rock(R"("up": "down")"), "shapes[3].displacement.noise.up"},
      {"/shapes/3", fmt::format(R"({{"type": "mesh", "file": "{}", "materials": 5}})", data_file("quad.obj")),
       "shapes[3].materials"},
      {"/shapes/4/alpha", R"("60")", "shapes[4].alpha"},
      {"/shapes/4/pitch", "true", "shapes[4].pitch"},
      {"/shapes/4/count", "4.5", "shapes[4].count"},
      {"/shapes/4/length", "[1]", "shapes[4].length"},
      {"/shapes/4/tile", "null", "shapes[4].tile"},
      {"/shapes/4/orientation", R"("x")", "shapes[4].orientation"},
      {"/shapes/5/height", R"("x")", "shapes[5].height"},
      {"/shapes/5/segments", "8.5", "shapes[5].segments"},
      {"/shapes/6/alpha", "180", "shapes[6].alpha"},
      {"/shapes/6/pitch", "0", "shapes[6].pitch"},
  };
}

CommandResult render(const std::filesystem::path& dir, const nlohmann::json& scene) {
  write_text(dir / "scene.json", scene.dump(2));
  return run_ochre("render scene.json -o out.exr", dir);
}

TEST(SceneFieldTypes, TheBaseSceneRenders) {
  const CommandResult r = render(scratch_dir(), base_scene());
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

// "camera" for "/camera/fov", "top" for a whole section ("/camera").
std::string section_of(const std::string& pointer) {
  const size_t slash = pointer.find('/', 1);
  return slash == std::string::npos ? "top" : pointer.substr(1, slash - 1);
}

// Renders the base scene with each wrong value of `section` (one test per section, so that ctest runs them
// side by side).
void check_section(const std::string& section) {
  const auto root = scratch_dir();
  int n = 0;
  for (const FieldCase& c : cases()) {
    if (section_of(c.pointer) != section) continue;
    nlohmann::json scene = base_scene();
    scene[nlohmann::json::json_pointer(c.pointer)] = nlohmann::json::parse(c.value);
    const auto dir = root / std::to_string(n++);
    std::filesystem::create_directories(dir);
    const CommandResult r = render(dir, scene);
    const std::string label = c.pointer + " = " + c.value;
    EXPECT_EQ(r.exit_code, 2) << label << "\n" << r.output;
    if (!c.path.empty()) {
      EXPECT_NE(r.output.find("scene.json: " + c.path + ":"), std::string::npos) << label << "\n" << r.output;
    }
    if (!c.also.empty()) {
      EXPECT_NE(r.output.find(c.also), std::string::npos) << label << "\n" << r.output;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr")) << label;
  }
  EXPECT_GT(n, 0) << "no case for " << section;
}

const char* const kSections[] = {"top",    "camera",    "film",   "integrator",
                                 "output", "materials", "lights", "shapes"};

TEST(SceneFieldTypes, TopLevel) {
  check_section("top");
}
TEST(SceneFieldTypes, Camera) {
  check_section("camera");
}
TEST(SceneFieldTypes, Film) {
  check_section("film");
}
TEST(SceneFieldTypes, Integrator) {
  check_section("integrator");
}
TEST(SceneFieldTypes, Output) {
  check_section("output");
}
TEST(SceneFieldTypes, Materials) {
  check_section("materials");
}
TEST(SceneFieldTypes, Lights) {
  check_section("lights");
}
TEST(SceneFieldTypes, Shapes) {
  check_section("shapes");
}

TEST(SceneFieldTypes, EveryCaseBelongsToATestedSection) {
  for (const FieldCase& c : cases())
    EXPECT_NE(std::find(std::begin(kSections), std::end(kSections), section_of(c.pointer)),
              std::end(kSections))
        << c.pointer;
}

// (section, key) for every key the document's tables list: "| key |" tables by their first column,
// "| type | keys |" tables (lights, shapes) by the identifiers of their second column.
std::set<std::pair<std::string, std::string>> documented_keys() {
  std::ifstream in(source_dir() / "docs" / "scene-format.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::regex code("`([a-z_]+)`");
  std::set<std::pair<std::string, std::string>> keys;
  std::string section, line;
  int column = -1;  // the column holding keys in the current table, -1 outside such a table
  bool in_table = false;
  while (std::getline(text, line)) {
    if (line.rfind("## ", 0) == 0) section = line.substr(3) == "Top level" ? "" : line.substr(3);
    if (line.rfind("|", 0) != 0) {
      in_table = false;
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
    if (!in_table) {  // the header
      in_table = true;
      column = cells[0] == " key " ? 0 : (cells.size() > 1 && cells[1] == " keys " ? 1 : -1);
      continue;
    }
    if (column < 0 || cells.size() <= size_t(column) || cells[0].find("---") != std::string::npos) continue;
    for (std::sregex_iterator m(cells[column].begin(), cells[column].end(), code), end; m != end; ++m)
      keys.insert({section, (*m)[1]});
  }
  return keys;
}

bool covers(const FieldCase& c, const std::string& given_section, const std::string& key) {
  if (given_section.empty()) return c.path == key;
  // Sections named in prose ("Presets") hold the keys of the lower-case field.
  std::string section = given_section;
  section[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(section[0])));
  const std::string prefix = section == "lights" || section == "shapes" ? section + "[" : section + ".";
  if (c.path.rfind(prefix, 0) != 0) return false;
  for (size_t at = c.path.find("." + key); at != std::string::npos; at = c.path.find("." + key, at + 1)) {
    const size_t after = at + 1 + key.size();
    if (after == c.path.size() || c.path[after] == '.' || c.path[after] == '[') return true;
  }
  return false;
}

TEST(SceneFieldTypes, DocumentedKeysAllHaveACase) {
  const auto keys = documented_keys();
  EXPECT_GT(keys.size(), 40u) << "the tables of docs/scene-format.md were not found";
  const std::vector<FieldCase> all = cases();
  for (const auto& [section, key] : keys) {
    bool covered = false;
    for (const FieldCase& c : all) covered = covered || covers(c, section, key);
    EXPECT_TRUE(covered) << "docs/scene-format.md documents " << (section.empty() ? "" : section + ".") << key
                         << " but no wrong-type case checks it";
  }
}

}  // namespace
}  // namespace ochre::test::scene_field_types_test
