#include "tools/render_command.h"

#include <fmt/format.h>

#include <chrono>
#include <iostream>
#include <new>
#include <optional>

#include "materials/graph/graph_error.h"
#include "renderer/frame_names.h"
#include "renderer/image_error.h"
#include "renderer/input_error.h"
#include "renderer/load_progress.h"
#include "renderer/memory_budget.h"
#include "renderer/output_files.h"
#include "renderer/progress.h"
#include "renderer/render.h"
#include "renderer/render_output.h"
#include "renderer/signal_cleanup.h"

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

// Renders the scene's current state into a film and writes `out`; returns the render statistics.
RenderStats render_and_write(const RenderCommand& command, const Scene& scene, const OutputSettings& out,
                             const std::string& label, Phase& phase) {
  phase = {"allocating the film", true};
  Film film(scene.settings.width, scene.settings.height, film_layers(out));
  const uint64_t total =
      static_cast<uint64_t>(scene.settings.width) * scene.settings.height * scene.settings.spp;
  std::optional<ProgressReporter> progress;
  if (!command.quiet) {
    try {
      progress.emplace(label, total, std::cerr, stderr_is_terminal());
    } catch (const std::invalid_argument& e) {  // a bad OCHRE_PROGRESS value is bad input, not a crash
      throw InputError(std::string("OCHRE_PROGRESS: ") + e.what());
    }
  }
  phase = {"rendering", false};
  const RenderStats stats = render(scene, film, [&](uint64_t done) {
    if (progress) progress->advance(done);
  });
  if (progress) progress->finish();
  if (!command.quiet) print_stats(stats);

  phase = {"writing the outputs", true};
  for (const std::string& line : write_outputs(film, out, scene.settings, stats, scene.file.string()))
    if (!command.quiet) std::cerr << "ochre: " << line << "\n";
  return stats;
}

// The outputs of frame `frame` of a sequence (frame_output_name).
OutputSettings frame_outputs(const OutputSettings& out, uint64_t frame) {
  OutputSettings f = out;
  for (std::string* path : {&f.exr, &f.png, &f.polarization_png})
    if (!path->empty()) *path = frame_output_name(*path, frame);
  return f;
}

int render_scene(const RenderCommand& command, Phase& phase) {
  const auto load_start = std::chrono::steady_clock::now();
  InputFileLog inputs;
  std::unique_ptr<Scene> scene;
  {
    const InputFileLog::Recording recording(inputs);  // every file the scene and its outputs read
    scene = load_scene(command.scene, command.overrides);
    apply_output_options(command, *scene);
  }
  const OutputSettings& out = scene->outputs;
  std::vector<std::string> paths;
  if (command.frames)  // every frame's names are checked before the first frame renders
    for (uint64_t k = 0; k < *command.frames; ++k)
      for (const std::string& p : output_paths(frame_outputs(out, command.first_frame + k)))
        paths.push_back(p);
  else
    paths = output_paths(out);
  check_output_files({paths.begin(), paths.end()}, inputs);
  const double load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();

  if (!command.quiet) {
    print_summary(*scene);
    std::cerr << fmt::format("ochre: scene loaded in {:.2f} s\n", load_seconds);
  }
  phase = {"allocating the film", true};
  check_render_memory(scene->settings.width, scene->settings.height, out);
  if (!command.frames) {
    render_and_write(command, *scene, out, "render", phase);
    return 0;
  }
  // Each frame is its own render and its own all-or-nothing set of files; the flames take their state at
  // the frame's time (renderer/flame_light.h), everything else is the scene as loaded.
  const uint64_t last = command.first_frame + *command.frames - 1;
  if (!command.quiet)
    std::cerr << fmt::format("ochre: frames {} to {} at {} fps, {} flickering flame(s)\n",
                             command.first_frame, last, command.fps, scene->flames.size());
  for (uint64_t frame = command.first_frame; frame <= last; ++frame) {
    scene->set_frame(frame - 1, command.fps);
    if (!command.quiet)
      std::cerr << fmt::format("ochre: frame {} of {} (t = {:.4f} s)\n", frame, last,
                               static_cast<double>(frame - 1) / command.fps);
    render_and_write(command, *scene, frame_outputs(out, frame), fmt::format("frame {} of {}", frame, last),
                     phase);
  }
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
  } catch (const InputError& e) {
    std::cerr << "ochre: error: " << e.what() << "\n";
    return 2;
  } catch (const GraphError& e) {
    std::cerr << "ochre: error: " << e.what() << "\n";
    return 2;
  } catch (const ImageError& e) {
    std::cerr << "ochre: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ochre: internal error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace ochre
