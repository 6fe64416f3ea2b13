#include "tools/render_command.h"

#include <fmt/format.h>

#include <chrono>
#include <iostream>
#include <new>
#include <optional>

#include "renderer/image_error.h"
#include "renderer/input_error.h"
#include "renderer/load_progress.h"
#include "renderer/memory_budget.h"
#include "renderer/output_files.h"
#include "renderer/output_transaction.h"
#include "renderer/partial_sums.h"
#include "renderer/progress.h"
#include "renderer/render.h"
#include "renderer/render_identity.h"
#include "renderer/render_output.h"
#include "renderer/signal_cleanup.h"
#include "tools/command_errors.h"

namespace ochre {

namespace {

// "auto" models only what the scene needs (docs/architecture.md, 'Design rules'): off when nothing polarizes.
std::string polarization_mode(const Scene& scene) {
  const PolarizationChoice choice = polarization_for(scene);
  return fmt::format("{} ({})", polarization_mode_name(choice.mode), choice.reason);
}

void print_summary(const Scene& scene) {
  size_t triangles = 0;
  for (const Mesh& m : scene.meshes) triangles += m.triangle_count();
  const RenderSettings& s = scene.settings;
  std::cerr << fmt::format(
      "ochre: {}: {}x{}, {} spp, max depth {}, {} meshes ({} triangles), {} lights, seed {}, {} sampler\n",
      scene.file.filename().string(), s.width, s.height, s.spp, s.max_depth, scene.meshes.size(), triangles,
      scene.lights.size(), s.seed, s.sampler);
  std::cerr << fmt::format(
      "ochre: BVH built in {:.2f} s, {:.1f} MB ({:.0f} bytes per triangle incl. vertices)\n",
      scene.accel->build_seconds(), scene.accel->memory_bytes() / 1e6,
      triangles ? static_cast<double>(scene.accel->memory_bytes()) / triangles : 0.0);
  std::cerr << fmt::format("ochre: polarization: {}\n", polarization_mode(scene));
}

void print_stats(const RenderStats& stats) {
  std::cerr << fmt::format(
      "ochre: rendered in {:.2f} s on {} threads: {:.3f} M samples/s, {:.3f} M rays/s ({} rays, {} shadow "
      "rays), "
      "{} discarded NaN/Inf samples, {} NaN/Inf shading values made finite\n",
      stats.seconds, stats.threads, stats.samples_per_second() * 1e-6, stats.rays_per_second() * 1e-6,
      stats.rays, stats.shadow_rays, stats.discarded, stats.nonfinite_values);
}

// What the command was doing, for an out-of-memory report.
struct Phase {
  const char* what = "loading the scene";
  bool from_input_size = true;  // the allocation grew with the scene or the outputs asked for
};

// Overrides the scene's output settings with the command line's and checks them (building the display
// transform reads the OCIO config).
void apply_output_options(const RenderCommand& command, Scene& scene) {
  OutputSettings& out = scene.outputs;
  if (!command.exr.empty()) out.exr = command.exr;
  if (!command.png.empty()) out.png = command.png;
  if (command.ocio_config) out.ocio_config = *command.ocio_config;
  if (command.display) out.display = *command.display;
  if (command.view) out.view = *command.view;
  if (command.colorspace) out.colorspace = *command.colorspace;
  if (command.exposure) out.exposure = *command.exposure;
  if (command.aovs) out.aovs = true;
  if (command.spectral_bins > 0) out.spectral_bins = command.spectral_bins;
  if (command.stokes) out.stokes = true;
  if (!command.polarization_png.empty()) out.polarization_png = command.polarization_png;
  if (!out.polarization_png.empty()) out.stokes = true;  // DoLP / AoLP need S1, S2
  if (out.stokes && scene.settings.polarization != "auto" && scene.settings.polarization != "stokes")
    throw InputError(fmt::format(
        "{}: integrator.polarization: Stokes output (--stokes, output.stokes or a polarization PNG) "
        "needs polarization mode stokes or auto, not '{}'",
        command.scene, scene.settings.polarization));
  if (out.colorspace != "rec709" && out.colorspace != "acescg")
    throw InputError(fmt::format("--colorspace: unknown '{}' (known: rec709, acescg)", out.colorspace));
  check_outputs(out);
}

// The samples and pixels this command renders: all of them, or the part that --sample-range, --part
// and --region select (InputError naming the option when it does not fit the scene).
struct RenderPart {
  PixelRect rect;
  SampleRange samples;
};

RenderPart select_part(const RenderCommand& command, const Scene& scene) {
  const RenderSettings& s = scene.settings;
  RenderPart part{{0, 0, s.width, s.height}, {0, s.spp}};
  if (command.part) {
    const auto [index, count] = *command.part;
    if (count > s.spp)
      throw InputError(
          fmt::format("--part {}/{}: more parts than the {} samples per pixel of {} (integrator.spp "
                      "or --spp)",
                      index, count, s.spp, command.scene));
    part.samples = part_of_samples(index, count, s.spp);
  }
  if (command.sample_range) {
    if (command.sample_range->end > s.spp)
      throw InputError(
          fmt::format("--sample-range {}: beyond the {} samples per pixel of {} (integrator.spp or "
                      "--spp)",
                      format_sample_range(*command.sample_range), s.spp, command.scene));
    part.samples = *command.sample_range;
  }
  if (command.region) {
    if (!part.rect.contains(*command.region))
      throw InputError(fmt::format("--region {}: outside the {}x{} image", format_pixel_rect(*command.region),
                                   s.width, s.height));
    part.rect = *command.region;
  }
  if (command.split() && command.exr.empty())
    throw InputError("--sample-range, --part and --region write partial sums: give -o PART.exr");
  return part;
}

// The header of the partial-sum file of `part` (docs/distributed.md): the render's identity, where the
// pixels sit, the samples held, and notes for `ochre merge` (the scene, the display settings).
PartialSumsHeader partial_header(const Scene& scene, const std::string& content_hash, const RenderPart& part,
                                 uint32_t samples_done, const RenderStats& stats) {
  PartialSumsHeader h;
  h.identity = render_identity(scene, content_hash);
  h.image_width = scene.settings.width;
  h.image_height = scene.settings.height;
  h.spp = scene.settings.spp;
  h.layers = film_layers(scene.outputs);
  h.rect = part.rect;
  if (samples_done > part.samples.begin) h.coverage = {{part.rect, {part.samples.begin, samples_done}}};
  h.discarded_samples = stats.discarded;
  h.nonfinite_values = stats.nonfinite_values;
  std::error_code error;
  h.notes["ochre.scene"] = std::filesystem::absolute(scene.file, error).lexically_normal().string();
  const OutputSettings& out = scene.outputs;
  h.notes["ochre.display.ocioConfig"] = out.ocio_config;
  h.notes["ochre.display.display"] = out.display;
  h.notes["ochre.display.view"] = out.view;
  h.notes["ochre.display.exposure"] = fmt::format("{}", out.exposure);
  return h;
}

int render_scene(const RenderCommand& command, Phase& phase) {
  const auto load_start = std::chrono::steady_clock::now();
  InputFileLog inputs;
  std::unique_ptr<Scene> scene;
  {
    const InputFileLog::Recording recording(inputs);  // every file the scene reads
    scene = load_scene(command.scene, command.overrides);
  }
  // Only parts of a split render need the content hash (it reads every input file again).
  const std::string content_hash = command.split() ? scene_content_hash(inputs.records()) : "";
  {
    const InputFileLog::Recording recording(inputs);  // and the files the outputs read (OCIO config)
    apply_output_options(command, *scene);
  }
  const RenderPart part = select_part(command, *scene);
  OutputSettings out = scene->outputs;
  const std::vector<std::string> paths = output_paths(out);
  check_output_files({paths.begin(), paths.end()}, inputs);
  const double load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();

  if (!command.quiet) {
    print_summary(*scene);
    if (command.split())
      std::cerr << fmt::format("ochre: rendering samples {} of region {} into partial sums\n",
                               format_sample_range(part.samples), format_pixel_rect(part.rect));
    std::cerr << fmt::format("ochre: scene loaded in {:.2f} s\n", load_seconds);
  }
  phase = {"allocating the film", true};
  check_render_memory(part.rect.width(), part.rect.height(), out);
  Film film(part.rect.width(), part.rect.height(), film_layers(out));
  const uint64_t total = static_cast<uint64_t>(part.rect.width()) * part.rect.height() * part.samples.size();
  std::optional<ProgressReporter> progress;
  if (!command.quiet) {
    try {
      progress.emplace("render", total, std::cerr, stderr_is_terminal());
    } catch (const std::invalid_argument& e) {  // a bad OCHRE_PROGRESS value is bad input, not a crash
      throw InputError(std::string("OCHRE_PROGRESS: ") + e.what());
    }
  }
  phase = {"rendering", false};
  const RenderStats stats = render_range(*scene, film, part.rect, part.samples, [&](uint64_t done) {
    if (progress) progress->advance(done);
  });
  if (progress) progress->finish();
  if (!command.quiet) print_stats(stats);

  phase = {"writing the outputs", true};
  OutputTransaction transaction;
  std::vector<std::string> written;
  if (command.split()) {
    const PartialSumsHeader header = partial_header(*scene, content_hash, part, part.samples.end, stats);
    write_partial_sums(transaction.add(out.exr), header, film);
    written.push_back(fmt::format("wrote {} (partial sums: samples {} of region {})", out.exr,
                                  format_sample_range(part.samples), format_pixel_rect(part.rect)));
    out.exr.clear();  // the display images of the part, when asked for, follow
  }
  for (const std::string& line :
       add_outputs(transaction, film, out, scene->settings, stats, scene->file.string()))
    written.push_back(line);
  transaction.commit();
  if (!command.quiet)
    for (const std::string& line : written) std::cerr << "ochre: " << line << "\n";
  return 0;
}

}  // namespace

int run_render(const RenderCommand& command) {
  install_signal_cleanup();
  set_memory_limit(command.memory_limit);
  enable_load_progress(command.quiet ? nullptr : &std::cerr);
  Phase phase;
  try {
    return render_scene(command, phase);
  } catch (const std::bad_alloc&) {
    // Memory exhausted despite the estimates: bad input when the allocation grew with the scene or the
    // outputs asked for, an internal error while rendering (whose memory use does not grow with them).
    std::cerr << fmt::format("ochre: {}: {}: out of memory while {} (see --memory-limit in docs/cli.md)\n",
                             phase.from_input_size ? "error" : "internal error", command.scene, phase.what);
    return phase.from_input_size ? 2 : 1;
  } catch (...) {
    return report_current_exception();
  }
}

}  // namespace ochre
