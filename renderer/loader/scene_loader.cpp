#include "renderer/loader/scene_loader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "materials/graph/graph_error.h"
#include "materials/graph/material_compiler.h"
#include "materials/nodes/resource_resolver.h"
#include "renderer/camera/camera_sensor.h"
#include "renderer/geometry/coordinate_limit.h"
#include "renderer/geometry/transform.h"
#include "renderer/json/json_fields.h"
#include "renderer/json/json_file.h"
#include "renderer/json/spectrum_json.h"
#include "renderer/lights/light_type.h"
#include "renderer/loader/material_templates.h"
#include "renderer/loader/mitsuba/mitsuba_import.h"
#include "renderer/loader/scene_sources.h"
#include "renderer/scene/polarization_significance.h"
#include "renderer/shapes/control_mesh.h"
#include "renderer/shapes/displacement.h"
#include "renderer/shapes/mesh_import.h"
#include "renderer/shapes/mesh_shape.h"
#include "renderer/shapes/procedural_shapes.h"
#include "renderer/shapes/shape_type.h"
#include "renderer/shapes/subdivision.h"
#include "renderer/util/memory_budget.h"
#include "spectra/cie.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

constexpr long long kMaxResolution = 65536;  // pixels per film side
constexpr int kMaxThreads = 4096;            // as --threads

// Files named by materials resolve relative to the scene file; textures go to the OIIO provider.
class SceneResources final : public ResourceResolver {
 public:
  SceneResources(std::filesystem::path dir, OiioTextureProvider& textures)
      : dir_(std::move(dir)), textures_(textures) {}
  std::filesystem::path resolve(const std::string& path) const override {
    const std::filesystem::path p(path);
    return p.is_absolute() ? p : dir_ / p;
  }
  int texture(const std::filesystem::path& file, const std::string& colorspace, int& channels) override {
    return textures_.add_texture(file, colorspace, channels);
  }

 private:
  std::filesystem::path dir_;
  OiioTextureProvider& textures_;
};

// Two numbers [a, b] of the field `key`, each checked like a number field (json_fields.h).
std::pair<double, double> number_pair(const JsonFields& f, const char* key, const char* shape, double min,
                                      double max, bool min_exclusive) {
  const std::string where = f.child(key);
  const nlohmann::json& pair = json_array(f.require(key), where, 2, shape);
  return {json_number(pair[0], where + "[0]", min, max, min_exclusive),
          json_number(pair[1], where + "[1]", min, max, min_exclusive)};
}

// "filter": {"type": "box", "radius": 0.5} or {"type": "gaussian", "stddev": 0.5} (pixel_filter.h).
PixelFilter parse_pixel_filter(const JsonFields& f) {
  const std::string type = f.required_string("type");
  if (type == "box") {
    f.check_known({"type", "radius"});
    return PixelFilter::box(static_cast<float>(f.number("radius", 0.5, 0.0, 64.0, true)));
  }
  if (type == "gaussian") {
    f.check_known({"type", "stddev"});
    return PixelFilter::gaussian(static_cast<float>(f.number("stddev", 0.5, 0.0, 64.0, true)));
  }
  f.fail("type", fmt::format("unknown filter '{}' (known: box, gaussian)", type));
}

// output.white_balance: an illuminant spectrum whose colour the display image shows as white.
std::array<double, 3> parse_white_balance(const JsonFields& f, const std::filesystem::path& dir) {
  const SpectrumPtr white =
      parse_spectrum(f.require("white_balance"), SpectrumRole::Illuminant, f.child("white_balance"), dir);
  const XYZ xyz = spectrum_to_xyz(*white);
  if (!(xyz.x > 0.0f && xyz.y > 0.0f && xyz.z > 0.0f) || !std::isfinite(xyz.x + xyz.y + xyz.z))
    f.fail("white_balance", "the illuminant must have a colour (positive, finite X, Y and Z)");
  return {double(xyz.x) / xyz.y, 1.0, double(xyz.z) / xyz.y};
}

