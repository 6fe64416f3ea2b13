#pragma once
// Settings of one render: the "integrator" and "film" blocks of a scene, overridable on the
// command line.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "spectra/mat3.h"

namespace ochre {

struct RenderSettings {
  int width = 512;
  int height = 512;
  uint32_t spp = 64;          // samples per pixel
  uint32_t sample_begin = 0;  // sample range [sample_begin, sample_begin + spp): split renders
  int max_depth = 8;          // maximum number of scattering events on a path
  int rr_depth = 5;           // Russian roulette starts after this many bounces (docs/performance.md)
  // Branched path tracing: each camera sample continues from its first vertex along this many paths, averaged
  // (docs/architecture.md#branched-paths).
  int branches = 1;
  static constexpr int kMaxBranches = 64;  // past a few, the first vertex's noise dominates
  bool mirror_lights = true;  // sample lights through planar mirrors (renderer/lights/planar_mirrors.h)
  // Light choice for next-event estimation: "local" (by importance at each point, for 2-8 lights; scene.h)
  // or "power" (by power alone).
  std::string light_selection = "local";
  uint64_t seed = 0;
  int threads = 0;                    // 0 = all cores
  std::string sampler = "sobol";      // independent | sobol (padded Owen-scrambled (0,2)-sequences)
  std::string polarization = "auto";  // auto | off | intensity | stokes (docs/polarization.md)
};

struct OutputSettings {
  std::string exr;                    // path of the EXR (empty = none)
  std::string png;                    // path of the display PNG (empty = none)
  std::string colorspace = "rec709";  // EXR working space: rec709 | acescg
  std::string ocio_config;            // "" = $OCIO, then the built-in config; "builtin"; "none"; or a path
  std::string display, view;          // OCIO display and view ("" = the config's defaults)
  float exposure = 0.0f;              // stops applied to the display image only
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
  float spectral_min = 360.0f,
        spectral_max = 830.0f;  // EXR layers albedo.RGB, normal.XYZ, depth.Z, samples.Y
};

}  // namespace ochre
