#include "renderer/scene_loader.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "materials/graph/graph_error.h"
#include "materials/graph/material_compiler.h"
#include "materials/graph/resource_resolver.h"
#include "renderer/control_mesh.h"
#include "renderer/displacement.h"
#include "renderer/input_error.h"
#include "renderer/json_fields.h"
#include "renderer/json_file.h"
#include "renderer/memory_budget.h"
#include "renderer/mesh_import.h"
#include "renderer/point_light.h"
#include "renderer/procedural_shapes.h"
#include "renderer/spectrum_json.h"
#include "renderer/spot_light.h"
#include "renderer/subdivision.h"
#include "renderer/transform.h"

namespace ochre {

namespace {

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

void load_settings(const nlohmann::json& root, const std::string& file, Scene& scene) {
  RenderSettings& s = scene.settings;
  if (root.contains("film")) {
    const JsonFields f(root["film"], file + ": film");
    f.check_known({"resolution", "colorspace"});
    if (f.has("resolution")) {
      const nlohmann::json& r = f.require("resolution");
      if (!r.is_array() || r.size() != 2 || !r[0].is_number_integer() || !r[1].is_number_integer())
        f.fail("resolution", "expected [width, height] (integers)");
      s.width = r[0].get<int>();
      s.height = r[1].get<int>();
    }
    scene.outputs.colorspace = f.string("colorspace", scene.outputs.colorspace);
  }
  if (root.contains("integrator")) {
    const JsonFields f(root["integrator"], file + ": integrator");
    f.check_known({"type", "spp", "max_depth", "rr_depth", "seed", "threads", "polarization", "sampler"});
    if (f.string("type", "path") != "path") f.fail("type", "unknown integrator (known: path)");
    s.spp = static_cast<uint32_t>(f.integer("spp", s.spp, 1, 1 << 24));
    s.max_depth = static_cast<int>(f.integer("max_depth", s.max_depth, 0, 1024));
    s.rr_depth = static_cast<int>(f.integer("rr_depth", s.rr_depth, 1, 1024));
    s.seed = static_cast<uint64_t>(f.integer("seed", 0, 0, std::numeric_limits<long long>::max()));
    s.threads = static_cast<int>(f.integer("threads", s.threads, 0, 4096));
    s.polarization = f.string("polarization", s.polarization);
    s.sampler = f.string("sampler", s.sampler);
  }
  if (root.contains("output")) {
    const JsonFields f(root["output"], file + ": output");
    f.check_known({"exr", "png", "ocio_config", "display", "view", "exposure", "aovs", "spectral_bins",
                   "spectral_range", "stokes", "polarization_png"});
    const std::filesystem::path dir = scene.file.parent_path();
    if (f.has("exr")) scene.outputs.exr = (dir / f.required_string("exr")).string();
    if (f.has("png")) scene.outputs.png = (dir / f.required_string("png")).string();
    scene.outputs.ocio_config = f.string("ocio_config", "");
    scene.outputs.display = f.string("display", "");
    scene.outputs.view = f.string("view", "");
    scene.outputs.exposure = static_cast<float>(f.number("exposure", 0.0, -64.0, 64.0));
    scene.outputs.spectral_bins = static_cast<int>(f.integer("spectral_bins", 0, 0, 471));
    if (f.has("spectral_range")) {
      const nlohmann::json& r = f.require("spectral_range");
      if (!r.is_array() || r.size() != 2 || !r[0].is_number() || !r[1].is_number() ||
          !(r[0].get<double>() >= 360) || !(r[1].get<double>() <= 830) ||
          !(r[0].get<double>() < r[1].get<double>()))
        f.fail("spectral_range", "expected [min, max] nm with 360 <= min < max <= 830");
      scene.outputs.spectral_min = r[0].get<float>();
      scene.outputs.spectral_max = r[1].get<float>();
    }
    if (f.has("stokes")) {
      if (!f.require("stokes").is_boolean()) f.fail("stokes", "expected true or false");
      scene.outputs.stokes = f.require("stokes").get<bool>();
    }
    if (f.has("polarization_png"))
      scene.outputs.polarization_png = (dir / f.required_string("polarization_png")).string();
    if (f.has("aovs")) {
      if (!f.require("aovs").is_boolean()) f.fail("aovs", "expected true or false");
      scene.outputs.aovs = f.require("aovs").get<bool>();
    }
  }
}

void check_settings(const Scene& scene, const std::string& file) {
  const RenderSettings& s = scene.settings;
  if (s.width < 1 || s.height < 1 || s.width > 65536 || s.height > 65536)
    throw InputError(fmt::format("{}: film.resolution: must be between 1x1 and 65536x65536 (got {}x{})", file,
                                 s.width, s.height));
  if (s.spp < 1) throw InputError(fmt::format("{}: integrator.spp: must be >= 1", file));
  const std::string& p = s.polarization;
  if (p != "auto" && p != "off" && p != "intensity" && p != "stokes")
    throw InputError(fmt::format(
        "{}: integrator.polarization: unknown mode '{}' (known: auto, off, intensity, stokes)", file, p));
  if (s.sampler != "independent" && s.sampler != "sobol")
    throw InputError(fmt::format("{}: integrator.sampler: unknown sampler '{}' (known: independent, sobol)",
                                 file, s.sampler));
  const std::string& cs = scene.outputs.colorspace;
  if (cs != "rec709" && cs != "acescg")
    throw InputError(fmt::format("{}: film.colorspace: unknown '{}' (known: rec709, acescg)", file, cs));
}

// "polarizer": {"axis": [x, y, z]} in front of a light or an emissive shape: the world transmission axis.
std::optional<Vec3> parse_light_polarizer(const JsonFields& f) {
  if (!f.has("polarizer")) return std::nullopt;
  const JsonFields p(f.require("polarizer"), f.child("polarizer"));
  p.check_known({"axis"});
  const Vec3 axis = p.required_vec3("axis");
  if (!(length(axis) > 0.0f)) p.fail("axis", "must be a non-zero vector");
  return normalize(axis);
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

Camera load_camera(const nlohmann::json& root, const std::string& file, const RenderSettings& s) {
  const nlohmann::json camera = root.contains("camera") ? root["camera"] : nlohmann::json::object();
  const JsonFields f(camera, file + ": camera");
  f.check_known({"type", "fov", "size", "eye", "target", "up", "transform", "polarizer"});
  CameraBasis basis;
  if (f.has("transform")) {
    // Camera-to-world; the camera looks along -z with +y up (glTF / OpenGL convention).
    const Transform t = parse_transform(f.require("transform"), f.child("transform"));
    basis.eye = t.point({0, 0, 0});
    basis.forward = normalize(t.vector({0, 0, -1}));
    basis.up = normalize(t.vector({0, 1, 0}));
    basis.right = normalize(cross(basis.forward, basis.up));
    basis.up = cross(basis.right, basis.forward);
  } else {
    const Vec3 eye = f.vec3("eye", {0, 0, 5}), target = f.vec3("target", {0, 0, 0}),
               up = f.vec3("up", {0, 1, 0});
    if (length(target - eye) <= 0.0f) f.fail("target", "must differ from eye");
    if (length(cross(normalize(target - eye), up)) < 1e-6f)
      f.fail("up", "must not be parallel to the view direction");
    basis = camera_basis_look_at(eye, target, up);
  }
  const std::string type = f.string("type", "perspective");
  if (type == "perspective")
    return Camera::perspective(basis, static_cast<float>(f.number("fov", 40.0, 0.0, 179.0, true)), s.width,
                               s.height);
  if (type == "orthographic")
    return Camera::orthographic(basis, static_cast<float>(f.number("size", 2.0, 0.0, 1e30, true)), s.width,
                                s.height);
  f.fail("type", fmt::format("unknown camera type '{}' (known: perspective, orthographic)", type));
}

void load_materials(const nlohmann::json& root, const std::string& file, Scene& scene) {
  if (!root.contains("materials")) return;
  const nlohmann::json& materials = root["materials"];
  if (!materials.is_object()) throw InputError(fmt::format("{}: materials: expected an object", file));
  SceneResources resources(scene.file.parent_path(), *scene.textures);
  for (const auto& [name, value] : materials.items()) {
    scene.material_names.push_back(name);
    scene.materials.push_back(compile_material(value, name, file, resources));
  }
}

int material_index(const Scene& scene, const JsonFields& f) {
  const std::string name = f.required_string("material");
  for (size_t i = 0; i < scene.material_names.size(); ++i)
    if (scene.material_names[i] == name) return static_cast<int>(i);
  f.fail("material", fmt::format("unknown material '{}'", name));
}

Mesh load_triangles(const JsonFields& f, const std::filesystem::path& path, const Transform& to_world) {
  MeshImportOptions options;
  if (f.has("smooth_normals")) options.smooth_normals = f.require("smooth_normals").get<bool>();
  if (f.has("flip_uv_v")) options.flip_uv_v = f.require("flip_uv_v").get<bool>();
  if (f.has("displacement"))
    f.fail("displacement", "needs \"subdivision\" (displacement moves the refined vertices)");
  return import_mesh(path, to_world, options);
}

// Polygonal control mesh -> OpenSubdiv uniform refinement -> optional displacement along the
// smooth normal (shading normals recomputed).
Mesh load_subdivided(const JsonFields& f, const std::filesystem::path& path, const Transform& to_world,
                     const Scene& scene) {
  const SubdivisionOptions options =
      parse_subdivision(JsonFields(f.require("subdivision"), f.child("subdivision")));
  Mesh mesh = subdivide(import_control_mesh(path, to_world), options);
  if (f.has("displacement")) {
    const DisplacementOptions d = parse_displacement(
        JsonFields(f.require("displacement"), f.child("displacement")), scene.file.parent_path());
    displace(mesh, d, *scene.textures);
  }
  return mesh;
}

Mesh load_shape(const JsonFields& f, const Scene& scene) {
  const std::string type = f.required_string("type");
  const Transform to_world = f.has("transform")
                                 ? parse_transform(f.require("transform"), f.child("transform"))
                                 : Transform::identity();
  Mesh mesh;
  if (type == "mesh") {
    f.check_known({"type", "file", "material", "transform", "smooth_normals", "flip_uv_v", "name",
                   "subdivision", "displacement", "polarizer"});
    std::filesystem::path path = f.required_string("file");
    if (path.is_relative()) path = scene.file.parent_path() / path;
    try {
      mesh = f.has("subdivision") ? load_subdivided(f, path, to_world, scene)
                                  : load_triangles(f, path, to_world);
    } catch (const InputError& e) {
      const std::string what = e.what();
      if (what.find(f.where()) != std::string::npos) throw;
      f.fail("file", what);
    }
  } else if (type == "sphere") {
    f.check_known({"type", "center", "radius", "subdivisions", "material", "transform", "name", "polarizer"});
    const float radius = static_cast<float>(f.number("radius", 1.0, 0.0, 1e30, true));
    const int subdivisions = static_cast<int>(f.integer("subdivisions", 96, 4, 4096));
    check_memory_estimate(sphere_memory_bytes(subdivisions),
                          fmt::format("{}: a sphere of {:.0f} triangles", f.child("subdivisions"),
                                      sphere_triangle_count(subdivisions)));
    mesh = make_sphere(radius, subdivisions);
    mesh.transform(to_world * Transform::translate(f.vec3("center", {0, 0, 0})));
  } else if (type == "plane") {
    f.check_known({"type", "size", "material", "transform", "name", "polarizer"});
    Vec2 size{2, 2};
    if (f.has("size")) {
      const nlohmann::json& s = f.require("size");
      if (!s.is_array() || s.size() != 2 || !s[0].is_number() || !s[1].is_number() ||
          !(s[0].get<double>() > 0) || !(s[1].get<double>() > 0))
        f.fail("size", "expected [width, height] > 0");
      size = {s[0].get<float>(), s[1].get<float>()};
    }
    mesh = make_plane(size);
    mesh.transform(to_world);
  } else if (type == "disk") {
    f.check_known({"type", "radius", "segments", "material", "transform", "name", "polarizer"});
    mesh = make_disk(static_cast<float>(f.number("radius", 1.0, 0.0, 1e30, true)),
                     static_cast<int>(f.integer("segments", 128, 3, 1 << 20)));
    mesh.transform(to_world);
  } else {
    f.fail("type", fmt::format("unknown shape type '{}' (known: mesh, sphere, plane, disk)", type));
  }
  mesh.name = f.string("name", type);
  mesh.material = material_index(scene, f);
  mesh.validate(f.where());
  return mesh;
}

void load_shapes(const nlohmann::json& root, const std::string& file, Scene& scene) {
  if (!root.contains("shapes") || !root["shapes"].is_array())
    throw InputError(fmt::format("{}: shapes: expected an array of shapes", file));
  const nlohmann::json& shapes = root["shapes"];
  for (size_t i = 0; i < shapes.size(); ++i) {
    const JsonFields f(shapes[i], fmt::format("{}: shapes[{}]", file, i));
    scene.meshes.push_back(load_shape(f, scene));
    scene.mesh_polarizers.push_back(parse_light_polarizer(f));
    if (scene.mesh_polarizers.back() && !scene.materials[scene.meshes.back().material]->facts().is_emissive)
      f.fail("polarizer", "a polarizer belongs in front of a light: this shape's material does not emit");
  }
}

std::unique_ptr<Light> load_spot_light(const JsonFields& f, const std::filesystem::path& dir) {
  f.check_known(
      {"type", "position", "direction", "target", "cone_angle", "falloff_start", "intensity", "polarizer"});
  const Vec3 position = f.required_vec3("position");
  if (f.has("direction") == f.has("target")) f.fail("", "give exactly one of \"direction\" or \"target\"");
  const char* aim = f.has("direction") ? "direction" : "target";
  const Vec3 direction =
      f.has("direction") ? f.required_vec3("direction") : f.required_vec3("target") - position;
  if (!(length(direction) > 0.0f)) f.fail(aim, "gives no direction");
  const double cone = f.number("cone_angle", 30.0, 0.0, 180.0, true);
  const double falloff = f.number("falloff_start", cone, 0.0, cone, true);
  auto light = std::make_unique<SpotLight>(
      position, direction, static_cast<float>(cone), static_cast<float>(falloff),
      parse_spectrum(f.require("intensity"), SpectrumRole::Illuminant, f.child("intensity"), dir));
  light->polarizer_axis = parse_light_polarizer(f);
  return light;
}

void load_lights(const nlohmann::json& root, const std::string& file, Scene& scene, float scene_radius) {
  if (!root.contains("lights")) return;
  const nlohmann::json& lights = root["lights"];
  if (!lights.is_array()) throw InputError(fmt::format("{}: lights: expected an array", file));
  const std::filesystem::path dir = scene.file.parent_path();
  for (size_t i = 0; i < lights.size(); ++i) {
    const JsonFields f(lights[i], fmt::format("{}: lights[{}]", file, i));
    const std::string type = f.required_string("type");
    if (type == "environment") {
      if (scene.environment) f.fail("type", "only one environment light is allowed");
      auto env = make_environment_light(f, dir, scene_radius);
      scene.environment = env.get();
      scene.lights.push_back(std::move(env));
    } else if (type == "point") {
      f.check_known({"type", "position", "intensity", "polarizer"});
      auto light = std::make_unique<PointLight>(
          f.required_vec3("position"),
          parse_spectrum(f.require("intensity"), SpectrumRole::Illuminant, f.child("intensity"), dir));
      light->polarizer_axis = parse_light_polarizer(f);
      scene.lights.push_back(std::move(light));
    } else if (type == "spot") {
      scene.lights.push_back(load_spot_light(f, dir));
    } else {
      f.fail("type",
             fmt::format(
                 "unknown light type '{}' (known: environment, point, spot; emissive shapes are area lights)",
                 type));
    }
  }
}

float bounding_radius(const std::vector<Mesh>& meshes) {
  Vec3 lo(INFINITY, INFINITY, INFINITY), hi(-INFINITY, -INFINITY, -INFINITY);
  for (const Mesh& m : meshes)
    for (const Vec3& p : m.positions) {
      lo = min(lo, p);
      hi = max(hi, p);
    }
  return meshes.empty() || !(hi.x >= lo.x) ? 1.0f : std::max(1e-3f, 0.5f * length(hi - lo));
}

void apply_overrides(const SceneOverrides& o, RenderSettings& s) {
  if (o.spp) s.spp = *o.spp;
  if (o.threads) s.threads = *o.threads;
  if (o.seed) s.seed = *o.seed;
  if (o.width) s.width = *o.width;
  if (o.height) s.height = *o.height;
  if (o.polarization) s.polarization = *o.polarization;
  if (o.sampler) s.sampler = *o.sampler;
}

}  // namespace

std::unique_ptr<Scene> load_scene(const std::filesystem::path& path, const SceneOverrides& overrides) {
  auto scene = std::make_unique<Scene>();
  scene->file = std::filesystem::absolute(path);
  const std::string file = path.string();
  const nlohmann::json root = read_json_file(scene->file, "scene file");
  const JsonFields top(root, file + ":");
  top.check_known(
      {"ochre", "camera", "film", "integrator", "output", "materials", "lights", "shapes", "description"});

  load_settings(root, file, *scene);
  apply_overrides(overrides, scene->settings);
  check_settings(*scene, file);
  scene->camera = load_camera(root, file, scene->settings);
  if (root.contains("camera"))
    scene->camera_analyzer = parse_camera_polarizer(JsonFields(root["camera"], file + ": camera"));

  scene->textures = std::make_unique<OiioTextureProvider>();
  try {
    load_materials(root, file, *scene);
  } catch (const GraphError& e) {
    throw InputError(e.what());
  }
  load_shapes(root, file, *scene);
  const float radius = bounding_radius(scene->meshes);
  load_lights(root, file, *scene, radius);

  scene->polarizing_filters = scene->camera_analyzer.has_value();
  for (const auto& light : scene->lights) scene->polarizing_filters |= light->polarizer_axis.has_value();
  for (const auto& p : scene->mesh_polarizers) scene->polarizing_filters |= p.has_value();
  for (const auto& m : scene->materials) {
    scene->polarizing_materials = scene->polarizing_materials || m->facts().polarizes;
    scene->needs_uv = scene->needs_uv || m->facts().needs_uv;
  }
  scene->accel = std::make_unique<Accel>(scene->meshes);
  scene->build_lights();
  return scene;
}

}  // namespace ochre
