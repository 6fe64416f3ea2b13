// ochre command line: `ochre render SCENE.json -o OUT.exr [--png OUT.png] ...` (docs/cli.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <regex>
#include <tuple>

#include "ochre/version.h"
#include "spectra/byte_size.h"
#include "spectra/input_error.h"
#include "tools/cli/command_line.h"
#include "tools/cli/duration.h"
#include "tools/cli/program.h"
#include "tools/ochre/export_mesh_command.h"
#include "tools/ochre/frame_options.h"
#include "tools/ochre/info_command.h"
#include "tools/ochre/merge_command.h"
#include "tools/ochre/relight_command.h"
#include "tools/ochre/render_command.h"

namespace {

// --ocio-config, --display, --view and --exposure of the commands that write the display image of an
// earlier render (merge, relight): each defaults to the render's.
struct DisplayOverrides {
  std::string ocio, display, view;
  float exposure = 0.0f;
  CLI::Option *ocio_opt = nullptr, *display_opt = nullptr, *view_opt = nullptr, *exposure_opt = nullptr;

  void add_to(CLI::App* app) {
    ocio_opt = app->add_option("--ocio-config", ocio, "OCIO config (default: the render's)");
    display_opt = app->add_option("--display", display, "OCIO display (default: the render's)");
    view_opt = app->add_option("--view", view, "OCIO view (default: the render's)");
    exposure_opt =
        app->add_option("--exposure", exposure, "Exposure of the display image (default: the render's)")
            ->check(ochre::finite_range(-64.0, 64.0));
  }
  template <class Command>
  void apply(Command& command) const {
    if (*ocio_opt) command.ocio_config = ocio;
    if (*display_opt) command.display = display;
    if (*view_opt) command.view = view;
    if (*exposure_opt) command.exposure = exposure;
  }
};

// "WxH" -> width, height.
bool parse_resolution(const std::string& text, int& width, int& height) {
  static const std::regex pattern(R"(^(\d{1,6})x(\d{1,6})$)");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return false;
  width = std::stoi(m[1]);
  height = std::stoi(m[2]);
  return true;
}

// --memory-limit SIZE; throws InputError when malformed.
uint64_t parse_memory_limit(const std::string& text) {
  const auto bytes = ochre::parse_byte_size(text);
  if (!bytes)
    throw ochre::InputError("--memory-limit: expected a size such as 8G, 512M or 1048576 (bytes), got '" +
                            text + "'");
  return *bytes;
}

// -D NAME=VALUE options -> (name, value) pairs; InputError for one without a name or '='.
std::vector<std::pair<std::string, std::string>> parsed_defines(const std::vector<std::string>& defines) {
  std::vector<std::pair<std::string, std::string>> parameters;
  for (const std::string& define : defines) {
    const size_t equals = define.find('=');
    if (equals == std::string::npos || equals == 0)
      throw ochre::InputError("-D: expected NAME=VALUE, got '" + define + "'");
    parameters.emplace_back(define.substr(0, equals), define.substr(equals + 1));
  }
  return parameters;
}

// The whole command: its exit code (docs/cli.md, "Exit codes"); bad input throws InputError.
int ochre_command(int argc, char** argv) {
  CLI::App app{"ochre: spectral path tracer with Mueller-matrix polarization"};
  app.set_version_flag("--version", "ochre " OCHRE_VERSION);
  app.require_subcommand(1);

  ochre::RenderCommand cmd;
  std::string resolution, ocio, display, view, colorspace;
  uint32_t spp = 0;
  int threads = -1;
  uint64_t seed = 0;
  float exposure = 0.0f;
  std::string polarization, sampler, guiding, preset;

  CLI::App* render = app.add_subcommand("render", "Render a scene to EXR and/or PNG");
  render->add_option(
      "scene", cmd.scene,
      "Scene file (JSON, docs/scene-format.md; or Mitsuba 3 XML, .xml); with --resume: the scene "
      "moved");
  std::vector<std::string> defines;
  render->add_option("-D,--define", defines, "Mitsuba XML scenes: set parameter $NAME to VALUE (NAME=VALUE)");
  render->add_option("-o,--output", cmd.exr, "Output EXR (linear working space)")
      ->check(ochre::non_empty_path());
  render->add_option("--png", cmd.png, "Output display PNG (through OpenColorIO)")
      ->check(ochre::non_empty_path());
  auto* spp_opt = render->add_option("--spp", spp, "Samples per pixel")->check(CLI::Range(1u, 1u << 24));
  auto* threads_opt =
      render->add_option("--threads", threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 4096));
  auto* seed_opt = render->add_option("--seed", seed, "Random seed")->check(ochre::unsigned_64_check());
  auto* res_opt = render->add_option("--resolution", resolution, "Film size WxH, e.g. 640x480");
  double noise_threshold = 0.0;
  auto* noise_opt = render
                        ->add_option("--noise-threshold", noise_threshold,
                                     "Sample each pixel until its relative standard error is at most E "
                                     "(e.g. 0.01), --spp at most; 0 = off (docs/cli.md#noise-threshold)")
                        ->check(ochre::finite_range(0.0, 1.0));
  auto* preset_opt = render->add_option("--preset", preset,
                                        "Named variant from the scene's \"presets\" (e.g. fast, final); the "
                                        "other options override it");
  auto* pol_opt = render->add_option("--polarization", polarization, "auto | off | intensity | stokes")
                      ->check(CLI::IsMember({"auto", "off", "intensity", "stokes"}));
  auto* sampler_opt = render->add_option("--sampler", sampler, "independent | sobol")
                          ->check(CLI::IsMember({"independent", "sobol"}));
  auto* guiding_opt =
      render->add_option("--guiding", guiding, "Path guiding: off | on (docs/architecture.md#path-guiding)")
          ->check(CLI::IsMember({"off", "on"}));
  auto* ocio_opt = render->add_option(
      "--ocio-config", ocio, "OCIO config path, 'builtin' or 'none' (default: $OCIO, else built-in)");
  auto* display_opt = render->add_option("--display", display, "OCIO display (default: the config's)");
  auto* view_opt = render->add_option("--view", view, "OCIO view (default: the display's)");
  auto* cs_opt = render->add_option("--colorspace", colorspace, "EXR working space: rec709 | acescg")
                     ->check(CLI::IsMember({"rec709", "acescg"}));
  auto* exposure_opt = render->add_option("--exposure", exposure, "Exposure of the display image, in stops")
                           ->check(ochre::finite_range(-64.0, 64.0));  // as output.exposure
  render->add_flag("-q,--quiet", cmd.quiet, "No progress or statistics");
  render
      ->add_option("--spectral-bins", cmd.spectral_bins, "Add N spectral radiance layers S0.<nm> to the EXR")
      ->check(CLI::Range(1, 471));
  render->add_flag("--aovs", cmd.aovs, "Add albedo, normal, depth and sample-count layers to the EXR");
  render->add_flag("--stokes", cmd.stokes,
                   "Add Stokes layers S0..S3 (XYZ-weighted; per spectral bin with --spectral-bins), DoLP and "
                   "AoLP to the EXR (polarization mode stokes)");
  render
      ->add_option("--polarization-png", cmd.polarization_png,
                   "Write a false-colour PNG of the degree (brightness) and angle (hue) of linear "
                   "polarization")
      ->check(ochre::non_empty_path());
  std::string memory_limit;
  auto* memory_opt = render->add_option(
      "--memory-limit", memory_limit,
      "Refuse (exit 2) a film, mesh or image whose estimated memory exceeds SIZE, e.g. 8G, 512M "
      "(default: the machine's memory)");

