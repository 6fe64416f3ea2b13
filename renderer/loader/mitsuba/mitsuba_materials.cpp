#include "renderer/loader/mitsuba/mitsuba_materials.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "renderer/loader/mitsuba/mitsuba_object.h"

namespace ochre {

namespace {

// Mitsuba 3's named indices of refraction (src/render/ior.h).
struct NamedIor {
  const char* name;
  double ior;
};
constexpr NamedIor kNamedIors[] = {
    {"vacuum", 1.0},      {"helium", 1.000036},        {"hydrogen", 1.000132},
    {"air", 1.000277},    {"carbon dioxide", 1.00045}, {"water", 1.3330},
    {"acetone", 1.36},    {"ethanol", 1.361},          {"carbon tetrachloride", 1.461},
    {"glycerol", 1.4729}, {"benzene", 1.501},          {"silicone oil", 1.52045},
    {"bromine", 1.661},   {"water ice", 1.31},         {"fused quartz", 1.458},
    {"pyrex", 1.470},     {"acrylic glass", 1.49},     {"polypropylene", 1.49},
    {"bk7", 1.5046},      {"sodium chloride", 1.544},  {"amber", 1.55},
    {"pet", 1.5750},      {"diamond", 2.419}};

// Mitsuba's conductor materials that ochre has optical constants for (docs/nodes.md, conductor).
constexpr const char* kMetals[] = {"Ag", "Al", "Au", "Cu"};

// Nodes of one material graph (docs/nodes.md), named n0, n1, ... after what they are.
class Graph {
 public:
  std::string add(const std::string& kind, nlohmann::json node) {
    const std::string name = fmt::format("{}{}", kind, count_++);
    nodes[name] = std::move(node);
    return name;
  }
  nlohmann::json nodes = nlohmann::json::object();
  bool textured = false;

 private:
  int count_ = 0;
};

class BsdfTranslator {
 public:
  BsdfTranslator(const MitsubaDocument& document, Graph& graph) : document_(document), graph_(graph) {}

  // The closure node of a <bsdf>.
  std::string bsdf(const MitsubaElement& element) {
    MitsubaObject obj(element, document_);
    const std::string& type = obj.type();
    if (type == "diffuse") {
      const nlohmann::json color = input(obj, "reflectance", MitsubaColourRole::Reflectance, 0.5);
      obj.finish({"reflectance"});
      return graph_.add("diffuse", {{"type", "lambert"}, {"color", color}});
    }
    if (type == "conductor" || type == "roughconductor") return conductor(obj);
    if (type == "dielectric") return dielectric(obj);
    if (type == "twosided") {
      const std::vector<const MitsubaElement*> sides = obj.objects("bsdf");
      obj.finish({"bsdf"});
      if (sides.size() != 1)
        obj.fail(sides.empty() ? "a twosided BSDF needs one nested <bsdf>"
                               : "a twosided BSDF with different front and back BSDFs is not supported");
      // ochre shades both sides of every surface (the shading normal is turned to the viewer), which is
      // what twosided does.
      return bsdf(*sides.front());
    }
    if (type == "roughdielectric")
      obj.fail(
          "not supported: ochre's rough dielectric reflects only (the refracted light is not traced), so "
          "rough glass cannot be reproduced (supported: dielectric, smooth)");
    if (type == "plastic" || type == "roughplastic")
      obj.fail("not supported: ochre has no plastic model (a diffuse base under a dielectric coating)");
    obj.fail(
        fmt::format("unsupported BSDF type \"{}\" (ochre reads: diffuse, conductor, roughconductor, "
                    "dielectric, twosided)",
                    type));
  }

  // The emission closure of an area <emitter>.
  std::string emission(const MitsubaElement& element) {
    MitsubaObject obj(element, document_);
    if (obj.type() != "area")
      obj.fail(fmt::format("a shape's emitter must be an area emitter (got type \"{}\")", obj.type()));
    const nlohmann::json radiance = input(obj, "radiance", MitsubaColourRole::Emission, {{"name", "D65"}});
    obj.finish({"radiance"});
    return graph_.add("emission", {{"type", "emission"}, {"color", radiance}});
  }

 private:
  // A colour-like input: a number, <rgb>, <spectrum> or a bitmap <texture> (nested or by <ref>).
  nlohmann::json input(MitsubaObject& obj, const std::string& name, MitsubaColourRole role,
                       const nlohmann::json& fallback) {
    const MitsubaElement* e = obj.has(name) ? obj.get(name) : nullptr;
    if (!e) return fallback;
    if (e->tag == "texture") return {{"link", texture(*e) + ".color"}};
    return colour_value(document_, *e, role);
  }

