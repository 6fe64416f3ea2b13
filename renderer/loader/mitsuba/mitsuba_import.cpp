#include "renderer/loader/mitsuba/mitsuba_import.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "renderer/loader/mitsuba/mitsuba_materials.h"
#include "renderer/loader/mitsuba/mitsuba_object.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

constexpr int kMaxDepth = 1024;  // ochre's integrator.max_depth limit (docs/scene-format.md)

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

// The rotation part of a camera or light transform, which must not scale, shear or mirror.
void require_rotation(const Matrix4d& m, const MitsubaObject& obj, const char* what) {
  const Vec3d x = m.vector({1, 0, 0}), y = m.vector({0, 1, 0}), z = m.vector({0, 0, 1});
  const double tolerance = 1e-4;
  if (std::abs(length(x) - 1) > tolerance || std::abs(length(y) - 1) > tolerance ||
      std::abs(length(z) - 1) > tolerance || std::abs(dot(x, y)) > tolerance ||
      std::abs(dot(y, z)) > tolerance || std::abs(dot(x, z)) > tolerance || m.determinant3() < 0)
    obj.fail(fmt::format("to_world of a {} must be a rotation and a translation (no scale, shear or mirror)",
                         what));
}

class Translator {
 public:
  explicit Translator(const MitsubaDocument& document) : document_(document), materials_(document) {}

  MitsubaTranslation run() {
    scene_["shapes"] = nlohmann::json::array();
    scene_["lights"] = nlohmann::json::array();
    const MitsubaElement* integrator = nullptr;
    const MitsubaElement* sensor = nullptr;
    for (const MitsubaElement& e : document_.scene.children) {
      if (e.tag == "integrator") {
        if (integrator)
          fail_at(e, fmt::format("a second <integrator> (the first is at line {})", integrator->line));
        integrator = &e;
      } else if (e.tag == "sensor") {
        if (sensor)
          fail_at(
              e, fmt::format("a second <sensor>: ochre renders one (the first is at line {})", sensor->line));
        sensor = &e;
      } else if (e.tag == "shape") {
        shape(e);
      } else if (e.tag == "emitter") {
        top_level_emitter(e);
      } else if (e.tag == "bsdf") {
        if (!e.has("id"))
          fail_at(e, "a <bsdf> at scene level needs an id (shapes refer to it with <ref id=.../>)");
        materials_.material(&e, nullptr, "");  // translated (and checked) even when no shape uses it
      } else if (e.tag == "texture") {
        if (!e.has("id"))
          fail_at(e, "a <texture> at scene level needs an id (BSDFs refer to it with <ref .../>)");
      } else if (e.tag == "alias") {
        continue;
      } else if (e.tag == "ref") {
        fail_at(e, "a <ref> at scene level refers to nothing ochre can use");
      } else {
        fail_at(
            e, fmt::format("unsupported element <{}> (ochre reads: integrator, sensor, shape, emitter, bsdf, "
                           "texture, include, default, path, alias)",
                           e.tag));
      }
    }
    for (const MitsubaElement* area : area_emitters_)
      if (!used_area_emitters_.count(area))
        fail_at(*area, "an area emitter that no shape refers to (attach it to a shape with <ref id=.../>)");
    if (!sensor)
      throw InputError(fmt::format("{}: the scene has no <sensor> (ochre needs a perspective sensor)",
                                   document_.scene.file));
    translate_sensor(*sensor);  // first: the sensor's sampler sets the integrator's samples
    translate_integrator(integrator);
    scene_["materials"] = materials_.json();
    MitsubaTranslation t;
    t.scene = std::move(scene_);
    t.origins = std::move(origins_);
    t.origins.insert(t.origins.end(), materials_.origins().begin(), materials_.origins().end());
    return t;
  }

