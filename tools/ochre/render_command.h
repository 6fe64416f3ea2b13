#pragma once
// `ochre render`: loads a scene, renders it, writes the outputs. Returns the process exit code
// (docs/cli.md, "Exit codes"; tools/cli/program.h): 0 success, 2 memory exhausted while loading the scene or
// allocating or writing the outputs (nothing written), 1 memory exhausted while rendering, 3 stopped at
// --time-limit with the image of the samples done and a checkpoint written. Bad input (a request larger
// than the memory limit included) throws InputError, GraphError or ImageError, as every other failure
// throws: run_program reports it (exit 2 or 1).

#include <cstdint>
#include <optional>
#include <string>

#include "renderer/film/render_split.h"
#include "renderer/loader/scene_loader.h"

namespace ochre {

struct RenderCommand {
  std::string scene;
  std::string exr, png;  // override the scene's outputs (relative to the working directory)
  SceneOverrides overrides;
  std::optional<std::string> ocio_config, display, view;
  std::optional<ColorSpace> colorspace;
  std::optional<float> exposure;
  bool quiet = false;
  bool aovs = false;
  int spectral_bins = 0;
  bool stokes = false;                        // Stokes layers in the EXR
  std::string polarization_png;               // false-colour DoLP / AoLP PNG
  std::optional<std::uint64_t> memory_limit;  // bytes (--memory-limit); default: the machine's memory

  // A part of a split render (docs/distributed.md): -o then names the file of its partial sums.
  std::optional<SampleRange> sample_range;            // --sample-range A:B
  std::optional<std::pair<uint32_t, uint32_t>> part;  // --part I/N: the I-th of N sample ranges
  std::optional<PixelRect> region;                    // --region x0,y0,x1,y1
  std::optional<GridTile> tile;                       // --tile I/CxR: a region of a grid of tiles
  bool split() const { return sample_range || part || region || tile; }

  // Checkpoints (docs/distributed.md): on when any of these is given.
  std::string checkpoint;                     // --checkpoint FILE (default: beside the first output)
  std::optional<double> checkpoint_interval;  // --checkpoint-interval, seconds
  std::optional<double> time_limit;           // --time-limit, seconds from the start of the command
  std::string resume;                         // --resume CHECKPOINT
  bool preview = false;                       // --preview: refresh the PNG at each checkpoint
  bool checkpointing() const {
    return !checkpoint.empty() || checkpoint_interval || time_limit || !resume.empty();
  }
  // A frame sequence (docs/cli.md#frame-sequences): frames first_frame .. first_frame + frames - 1 at fps
  // frames per second, each written to the output names with the frame number inserted.
  std::optional<std::uint64_t> frames;
  std::uint64_t first_frame = 1;
  double fps = 24.0;
  // --relight: the sequence from one render, relit per frame (tools/ochre/relit_frames.h).
  bool relight = false;
  // One frame of a sequence rendered like a still, so that it can be split and checkpointed (`--frames 1
  // --first-frame K` with a split or checkpoint option; a resumed frame): frame `still_frame` at `fps`.
  // `number_outputs` inserts the frame number into the output names as a sequence does (a resumed render
  // has the numbered names from its checkpoint).
  std::optional<std::uint64_t> still_frame;
  bool number_outputs = false;
  // --check-settings: check the command line against the scene's settings (load_render_job: no geometry,
  // materials or lights), print what would be rendered, render and write nothing (docs/cli.md).
  bool check_settings = false;
};

int run_render(const RenderCommand& command);

}  // namespace ochre
