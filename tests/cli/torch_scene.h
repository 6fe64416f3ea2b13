#pragma once
// The scene of the frame-sequence tests (tests/cli/frame_sequences_test.cpp, the Slurm frame tests): a wall
// lit by a torch and a grease lamp whose flames flicker from frame to frame (docs/cli.md#frame-sequences),
// 24x16 pixels, 4 samples per pixel: a frame renders in milliseconds.

namespace ochre::test {

inline constexpr const char* kTorchScene = R"({
  "camera": {"eye": [0, 1, 4], "target": [0, 1, 0], "fov": 50},
  "film": {"resolution": [24, 16]},
  "integrator": {"spp": 4},
  "materials": {"rock": {"type": "lambert", "color": [0.6, 0.5, 0.4]}},
  "lights": [{"type": "flame", "preset": "torch", "position": [0.3, 1.2, 0.5]},
             {"type": "flame", "preset": "grease_lamp", "position": [-0.5, 0.8, 0.4],
              "flicker": {"cct_std": 50, "position_std": 0.01}}],
  "shapes": [{"type": "plane", "size": [6, 4], "material": "rock", "transform": [{"translate": [0, 1, 0]}]}]
})";

}  // namespace ochre::test