// A choice field of the scene (film.colorspace, integrator.sampler, ...): its enum value, or an error
// naming the field and the known values.
template <class Enum, size_t N>
Enum parse_choice(const JsonFields& f, const char* key, const NamedChoices<Enum, N>& choices, Enum fallback,
                  const char* what) {
  if (!f.has(key)) return fallback;
  const std::string text = f.required_string(key);
  const std::optional<Enum> value = choices.parse(text);
  if (!value) f.fail(key, fmt::format("unknown {} '{}' (known: {})", what, text, choices.list()));
  return *value;
}

void load_settings(const JsonFields& top, const std::filesystem::path& scene_dir, RenderJob& job,
                   PixelFilter& pixel_filter) {
  RenderSettings& s = job.settings;
  OutputSettings& outputs = job.outputs;
  if (top.has("film")) {
    const JsonFields f(top.require("film"), top.child("film"));
    f.check_known({"resolution", "colorspace", "filter"});
    if (f.has("resolution")) {
      const std::string where = f.child("resolution");
      const nlohmann::json& r = json_array(f.require("resolution"), where, 2, "[width, height]");
      s.width = static_cast<int>(json_integer(r[0], where + "[0]", 1, kMaxResolution));
      s.height = static_cast<int>(json_integer(r[1], where + "[1]", 1, kMaxResolution));
    }
    outputs.colorspace = parse_choice(f, "colorspace", kWorkingSpaces, outputs.colorspace, "colorspace");
    if (f.has("filter"))
      pixel_filter = parse_pixel_filter(JsonFields(f.require("filter"), f.child("filter")));
  }
  if (top.has("integrator")) {
    const JsonFields f(top.require("integrator"), top.child("integrator"));
    f.check_known({"type", "spp", "max_depth", "rr_depth", "branches", "seed", "threads", "polarization",
                   "sampler", "mirror_lights", "light_selection", "noise_threshold", "guiding"});
    if (f.string("type", "path") != "path") f.fail("type", "unknown integrator (known: path)");
    s.spp = static_cast<uint32_t>(f.integer("spp", s.spp, 1, 1 << 24));
    s.max_depth = static_cast<int>(f.integer("max_depth", s.max_depth, 0, 1024));
    if (f.has("rr_depth") && f.require("rr_depth").is_string()) {
      if (f.string("rr_depth", "") != "auto")
        f.fail("rr_depth", "must be \"auto\" or an integer in [1, 1024]");
      s.rr_depth = RenderSettings::kAutoRoulette;
    } else {
      s.rr_depth = static_cast<int>(f.integer("rr_depth", s.rr_depth, 1, 1024));
    }
    if (f.has("branches") && f.require("branches").is_string()) {
      if (f.string("branches", "") != "auto") f.fail("branches", "must be \"auto\" or an integer in [1, 64]");
      s.branches = RenderSettings::kAutoBranches;
    } else {
      s.branches = static_cast<int>(f.integer("branches", s.branches, 1, RenderSettings::kMaxBranches));
    }
    s.noise_threshold = f.number("noise_threshold", s.noise_threshold, 0.0, 1.0);
    s.mirror_lights = f.boolean("mirror_lights", s.mirror_lights);
    s.light_selection =
        parse_choice(f, "light_selection", kLightSelections, s.light_selection, "light selection");
    s.guiding = parse_choice(f, "guiding", kGuidingSettings, s.guiding, "guiding setting");
    s.seed = static_cast<uint64_t>(f.integer("seed", 0, 0, std::numeric_limits<long long>::max()));
    s.threads = static_cast<int>(f.integer("threads", s.threads, 0, kMaxThreads));
    s.polarization = parse_choice(f, "polarization", kPolarizationSettings, s.polarization, "mode");
    s.sampler = parse_choice(f, "sampler", kSamplerKinds, s.sampler, "sampler");
  }
  if (top.has("output")) {
    const JsonFields f(top.require("output"), top.child("output"));
    f.check_known({"exr", "png", "ocio_config", "display", "view", "exposure", "white_balance", "aovs",
                   "spectral_bins", "spectral_range", "stokes", "polarization_png"});
    const std::filesystem::path& dir = scene_dir;
    if (f.has("exr")) outputs.exr = (dir / f.required_string("exr")).string();
    if (f.has("png")) outputs.png = (dir / f.required_string("png")).string();
    outputs.ocio_config = f.string("ocio_config", "");
    outputs.display = f.string("display", "");
    outputs.view = f.string("view", "");
    outputs.exposure = static_cast<float>(f.number("exposure", 0.0, -64.0, 64.0));
    if (f.has("white_balance")) outputs.white_balance_xyz = parse_white_balance(f, dir);
    outputs.spectral_bins = static_cast<int>(f.integer("spectral_bins", 0, 0, 471));
    if (f.has("spectral_range")) {
      // Up to 1200 nm: a camera sensor may see beyond the visible (docs/cameras.md).
      const auto [lo, hi] = number_pair(f, "spectral_range", "[min, max] in nm", 300.0, 1200.0, false);
      if (!(lo < hi)) f.fail("spectral_range", fmt::format("min must be < max (got [{}, {}])", lo, hi));
      outputs.spectral_min = static_cast<float>(lo);
      outputs.spectral_max = static_cast<float>(hi);
    }
    outputs.stokes = f.boolean("stokes", outputs.stokes);
    if (f.has("polarization_png"))
      outputs.polarization_png = (dir / f.required_string("polarization_png")).string();
    outputs.aovs = f.boolean("aovs", outputs.aovs);
  }
}