 private:
  void translate_integrator(const MitsubaElement* element) {
    nlohmann::json integrator = {{"type", "path"}};
    long long max_depth = -1, rr_depth = 5;  // Mitsuba's defaults
    if (element) {
      MitsubaObject obj(*element, document_);
      if (obj.type() != "path" && obj.type() != "volpath")
        obj.fail(fmt::format(
            "unsupported integrator \"{}\" (ochre reads: path, and volpath in scenes without media)",
            obj.type()));
      max_depth = obj.integer("max_depth").value_or(-1);
      rr_depth = obj.integer("rr_depth").value_or(5);
      if (obj.boolean("hide_emitters", false)) obj.fail("hide_emitters is not supported");
      if (max_depth == 0 || max_depth < -1)
        obj.fail(
            fmt::format("max_depth {}: ochre's shortest path is Mitsuba's max_depth 1 (emitters seen "
                        "directly); -1 means no limit",
                        max_depth));
      if (rr_depth < 1) obj.fail(fmt::format("rr_depth {} must be >= 1", rr_depth));
      obj.finish({"max_depth", "rr_depth", "hide_emitters"});
      origins_.emplace_back("integrator", element->where());
    }
    // Mitsuba's max_depth counts path segments including the camera ray (1: emitters seen directly, 2:
    // direct lighting); ochre's counts scattering events (0: emission only, 1: direct lighting). Russian
    // roulette starts at the same vertex in both with the same number.
    integrator["max_depth"] = max_depth == -1 ? kMaxDepth : std::min<long long>(max_depth - 1, kMaxDepth);
    integrator["rr_depth"] = std::min<long long>(rr_depth, kMaxDepth);
    for (const auto& [key, value] : sampler_.items()) integrator[key] = value;
    scene_["integrator"] = integrator;
  }

  void translate_sensor(const MitsubaElement& element) {
    MitsubaObject obj(element, document_);
    if (obj.type() != "perspective")
      obj.fail(fmt::format("unsupported sensor \"{}\" (ochre reads: perspective)", obj.type()));
    nlohmann::json camera = {{"type", "perspective"}};
    if (obj.has("fov") && obj.has("focal_length")) obj.fail("give either fov or focal_length, not both");
    if (obj.has("fov")) {
      camera["fov"] = obj.number("fov", 0.0);
      const std::string axis = lower(obj.string("fov_axis", "x"));  // Mitsuba's default: x
      if (axis != "x" && axis != "y" && axis != "diagonal" && axis != "smaller" && axis != "larger")
        obj.fail(fmt::format("fov_axis \"{}\" is not one of x, y, diagonal, smaller, larger", axis));
      camera["fov_axis"] = axis;
    } else {
      // Mitsuba's "<x>mm" of a 35 mm film (36 x 24 mm): the field of view across its diagonal.
      std::string focal = obj.string("focal_length", "50mm");
      if (focal.size() > 2 && focal.compare(focal.size() - 2, 2, "mm") == 0) focal.resize(focal.size() - 2);
      const double mm = parse_number(focal, element, "focal_length");
      if (!(mm > 0.0)) obj.fail("focal_length must be > 0");
      camera["fov"] = 2.0 * std::atan(std::sqrt(36.0 * 36.0 + 24.0 * 24.0) / (2.0 * mm)) * 180.0 / M_PI;
      camera["fov_axis"] = "diagonal";
    }
    const Matrix4d to_world = obj.transform("to_world").value_or(Matrix4d());
    require_rotation(to_world, obj, "sensor");
    // Mitsuba's camera looks along its +z with +y up (the image's x runs along its -x).
    const Vec3d eye = to_world.point({0, 0, 0});
    camera["eye"] = to_json(eye);
    camera["target"] = to_json(eye + to_world.vector({0, 0, 1}));
    camera["up"] = to_json(to_world.vector({0, 1, 0}));
    // Clipping planes and the focus distance change nothing for a pinhole camera whose scene lies between
    // the planes; ochre has no clipping planes.
    const double near_clip = obj.number("near_clip", 0.01), far_clip = obj.number("far_clip", 1e4);
    obj.number("focus_distance");
    if (!(near_clip > 0.0) || !(near_clip < far_clip)) obj.fail("near_clip must be > 0 and < far_clip");
    translate_sampler(obj.object("sampler"));
    translate_film(obj.object("film"));
    obj.finish({"fov", "fov_axis", "focal_length", "to_world", "near_clip", "far_clip", "focus_distance",
                "film", "sampler"});
    scene_["camera"] = camera;
    origins_.emplace_back("camera", element.where());
  }