  uint64_t frames = 0, first_frame = 1;
  double fps = 24.0;
  auto* frames_opt = render
                         ->add_option("--frames", frames,
                                      "Render a sequence of N frames in which flames flicker, written as "
                                      "OUT.0001.exr ... (docs/cli.md#frame-sequences)")
                         ->check(ochre::unsigned_range_check(1, ochre::kMaxFrames));
  auto* first_frame_opt =
      render
          ->add_option("--first-frame", first_frame, "Number of the first frame of the sequence (default 1)")
          ->check(ochre::unsigned_range_check(1, ochre::kMaxFrameNumber));
  auto* fps_opt = render->add_option("--fps", fps, "Frames per second of the sequence (default 24)");
  bool relight_frames = false;
  auto* relight_opt = render->add_flag(
      "--relight", relight_frames,
      "With --frames: render once, a light group per flame, and relight each frame from it (docs/lights.md)");

  std::string sample_range, part, region, tile;
  auto* range_opt = render->add_option(
      "--sample-range", sample_range, "Render samples [A, B) of every pixel into partial sums (-o PART.exr)");
  auto* part_opt =
      render->add_option("--part", part, "Render the I-th of N equal sample ranges (I/N, from 0)")
          ->excludes(range_opt);
  auto* region_opt =
      render->add_option("--region", region, "Render the pixels [x0, x1) x [y0, y1) into partial sums");
  auto* tile_opt =
      render->add_option("--tile", tile, "Render tile I (from 0, row by row) of a C x R grid (I/CxR)")
          ->excludes(region_opt);