void check_settings(const RenderSettings& s, const std::string& file) {
  if (s.width < 1 || s.height < 1 || s.width > kMaxResolution || s.height > kMaxResolution)
    throw InputError(fmt::format("{}: film.resolution: must be between 1x1 and {}x{} (got {}x{})", file,
                                 kMaxResolution, kMaxResolution, s.width, s.height));
  if (s.spp < 1) throw InputError(fmt::format("{}: integrator.spp: must be >= 1", file));
  if (s.threads < 0 || s.threads > kMaxThreads)  // an override (the scene's own value is checked on reading)
    throw InputError(
        fmt::format("{}: integrator.threads: must be in [0, {}] (got {})", file, kMaxThreads, s.threads));
}

// "polarizer": {"angle": degrees} on the camera: a linear analyzer whose transmission axis is turned by
// `angle` from the image x axis toward the image's up direction (docs/polarization.md).
std::optional<Mueller> parse_camera_polarizer(const JsonFields& f) {
  if (!f.has("polarizer")) return std::nullopt;
  const JsonFields p(f.require("polarizer"), f.child("polarizer"));
  p.check_known({"angle"});
  const double degrees = p.number("angle", 0.0, -360.0, 360.0);
  return rotated_element(static_cast<float>(degrees * M_PI / 180.0), linear_polarizer());
}

FovAxis parse_fov_axis(const JsonFields& f) {
  const std::string axis = f.string("fov_axis", "smaller");
  if (axis == "smaller") return FovAxis::Smaller;
  if (axis == "larger") return FovAxis::Larger;
  if (axis == "x") return FovAxis::X;
  if (axis == "y") return FovAxis::Y;
  if (axis == "diagonal") return FovAxis::Diagonal;
  f.fail("fov_axis", fmt::format("unknown axis '{}' (known: smaller, larger, x, y, diagonal)", axis));
}

