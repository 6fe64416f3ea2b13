#pragma once
// Scene: what is rendered, built by load_scene() (renderer/loader/scene_loader.h) from a scene file: camera,
// materials, meshes, the BVH, textures and lights, and the facts the integrator models from. How it is
// rendered (samples, sampler, outputs) is the render job beside it (renderer/scene/render_settings.h).
// After loading only the frame state changes: the flames' state at a frame of a sequence (set_frame) and the
// light selection that follows their powers.

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "materials/core/mueller.h"
#include "materials/graph/compiled_material.h"
#include "renderer/camera/camera.h"
#include "renderer/film/film.h"
#include "renderer/film/pixel_filter.h"
#include "renderer/geometry/accel.h"
#include "renderer/geometry/mesh.h"
#include "renderer/lights/area_light.h"
#include "renderer/lights/environment_light.h"
#include "renderer/lights/flame_light.h"
#include "renderer/lights/planar_mirrors.h"
#include "renderer/sampling/distribution_1d.h"
#include "renderer/scene/polarization_mode.h"
#include "renderer/scene/render_settings.h"
#include "renderer/texture/texture_system.h"
#include "spectra/sensor_response.h"

namespace ochre {

struct Scene {
  std::filesystem::path file;
  std::string description;  // the scene file's "description", shown by reports
  // The rendering origin: the camera's position in the scene's coordinates (in double precision). Every
  // position the scene holds (vertices, lights, the camera at 0) is relative to it, rounded to single
  // precision once, so that an image does not depend on where the scene sits (georeferenced scans 5e6 units
  // from the origin render as at the origin; docs/scene-format.md, "Coordinate range"). Materials see world
  // positions (origin + p).
  Vec3d origin;
  // What the scene loads but a user should know, one message each (a mesh file whose coordinates are too
  // large for its detail in single precision, renderer/shapes/float_detail.h); the tools print them.
  std::vector<std::string> warnings;
  Camera camera;
  PixelFilter pixel_filter;  // film.filter: where in (and around) its pixel a camera sample lands
  SensorPtr sensor;          // a camera sensor's response (docs/cameras.md); nullptr: the CIE 1931 observer

  std::vector<std::shared_ptr<const CompiledMaterial>> materials;
  std::vector<std::string> material_names;
  std::vector<Mesh> meshes;
  std::unique_ptr<Accel> accel;
  std::unique_ptr<OiioTextureProvider> textures;

  std::vector<std::unique_ptr<Light>> lights;
  Distribution1D light_selection;  // proportional to light power
  std::vector<int> mesh_light;     // light index of an emissive mesh, -1 otherwise
  const EnvironmentLight* environment = nullptr;
  int environment_light = -1;
  // Planar mirrors and the lights' images in them (planar_mirrors.h); empty with integrator.mirror_lights
  // false.
  MirrorLights mirror_lights;
  std::vector<FlameLight> flames;  // sphere lights in `lights` that flicker in a frame sequence

  // Linear polarizers: on the camera (Mueller matrix in the camera's Stokes frame: x along the image x
  // axis, y up) and in front of emissive shapes (per mesh; point and spot lights hold their own).
  std::optional<Mueller> camera_analyzer;
  std::vector<std::optional<Vec3>> mesh_polarizers;
  std::vector<std::string> mesh_light_groups;  // per mesh: the light group of an emissive shape ("": none)

  // Light groups (docs/lights.md, "Light groups"): empty when no light names one. Otherwise the groups'
  // names, in the order they first appear, then "other" when some emitter has no group; light_group_of[i]
  // is light i's group and other_light_group the group of emission without a group (-1: none).
  std::vector<std::string> light_groups;
  std::vector<int> light_group_of;
  int other_light_group = -1;
  // Fills light_groups, light_group_of and other_light_group from the lights' groups.
  void build_light_groups();
  // Per light group, the shape of the emission spectrum its lights share (format_emission_shape), or empty
  // when they share none: a light without one (a map, a textured emissive surface), lights of different
  // spectra, or the group "other" (which also holds emission that is no light's).
  std::vector<std::string> light_group_emission() const;

  // Facts the integrator uses to model only what the scene needs.
  bool polarizing_materials = false;
  bool polarizing_filters = false;
  PolarizationSignificance polarization_significance;  // estimated at load when a material polarizes
  bool needs_uv = false;
  // Whether a ray can find light by hitting something (an environment, or a mesh whose material may emit):
  // otherwise only light sampling finds the lights (point, spot, sphere and flame lights are not geometry)
  // and a path's last bounce, which could only find emission, can be left out.
  bool rays_find_emission() const;

  // Builds the light list and selection distribution (after meshes and materials exist); with
  // `mirror_lights`, the lights' images in planar mirrors too; then the light groups.
  void build_lights(bool mirror_lights);

  // Frame state. Sets every flame to its state at frame `frame` (0-based) of a sequence at `fps` frames per
  // second for the render seed `seed` (renderer/lights/flame_light.h) and updates the light selection to the
  // new powers.
  void set_frame(uint64_t frame, double fps, uint64_t seed);
  // The light selection distribution, proportional to the lights' powers.
  void update_light_selection();
  float light_pmf(int light) const { return light_selection.pmf(static_cast<size_t>(light)); }

  // A scene of 2 to kMaxLocalLights lights chooses the light for each shading point from the lights'
  // importance there (Light::importance): a spot light's pool of light is not starved by a bright sky whose
  // power, integrated over the whole scene, dwarfs it. More lights: by power alone (light_selection).
  static constexpr size_t kMaxLocalLights = 8;
  using LightPmfs = std::array<float, kMaxLocalLights>;
  bool local_light_selection(LightSelection selection) const {
    return (selection == LightSelection::kLocal || selection == LightSelection::kAuto) &&
           lights.size() >= 2 && lights.size() <= kMaxLocalLights;
  }
  // The probability of choosing each light at p: a quarter in proportion to the importance, three quarters by
  // power (a defensive mix: the estimates ignore occlusion and the receiver's orientation).
  void light_pmfs(const Vec3& p, LightPmfs& out) const;
};

}  // namespace ochre