  std::string texture(const MitsubaElement& element) {
    MitsubaObject obj(element, document_);
    if (obj.type() != "bitmap")
      obj.fail(fmt::format("unsupported texture type \"{}\" (ochre reads: bitmap)", obj.type()));
    const std::string file = obj.required_string("filename");
    const bool raw = obj.boolean("raw", false);
    const std::string filter = obj.string("filter_type", "bilinear");
    if (filter != "bilinear")
      obj.fail(
          fmt::format("filter_type \"{}\" is not supported (ochre filters textures: bilinear within MIP "
                      "levels, trilinear across)",
                      filter));
    const std::string wrap = obj.string("wrap_mode", "repeat");
    if (wrap != "repeat")
      obj.fail(fmt::format("wrap_mode \"{}\" is not supported (ochre's textures repeat)", wrap));
    const std::string format = obj.string("format", "auto");  // storage precision only
    if (format != "auto" && format != "variant" && format != "fp16")
      obj.fail(fmt::format("format \"{}\" is not one of auto, variant, fp16", format));
    obj.boolean("accel", true);  // a CUDA lookup setting
    const std::optional<Matrix4d> to_uv = obj.transform("to_uv");
    obj.finish({"filename", "raw", "filter_type", "wrap_mode", "to_uv", "format", "accel"});

    nlohmann::json node = {{"type", "texture"},
                           {"file", mitsuba_file_for_json(document_, element, file)},
                           {"colorspace", raw ? "linear" : "auto"}};
    if (to_uv && !to_uv->is_identity()) node["uv"] = {{"link", uv_transform(*to_uv, element)}};
    graph_.textured = true;
    return graph_.add("texture", node);
  }

  // Mitsuba looks a texture up at to_uv(uv) with v = 0 at the image's top row; ochre at uv with v = 0 at
  // the bottom row (docs/nodes.md, texture). With uv_M = (u, 1 - v) and to_uv = scale s, offset t
  // (diagonal), ochre's coordinates are (s_u u + t_u, s_v v + 1 - s_v - t_v).
  std::string uv_transform(const Matrix4d& m, const MitsubaElement& element) {
    if (m(0, 1) != 0.0 || m(1, 0) != 0.0)
      fail_at(element, "to_uv: only scaling and translation are supported (no rotation or shear)");
    const double su = m(0, 0), sv = m(1, 1), tu = m(0, 3), tv = m(1, 3);
    const std::string uv = graph_.add("uv", {{"type", "uv"}});
    const std::string scaled = graph_.add(
        "uv_scale", {{"type", "multiply"}, {"a", {{"link", uv}}}, {"b", {{"vector", {su, sv, 0.0}}}}});
    return graph_.add(
        "uv_offset",
        {{"type", "add"}, {"a", {{"link", scaled}}}, {"b", {{"vector", {tu, 1.0 - sv - tv, 0.0}}}}});
  }

  std::string conductor(MitsubaObject& obj) {
    nlohmann::json node = {{"type", "conductor"}};
    const std::optional<std::string> material = obj.string("material");
    if (obj.has("eta") || obj.has("k") || !material || *material == "none") {
      if (material && *material != "none")
        obj.fail("give either \"material\" or \"eta\" and \"k\", not both");
      // Mitsuba's default "none": eta 0, k 1, a perfect mirror.
      node["eta"] = input(obj, "eta", MitsubaColourRole::Unbounded, 0.0);
      node["k"] = input(obj, "k", MitsubaColourRole::Unbounded, 1.0);
    } else {
      if (std::find_if(std::begin(kMetals), std::end(kMetals),
                       [&](const char* m) { return *material == m; }) == std::end(kMetals))
        obj.fail(
            fmt::format("conductor material \"{}\" has no optical constants in ochre (ochre has: Ag, Al, Au, "
                        "Cu, none; or give eta and k)",
                        *material));
      node["metal"] = *material;
    }
    std::vector<std::string> supported = {"material", "eta", "k", "specular_reflectance"};
    if (obj.type() == "roughconductor") {
      const std::string distribution = obj.string("distribution", "beckmann");
      if (distribution != "ggx")
        obj.fail(
            fmt::format("distribution \"{}\": ochre's rough conductor is GGX (set <string "
                        "name=\"distribution\" value=\"ggx\"/>)",
                        distribution));
      double alpha = obj.number("alpha", 0.1);
      if (obj.has("alpha_u") || obj.has("alpha_v")) {
        const double au = obj.number("alpha_u", alpha), av = obj.number("alpha_v", alpha);
        if (au != av) obj.fail("anisotropic roughness (alpha_u != alpha_v) is not supported");
        alpha = au;
      }
      obj.boolean("sample_visible", true);  // a sampling choice: ochre samples visible normals
      node["roughness"] = alpha;
      supported.insert(supported.end(), {"distribution", "alpha", "alpha_u", "alpha_v", "sample_visible"});
    }
    const nlohmann::json tint = input(obj, "specular_reflectance", MitsubaColourRole::Reflectance, 1.0);
    obj.finish(supported);
    return tinted(graph_.add(obj.type(), node), tint);
  }