// The camera, placed at the rendering origin (Scene::origin, set here to the camera's position in the
// scene's coordinates): what the camera sees is rendered in coordinates relative to it.
Camera load_camera(const JsonFields& top, const RenderSettings& s, Vec3d& origin) {
  const nlohmann::json camera = top.has("camera") ? top.require("camera") : nlohmann::json::object();
  const JsonFields f(camera, top.child("camera"));
  f.check_known(
      {"type", "fov", "fov_axis", "size", "eye", "target", "up", "transform", "polarizer", "sensor"});
  // Every given field is checked, also those the chosen placement or type does not use.
  const std::string type = f.string("type", "perspective");
  const auto fov = static_cast<float>(
      fov_across_shorter_axis(f.number("fov", 40.0, 0.0, 179.0, true), parse_fov_axis(f), s.width, s.height));
  const auto size = static_cast<float>(f.number("size", 2.0, 0.0, kMaxSceneCoordinate, true));
  CameraBasis basis;
  if (f.has("transform") && (f.has("eye") || f.has("target") || f.has("up")))
    f.fail("transform", "give either \"transform\" or \"eye\", \"target\", \"up\", not both");
  if (f.has("transform")) {
    // Camera-to-world; the camera looks along -z with +y up (glTF / OpenGL convention).
    const Transform t = parse_transform(f.require("transform"), f.child("transform"));
    origin = t.point_double(Vec3d{0, 0, 0});
    if (!within_scene_limit(origin.to_float()))
      f.fail("transform", "places the camera " + beyond_scene_limit());
    basis.eye = {0, 0, 0};
    basis.forward = normalize(t.vector({0, 0, -1}));
    basis.up = normalize(t.vector({0, 1, 0}));
    basis.right = normalize(cross(basis.forward, basis.up));
    basis.up = cross(basis.right, basis.forward);
  } else {
    const Vec3d eye = f.vec3d("eye", {0, 0, 5}), target = f.vec3d("target", {0, 0, 0});
    const Vec3 up = f.vec3("up", {0, 1, 0});
    if (!within_scene_limit(eye.to_float())) f.fail("eye", "lies " + beyond_scene_limit());
    // The view direction from the two positions in double precision: a target 1 m from an eye at 5e6 keeps
    // its direction.
    const Vec3 view = (target - eye).to_float();
    if (!(length(view) > 0.0f)) f.fail("target", "must differ from eye");
    if (!std::isfinite(length(view)))
      f.fail("target", "is too far from eye (the distance overflows single precision)");
    if (length(cross(normalize(view), up)) < 1e-6f)
      f.fail("up", "must not be parallel to the view direction");
    origin = eye;
    basis = camera_basis_look_at({0, 0, 0}, view, up);
  }
  if (type == "perspective") return Camera::perspective(basis, fov, s.width, s.height);
  if (type == "orthographic") return Camera::orthographic(basis, size, s.width, s.height);
  f.fail("type", fmt::format("unknown camera type '{}' (known: perspective, orthographic)", type));
}

// Materials whose textures are "mtl:" placeholders (material_templates.h): compiled once per material of
// each mesh file that uses them, not on their own.
struct MaterialTemplates {
  std::map<std::string, const SceneItem*> items;
  std::map<std::pair<std::string, std::string>, int> instances;  // (template, file material) -> material
};

void load_materials(const SceneSources& sources, Scene& scene, MaterialTemplates& templates) {
  for (const SceneItem& m : sources.materials) {
    if (is_material_template(m.json)) {
      templates.items[m.name] = &m;
      continue;
    }
    SceneResources resources(m.file.parent_path(), *scene.textures);
    scene.material_names.push_back(m.name);
    scene.materials.push_back(compile_material(m.json, m.name, m.file.string(), resources));
  }
}

int material_index(const Scene& scene, const MaterialTemplates& templates, const JsonFields& f,
                   const char* key, const std::string& name) {
  for (size_t i = 0; i < scene.material_names.size(); ++i)
    if (scene.material_names[i] == name) return static_cast<int>(i);
  if (templates.items.count(name))
    f.fail(key, fmt::format("material '{}' is a template (it names \"mtl:\" textures): use it in a mesh's "
                            "\"materials\" map",
                            name));
  f.fail(key, fmt::format("unknown material '{}'", name));
}

