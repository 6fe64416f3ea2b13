#pragma once
// How a scene is rendered (the render job): the "integrator", "film" and "output" blocks of a scene file,
// overridable on the command line and in Python, apart from the scene they render (renderer/scene/scene.h).
// Every choice is an enum parsed once where it is read, with the error naming the field or the option; its
// text form (named_choices below) is the one scene files, command lines and EXR headers use.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "spectra/color_space.h"
#include "spectra/mat3.h"

namespace ochre {

// The names of an enum's values, in one table per enum: parse and name in both directions, and the list
// for messages ("known: independent, sobol").
template <class Enum, size_t N>
struct NamedChoices {
  std::array<std::pair<Enum, const char*>, N> entries;

  std::optional<Enum> parse(std::string_view text) const {
    for (const auto& [value, name] : entries)
      if (text == name) return value;
    return std::nullopt;
  }
  const char* name(Enum value) const {
    for (const auto& [v, name] : entries)
      if (v == value) return name;
    return entries[0].second;
  }
  std::string list() const {
    std::string out;
    for (const auto& entry : entries) out += (out.empty() ? "" : ", ") + std::string(entry.second);
    return out;
  }
};

// integrator.sampler: independent random numbers, or padded Owen-scrambled (0,2)-sequences.
enum class SamplerKind { kIndependent, kSobol };
inline constexpr NamedChoices<SamplerKind, 2> kSamplerKinds{
    {{{SamplerKind::kIndependent, "independent"}, {SamplerKind::kSobol, "sobol"}}}};

// integrator.polarization (docs/polarization.md): auto chooses the mode from the scene
// (renderer/scene/polarization_mode.h).
enum class PolarizationSetting { kAuto, kOff, kIntensity, kStokes };
inline constexpr NamedChoices<PolarizationSetting, 4> kPolarizationSettings{
    {{{PolarizationSetting::kAuto, "auto"},
      {PolarizationSetting::kOff, "off"},
      {PolarizationSetting::kIntensity, "intensity"},
      {PolarizationSetting::kStokes, "stokes"}}}};

// integrator.light_selection: next-event estimation samples one light per vertex, chosen by importance at
// each point (2-8 lights; Scene::light_pmfs) or by power, or every light (`all`). kAuto (the default): the
// branch pilot (renderer/integrator/branch_choice.h) weighs `all` against `local` for 2-8 lights;
// resolve_branches turns it into one of them (`local` where the pilot does not run).
enum class LightSelection { kAuto, kLocal, kPower, kAll };
inline constexpr NamedChoices<LightSelection, 4> kLightSelections{{{{LightSelection::kAuto, "auto"},
                                                                    {LightSelection::kLocal, "local"},
                                                                    {LightSelection::kPower, "power"},
                                                                    {LightSelection::kAll, "all"}}}};

// integrator.guiding: path guiding (renderer/integrator/path_guide.h), off by default.
enum class GuidingSetting { kOff, kOn };
inline constexpr NamedChoices<GuidingSetting, 2> kGuidingSettings{
    {{{GuidingSetting::kOff, "off"}, {GuidingSetting::kOn, "on"}}}};

class PathGuide;

// film.colorspace: the EXR's working space.
inline constexpr NamedChoices<ColorSpace, 2> kWorkingSpaces{
    {{{ColorSpace::LinearRec709, "rec709"}, {ColorSpace::ACEScg, "acescg"}}}};

struct RenderSettings {
  int width = 512;
  int height = 512;
  uint32_t spp = 64;          // samples per pixel
  uint32_t sample_begin = 0;  // sample range [sample_begin, sample_begin + spp): split renders
  // > 0: each pixel stops sampling once its relative standard error is at most this; spp is then the
  // maximum (renderer/film/noise_threshold.h). Requires sample_begin 0.
  double noise_threshold = 0.0;
  int max_depth = 8;  // maximum number of scattering events on a path
  // Russian roulette starts after this many bounces (docs/performance.md). kAutoRoulette ("auto", the
  // default): the pilot of renderer/integrator/branch_choice.h chooses between kRouletteCandidates, and
  // renders it does not run for start at kDefaultRouletteDepth; resolve_branches turns it into a number.
  static constexpr int kAutoRoulette = 0;
  static constexpr int kDefaultRouletteDepth = 5;
  int rr_depth = kAutoRoulette;
  // Branched path tracing: each camera sample continues from its first vertex along this many paths, averaged
  // (docs/architecture.md#branched-paths). kAutoBranches ("auto", the default): the renderer chooses from a
  // pilot (renderer/integrator/branch_choice.h), and spp counts paths per pixel; resolve_branches turns it
  // into a number and spp into camera samples before a render.
  static constexpr int kAutoBranches = 0;
  int branches = kAutoBranches;
  static constexpr int kMaxBranches = 64;  // past a few, the first vertex's noise dominates
  bool branches_chosen = false;  // set by resolve_branches: `branches` was chosen for auto, spp converted
  bool roulette_chosen = false;  // set by resolve_branches: `rr_depth` was chosen for auto
  bool light_selection_chosen = false;  // set by resolve_branches: `light_selection` was chosen for auto
  bool mirror_lights = true;  // sample lights through planar mirrors (renderer/lights/planar_mirrors.h)
  LightSelection light_selection = LightSelection::kAuto;
  GuidingSetting guiding = GuidingSetting::kOff;
  // The trained guide where guiding is on (resolve_branches trains it before a render), else null.
  std::shared_ptr<const PathGuide> guide;
  uint64_t seed = 0;
  int threads = 0;  // 0 = all cores
  SamplerKind sampler = SamplerKind::kSobol;
  PolarizationSetting polarization = PolarizationSetting::kAuto;
  // The frame (1-based) of a flicker sequence at `fps` frames per second that a still render shows, for the
  // render's identity (the flames' state is the scene's, Scene::set_frame); none: not a frame.
  std::optional<uint64_t> frame;
  double fps = 24.0;
};

struct OutputSettings {
  std::string exr;                                   // path of the EXR (empty = none)
  std::string png;                                   // path of the display PNG (empty = none)
  ColorSpace colorspace = ColorSpace::LinearRec709;  // EXR working space
  std::string ocio_config;    // "" = $OCIO, then the built-in config; "builtin"; "none"; or a path
  std::string display, view;  // OCIO display and view ("" = the config's defaults)
  float exposure = 0.0f;      // stops applied to the display image only
  // White balance of the display image only: the XYZ of the illuminant shown as display white
  // (Bradford-adapted to D65); none = no white balance.
  std::optional<std::array<double, 3>> white_balance_xyz;
  bool aovs = false;
  bool stokes = false;           // Stokes layers S0..S3 (XYZ-weighted, and per spectral bin), DoLP and AoLP
  std::string polarization_png;  // false-colour PNG of DoLP / AoLP (empty = none)
  // A camera sensor (camera.sensor, docs/cameras.md): the film holds the sensor's R, G, B. camera_rgb writes
  // them as they are (no chromaticities in the EXR); otherwise sensor_to_xyz turns them into XYZ.
  std::string sensor = "cie1931";
  bool camera_rgb = false;
  std::optional<Mat3> sensor_to_xyz;
  int spectral_bins = 0;  // > 0: EXR layers S0.<centre>nm of spectral radiance (Fichet et al. 2021 layout)
  // The scene's light groups (Scene::light_groups): EXR layers group.<name>.R/G/B (docs/lights.md).
  std::vector<std::string> light_groups;
  // Per group, the shape of its emission spectrum (spectra/emission_shape.h) as text, or empty when its
  // emitters have none in common (Scene::light_group_emission): attributes ochre.lightGroup.<name>.emission.
  std::vector<std::string> light_group_emission;
  float spectral_min = 360.0f,
        spectral_max = 830.0f;  // EXR layers albedo.RGB, normal.XYZ, depth.Z, samples.Y
};

// The render job: how a scene is rendered and where its images go.
struct RenderJob {
  RenderSettings settings;
  OutputSettings outputs;
};

}  // namespace ochre
