#include "renderer/output/render_identity.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <map>

#include "ochre/version.h"
#include "renderer/integrator/render.h"
#include "renderer/output/render_output.h"
#include "renderer/scene/scene.h"
#include "renderer/util/fnv1a.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

std::uint64_t file_content_hash(const InputFileRecord& record) {
  InputFile file = InputFile::open(record.path, {record.kind, UINT64_MAX});
  Fnv1a64 hash;
  std::array<char, 1 << 16> buffer;
  for (std::uint64_t offset = 0;;) {
    const ssize_t got = ::pread(file.fd(), buffer.data(), buffer.size(), static_cast<off_t>(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0)
      throw InputError(fmt::format("{}: cannot read the {} to hash it: {}", record.path.string(), record.kind,
                                   std::strerror(errno)));
    if (got == 0) break;
    hash.add(buffer.data(), static_cast<std::size_t>(got));
    offset += static_cast<std::uint64_t>(got);
  }
  return hash.value();
}

}  // namespace

std::string sensor_identity(const OutputSettings& outputs) {
  if (outputs.sensor == "cie1931") return outputs.sensor;
  return outputs.sensor + (outputs.camera_rgb ? " camera_rgb" : " white_balanced");
}

std::string scene_content_hash(const std::vector<InputFileRecord>& scene_inputs) {
  std::vector<std::string> files;
  for (const InputFileRecord& record : scene_inputs)
    files.push_back(fmt::format("{}:{:016x}", record.kind, file_content_hash(record)));
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());  // a file read twice counts once
  Fnv1a64 hash;
  for (const std::string& file : files) hash.add(file + "\n");
  return fmt::format("fnv1a64:{:016x}", hash.value());
}

const std::vector<std::string>& identity_field_names() {
  static const std::vector<std::string> names = {
      "ochre.version",       "ochre.sceneHash",      "ochre.resolution",     "ochre.spp",
      "ochre.seed",          "ochre.sampler",        "ochre.polarization",   "ochre.maxDepth",
      "ochre.rrDepth",       "ochre.aovs",           "ochre.stokes",         "ochre.spectralBins",
      "ochre.spectralRange", "ochre.colorspace",     "ochre.sensor",         "ochre.branches",
      "ochre.mirrorLights",  "ochre.lightSelection", "ochre.noiseThreshold", "ochre.frame",
      "ochre.lightGroups",   "ochre.guiding"};
  return names;
}

RenderIdentity render_identity(const Scene& scene, const RenderJob& job, const std::string& content_hash) {
  const RenderSettings& s = job.settings;
  const FilmLayers layers = film_layers(job.outputs);
  const std::map<std::string, std::string> values = {
      {"ochre.version", OCHRE_VERSION},
      {"ochre.sceneHash", content_hash},
      {"ochre.resolution", fmt::format("{}x{}", s.width, s.height)},
      {"ochre.spp", std::to_string(s.spp)},
      {"ochre.seed", std::to_string(s.seed)},
      {"ochre.sampler", kSamplerKinds.name(s.sampler)},
      {"ochre.polarization", polarization_mode_name(polarization_for(scene, job).mode)},
      {"ochre.maxDepth", std::to_string(s.max_depth)},
      {"ochre.rrDepth", std::to_string(s.rr_depth)},
      {"ochre.aovs", layers.aovs ? "1" : "0"},
      {"ochre.stokes", layers.stokes ? "1" : "0"},
      {"ochre.spectralBins", std::to_string(layers.spectral_bins)},
      {"ochre.spectralRange", fmt::format("{}-{}", layers.spectral_min, layers.spectral_max)},
      {"ochre.colorspace", kWorkingSpaces.name(job.outputs.colorspace)},
      {"ochre.sensor", sensor_identity(job.outputs)},
      {"ochre.branches", std::to_string(s.branches)},
      {"ochre.mirrorLights", s.mirror_lights ? "1" : "0"},
      {"ochre.lightSelection", kLightSelections.name(s.light_selection)},
      {"ochre.noiseThreshold", fmt::format("{}", s.noise_threshold)},
      {"ochre.frame", s.frame ? fmt::format("{} at {} fps", *s.frame, s.fps) : std::string()},
      {"ochre.lightGroups", fmt::format("{}", fmt::join(layers.light_groups, ","))},
      {"ochre.guiding", kGuidingSettings.name(s.guiding)},
  };
  RenderIdentity identity;
  for (const std::string& name : identity_field_names()) identity.emplace_back(name, values.at(name));
  return identity;
}

const std::string* identity_field(const RenderIdentity& identity, const std::string& name) {
  for (const auto& [key, value] : identity)
    if (key == name) return &value;
  return nullptr;
}

}  // namespace ochre