// The scene material for one material of a mesh file: `name` itself, or for a template its instance with
// that file material's textures (compiled on first use).
int part_material(Scene& scene, MaterialTemplates& templates, const JsonFields& map, const std::string& key,
                  const MeshMaterialPart& part, const std::filesystem::path& mesh_dir) {
  const std::string name = json_string(map.require(key.c_str()), map.child(key));
  const auto it = templates.items.find(name);
  if (it == templates.items.end()) return material_index(scene, templates, map, key.c_str(), name);
  const auto cached = templates.instances.find({name, part.material});
  if (cached != templates.instances.end()) return cached->second;
  const SceneItem& item = *it->second;
  const nlohmann::json json =
      instantiate_material_template(item.json, part.textures, mesh_dir, part.material, map.child(key));
  const std::string instance = name + "@" + part.material;
  SceneResources resources(item.file.parent_path(), *scene.textures);
  scene.material_names.push_back(instance);
  scene.materials.push_back(compile_material(json, instance, item.file.string(), resources));
  const int index = static_cast<int>(scene.materials.size() - 1);
  templates.instances[{name, part.material}] = index;
  return index;
}

// The shape's "transform" followed by the shift to the rendering origin (Scene::origin), composed in double
// precision: the vertices are rounded to single precision once, relative to the camera.
Transform shape_transform(const JsonFields& f, const Vec3d& origin) {
  const Transform to_world = f.has("transform")
                                 ? parse_transform(f.require("transform"), f.child("transform"))
                                 : Transform::identity();
  return Transform::translate(-origin) * to_world;
}

// A mesh file with several materials (photogrammetry with several texture atlases): one scene mesh per
// file material, with the scene material the shape's "materials" map gives it (by name, or "*").
std::vector<Mesh> load_material_parts(const DeclaredFields& f, const std::filesystem::path& dir, Scene& scene,
                                      MaterialTemplates& templates) {
  for (const char* key : {"subdivision", "displacement"})
    if (f.has(key)) f.fail(key, "is not supported with \"materials\" (one mesh per file material)");
  const JsonFields map(f.fields().require("materials"), f.fields().child("materials"));
  const std::filesystem::path path = mesh_file(f, dir);
  const Transform to_world = shape_transform(f.fields(), scene.origin);
  const MeshImportOptions options = mesh_import_options(f);
  std::vector<MeshMaterialPart> parts = f.fields().in_context(
      "file", [&] { return import_mesh_by_material(path, to_world, options, &scene.warnings); });
  std::string file_materials;
  for (const MeshMaterialPart& part : parts)
    file_materials += (file_materials.empty() ? "'" : ", '") + part.material + "'";
  for (const auto& item : map.json().items()) {
    const std::string& key = item.key();
    const bool in_file =
        std::any_of(parts.begin(), parts.end(), [&](const auto& p) { return p.material == key; });
    if (key != "*" && !in_file)
      map.fail(key, fmt::format("the file has no material '{}' (it has: {})", key, file_materials));
  }
  const std::string shape_name = f.fields().string("name", "mesh");
  std::vector<Mesh> meshes;
  for (MeshMaterialPart& part : parts) {
    const std::string key = map.has(part.material.c_str()) ? part.material : "*";
    if (!map.has(key.c_str()))
      f.fail("materials",
             fmt::format("the file's material '{}' is not mapped (name it, or map \"*\"; the file's "
                         "materials: {})",
                         part.material, file_materials));
    part.mesh.material = part_material(scene, templates, map, key, part, path.parent_path());
    part.mesh.name = shape_name + "/" + part.material;
    if (f.boolean("flip_normals")) flip_normals(part.mesh);
    meshes.push_back(std::move(part.mesh));
  }
  return meshes;
}

// `dir`: the folder of the file that holds the shape (its paths are relative to it).
Mesh load_shape(const DeclaredFields& f, const ShapeType& type, Scene& scene,
                const MaterialTemplates& templates, const std::filesystem::path& dir) {
  const Transform to_world = shape_transform(f.fields(), scene.origin);
  Mesh mesh = type.build(ShapeContext{f, to_world, dir, *scene.textures, scene.origin, scene.warnings});
  // Every shape may face the other way; procedural ones may flip their uvs (meshes do it on import).
  if (f.boolean("flip_normals")) flip_normals(mesh);
  if (type.loader_flips_uv && f.boolean("flip_uv_v")) flip_uv_v(mesh);
  mesh.name = f.fields().string("name", type.name);
  mesh.material = material_index(scene, templates, f.fields(), "material", f.string("material"));
  mesh.validate(f.fields().where());
  return mesh;
}

