#include "json_mutator.h"

#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

// libFuzzer's byte mutator; absent (null) in the corpus-replay build, which never mutates.
extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size) __attribute__((weak));

namespace ochre::fuzz {

namespace {

using json = nlohmann::json;

// Keys of docs/scene-format.md and parameters of docs/nodes.md.
const char* const kKeys[] = {"camera",
                             "film",
                             "integrator",
                             "output",
                             "materials",
                             "lights",
                             "shapes",
                             "type",
                             "fov",
                             "size",
                             "eye",
                             "target",
                             "up",
                             "transform",
                             "polarizer",
                             "resolution",
                             "colorspace",
                             "spp",
                             "max_depth",
                             "rr_depth",
                             "branches",
                             "seed",
                             "threads",
                             "polarization",
                             "sampler",
                             "exr",
                             "png",
                             "aovs",
                             "spectral_bins",
                             "spectral_range",
                             "stokes",
                             "polarization_png",
                             "exposure",
                             "file",
                             "material",
                             "smooth_normals",
                             "flip_uv_v",
                             "name",
                             "subdivision",
                             "displacement",
                             "center",
                             "radius",
                             "subdivisions",
                             "segments",
                             "position",
                             "direction",
                             "cone_angle",
                             "falloff_start",
                             "intensity",
                             "radiance",
                             "scale",
                             "rotation",
                             "axis",
                             "angle",
                             "level",
                             "scheme",
                             "offset",
                             "translate",
                             "rotate",
                             "matrix",
                             "look_at",
                             "nodes",
                             "output",
                             "link",
                             "column",
                             "blackbody",
                             "color",
                             "strength",
                             "roughness",
                             "ior",
                             "opaque",
                             "metal",
                             "sigma",
                             "albedo",
                             "particle_albedo",
                             "kd",
                             "factor",
                             "value",
                             "channel",
                             "mode",
                             "uv",
                             "a",
                             "b"};

const char* const kStrings[] = {"",
                                "x",
                                "lambert",
                                "mesh",
                                "sphere",
                                "plane",
                                "disk",
                                "environment",
                                "point",
                                "spot",
                                "texture",
                                "mix",
                                "add",
                                "multiply",
                                "constant",
                                "spectrum",
                                "rgb_to_spectrum",
                                "conductor",
                                "dielectric",
                                "emission",
                                "oren_nayar",
                                "chandrasekhar",
                                "lambert_sphere",
                                "uv",
                                "vertex_colour",
                                "quad.obj",
                                "cube_quads.obj",
                                "colours.ply",
                                "two_triangles.gltf",
                                "checker.ppm",
                                "sky.exr",
                                "red.csv",
                                "D65",
                                "metal-Au",
                                "auto",
                                "srgb",
                                "linear",
                                "stokes",
                                "sobol",
                                "catmull-clark",
                                "loop",
                                "a.color",
                                "a.value",
                                "b.out",
                                ".",
                                "..",
                                "/"};

const double kNumbers[] = {0.0,    -0.0,   1.0,   -1.0,  0.5,    2.0,    3.0,     7.0,         16.0,
                           64.0,   255.0,  1e-6,  1e-38, 1e-320, 1e6,    1e30,    3.5e38,      1e308,
                           -1e308, 179.99, 360.0, 830.0, -360.0, 4097.0, 65537.0, 4294967296.0};

const long long kIntegers[] = {0,
                               1,
                               -1,
                               2,
                               3,
                               8,
                               9,
                               1024,
                               1 << 24,
                               (1LL << 31),
                               -(1LL << 31),
                               std::numeric_limits<long long>::max(),
                               std::numeric_limits<long long>::min()};

template <class T, size_t N>
const T& pick(const T (&values)[N], std::minstd_rand& rng) {
  return values[rng() % N];
}

json random_scalar(std::minstd_rand& rng) {
  switch (rng() % 6) {
    case 0:
      return pick(kNumbers, rng);
    case 1:
      return pick(kIntegers, rng);
    case 2:
      return pick(kStrings, rng);
    case 3:
      return rng() % 2 == 0;
    case 4:
      return nullptr;
    default:
      return json::array({pick(kNumbers, rng), pick(kNumbers, rng), pick(kNumbers, rng)});
  }
}

void collect(json& j, std::vector<json*>& nodes) {
  nodes.push_back(&j);
  if (j.is_structured())
    for (auto& child : j) collect(child, nodes);
}

void mutate_value(json& target, const std::vector<json*>& nodes, std::minstd_rand& rng) {
  switch (rng() % 9) {
    case 0:
    case 1:
      target = random_scalar(rng);
      break;
    case 2:
      target = json::array({target});
      break;
    case 3:
      target = json::object({{pick(kKeys, rng), target}});
      break;
    case 4:
      if (target.is_object() && !target.empty()) {
        auto it = target.begin();
        std::advance(it, rng() % target.size());
        target.erase(it.key());
      }
      break;
    case 5:
      if (target.is_object()) target[pick(kKeys, rng)] = random_scalar(rng);
      break;
    case 6:
      if (target.is_array() && !target.empty()) {
        const size_t i = rng() % target.size();
        if (rng() % 2 == 0)
          target.erase(i);
        else
          target.push_back(json(target[i]));
      }
      break;
    case 7:
      target = json(*nodes[rng() % nodes.size()]);  // a copy: the source may lie inside the target
      break;
    default:
      if (target.is_number()) target = target.get<double>() * pick(kNumbers, rng);
      break;
  }
}

}  // namespace

size_t mutate_json(uint8_t* data, size_t size, size_t max_size, unsigned seed) {
  std::minstd_rand rng(seed);
  const auto bytes = [&] { return LLVMFuzzerMutate ? LLVMFuzzerMutate(data, size, max_size) : size; };
  json document =
      json::parse(data, data + size, nullptr, /*allow_exceptions=*/false, /*ignore_comments=*/true);
  if (document.is_discarded() || rng() % 4 == 0) return bytes();
  std::vector<json*> nodes;
  collect(document, nodes);
  mutate_value(*nodes[rng() % nodes.size()], nodes, rng);
  const std::string text = document.dump();
  if (text.size() > max_size) return bytes();
  std::memcpy(data, text.data(), text.size());
  return text.size();
}

}  // namespace ochre::fuzz
