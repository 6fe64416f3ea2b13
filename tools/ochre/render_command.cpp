#include "tools/ochre/render_command.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <new>
#include <optional>

#include "materials/graph/graph_error.h"
#include "renderer/integrator/branch_choice.h"
#include "renderer/integrator/render.h"
#include "renderer/integrator/render_passes.h"
#include "renderer/output/output_files.h"
#include "renderer/output/partial_sums.h"
#include "renderer/output/relight.h"
#include "renderer/output/render_identity.h"
#include "renderer/output/render_output.h"
#include "renderer/util/image_error.h"
#include "renderer/util/load_progress.h"
#include "renderer/util/memory_budget.h"
#include "renderer/util/output_transaction.h"
#include "renderer/util/progress.h"
#include "renderer/util/signal_cleanup.h"
#include "spectra/input_error.h"
#include "tools/cli/frame_names.h"
#include "tools/cli/program.h"
#include "tools/ochre/checkpoint_resume.h"
#include "tools/ochre/relit_frames.h"
#include "tools/ochre/render_part.h"

namespace ochre {

namespace {

// "auto" models only what the scene needs (docs/architecture.md, 'Design rules'): off when nothing polarizes.
std::string polarization_mode(const Scene& scene, const RenderJob& job) {
  const PolarizationChoice choice = polarization_for(scene, job);
  return fmt::format("{} ({})", polarization_mode_name(choice.mode), choice.reason);
}

void print_summary(const Scene& scene, const RenderJob& job) {
  size_t triangles = 0;
  for (const Mesh& m : scene.meshes) triangles += m.triangle_count();
  const RenderSettings& s = job.settings;
  const std::string branches =
      s.branches > 1 ? fmt::format(" x {} branches ({} paths per pixel{})", s.branches, s.spp * s.branches,
                                   s.branches_chosen ? ", branches auto" : "")
                     : "";
  const std::string spp = s.noise_threshold > 0.0
                              ? fmt::format("noise threshold {}, at most {} spp", s.noise_threshold, s.spp)
                              : fmt::format("{} spp", s.spp);
  std::cerr << fmt::format(
      "ochre: {}: {}x{}, {}{}, max depth {}, roulette from depth {}, {} meshes ({} triangles), {} lights, "
      "seed {}, "
      "{} sampler\n",
      scene.file.filename().string(), s.width, s.height, spp, branches, s.max_depth, s.rr_depth,
      scene.meshes.size(), triangles, scene.lights.size(), s.seed, kSamplerKinds.name(s.sampler));
  std::cerr << fmt::format(
      "ochre: BVH built in {:.2f} s, {:.1f} MB ({:.0f} bytes per triangle incl. vertices)\n",
      scene.accel->build_seconds(), scene.accel->memory_bytes() / 1e6,
      triangles ? static_cast<double>(scene.accel->memory_bytes()) / triangles : 0.0);
  std::cerr << fmt::format("ochre: polarization: {}\n", polarization_mode(scene, job));
  const std::vector<PlanarMirror>& mirrors = scene.mirror_lights.mirrors();
  if (!mirrors.empty()) {
    std::string names;
    for (const PlanarMirror& m : mirrors) names += (names.empty() ? "" : ", ") + scene.meshes[m.mesh].name;
    std::cerr << fmt::format("ochre: lights sampled through {} planar mirror{}: {}\n", mirrors.size(),
                             mirrors.size() == 1 ? "" : "s", names);
  }
}

void print_stats(const RenderStats& stats) {
  std::cerr << fmt::format(
      "ochre: rendered in {:.2f} s on {} threads: {:.3f} M samples/s, {:.3f} M rays/s ({} rays, {} shadow "
      "rays), "
      "{} discarded NaN/Inf samples, {} NaN/Inf shading values made finite\n",
      stats.seconds, stats.threads, stats.samples_per_second() * 1e-6, stats.rays_per_second() * 1e-6,
      stats.rays, stats.shadow_rays, stats.discarded, stats.nonfinite_values);
}

// Where a noise-threshold render put its samples: the mean per pixel and the share of pixels that stopped at
// each decision point (the last one: at the maximum, not converged).
void print_sample_counts(const Film& film, const RenderSettings& s) {
  if (s.noise_threshold <= 0.0) return;
  std::map<uint64_t, uint64_t> pixels_at;
  uint64_t total = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      ++pixels_at[film.sample_count(x, y)];
      total += film.sample_count(x, y);
    }
  const double pixels = static_cast<double>(film.width()) * film.height();
  std::string shares;
  for (const auto& [count, n] : pixels_at)
    shares += fmt::format("{}{}{}: {:.1f} %", shares.empty() ? "" : ", ", count,
                          count == s.spp ? " (the maximum)" : "", 100.0 * n / pixels);
  // With branches a pixel counts camera samples, each the mean of `branches` paths.
  const bool branched = s.branches > 1;
  const char* unit = branched ? "camera samples" : "samples";
  const std::string of_paths = branched ? fmt::format(" of {} paths", s.branches) : std::string();
  const std::string paths =
      branched ? fmt::format(" ({:.1f} paths)", s.branches * total / pixels) : std::string();
  std::cerr << fmt::format(
      "ochre: noise threshold {}: {:.1f} {}{} per pixel on average{} (at most {}); pixels by {} taken: {}\n",
      s.noise_threshold, total / pixels, unit, of_paths, paths, s.spp, unit, shares);
}

// Samples the image does not hold as rendered: said even with -q (the image is not what the scene gives).
void warn_about_lost_samples(const RenderStats& stats) {
  if (stats.discarded > 0)
    std::cerr << fmt::format(
        "ochre: warning: {} of {} samples were NaN or infinite and count as zero (a radiance or emission "
        "beyond "
        "single precision?): the image is darker than the scene\n",
        stats.discarded, stats.samples);
  if (stats.clamped > 0)
    std::cerr << fmt::format(
        "ochre: warning: {} of {} samples exceeded the film's range and were clamped to {:g}: the image is "
        "darker than the scene\n",
        stats.clamped, stats.samples, kMaxSampleMagnitude);
}

// What the command was doing, for an out-of-memory report.
struct Phase {
  const char* what = "loading the scene";
  bool from_input_size = true;  // the allocation grew with the scene or the outputs asked for
};

// Overrides the scene's output settings with the command line's and checks them (building the display
// transform reads the OCIO config).
void apply_output_options(const RenderCommand& command, RenderJob& job) {
  OutputSettings& out = job.outputs;
  if (command.split()) {
    // A part's display images are previews, written only when asked for: the scene's own paths are for the
    // final image, which `ochre merge` writes (with the Stokes layers a polarization PNG implies).
    if (!out.polarization_png.empty()) out.stokes = true;
    out.png.clear();
    out.polarization_png.clear();
  }
  // An output on the command line decides where every output goes (as pbrt's --outfile): the scene's own
  // output paths apply only when none is given (docs/cli.md, "Output files").
  if (!command.exr.empty() || !command.png.empty() || !command.polarization_png.empty()) {
    out.exr.clear();
    out.png.clear();
    out.polarization_png.clear();
  }
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
  check_stokes_mode(job, command.scene);
  check_outputs(out);
}

// Renders the scene's current state into `film`, with progress and the report.
RenderStats render_film(const RenderCommand& command, const Scene& scene, const RenderJob& job, Film& film,
                        const std::string& label, Phase& phase) {
  const RenderSettings& s = job.settings;
  const uint64_t total = static_cast<uint64_t>(s.width) * s.height * s.spp;
  std::optional<ProgressReporter> progress;
  if (!command.quiet) {
    try {
      progress.emplace(label, total, std::cerr, stderr_is_terminal());
    } catch (const std::invalid_argument& e) {  // a bad OCHRE_PROGRESS value is bad input, not a crash
      throw InputError(std::string("OCHRE_PROGRESS: ") + e.what());
    }
  }
  phase = {"rendering", false};
  const RenderStats stats = render(scene, job, film, [&](uint64_t done) {
    if (progress) progress->advance(done);
  });
  if (progress) progress->finish();
  if (!command.quiet) {
    print_stats(stats);
    print_sample_counts(film, job.settings);
  }
  warn_about_lost_samples(stats);
  return stats;
}

// Renders the scene's current state (one frame of a sequence) into a film and writes `out`.
RenderStats render_and_write(const RenderCommand& command, const Scene& scene, const RenderJob& job,
                             const OutputSettings& out, const std::string& label, Phase& phase) {
  const RenderSettings& s = job.settings;
  phase = {"allocating the film", true};
  Film film(s.width, s.height, film_layers(out));
  const RenderStats stats = render_film(command, scene, job, film, label, phase);
  phase = {"writing the outputs", true};
  for (const std::string& line : write_outputs(film, out, s, stats, scene.file.string()))
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

// --frames N --relight (tools/ochre/relit_frames.h): one render of the flames at their mean, each frame that
// render relit and written as its own all-or-nothing set of files (names checked by the caller).
void render_relit_frames(const RenderCommand& command, Scene& scene, const RenderJob& given,
                         const InputFileLog& inputs, Phase& phase) {
  RenderJob job = given;
  if (!job.outputs.polarization_png.empty())
    throw InputError("--relight: no polarization image: relit frames hold no Stokes layers");
  for (const std::string& warning : prepare_relit_flames(scene, job))
    std::cerr << "ochre: warning: " << warning << "\n";
  OutputSettings base = job.outputs;
  base.exr = "<the render relit per frame>";  // the layers of an EXR (groups, bins); not written
  check_render_memory(job.settings.width, job.settings.height, base);
  const uint64_t last = command.first_frame + *command.frames - 1;
  if (!command.quiet)
    std::cerr << fmt::format(
        "ochre: --relight: one render of the flames at their mean, relit for frames {} to {} "
        "(groups {})\n",
        command.first_frame, last, fmt::join(job.outputs.light_groups, ", "));
  phase = {"allocating the film", true};
  Film film(job.settings.width, job.settings.height, film_layers(base));
  const RenderStats stats =
      render_film(command, scene, job, film, "the flames at their mean (relit per frame)", phase);
  phase = {"writing the outputs", true};
  const ExrImage image =
      render_exr_image(film, film_to_rgb(film, base), base, job.settings, stats, scene.file.string());
  const DisplayOptions display = display_options(job.outputs);
  for (uint64_t frame = command.first_frame; frame <= last; ++frame) {
    const std::vector<GroupChange> changes =
        flame_frame_changes(scene, frame - 1, command.fps, job.settings.seed);
    ExrImage relit = relight(image, changes, scene.file.string());
    relit.string_attributes["ochre.frame"] = std::to_string(frame);
    const OutputSettings f = frame_outputs(job.outputs, frame);
    for (const std::string& line : write_relit(relit, display, f.exr, f.png, inputs))
      if (!command.quiet) std::cerr << fmt::format("ochre: frame {}: {}\n", frame, line);
  }
}

// A frame sequence (docs/cli.md#frame-sequences): each frame is its own render and its own all-or-nothing
// set of files; the flames take their state at the frame's time (renderer/lights/flame_light.h), everything
// else is the scene as loaded. Every frame's file names are checked before the first frame renders.
int render_frames(const RenderCommand& command, Scene& scene, const RenderJob& job,
                  const InputFileLog& inputs, Phase& phase, double load_seconds) {
  const OutputSettings& out = job.outputs;
  std::vector<std::filesystem::path> paths;
  for (uint64_t k = 0; k < *command.frames; ++k)
    for (const std::string& p : output_paths(frame_outputs(out, command.first_frame + k)))
      paths.emplace_back(p);
  check_output_files(paths, inputs);
  const uint64_t last = command.first_frame + *command.frames - 1;
  if (!command.quiet) {
    print_summary(scene, job);
    std::cerr << fmt::format("ochre: scene loaded in {:.2f} s\n", load_seconds);
    std::cerr << fmt::format("ochre: frames {} to {} at {} fps, {} flickering flame(s)\n",
                             command.first_frame, last, command.fps, scene.flames.size());
  }
  if (command.relight) {
    render_relit_frames(command, scene, job, inputs, phase);
    return 0;
  }
  phase = {"allocating the film", true};
  check_render_memory(job.settings.width, job.settings.height, out);
  for (uint64_t frame = command.first_frame; frame <= last; ++frame) {
    scene.set_frame(frame - 1, command.fps, job.settings.seed);
    if (!command.quiet)
      std::cerr << fmt::format("ochre: frame {} of {} (t = {:.4f} s)\n", frame, last,
                               static_cast<double>(frame - 1) / command.fps);
    OutputSettings frame_out = frame_outputs(out, frame);
    frame_out.light_group_emission = scene.light_group_emission();  // the frame's flame colours
    render_and_write(command, scene, job, frame_out, fmt::format("frame {} of {}", frame, last), phase);
  }
  return 0;
}

// The files of a render that checkpoints, and how it writes them.
struct Checkpointing {
  std::filesystem::path path;
  const Scene* scene = nullptr;
  const RenderJob* job = nullptr;
  std::string content_hash;
  RenderPart part;
  bool split = false;
  bool preview = false;            // refresh the display PNG with each checkpoint
  std::optional<double> interval;  // --checkpoint-interval, recorded for --resume
  OutputSettings out;
  // The rendering seconds of the samples a resumed checkpoint held (0 for a new render; none when it did not
  // record them): the checkpoints record the total.
  std::optional<double> earlier_seconds = 0.0;
  uint32_t written_at = UINT32_MAX;  // the sample the last checkpoint written ends at

  // The rendering seconds of the samples held after this run's `stats`.
  std::optional<double> seconds(const RenderStats& stats) const {
    return earlier_seconds ? std::optional<double>(*earlier_seconds + stats.seconds) : std::nullopt;
  }

  // Writes the checkpoint of samples [part.samples.begin, next) (and the preview) atomically.
  void write(const Film& film, uint32_t next, const RenderStats& stats) {
    PartialSumsHeader header = partial_header(*scene, *job, content_hash, part, next, stats);
    add_checkpoint_notes(header, part, split, out, interval, seconds(stats));
    OutputTransaction transaction;
    write_partial_sums(transaction.add(path), header, film);
    if (preview && !out.png.empty()) {
      OutputSettings png_only = out;
      png_only.exr.clear();
      png_only.polarization_png.clear();
      add_outputs(transaction, film, png_only, job->settings, stats, scene->file.string());
    }
    transaction.commit();
    written_at = next;
  }
};

// --check-settings: what the render would be, from the scene's settings alone (docs/cli.md). The checks are
// those of a render before its first sample that need no geometry: the options and settings (the split
// against the resolution and samples, a noise threshold against --part).
int check_settings_only(const RenderCommand& command) {
  const RenderJob job = load_render_job(command.scene, command.overrides);
  const RenderSettings& s = job.settings;
  const RenderPart part = select_part(command, s);
  std::string line = fmt::format("{}: {}x{}, {} spp, noise threshold {}", command.scene, s.width, s.height,
                                 s.spp, s.noise_threshold);
  if (command.still_frame)
    line += fmt::format(", frame {} at {} fps", *command.still_frame, command.fps);
  else if (command.frames)
    line += fmt::format(", frames {} to {} at {} fps", command.first_frame,
                        command.first_frame + *command.frames - 1, command.fps);
  if (command.split())
    line += fmt::format(", samples {} of region {} (partial sums)", format_sample_range(part.samples),
                        format_pixel_rect(part.rect));
  std::cout << line << "\n";
  return 0;
}

int render_scene(const RenderCommand& given, Phase& phase) {
  if (given.check_settings) return check_settings_only(given);
  const auto start = std::chrono::steady_clock::now();
  // A resumed render takes its scene, settings and outputs from the checkpoint.
  std::optional<PartialSumsFile> resumed;
  if (!given.resume.empty()) resumed.emplace(given.resume);
  const RenderCommand command = resumed ? resumed_command(given, *resumed) : given;

  InputFileLog inputs;
  LoadedScene loaded;
  {
    const InputFileLog::Recording recording(inputs);  // every file the scene reads
    loaded = load_scene(command.scene, command.overrides);
  }
  Scene* scene = loaded.scene.get();
  RenderJob& job = loaded.job;
  // Warnings show even with -q: they are about the image, not the progress.
  for (const std::string& warning : scene->warnings) std::cerr << "ochre: warning: " << warning << "\n";
  // Only partial sums need the content hash (it reads every input file again).
  const bool partial_sums = command.split() || command.checkpointing();
  const std::string content_hash = partial_sums ? scene_content_hash(inputs.records()) : "";
  {
    const InputFileLog::Recording recording(inputs);  // and the files the outputs read (OCIO config)
    apply_output_options(command, job);
  }
  // integrator.branches, rr_depth and light_selection auto: chosen now, and the path guide trained, for every
  // frame, part and resumed piece alike.
  BranchChoice branch_choice;
  job = resolve_branches(*scene, job, &branch_choice);
  if (!command.quiet &&
      (job.settings.branches_chosen || job.settings.roulette_chosen || job.settings.light_selection_chosen))
    std::cerr << fmt::format("ochre: paths: {}\n", branch_choice.reason);
  if (!command.quiet && !branch_choice.guide.summary.empty())
    std::cerr << fmt::format("ochre: path guiding: {}\n", branch_choice.guide.summary);
  if (command.frames) return render_frames(command, *scene, job, inputs, phase, seconds_since(start));
  if (command.still_frame) {
    // One frame of a sequence, rendered like a still (the frame is part of the render's identity).
    job.settings.frame = *command.still_frame;
    job.settings.fps = command.fps;
    scene->set_frame(*command.still_frame - 1, command.fps, job.settings.seed);
    job.outputs.light_group_emission = scene->light_group_emission();  // the frame's flame colours
    if (command.number_outputs) job.outputs = frame_outputs(job.outputs, *command.still_frame);
  }
  if (resumed) check_resumable(*resumed, render_identity(*scene, job, content_hash));
  const RenderPart part = select_part(command, job.settings);
  OutputSettings out = job.outputs;
  Checkpointing checkpoints{
      command.checkpoint.empty() ? default_checkpoint_path(out) : std::filesystem::path(command.checkpoint),
      scene,
      &job,
      content_hash,
      part,
      command.split(),
      command.preview,
      command.checkpoint_interval,
      out,
      resumed ? recorded_seconds(resumed->header()) : std::optional<double>(0.0)};
  std::vector<std::filesystem::path> paths;
  for (const std::string& path : output_paths(out)) paths.emplace_back(path);
  if (command.checkpointing()) {
    check_output_writable(checkpoints.path);
    paths.push_back(checkpoints.path);
  }
  check_output_files(paths, inputs);

  if (!command.quiet) {
    print_summary(*scene, job);
    if (command.split())
      std::cerr << fmt::format("ochre: rendering samples {} of region {} into partial sums\n",
                               format_sample_range(part.samples), format_pixel_rect(part.rect));
    std::cerr << fmt::format("ochre: scene loaded in {:.2f} s\n", seconds_since(start));
  }
  phase = {"allocating the film", true};
  check_render_memory(part.rect.width(), part.rect.height(), out);
  Film film = resumed ? resumed->read_film() : Film(part.rect.width(), part.rect.height(), film_layers(out));
  const uint32_t first = resumed ? resume_point(*resumed, part) : part.samples.begin;
  RenderStats stats;  // the NaN/Inf counts include the checkpoint's
  if (resumed) {
    stats.discarded = resumed->header().discarded_samples;
    stats.nonfinite_values = resumed->header().nonfinite_values;
    if (!command.quiet)
      std::cerr << fmt::format("ochre: resuming {}: samples {}:{} of {} done\n", given.resume,
                               part.samples.begin, first, format_sample_range(part.samples));
  }
  const uint64_t total =
      static_cast<uint64_t>(part.rect.width()) * part.rect.height() * (part.samples.end - first);
  std::optional<ProgressReporter> progress;
  if (!command.quiet) {
    try {
      progress.emplace("render", total, std::cerr, stderr_is_terminal());
    } catch (const std::invalid_argument& e) {  // a bad OCHRE_PROGRESS value is bad input, not a crash
      throw InputError(std::string("OCHRE_PROGRESS: ") + e.what());
    }
  }
  phase = {"rendering", false};
  const ProgressCallback advance = [&](uint64_t done) {
    if (progress) progress->advance(done);
  };
  uint32_t next = part.samples.end;
  PassStop stop = PassStop::finished;
  if (!command.checkpointing()) {
    stats.add(render_range(*scene, job, film, part.rect, {first, part.samples.end}, advance));
  } else {
    GracefulStop signals;  // the first SIGINT / SIGTERM ends the render at a pass boundary
    PassSchedule schedule;
    schedule.checkpoint_interval = command.checkpoint_interval.value_or(0.0);
    if (command.time_limit) {
      // Writing the checkpoint and the image follows the last pass: measured about 0.05 us per pixel and
      // accumulator for the partial sums and 0.5 us per pixel for the EXR and PNG (docs/distributed.md,
      // Figures), reserved so that the command ends before the limit.
      const double pixels = static_cast<double>(part.rect.width()) * part.rect.height();
      const double reserve = 0.5 + pixels * (0.05e-6 * film.accumulator_names().size() + 0.5e-6);
      schedule.deadline = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(*command.time_limit - reserve));
    }
    const RenderStats before = stats;
    const PassResult result = render_in_passes(
        *scene, job, film, part.rect, {first, part.samples.end}, schedule, advance,
        [&](uint32_t at, const RenderStats& passes) {
          RenderStats so_far = before;
          so_far.add(passes);
          checkpoints.write(film, at, so_far);
        },
        [] { return GracefulStop::requested_signal() != 0; });
    stats.add(result.stats);
    next = result.next;
    stop = result.stop;
    if (stop == PassStop::stop_requested) {
      if (checkpoints.written_at != next) checkpoints.write(film, next, stats);
      if (!command.quiet)
        std::cerr << fmt::format(
            "\nochre: stopped by a signal after samples {}:{}; wrote {}; continue with: ochre "
            "render --resume {}\n",
            part.samples.begin, next, checkpoints.path.string(), checkpoints.path.string());
      progress.reset();
      signals.end_by_signal();
    }
  }
  if (progress && stop == PassStop::finished) progress->finish();
  progress.reset();
  if (!command.quiet) {
    print_stats(stats);
    print_sample_counts(film, job.settings);
  }
  warn_about_lost_samples(stats);

  if (stop == PassStop::deadline && next == first) {
    // Not one sample finished: an image of no samples would replace the outputs with black.
    std::cerr << fmt::format(
        "ochre: time limit reached before any sample finished; nothing written{}\n",
        resumed ? " (the checkpoint keeps what it held)" : " (existing outputs are kept)");
    return kExitTimeLimit;
  }
  phase = {"writing the outputs", true};
  OutputTransaction transaction;
  std::vector<std::string> written;
  if (stop == PassStop::deadline) {
    // The time limit: the image of the samples done (a split part's partial sums are its checkpoint).
    PartialSumsHeader header = partial_header(*scene, job, content_hash, part, next, stats);
    add_checkpoint_notes(header, part, command.split(), out, command.checkpoint_interval,
                         checkpoints.seconds(stats));
    const auto write_start = std::chrono::steady_clock::now();
    write_partial_sums(transaction.add(checkpoints.path), header, film);
    written.push_back(fmt::format("wrote {} (checkpoint: samples {}:{} of {}, {:.2f} s)",
                                  checkpoints.path.string(), part.samples.begin, next,
                                  format_sample_range(part.samples), seconds_since(write_start)));
    if (command.split()) out.exr.clear();
  } else if (command.split()) {
    const PartialSumsHeader header = partial_header(*scene, job, content_hash, part, next, stats);
    const auto write_start = std::chrono::steady_clock::now();
    write_partial_sums(transaction.add(out.exr), header, film);
    written.push_back(fmt::format("wrote {} (partial sums: samples {} of region {}, {:.2f} s)", out.exr,
                                  format_sample_range(part.samples), format_pixel_rect(part.rect),
                                  seconds_since(write_start)));
    out.exr.clear();  // the display images of the part, when asked for, follow
  }
  RenderSettings done = job.settings;  // the EXR header names the samples it holds
  done.sample_begin = part.samples.begin;
  done.spp = next - part.samples.begin;
  if (!out.exr.empty() || !out.png.empty() || !out.polarization_png.empty())
    for (const std::string& line : add_outputs(transaction, film, out, done, stats, scene->file.string()))
      written.push_back(line);
  transaction.commit();
  if (!command.quiet)
    for (const std::string& line : written) std::cerr << "ochre: " << line << "\n";
  if (stop == PassStop::deadline) {
    if (!command.quiet)
      std::cerr << fmt::format("ochre: time limit reached; continue with: ochre render --resume {}\n",
                               checkpoints.path.string());
    return kExitTimeLimit;
  }
  // Finished: the checkpoint (this render's, or the one resumed) has served.
  std::error_code error;
  const bool ours = checkpoints.written_at != UINT32_MAX || resumed;
  if (ours && std::filesystem::exists(checkpoints.path, error) &&
      !std::filesystem::remove(checkpoints.path, error) && !command.quiet)
    std::cerr << fmt::format("ochre: warning: could not remove the checkpoint {}: {}\n",
                             checkpoints.path.string(), error.message());
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
    return phase.from_input_size ? kExitBadInput : kExitInternalError;
  }  // any other exception: run_program (tools/cli/program.h)
}

}  // namespace ochre