void load_shapes(const SceneSources& sources, const JsonFields& top, Scene& scene,
                 MaterialTemplates& templates) {
  if (!top.has("shapes") && sources.shapes.empty()) top.fail("shapes", "expected an array of shapes");
  for (const SceneItem& shape : sources.shapes) {
    const JsonFields f(shape.json, shape.where);
    const ShapeType& type = ShapeRegistry::builtin().type_of(f);
    const std::vector<const FieldSpec*> declarations = type.declarations();
    const DeclaredFields fields(f, declarations);
    if (f.has("materials") && type.name != "mesh")
      f.fail("materials", "only a \"mesh\" shape has a materials map");
    fields.check_known();
    std::vector<Mesh> meshes;
    if (f.has("materials")) {
      if (f.has("material")) f.fail("materials", "give either \"material\" or \"materials\", not both");
      meshes = load_material_parts(fields, shape.file.parent_path(), scene, templates);
    } else {
      f.required_string("material");  // before any work: a shape without one is refused at once
      meshes.push_back(load_shape(fields, type, scene, templates, shape.file.parent_path()));
    }
    const std::optional<Vec3> polarizer = parse_light_polarizer(f);
    const std::string group = parse_light_group(f, "light_group");
    for (Mesh& mesh : meshes) {
      if (polarizer && !scene.materials[mesh.material]->facts().is_emissive)
        f.fail("polarizer", "a polarizer belongs in front of a light: this shape's material does not emit");
      if (!group.empty() && !scene.materials[mesh.material]->facts().is_emissive)
        f.fail("light_group", "a light group holds lights: this shape's material does not emit");
      scene.meshes.push_back(std::move(mesh));
      scene.mesh_polarizers.push_back(polarizer);
      scene.mesh_light_groups.push_back(group);
    }
  }
}

// Lights are chosen in proportion to their power: a power that overflows single precision (an intensity
// near 3.4e38 times 4 pi) would make every choice probability NaN.
void check_power(const Light& light, const JsonFields& f, const char* key) {
  if (!std::isfinite(light.power()))
    f.fail(key, "the light's power overflows single precision (the value is too large)");
}

void load_lights(const SceneSources& sources, Scene& scene, float scene_radius) {
  for (const SceneItem& item : sources.lights) {
    const std::filesystem::path dir = item.file.parent_path();
    const JsonFields f(item.json, item.where);
    const LightType& type = LightRegistry::builtin().type_of(f);
    if (type.one_per_scene && scene.environment)
      f.fail("type", fmt::format("only one {} light is allowed", type.name));
    BuiltLight built = type.load(f, dir, scene.camera, scene.origin, scene_radius);
    if (!built.power_field.empty()) check_power(*built.light, f, built.power_field.c_str());
    if (type.one_per_scene) scene.environment = static_cast<const EnvironmentLight*>(built.light.get());
    if (built.flame) {
      built.flame->index = static_cast<int>(scene.flames.size());
      scene.flames.push_back(*built.flame);
    }
    scene.lights.push_back(std::move(built.light));
  }
}

float bounding_radius(const std::vector<Mesh>& meshes) {
  Mesh::Bounds b;
  for (const Mesh& m : meshes) b.include(m.bounds());
  return meshes.empty() || !(b.hi.x >= b.lo.x) ? 1.0f : std::max(1e-3f, 0.5f * length(b.hi - b.lo));
}

void apply_overrides(const SceneOverrides& o, RenderSettings& s) {
  if (o.spp) s.spp = *o.spp;
  if (o.threads) s.threads = *o.threads;
  if (o.seed) s.seed = *o.seed;
  if (o.width) s.width = *o.width;
  if (o.height) s.height = *o.height;
  if (o.polarization) s.polarization = *o.polarization;
  if (o.sampler) s.sampler = *o.sampler;
  if (o.branches) s.branches = *o.branches;
  if (o.rr_depth) s.rr_depth = *o.rr_depth;
  if (o.light_selection) s.light_selection = *o.light_selection;
  if (o.guiding) s.guiding = *o.guiding;
  if (o.noise_threshold) s.noise_threshold = *o.noise_threshold;
}