  void translate_sampler(const MitsubaElement* element) {
    sampler_ = {{"sampler", "independent"}, {"spp", 4}, {"seed", 0}};  // Mitsuba's default sampler
    if (!element) return;
    MitsubaObject obj(*element, document_);
    const std::string& type = obj.type();
    if (type != "independent" && type != "stratified" && type != "multijitter" && type != "orthogonal" &&
        type != "ldsampler")
      obj.fail(
          fmt::format("unsupported sampler \"{}\" (ochre reads: independent, stratified, multijitter, "
                      "orthogonal, ldsampler)",
                      type));
    // The stratified and low-discrepancy samplers become ochre's sobol sampler: another stratified
    // sequence, the same image in expectation.
    sampler_["sampler"] = type == "independent" ? "independent" : "sobol";
    sampler_["spp"] = obj.integer("sample_count").value_or(4);
    sampler_["seed"] = obj.integer("seed").value_or(0);
    if (type == "stratified" || type == "multijitter") obj.boolean("jitter", true);
    obj.finish({"sample_count", "seed", "jitter"});
    for (const auto& [key, value] : sampler_.items())
      origins_.emplace_back("integrator." + key, element->where());
  }

  void translate_film(const MitsubaElement* element) {
    nlohmann::json film = {{"resolution", {768, 576}}, {"filter", {{"type", "gaussian"}, {"stddev", 0.5}}}};
    if (element) {
      MitsubaObject obj(*element, document_);
      if (obj.type() != "hdrfilm")
        obj.fail(fmt::format("unsupported film \"{}\" (ochre reads: hdrfilm)", obj.type()));
      film["resolution"] = {obj.integer("width").value_or(768), obj.integer("height").value_or(576)};
      // Output encodings: ochre writes a float RGB EXR (and no alpha) whatever these say.
      const std::string pixel_format = lower(obj.string("pixel_format", "rgba"));
      if (pixel_format != "rgb" && pixel_format != "rgba")
        obj.fail(
            fmt::format("pixel_format \"{}\" is not supported (ochre writes RGB: rgb, rgba)", pixel_format));
      const std::string component = lower(obj.string("component_format", "float16"));
      if (component != "float16" && component != "float32")
        obj.fail(fmt::format("component_format \"{}\" is not one of float16, float32", component));
      const std::string file_format = lower(obj.string("file_format", "openexr"));
      if (file_format != "openexr" && file_format != "exr")
        obj.fail(fmt::format("file_format \"{}\" is not supported (ochre writes OpenEXR)", file_format));
      if (obj.boolean("sample_border", false)) obj.fail("sample_border is not supported");
      if (const MitsubaElement* rfilter = obj.object("rfilter")) film["filter"] = filter(*rfilter);
      obj.finish(
          {"width", "height", "rfilter", "pixel_format", "component_format", "file_format", "sample_border"});
      origins_.emplace_back("film", element->where());
    }
    scene_["film"] = film;
  }

  nlohmann::json filter(const MitsubaElement& element) {
    MitsubaObject obj(element, document_);
    nlohmann::json f;
    if (obj.type() == "box") {
      f = {{"type", "box"}, {"radius", obj.number("radius", 0.5)}};
      obj.finish({"radius"});
    } else if (obj.type() == "gaussian") {
      f = {{"type", "gaussian"}, {"stddev", obj.number("stddev", 0.5)}};
      obj.finish({"stddev"});
    } else {
      obj.fail(
          fmt::format("unsupported reconstruction filter \"{}\" (ochre reads: box, gaussian)", obj.type()));
    }
    origins_.emplace_back("film.filter", element.where());
    return f;
  }

