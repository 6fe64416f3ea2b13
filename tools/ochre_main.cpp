// ochre command line: `ochre render SCENE.json -o OUT.exr [--png OUT.png] ...` (docs/cli.md).
#include <CLI/CLI.hpp>
#include <iostream>
#include <regex>

#include "ochre/version.h"
#include "spectra/byte_size.h"
#include "tools/frame_options.h"
#include "tools/render_command.h"
#include "tools/unsigned_option.h"

namespace {

// "WxH" -> width, height.
bool parse_resolution(const std::string& text, int& width, int& height) {
  static const std::regex pattern(R"(^(\d{1,6})x(\d{1,6})$)");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return false;
  width = std::stoi(m[1]);
  height = std::stoi(m[2]);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ochre: spectral path tracer with Mueller-matrix polarization"};
  app.set_version_flag("--version", "ochre " OCHRE_VERSION);
  app.require_subcommand(1);

  ochre::RenderCommand cmd;
  std::string resolution, ocio, display, view, colorspace;
  uint32_t spp = 0;
  int threads = -1;
  uint64_t seed = 0;
  float exposure = 0.0f;
  std::string polarization, sampler;

  CLI::App* render = app.add_subcommand("render", "Render a scene to EXR and/or PNG");
  render->add_option("scene", cmd.scene, "Scene file (JSON, docs/scene-format.md)")->required();
  render->add_option("-o,--output", cmd.exr, "Output EXR (linear working space)");
  render->add_option("--png", cmd.png, "Output display PNG (through OpenColorIO)");
  auto* spp_opt = render->add_option("--spp", spp, "Samples per pixel")->check(CLI::Range(1u, 1u << 24));
  auto* threads_opt =
      render->add_option("--threads", threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 4096));
  auto* seed_opt = render->add_option("--seed", seed, "Random seed")->check(ochre::unsigned_64_check());
  auto* res_opt = render->add_option("--resolution", resolution, "Film size WxH, e.g. 640x480");
  auto* pol_opt = render->add_option("--polarization", polarization, "auto | off | intensity | stokes")
                      ->check(CLI::IsMember({"auto", "off", "intensity", "stokes"}));
  auto* sampler_opt = render->add_option("--sampler", sampler, "independent | sobol")
                          ->check(CLI::IsMember({"independent", "sobol"}));
  auto* ocio_opt = render->add_option(
      "--ocio-config", ocio, "OCIO config path, 'builtin' or 'none' (default: $OCIO, else built-in)");
  auto* display_opt = render->add_option("--display", display, "OCIO display (default: the config's)");
  auto* view_opt = render->add_option("--view", view, "OCIO view (default: the display's)");
  auto* cs_opt = render->add_option("--colorspace", colorspace, "EXR working space: rec709 | acescg")
                     ->check(CLI::IsMember({"rec709", "acescg"}));
  auto* exposure_opt = render->add_option("--exposure", exposure, "Exposure of the display image, in stops")
                           ->check(CLI::Range(-64.0, 64.0));  // as output.exposure
  render->add_flag("-q,--quiet", cmd.quiet, "No progress or statistics");
  render
      ->add_option("--spectral-bins", cmd.spectral_bins, "Add N spectral radiance layers S0.<nm> to the EXR")
      ->check(CLI::Range(1, 471));
  render->add_flag("--aovs", cmd.aovs, "Add albedo, normal, depth and sample-count layers to the EXR");
  render->add_flag("--stokes", cmd.stokes,
                   "Add Stokes layers S0..S3 (XYZ-weighted; per spectral bin with --spectral-bins), DoLP and "
                   "AoLP to the EXR (polarization mode stokes)");
  render->add_option("--polarization-png", cmd.polarization_png,
                     "Write a false-colour PNG of the degree (brightness) and angle (hue) of linear "
                     "polarization");
  std::string memory_limit;
  auto* memory_opt = render->add_option(
      "--memory-limit", memory_limit,
      "Refuse (exit 2) a film, mesh or image whose estimated memory exceeds SIZE, e.g. 8G, 512M "
      "(default: the machine's memory)");

  uint64_t frames = 0, first_frame = 1;
  double fps = 24.0;
  auto* frames_opt = render->add_option("--frames", frames,
                                        "Render a sequence of N frames in which flames flicker, written as "
                                        "OUT.0001.exr ... (docs/cli.md#frame-sequences)");
  auto* first_frame_opt = render->add_option("--first-frame", first_frame,
                                             "Number of the first frame of the sequence (default 1)");
  auto* fps_opt = render->add_option("--fps", fps, "Frames per second of the sequence (default 24)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // --help / --version exit 0; bad usage is bad input
  }

  if (*spp_opt) cmd.overrides.spp = spp;
  if (*threads_opt) cmd.overrides.threads = threads;
  if (*seed_opt) cmd.overrides.seed = seed;
  if (*pol_opt) cmd.overrides.polarization = polarization;
  if (*sampler_opt) cmd.overrides.sampler = sampler;
  if (*res_opt) {
    int w = 0, h = 0;
    if (!parse_resolution(resolution, w, h) || w < 1 || h < 1) {
      std::cerr << "ochre: error: --resolution: expected WxH with positive integers, got '" << resolution
                << "'\n";
      return 2;
    }
    cmd.overrides.width = w;
    cmd.overrides.height = h;
  }
  if (*memory_opt) {
    cmd.memory_limit = ochre::parse_byte_size(memory_limit);
    if (!cmd.memory_limit) {
      std::cerr << "ochre: error: --memory-limit: expected a size such as 8G, 512M or 1048576 (bytes), got '"
                << memory_limit << "'\n";
      return 2;
    }
  }
  if (const std::string error =
          ochre::check_frame_options(*frames_opt ? std::optional<uint64_t>(frames) : std::nullopt,
                                     *first_frame_opt ? std::optional<uint64_t>(first_frame) : std::nullopt,
                                     *fps_opt ? std::optional<double>(fps) : std::nullopt);
      !error.empty()) {
    std::cerr << "ochre: error: " << error << "\n";
    return 2;
  }
  if (*frames_opt) {
    cmd.frames = frames;
    cmd.first_frame = first_frame;
    cmd.fps = fps;
  }
  if (*ocio_opt) cmd.ocio_config = ocio;
  if (*display_opt) cmd.display = display;
  if (*view_opt) cmd.view = view;
  if (*cs_opt) cmd.colorspace = colorspace;
  if (*exposure_opt) cmd.exposure = exposure;
  return ochre::run_render(cmd);
}