// An emissive shape whose emission is the same everywhere (known when the scene loads) and whose power
// overflows (see check_power). Emission that varies over the surface is made finite where it is evaluated.
void check_area_light_power(const Scene& scene, const JsonFields& top) {
  for (size_t m = 0; m < scene.mesh_light.size(); ++m) {
    if (scene.mesh_light[m] < 0 || !scene.materials[scene.meshes[m].material]->facts().uniform_over_surface)
      continue;
    if (!std::isfinite(scene.lights[size_t(scene.mesh_light[m])]->power()))
      top.fail(fmt::format("shapes[{}]", m),
               "the emitted power overflows single precision (the material's emission is too large)");
  }
}

void check_no_parameters(const SceneOverrides& overrides, const std::string& file) {
  if (!overrides.parameters.empty())
    throw InputError(fmt::format("{}: scene parameters ({}=...) apply to Mitsuba XML scenes only", file,
                                 overrides.parameters.front().first));
}

// What every load starts with: the scene's top-level keys checked, its film, integrator and output settings
// read and the overrides applied (build_scene goes on with the rest; job_of_json stops here).
void load_job_settings(const JsonFields& top, const std::filesystem::path& scene_dir,
                       const SceneOverrides& overrides, const std::string& file, RenderJob& job,
                       PixelFilter& pixel_filter) {
  top.check_known({"ochre", "camera", "film", "integrator", "output", "materials", "lights", "shapes",
                   "description", "include", "presets"});
  (void)top.string("description", "");  // its type, checked here as when the whole scene loads
  if (top.has("ochre") && !top.require("ochre").is_string() && !top.require("ochre").is_number())
    top.fail("ochre", "expected a version string or number");
  load_settings(top, scene_dir, job, pixel_filter);
  apply_overrides(overrides, job.settings);
  check_settings(job.settings, file);
}

LoadedScene build_scene(const nlohmann::json& root, const std::string& file,
                        const std::filesystem::path& scene_path, const SceneOverrides& overrides) {
  check_no_parameters(overrides, file);
  LoadedScene loaded{std::make_unique<Scene>(), RenderJob{}};
  Scene* scene = loaded.scene.get();
  RenderJob& job = loaded.job;
  scene->file = std::filesystem::absolute(scene_path);
  const SceneSources sources = load_scene_sources(root, scene_path, file, overrides.preset);
  const JsonFields top(sources.root, file + ":");
  load_job_settings(top, scene->file.parent_path(), overrides, file, job, scene->pixel_filter);
  scene->description = top.string("description", "");
  scene->camera = load_camera(top, job.settings, scene->origin);
  if (top.has("camera")) {
    const JsonFields camera(top.require("camera"), top.child("camera"));
    scene->camera_analyzer = parse_camera_polarizer(camera);
    const CameraSensor sensor = parse_camera_sensor(camera, scene->file.parent_path());
    scene->sensor = sensor.response;
    job.outputs.sensor = sensor.name;
    job.outputs.camera_rgb = sensor.camera_rgb;
    job.outputs.sensor_to_xyz = sensor.sensor_to_xyz;
  }

  scene->textures = std::make_unique<OiioTextureProvider>();
  MaterialTemplates templates;
  load_materials(sources, *scene, templates);
  load_shapes(sources, top, *scene, templates);
  const float radius = bounding_radius(scene->meshes);
  load_lights(sources, *scene, radius);

  scene->polarizing_filters = scene->camera_analyzer.has_value();
  for (const auto& light : scene->lights) scene->polarizing_filters |= light->polarizer_axis.has_value();
  for (const auto& p : scene->mesh_polarizers) scene->polarizing_filters |= p.has_value();
  for (const auto& m : scene->materials) {
    scene->polarizing_materials = scene->polarizing_materials || m->facts().polarizes;
    scene->needs_uv = scene->needs_uv || m->facts().needs_uv;
  }
  if (scene->polarizing_materials && !scene->polarizing_filters)
    scene->polarization_significance = polarization_significance(*scene);
  scene->accel = std::make_unique<Accel>(scene->meshes);
  scene->build_lights(job.settings.mirror_lights);
  job.outputs.light_groups = scene->light_groups;
  job.outputs.light_group_emission = scene->light_group_emission();
  check_area_light_power(*scene, top);
  if (scene->light_groups.size() > kMaxLightGroups)
    top.fail("lights",
             fmt::format("{} light groups (with \"other\", the emitters that name none); at most {}",
                         scene->light_groups.size(), kMaxLightGroups));
  return loaded;
}