  void shape(const MitsubaElement& element) {
    MitsubaObject obj(element, document_);
    const std::string index = fmt::format("shapes[{}]", scene_["shapes"].size());
    nlohmann::json s;
    const std::string& type = obj.type();
    std::vector<std::string> supported = {"to_world", "flip_normals", "bsdf", "emitter"};
    if (type == "obj" || type == "ply") {
      const std::string file = obj.required_string("filename");
      const bool face_normals = obj.boolean("face_normals", false);
      // Mitsuba flips the v of OBJ uvs by default (flip_tex_coords: true), not of PLY ones; ochre's v runs
      // up, Mitsuba's down the image: an OBJ needs no flip in ochre, a PLY one.
      const bool flip_tex_coords = obj.boolean("flip_tex_coords", type == "obj");
      s = {{"type", "mesh"}, {"file", mitsuba_file_for_json(document_, element, file)}};
      if (face_normals)
        s["face_normals"] = true;
      else
        s["smooth_normals"] = true;  // Mitsuba computes smooth normals for files without them
      if (!flip_tex_coords) s["flip_uv_v"] = true;
      supported.insert(supported.end(), {"filename", "face_normals", "flip_tex_coords"});
    } else if (type == "rectangle") {
      s = {{"type", "plane"}, {"size", {2, 2}}, {"flip_uv_v", true}};
    } else if (type == "cube") {
      s = {{"type", "cube"}};
    } else if (type == "sphere") {
      s = {{"type", "sphere"},
           {"center", to_json(obj.point("center").value_or(Vec3d{}))},
           {"radius", obj.number("radius", 1.0)}};
      supported.insert(supported.end(), {"center", "radius"});
    } else if (type == "disk") {
      s = {{"type", "disk"}, {"radius", 1.0}};
    } else {
      obj.fail(fmt::format(
          "unsupported shape type \"{}\" (ochre reads: obj, ply, rectangle, cube, sphere, disk)", type));
    }
    if (const std::optional<Matrix4d> to_world = obj.transform("to_world");
        to_world && !to_world->is_identity())
      s["transform"] = to_world->to_json();
    if (obj.boolean("flip_normals", false)) s["flip_normals"] = true;
    if (const std::string* id = element.attribute("id")) s["name"] = *id;
    const MitsubaElement* emitter = obj.object("emitter");
    if (emitter) used_area_emitters_.insert(emitter);
    s["material"] = materials_.material(obj.object("bsdf"), emitter, index);
    if (type == "disk" && materials_.uses_textures(s["material"].get<std::string>()))
      obj.fail("a textured disk: Mitsuba's disk uv (radius, angle) is not ochre's (planar); use a mesh");
    obj.finish(supported);
    scene_["shapes"].push_back(s);
    origins_.emplace_back(index, element.where());
  }

  void top_level_emitter(const MitsubaElement& element) {
    MitsubaObject obj(element, document_);
    const std::string& type = obj.type();
    if (type == "area") {
      if (!element.has("id"))
        fail_at(element,
                "an area emitter at scene level needs an id (shapes refer to it with <ref id=.../>)");
      area_emitters_.push_back(&element);
      return;
    }
    const std::string index = fmt::format("lights[{}]", scene_["lights"].size());
    nlohmann::json light;
    const nlohmann::json d65 = {{"name", "D65"}};  // Mitsuba's default emission: D65 at luminance 1
    if (type == "point") {
      if (obj.has("position") && obj.has("to_world")) obj.fail("give either position or to_world, not both");
      const Vec3d position = obj.has("position")
                                 ? *obj.point("position")
                                 : obj.transform("to_world").value_or(Matrix4d()).point({0, 0, 0});
      light = {{"type", "point"},
               {"position", to_json(position)},
               {"intensity", obj.colour("intensity", MitsubaColourRole::Emission).value_or(d65)}};
      obj.finish({"position", "to_world", "intensity"});
    } else if (type == "spot") {
      const Matrix4d to_world = obj.transform("to_world").value_or(Matrix4d());
      const double cutoff = obj.number("cutoff_angle", 20.0);
      const double beam = obj.number("beam_width", cutoff * 0.75);
      if (!(cutoff > 0.0 && cutoff <= 180.0)) obj.fail("cutoff_angle must be in (0, 180]");
      if (!(beam > 0.0 && beam <= cutoff)) obj.fail("beam_width must be in (0, cutoff_angle]");
      light = {{"type", "spot"},
               {"position", to_json(to_world.point({0, 0, 0}))},
               {"direction", to_json(to_world.vector({0, 0, 1}))},
               {"cone_angle", cutoff},
               {"falloff_start", beam},
               {"falloff", "linear"},  // Mitsuba's ramp is linear in the angle
               {"intensity", obj.colour("intensity", MitsubaColourRole::Emission).value_or(d65)}};
      obj.finish({"to_world", "cutoff_angle", "beam_width", "intensity"});
    } else if (type == "constant") {
      light = {{"type", "environment"},
               {"radiance", obj.colour("radiance", MitsubaColourRole::Emission).value_or(d65)}};
      obj.finish({"radiance"});
    } else if (type == "envmap") {
      light = environment_map(obj);
    } else {
      obj.fail(fmt::format(
          "unsupported emitter type \"{}\" (ochre reads: area (on shapes), point, spot, constant, "
          "envmap)",
          type));
    }
    if (light["type"] == "environment") {
      if (environment_)
        obj.fail(fmt::format("a second environment emitter (the first is at line {})", environment_->line));
      environment_ = &element;
    }
    scene_["lights"].push_back(light);
    origins_.emplace_back(index, element.where());
  }