  std::string checkpoint_interval, time_limit;
  render
      ->add_option("--checkpoint", cmd.checkpoint,
                   "Checkpoint file (default: beside the output, NAME.checkpoint.exr)")
      ->check(ochre::non_empty_path());
  auto* interval_opt = render->add_option("--checkpoint-interval", checkpoint_interval,
                                          "Write a checkpoint every DURATION (e.g. 600, 10m, 1h30m)");
  auto* time_limit_opt =
      render->add_option("--time-limit", time_limit,
                         "Stop before DURATION has passed: image of the samples done, checkpoint, exit 3");
  auto* resume_opt = render->add_option("--resume", cmd.resume, "Continue the render a checkpoint holds")
                         ->check(ochre::non_empty_path());
  render->add_flag("--preview", cmd.preview, "Refresh the display PNG with each checkpoint");
  auto* check_opt = render->add_flag(
      "--check-settings", cmd.check_settings,
      "Check the options against the scene's settings (no geometry, materials or lights are loaded), "
      "print what would be rendered; render and write nothing");

  ochre::MergeCommand merge_cmd;
  CLI::App* merge = app.add_subcommand("merge", "Merge partial-sum files into the image of one render");
  merge->add_option("parts", merge_cmd.parts, "Partial-sum files (ochre render --sample-range/--region)")
      ->required();
  merge->add_option("-o,--output", merge_cmd.exr, "Output EXR (as ochre render -o)")
      ->check(ochre::non_empty_path());
  merge->add_option("--png", merge_cmd.png, "Output display PNG (through OpenColorIO)")
      ->check(ochre::non_empty_path());
  merge->add_option("--sums", merge_cmd.sums, "Write the merged partial sums, to merge again with more parts")
      ->check(ochre::non_empty_path());
  merge->add_flag("--partial", merge_cmd.partial, "Accept missing samples: a lower-sample image");
  merge->add_flag("--check", merge_cmd.check, "Only check the parts; list missing samples (exit 4 if any)");
  merge->add_flag("-q,--quiet", merge_cmd.quiet, "No report");
  std::string merge_memory;
  DisplayOverrides merge_display;
  merge_display.add_to(merge);
  auto* merge_memory_opt = merge->add_option("--memory-limit", merge_memory, "As for ochre render");

  ochre::RelightCommand relight_cmd;
  CLI::App* relight = app.add_subcommand(
      "relight", "Recombine a render's light groups with new intensities and spectra (docs/lights.md)");
  relight->add_option("render", relight_cmd.render, "EXR of a render whose lights name groups")
      ->required()
      ->check(ochre::non_empty_path());
  relight->add_option(
      "--group", relight_cmd.groups,
      "NAME:scale=S (times S), NAME:off, NAME:on, NAME:cct=T (a blackbody at T K) or "
      "NAME:spectrum=NAME|FILE.csv, joined by commas; repeatable (the other groups: unchanged)");
  relight->add_option("-o,--output", relight_cmd.exr, "Output EXR (the relit image and groups)")
      ->check(ochre::non_empty_path());
  relight->add_option("--png", relight_cmd.png, "Output display PNG (the render's display transform)")
      ->check(ochre::non_empty_path());
  relight
      ->add_option("--html", relight_cmd.html,
                   "Output directory for a page that relights the render in a browser (sliders per group)")
      ->check(ochre::non_empty_path());
  relight->add_flag("-q,--quiet", relight_cmd.quiet, "No report");
  DisplayOverrides relight_display;
  relight_display.add_to(relight);