RenderJob job_of_json(const nlohmann::json& root, const std::string& file,
                      const std::filesystem::path& scene_path, const SceneOverrides& overrides) {
  check_no_parameters(overrides, file);
  const SceneSources sources = load_scene_sources(root, scene_path, file, overrides.preset);
  RenderJob job;
  PixelFilter pixel_filter;
  load_job_settings(JsonFields(sources.root, file + ":"), std::filesystem::absolute(scene_path).parent_path(),
                    overrides, file, job, pixel_filter);
  return job;
}

// `load()` (build_scene or job_of_json for the scene `name`), its errors as InputError naming the file; a
// value a preset wrote is reported where it landed, with the preset that put it there.
template <class Load>
auto with_scene_messages(const std::string& name, const SceneOverrides& overrides, const Load& load)
    -> decltype(load()) {
  try {
    try {
      return load();
    } catch (const GraphError& e) {
      throw InputError(e.what());
    } catch (const nlohmann::json::exception& e) {
      // A read of the scene that escaped the checks of json_fields.h: still bad input in this file.
      throw InputError(fmt::format("{}: {}", name, e.what()));
    }
  } catch (const InputError& e) {
    if (!overrides.preset) throw;
    const std::string message = e.what();
    if (message.find("presets") != std::string::npos) throw;
    throw InputError(fmt::format("{} (with preset '{}': presets.{} of {})", message, *overrides.preset,
                                 *overrides.preset, name));
  }
}

// translate_mitsuba_scene, then `load(json, overrides)` with the overrides of the JSON scene
// (overrides.parameters are the $name parameters); the loader's messages are told at the XML element the
// failing part came from.
template <class Load>
auto load_mitsuba(const std::filesystem::path& file, const SceneOverrides& overrides, const Load& load)
    -> decltype(load(nlohmann::json(), overrides)) {
  const MitsubaTranslation translation = translate_mitsuba_scene(file, overrides.parameters);
  SceneOverrides json_overrides = overrides;
  json_overrides.parameters.clear();
  try {
    return load(translation.scene, json_overrides);
  } catch (const InputError& e) {
    throw InputError(translation.at_origin(e.what(), file.string()));
  }
}

}  // namespace

LoadedScene load_scene_json(const nlohmann::json& root, const std::string& name,
                            const std::filesystem::path& scene_path, const SceneOverrides& overrides) {
  return with_scene_messages(name, overrides, [&] { return build_scene(root, name, scene_path, overrides); });
}

LoadedScene load_scene(const std::filesystem::path& path, const SceneOverrides& overrides) {
  if (is_mitsuba_scene_file(path))
    return load_mitsuba(path, overrides,
                        [&](const nlohmann::json& root, const SceneOverrides& json_overrides) {
                          return load_scene_json(root, path.string(), path, json_overrides);
                        });
  return load_scene_json(read_json_file(path, "scene file"), path.string(), path, overrides);
}

RenderJob load_render_job(const std::filesystem::path& path, const SceneOverrides& overrides) {
  const auto load_json = [&](const nlohmann::json& root, const SceneOverrides& json_overrides) {
    return with_scene_messages(path.string(), json_overrides,
                               [&] { return job_of_json(root, path.string(), path, json_overrides); });
  };
  if (is_mitsuba_scene_file(path)) return load_mitsuba(path, overrides, load_json);
  return load_json(read_json_file(path, "scene file"), overrides);
}

}  // namespace ochre