  std::string dielectric(MitsubaObject& obj) {
    const double inside = ior(obj, "int_ior", 1.5046), outside = ior(obj, "ext_ior", 1.000277);
    for (const char* name : {"specular_reflectance", "specular_transmittance"}) {
      const nlohmann::json v = input(obj, name, MitsubaColourRole::Reflectance, 1.0);
      if (v != nlohmann::json(1.0))
        obj.fail(fmt::format(
            "{} other than 1 is not supported (ochre's dielectric splits light by Fresnel alone)", name));
    }
    obj.finish({"int_ior", "ext_ior", "specular_reflectance", "specular_transmittance"});
    return graph_.add("dielectric", {{"type", "dielectric"}, {"ior", inside / outside}});
  }

  // An index of refraction: a number or one of Mitsuba's named materials.
  static double ior(MitsubaObject& obj, const std::string& name, double fallback) {
    const MitsubaElement* e = obj.has(name) ? obj.get(name) : nullptr;
    if (!e) return fallback;
    if (e->tag == "float") {
      const double v = number_value(*e);
      if (!(v > 0.0)) fail_at(*e, fmt::format("{} must be > 0", name));
      return v;
    }
    if (e->tag == "string" && e->attribute("value")) {
      std::string key = *e->attribute("value");
      std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return std::tolower(c); });
      for (const NamedIor& n : kNamedIors)
        if (key == n.name) return n.ior;
      std::string names;
      for (const NamedIor& n : kNamedIors) names += (names.empty() ? "" : ", ") + std::string(n.name);
      fail_at(*e, fmt::format("unknown material \"{}\" (known: {})", *e->attribute("value"), names));
    }
    fail_at(*e, fmt::format("{} must be a <float> or a <string> naming a material", name));
  }

  // The closure times `tint` (specular_reflectance), unless the tint is 1.
  std::string tinted(const std::string& closure, const nlohmann::json& tint) {
    if (tint == nlohmann::json(1.0)) return closure;
    return graph_.add("tint", {{"type", "multiply"}, {"a", {{"link", closure}}}, {"b", tint}});
  }

  const MitsubaDocument& document_;
  Graph& graph_;
};

}  // namespace

std::string MitsubaMaterials::material(const MitsubaElement* bsdf, const MitsubaElement* emitter,
                                       const std::string& owner) {
  const auto key = std::make_pair(bsdf, emitter);
  if (const auto it = made_.find(key); it != made_.end()) return it->second;

  const std::string* id = bsdf ? bsdf->attribute("id") : nullptr;
  std::string name = bsdf ? (id ? *id : owner + ".bsdf") : "mitsuba-default-diffuse";
  if (emitter) name += " + " + (emitter->attribute("id") ? *emitter->attribute("id") : owner + ".emitter");

  Graph graph;
  BsdfTranslator translate(document_, graph);
  std::string out = bsdf ? translate.bsdf(*bsdf)
                         : graph.add("diffuse", {{"type", "lambert"}, {"color", 0.5}});  // Mitsuba's default
  if (emitter) {
    const std::string glow = translate.emission(*emitter);
    out =
        graph.add("surface_and_emission", {{"type", "add"}, {"a", {{"link", out}}}, {"b", {{"link", glow}}}});
  }
  materials_[name] = {{"nodes", graph.nodes}, {"output", out}};
  made_[key] = name;
  textured_[name] = graph.textured;
  std::string origin = bsdf ? bsdf->where() : std::string("Mitsuba's default BSDF");
  if (emitter) origin += " with " + emitter->where();
  origins_.emplace_back(fmt::format("material '{}'", name), origin);
  return name;
}

bool MitsubaMaterials::uses_textures(const std::string& material) const {
  const auto it = textured_.find(material);
  return it != textured_.end() && it->second;
}

}  // namespace ochre