  ochre::InfoCommand info_cmd;
  CLI::App* info = app.add_subcommand(
      "info",
      "What partial-sum files and checkpoints hold: frame, pixels, samples, time left (headers only)");
  info->add_option("parts", info_cmd.parts, "Partial-sum files or checkpoints")->required();

  ochre::ExportMeshCommand export_cmd;
  CLI::App* export_mesh = app.add_subcommand(
      "export-mesh",
      "Write one mesh of a scene as rendered (subdivided, displaced, in world coordinates) as PLY");
  export_mesh->add_option("scene", export_cmd.scene, "Scene file (JSON or Mitsuba 3 XML)")->required();
  export_mesh->add_option("-o,--output", export_cmd.output, "Output PLY file")
      ->required()
      ->check(ochre::non_empty_path());
  export_mesh->add_option("--shape", export_cmd.shape, "The mesh's name (needed when the scene has several)");
  std::string export_preset;
  auto* export_preset_opt =
      export_mesh->add_option("--preset", export_preset, "Named variant from the scene's \"presets\"");
  std::vector<std::string> export_defines;
  export_mesh->add_option("-D,--define", export_defines, "Mitsuba XML scenes: set parameter $NAME to VALUE");
  export_mesh->add_flag("-q,--quiet", export_cmd.quiet, "No report");

  if (!ochre::parse_command_line(app, argc, argv)) return ochre::kExitDone;  // --help, --version

  if (app.got_subcommand(info)) return ochre::run_info(info_cmd);

  if (app.got_subcommand(export_mesh)) {
    if (*export_preset_opt) export_cmd.overrides.preset = export_preset;
    export_cmd.overrides.parameters = parsed_defines(export_defines);
    return ochre::run_export_mesh(export_cmd);
  }

  if (app.got_subcommand(relight)) {
    relight_display.apply(relight_cmd);
    return ochre::run_relight(relight_cmd);
  }

  if (app.got_subcommand(merge)) {
    merge_display.apply(merge_cmd);
    if (*merge_memory_opt) merge_cmd.memory_limit = parse_memory_limit(merge_memory);
    return ochre::run_merge(merge_cmd);
  }