  // Mitsuba's map: u = 0 (its left edge) looks along -z, u = 1/4 along +x, +y at the top row; ochre's map is
  // the same turned by 180 degrees about +y (its centre column looks along -z, docs/scene-format.md), so
  // a Mitsuba to_world turning by theta about +y is ochre's rotation theta + 180.
  nlohmann::json environment_map(MitsubaObject& obj) {
    const std::string file = obj.required_string("filename");
    const Matrix4d m = obj.transform("to_world").value_or(Matrix4d());
    require_rotation(m, obj, "environment map");
    if (std::abs(m(1, 1) - 1.0) > 1e-6)
      obj.fail("to_world of an envmap may only turn it about +y (ochre's environment rotation)");
    const double theta = std::atan2(m(0, 2), m(0, 0)) * 180.0 / M_PI;
    const double scale = obj.number("scale", 1.0);
    if (obj.boolean("mis_compensation", false)) obj.fail("mis_compensation is not supported");
    obj.finish({"filename", "scale", "to_world", "mis_compensation"});
    double rotation = theta + 180.0;
    if (rotation > 180.0) rotation -= 360.0;
    return {{"type", "environment"},
            {"file", mitsuba_file_for_json(document_, obj.element(), file)},
            {"scale", scale},
            {"rotation", rotation}};
  }

  const MitsubaDocument& document_;
  MitsubaMaterials materials_;
  nlohmann::json scene_ = nlohmann::json::object();
  nlohmann::json sampler_ = nlohmann::json::object();
  std::vector<std::pair<std::string, std::string>> origins_;
  std::vector<const MitsubaElement*> area_emitters_;
  std::set<const MitsubaElement*> used_area_emitters_;
  const MitsubaElement* environment_ = nullptr;
};

}  // namespace

bool is_mitsuba_scene_file(const std::filesystem::path& file) {
  return lower(file.extension().string()) == ".xml";
}

MitsubaTranslation translate_mitsuba_scene(
    const std::filesystem::path& file, const std::vector<std::pair<std::string, std::string>>& parameters) {
  std::error_code error;
  if (!std::filesystem::exists(file, error))
    throw InputError(fmt::format("{}: cannot open scene file", file.string()));
  const std::unique_ptr<MitsubaDocument> document = read_mitsuba_xml(file, parameters);
  return Translator(*document).run();
}

// "scene.xml: shapes[3].file: ..." -> "fragments/shapes.xml:5: <shape type="obj">: shapes[3].file: ...":
// a message of the JSON loader about the translated scene, told at the XML element the part came from.
std::string MitsubaTranslation::at_origin(const std::string& message, const std::string& file) const {
  const std::string prefix = file + ": ";
  if (message.compare(0, prefix.size(), prefix) != 0) return message;
  const std::string rest = message.substr(prefix.size());
  const std::pair<std::string, std::string>* best = nullptr;
  for (const auto& origin : origins) {
    const std::string& key = origin.first;
    if (rest.compare(0, key.size(), key) != 0) continue;
    const char next = rest.size() > key.size() ? rest[key.size()] : ':';
    if (next != '.' && next != '[' && next != ':' && next != ',') continue;
    if (!best || key.size() > best->first.size()) best = &origin;
  }
  return best ? fmt::format("{}: {}", best->second, rest) : message;
}

}  // namespace ochre
