#include "tools/ochre/render_part.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <string>

#include "renderer/output/render_output.h"
#include "renderer/scene/scene.h"
#include "spectra/input_error.h"

namespace ochre {

RenderPart select_part(const RenderCommand& command, const RenderSettings& s) {
  RenderPart part{{0, 0, s.width, s.height}, {0, s.spp}};
  if (s.noise_threshold > 0.0 && (command.part || command.sample_range))
    throw InputError(fmt::format(
        "{}: {} cannot split a noise-threshold render (--noise-threshold or integrator.noise_threshold {}): "
        "each pixel decides from all of its samples when to stop; split it by pixels with --tile or --region",
        command.scene, command.part ? "--part" : "--sample-range", s.noise_threshold));
  // With branches auto the range counts camera samples, spp / k
  // (docs/architecture.md#automatic-branch-count).
  const std::string samples =
      s.branches_chosen && s.branches > 1
          ? fmt::format(
                "{} camera samples per pixel ({} paths as {} x {} branches, integrator.branches auto; "
                "set it to 1 to count paths)",
                s.spp, s.spp * s.branches, s.spp, s.branches)
          : fmt::format("{} samples per pixel", s.spp);
  if (command.part) {
    const auto [index, count] = *command.part;
    if (count > s.spp)
      throw InputError(fmt::format("--part {}/{}: more parts than the {} of {} (integrator.spp or --spp)",
                                   index, count, samples, command.scene));
    part.samples = part_of_samples(index, count, s.spp);
  }
  if (command.sample_range) {
    if (command.sample_range->end > s.spp)
      throw InputError(fmt::format("--sample-range {}: beyond the {} of {} (integrator.spp or --spp)",
                                   format_sample_range(*command.sample_range), samples, command.scene));
    part.samples = *command.sample_range;
  }
  if (command.region) {
    if (!part.rect.contains(*command.region))
      throw InputError(fmt::format("--region {}: outside the {}x{} image", format_pixel_rect(*command.region),
                                   s.width, s.height));
    part.rect = *command.region;
  }
  if (command.tile) {
    const GridTile& t = *command.tile;
    part.rect = tile_rect(t, s.width, s.height);
    if (part.rect.empty())
      throw InputError(fmt::format("--tile {}/{}x{}: more columns or rows than the {}x{} image has pixels",
                                   t.index, t.columns, t.rows, s.width, s.height));
  }
  if (command.split() && command.exr.empty())
    throw InputError("--sample-range, --part, --region and --tile write partial sums: give -o PART.exr");
  return part;
}

PartialSumsHeader partial_header(const Scene& scene, const RenderJob& job, const std::string& content_hash,
                                 const RenderPart& part, uint32_t samples_done, const RenderStats& stats) {
  PartialSumsHeader h;
  h.identity = render_identity(scene, job, content_hash);
  h.image_width = job.settings.width;
  h.image_height = job.settings.height;
  h.spp = job.settings.spp;
  h.layers = film_layers(job.outputs);
  h.rect = part.rect;
  if (samples_done > part.samples.begin) h.coverage = {{part.rect, {part.samples.begin, samples_done}}};
  h.discarded_samples = stats.discarded;
  h.nonfinite_values = stats.nonfinite_values;
  std::error_code error;
  h.notes["ochre.scene"] = std::filesystem::absolute(scene.file, error).lexically_normal().string();
  const OutputSettings& out = job.outputs;
  const bool config_path =
      !out.ocio_config.empty() && out.ocio_config != "builtin" && out.ocio_config != "none";
  h.notes["ochre.display.ocioConfig"] =
      config_path ? std::filesystem::absolute(out.ocio_config, error).lexically_normal().string()
                  : out.ocio_config;
  h.notes["ochre.display.display"] = out.display;
  h.notes["ochre.display.view"] = out.view;
  h.notes["ochre.display.exposure"] = fmt::format("{}", out.exposure);
  // What turns the film into the output's RGB and display image, for ochre merge (which has no scene).
  if (out.sensor_to_xyz)
    h.notes["ochre.sensorToXYZ"] = fmt::format("{}", fmt::join(out.sensor_to_xyz->m, " "));
  if (out.white_balance_xyz)
    h.notes["ochre.display.whiteBalance"] = fmt::format("{}", fmt::join(*out.white_balance_xyz, " "));
  for (size_t g = 0; g < out.light_groups.size() && g < out.light_group_emission.size(); ++g)
    if (!out.light_group_emission[g].empty())
      h.notes[light_group_emission_attribute(out.light_groups[g])] = out.light_group_emission[g];
  return h;
}

}  // namespace ochre