  for (auto [option, text, value] : {std::tuple{interval_opt, &checkpoint_interval, &cmd.checkpoint_interval},
                                     std::tuple{time_limit_opt, &time_limit, &cmd.time_limit}})
    if (*option && !(*value = ochre::parse_duration(*text)))
      throw ochre::InputError(
          option->get_name() +
          ": expected a duration such as 90, 90s, 10m, 1h30m or 1.5h (at most a year), got '" + *text + "'");
  if (*check_opt && *resume_opt)
    throw ochre::InputError(
        "--check-settings: not with --resume (a resumed render takes its settings from the checkpoint)");
  if (*resume_opt) {
    // A resumed render is the render the checkpoint holds: what changes the image cannot change.
    for (const CLI::Option* fixed :
         {spp_opt, seed_opt, res_opt, pol_opt, sampler_opt, guiding_opt, cs_opt, range_opt, part_opt,
          region_opt, tile_opt, render->get_option("--spectral-bins"), render->get_option("--aovs"),
          render->get_option("--stokes"), render->get_option("--define")})
      if (*fixed)
        throw ochre::InputError(fixed->get_name() +
                                ": a resumed render keeps the settings of its checkpoint (give only outputs, "
                                "display and checkpoint options, --threads, --memory-limit, -q)");
  } else if (cmd.scene.empty()) {
    throw ochre::InputError("render: give a scene file (or --resume CHECKPOINT)");
  }
  if (*range_opt && !(cmd.sample_range = ochre::parse_sample_range(sample_range)))
    throw ochre::InputError("--sample-range: expected A:B with integers 0 <= A < B < 2^32, got '" +
                            sample_range + "'");
  if (*part_opt && !(cmd.part = ochre::parse_part(part)))
    throw ochre::InputError("--part: expected I/N with integers 0 <= I < N, got '" + part + "'");
  if (*tile_opt && !(cmd.tile = ochre::parse_grid_tile(tile)))
    throw ochre::InputError("--tile: expected I/CxR with integers C, R >= 1 and 0 <= I < C R, got '" + tile +
                            "'");
  if (*region_opt && !(cmd.region = ochre::parse_pixel_rect(region)))
    throw ochre::InputError("--region: expected x0,y0,x1,y1 with integers 0 <= x0 < x1, 0 <= y0 < y1, got '" +
                            region + "'");
  cmd.overrides.parameters = parsed_defines(defines);
  if (*spp_opt) cmd.overrides.spp = spp;
  if (*noise_opt) cmd.overrides.noise_threshold = noise_threshold;
  if (*threads_opt) cmd.overrides.threads = threads;
  if (*seed_opt) cmd.overrides.seed = seed;
  // CLI11 checked the names: the parses succeed.
  if (*pol_opt) cmd.overrides.polarization = ochre::kPolarizationSettings.parse(polarization);
  if (*sampler_opt) cmd.overrides.sampler = ochre::kSamplerKinds.parse(sampler);
  if (*guiding_opt) cmd.overrides.guiding = ochre::kGuidingSettings.parse(guiding);
  if (*preset_opt) cmd.overrides.preset = preset;
  if (*res_opt) {
    int w = 0, h = 0;
    if (!parse_resolution(resolution, w, h) || w < 1 || h < 1)
      throw ochre::InputError("--resolution: expected WxH with positive integers, got '" + resolution + "'");
    cmd.overrides.width = w;
    cmd.overrides.height = h;
  }
  if (*memory_opt) cmd.memory_limit = parse_memory_limit(memory_limit);
  if (const std::string error =
          ochre::check_frame_options(*frames_opt ? std::optional<uint64_t>(frames) : std::nullopt,
                                     *first_frame_opt ? std::optional<uint64_t>(first_frame) : std::nullopt,
                                     *fps_opt ? std::optional<double>(fps) : std::nullopt);
      !error.empty())
    throw ochre::InputError(error);
  if (*relight_opt && !*frames_opt)
    throw ochre::InputError("--relight: only with --frames N (it relights the frames of a flicker sequence)");
  if (*frames_opt) {
    // A sequence renders whole frames; one frame of it may be split and checkpointed like a still.
    const std::vector<const CLI::Option*> still_options = {range_opt,
                                                           part_opt,
                                                           region_opt,
                                                           tile_opt,
                                                           interval_opt,
                                                           time_limit_opt,
                                                           render->get_option("--checkpoint"),
                                                           render->get_option("--preview")};
    const CLI::Option* still = nullptr;
    for (const CLI::Option* option : still_options)
      if (*option && !still) still = option;
    if (*resume_opt)
      throw ochre::InputError("--frames: not with --resume (the checkpoint records the frame it renders)");
    if (still && *relight_opt)
      throw ochre::InputError(fmt::format(
          "{}: not with --relight (a relit sequence is one render: split or checkpoint frames rendered "
          "without --relight)",
          still->get_name()));
    if (still && frames != 1)
      throw ochre::InputError(fmt::format(
          "{}: not with --frames {} (a sequence renders whole frames; split or checkpoint one frame at a "
          "time: --frames 1 --first-frame K)",
          still->get_name(), frames));
    cmd.first_frame = first_frame;
    cmd.fps = fps;
    if (still) {
      cmd.still_frame = first_frame;
      cmd.number_outputs = true;
    } else {
      cmd.frames = frames;
      cmd.relight = relight_frames;
    }
  }
  if (*ocio_opt) cmd.ocio_config = ocio;
  if (*display_opt) cmd.display = display;
  if (*view_opt) cmd.view = view;
  if (*cs_opt) cmd.colorspace = ochre::kWorkingSpaces.parse(colorspace);
  if (*exposure_opt) cmd.exposure = exposure;
  return ochre::run_render(cmd);
}

}  // namespace

int main(int argc, char** argv) {
  return ochre::run_program("ochre", [&] { return ochre_command(argc, argv); });
}
